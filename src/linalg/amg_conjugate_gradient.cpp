#include "linalg/amg_conjugate_gradient.hpp"

#include <mpi.h>
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>

#include <algorithm>
#include <cstdlib>
#include <new>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "fabform/error.hpp"
#include "linalg/sparse_transpose.hpp"

namespace fabform {

namespace {

static_assert(sizeof(HYPRE_BigInt) == sizeof(int) && sizeof(HYPRE_Int) == sizeof(int),
              "hypre built with 64-bit indices: the index arrays below are int");

void check(HYPRE_Int code, const char* what) {
  if (code == 0) return;
  char description[256] = {};
  HYPRE_DescribeError(code, description);
  HYPRE_ClearAllErrors();
  throw std::runtime_error(std::string("hypre ") + what + " failed: " + description);
}

// MPI and hypre are started once per process, on first use, and finished at its exit; a process
// that never solves with multigrid never starts MPI.
class HypreSession {
 public:
  static void ensure() { static HypreSession session; }

 private:
  HypreSession() {
    int running = 0;
    MPI_Initialized(&running);
    if (!running) {
      int provided = 0;
      if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        throw SystemError("MPI", "start for hypre's multigrid", "MPI_Init_thread failed");
      started_mpi_ = true;
    }
    check(HYPRE_Init(), "initialisation");
  }
  ~HypreSession() {
    HYPRE_Finalize();
    int finished = 0;
    MPI_Finalized(&finished);
    if (started_mpi_ && !finished) MPI_Finalize();
  }
  bool started_mpi_ = false;
};

// The one process owns every row.
struct IjMatrix {
  HYPRE_IJMatrix ij = nullptr;
  explicit IjMatrix(int n) { check(HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, n - 1, 0, n - 1, &ij), "matrix creation"); }
  ~IjMatrix() { HYPRE_IJMatrixDestroy(ij); }
  IjMatrix(const IjMatrix&) = delete;
  IjMatrix& operator=(const IjMatrix&) = delete;
  HYPRE_ParCSRMatrix parcsr() const {
    void* object = nullptr;
    check(HYPRE_IJMatrixGetObject(ij, &object), "matrix access");
    return static_cast<HYPRE_ParCSRMatrix>(object);
  }
};

struct IjVector {
  HYPRE_IJVector ij = nullptr;
  IjVector(const std::vector<int>& rows, const double* values) {
    const int n = static_cast<int>(rows.size());
    check(HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, &ij), "vector creation");
    check(HYPRE_IJVectorSetObjectType(ij, HYPRE_PARCSR), "vector creation");
    check(HYPRE_IJVectorInitialize(ij), "vector creation");
    check(HYPRE_IJVectorSetValues(ij, n, rows.data(), values), "vector values");
    check(HYPRE_IJVectorAssemble(ij), "vector assembly");
  }
  ~IjVector() { HYPRE_IJVectorDestroy(ij); }
  IjVector(const IjVector&) = delete;
  IjVector& operator=(const IjVector&) = delete;
  HYPRE_ParVector par() const {
    void* object = nullptr;
    check(HYPRE_IJVectorGetObject(ij, &object), "vector access");
    return static_cast<HYPRE_ParVector>(object);
  }
};

// BoomerAMG as a preconditioner for a stiffness matrix: HMIS coarsening with extended+i
// interpolation (at most 4 entries a row) and one level of aggressive coarsening keep the
// hierarchy's cost near the matrix's own; l1 Gauss–Seidel, forward then backward, keeps the
// V-cycle symmetric, as conjugate gradients require. The "unknown" approach (the node's
// components coarsened separately) is hypre's advice for systems such as elasticity.
struct BoomerAmg {
  HYPRE_Solver solver = nullptr;
  explicit BoomerAmg(const std::vector<int>& component) {
    check(HYPRE_BoomerAMGCreate(&solver), "BoomerAMG creation");
    HYPRE_BoomerAMGSetMaxIter(solver, 1);
    HYPRE_BoomerAMGSetTol(solver, 0.0);
    HYPRE_BoomerAMGSetPrintLevel(solver, 0);
    HYPRE_BoomerAMGSetCoarsenType(solver, 10);
    HYPRE_BoomerAMGSetInterpType(solver, 6);
    HYPRE_BoomerAMGSetPMaxElmts(solver, 4);
    HYPRE_BoomerAMGSetAggNumLevels(solver, 1);
    HYPRE_BoomerAMGSetStrongThreshold(solver, 0.25);
    HYPRE_BoomerAMGSetRelaxType(solver, 8);
    int functions = 1;
    for (int c : component) functions = std::max(functions, c + 1);
    HYPRE_BoomerAMGSetNumFunctions(solver, functions);
    // hypre takes the array and frees it with its host allocator, which is free().
    auto* owned = static_cast<HYPRE_Int*>(std::malloc(component.size() * sizeof(HYPRE_Int)));
    if (!owned) throw std::bad_alloc();
    std::copy(component.begin(), component.end(), owned);
    HYPRE_BoomerAMGSetDofFunc(solver, owned);
  }
  ~BoomerAmg() { HYPRE_BoomerAMGDestroy(solver); }
  BoomerAmg(const BoomerAmg&) = delete;
  BoomerAmg& operator=(const BoomerAmg&) = delete;
};

