#include "linalg/linear_solver.hpp"

#include <stdexcept>
#include <utility>

#include "linalg/amg_conjugate_gradient.hpp"
#include "linalg/lattice_multigrid.hpp"
#include "linalg/sparse_cholesky.hpp"

namespace fabform {

std::string to_string(LinearMethod method) {
  switch (method) {
    case LinearMethod::automatic: return "auto";
    case LinearMethod::cholesky: return "cholesky";
    case LinearMethod::multigrid: return "multigrid";
  }
  return "";
}

bool linear_method_named(const std::string& name, LinearMethod* method) {
  for (LinearMethod m : {LinearMethod::automatic, LinearMethod::cholesky, LinearMethod::multigrid})
    if (to_string(m) == name) {
      *method = m;
      return true;
    }
  return false;
}

LinearMethod concrete_method(LinearMethod method, const LinearSystemShape& shape) {
  if (method != LinearMethod::automatic) return method;
  const int from = !shape.lattice ? kAlgebraicMultigridMinUnknowns
                   : shape.bending ? kLatticeMultigridMinUnknowns
                                   : kMembraneMultigridMinUnknowns;
  return shape.unknowns >= from ? LinearMethod::multigrid : LinearMethod::cholesky;
}

namespace {

class CholeskySolver final : public LinearSolver {
 public:
  bool set_matrix(const Eigen::SparseMatrix<double>& lower, const UnknownLayout&) override {
    return factor_.factorize(lower);
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b, double) override { return factor_.solve(b); }
  LinearMethod method() const override { return LinearMethod::cholesky; }
  std::string name() const override { return "cholesky"; }
  long iterations() const override { return 0; }

 private:
  SparseCholesky factor_;
};

// At most this many iterations a solve: a step that has not reached its tolerance by then is
// still a descent direction, and Newton's line search judges it.
constexpr int kMaxCgIterations = 500;

// Geometric on a lattice, algebraic (BoomerAMG) without one; BoomerAMG, and the MPI it runs on,
// only started for a fabric without a lattice. A hierarchy is built for every matrix: kept for
// the next Newton step's (hypre's V-cycle takes the finest matrix from its argument), its stale
// smoother made the preconditioner indefinite.
class MultigridSolver final : public LinearSolver {
 public:
  bool set_matrix(const Eigen::SparseMatrix<double>& lower, const UnknownLayout& layout) override {
    lattice_ = layout.lattice.has_value();
    if (lattice_) {
      geometric_.set_matrix(lower, *layout.lattice);
      return true;
    }
    if (!algebraic_) algebraic_ = std::make_unique<AmgConjugateGradient>();
    algebraic_->set_matrix(lower, layout.component);
    return true;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b, double relative_tolerance) override {
    CgResult r = lattice_ ? geometric_.solve(b, relative_tolerance, kMaxCgIterations)
                          : algebraic_->solve(b, relative_tolerance, kMaxCgIterations);
    iterations_ += r.iterations;
    return std::move(r.x);
  }
  LinearMethod method() const override { return LinearMethod::multigrid; }
  std::string name() const override { return lattice_ ? "multigrid (lattice)" : "multigrid (algebraic)"; }
  long iterations() const override { return iterations_; }

 private:
  bool lattice_ = false;
  LatticeMultigrid geometric_;
  std::unique_ptr<AmgConjugateGradient> algebraic_;
  long iterations_ = 0;
};

}  // namespace

std::unique_ptr<LinearSolver> make_linear_solver(LinearMethod method) {
  switch (method) {
    case LinearMethod::cholesky: return std::make_unique<CholeskySolver>();
    case LinearMethod::multigrid: return std::make_unique<MultigridSolver>();
    case LinearMethod::automatic: break;
  }
  throw std::invalid_argument("make_linear_solver: automatic is not a method; resolve it first");
}

}  // namespace fabform