struct Pcg {
  HYPRE_Solver solver = nullptr;
  Pcg() {
    check(HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &solver), "PCG creation");
    HYPRE_PCGSetTwoNorm(solver, 1);  // ‖r‖₂ / ‖b‖₂, not the preconditioned norm
    HYPRE_PCGSetPrintLevel(solver, 0);
  }
  ~Pcg() { HYPRE_ParCSRPCGDestroy(solver); }
  Pcg(const Pcg&) = delete;
  Pcg& operator=(const Pcg&) = delete;
};

}  // namespace

struct AmgConjugateGradient::Impl {
  std::vector<int> rows;  // 0 … n−1, the index list hypre's setters take
  std::unique_ptr<IjMatrix> matrix;
  std::unique_ptr<BoomerAmg> amg;
  std::unique_ptr<Pcg> pcg;

  // PCG's setup on `matrix`, which builds the hierarchy.
  void setup() {
    check(HYPRE_PCGSetPrecond(pcg->solver, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                              reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), amg->solver),
          "PCG preconditioner");
    const std::vector<double> zero(rows.size(), 0.0);
    const IjVector b(rows, zero.data()), x(rows, zero.data());
    check(HYPRE_ParCSRPCGSetup(pcg->solver, matrix->parcsr(), b.par(), x.par()), "BoomerAMG setup");
  }
};

AmgConjugateGradient::AmgConjugateGradient() : impl_(std::make_unique<Impl>()) { HypreSession::ensure(); }
AmgConjugateGradient::~AmgConjugateGradient() = default;

namespace {

std::unique_ptr<IjMatrix> to_hypre(const Eigen::SparseMatrix<double>& lower, const std::vector<int>& rows) {
  const RowMatrix full = whole_symmetric(lower);
  const int n = static_cast<int>(full.rows());
  std::vector<int> sizes(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) sizes[i] = full.outerIndexPtr()[i + 1] - full.outerIndexPtr()[i];
  auto m = std::make_unique<IjMatrix>(n);
  check(HYPRE_IJMatrixSetObjectType(m->ij, HYPRE_PARCSR), "matrix creation");
  check(HYPRE_IJMatrixSetRowSizes(m->ij, sizes.data()), "matrix creation");
  check(HYPRE_IJMatrixInitialize(m->ij), "matrix creation");
  check(HYPRE_IJMatrixSetValues(m->ij, n, sizes.data(), rows.data(), full.innerIndexPtr(), full.valuePtr()),
        "matrix values");
  check(HYPRE_IJMatrixAssemble(m->ij), "matrix assembly");
  return m;
}

}  // namespace

void AmgConjugateGradient::set_matrix(const Eigen::SparseMatrix<double>& lower, const std::vector<int>& component) {
  Impl& impl = *impl_;
  const int n = static_cast<int>(lower.rows());
  if (n == 0 || static_cast<int>(component.size()) != n)
    throw std::invalid_argument("AmgConjugateGradient: an empty matrix or a component per unknown missing");
  impl.rows.resize(static_cast<std::size_t>(n));
  std::iota(impl.rows.begin(), impl.rows.end(), 0);
  impl.pcg.reset();
  impl.amg.reset();
  impl.matrix = to_hypre(lower, impl.rows);
  impl.amg = std::make_unique<BoomerAmg>(component);
  impl.pcg = std::make_unique<Pcg>();
  impl.setup();
}

CgResult AmgConjugateGradient::solve(const Eigen::VectorXd& b, double relative_tolerance, int max_iterations) const {
  const Impl& impl = *impl_;
  if (!impl.pcg) throw std::logic_error("AmgConjugateGradient::solve before set_matrix");
  if (b.size() != static_cast<Eigen::Index>(impl.rows.size()))
    throw std::invalid_argument("AmgConjugateGradient::solve: b has the wrong size");
  CgResult result;
  result.x = Eigen::VectorXd::Zero(b.size());
  if (b.squaredNorm() == 0.0) return result;
  const IjVector rhs(impl.rows, b.data()), x(impl.rows, result.x.data());
  HYPRE_PCGSetTol(impl.pcg->solver, relative_tolerance);
  HYPRE_PCGSetMaxIter(impl.pcg->solver, max_iterations);
  const HYPRE_Int code = HYPRE_ParCSRPCGSolve(impl.pcg->solver, impl.matrix->parcsr(), rhs.par(), x.par());
  // Stopping at the iteration cap is an answer (the last iterate), not a failure.
  check(code & ~HYPRE_ERROR_CONV, "PCG solve");
  HYPRE_ClearAllErrors();
  HYPRE_PCGGetNumIterations(impl.pcg->solver, &result.iterations);
  HYPRE_PCGGetFinalRelativeResidualNorm(impl.pcg->solver, &result.relative_residual);
  check(HYPRE_IJVectorGetValues(x.ij, static_cast<int>(impl.rows.size()), impl.rows.data(), result.x.data()),
        "solution");
  return result;
}

}  // namespace fabform
