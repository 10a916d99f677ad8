// Newton's choice of linear solve: the names a scene gives, the size at which `auto` turns to
// multigrid, and both methods solving the same system to the accuracy each promises.
#include "linalg/linear_solver.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "support/grid_stiffness.hpp"

namespace fabform::linear_solver_test {
namespace {

TEST(LinearSolver, NamesRoundTrip) {
  for (LinearMethod m : {LinearMethod::automatic, LinearMethod::cholesky, LinearMethod::multigrid}) {
    LinearMethod read = LinearMethod::automatic;
    ASSERT_TRUE(linear_method_named(to_string(m), &read)) << to_string(m);
    EXPECT_EQ(read, m);
  }
  LinearMethod unchanged = LinearMethod::cholesky;
  EXPECT_FALSE(linear_method_named("lu", &unchanged));
  EXPECT_FALSE(linear_method_named("Multigrid", &unchanged));
  EXPECT_EQ(unchanged, LinearMethod::cholesky);
}

TEST(LinearSolver, AutoTurnsToMultigridAtItsSize) {
  struct Case {
    bool lattice, bending;
    int from;
  };
  for (const Case& c : {Case{true, false, kMembraneMultigridMinUnknowns}, Case{true, true, kLatticeMultigridMinUnknowns},
                        Case{false, false, kAlgebraicMultigridMinUnknowns},
                        Case{false, true, kAlgebraicMultigridMinUnknowns}}) {
    SCOPED_TRACE(testing::Message() << "lattice " << c.lattice << ", bending " << c.bending);
    const auto of = [&](int unknowns) { return LinearSystemShape{unknowns, c.lattice, c.bending}; };
    EXPECT_EQ(concrete_method(LinearMethod::automatic, of(c.from - 1)), LinearMethod::cholesky);
    EXPECT_EQ(concrete_method(LinearMethod::automatic, of(c.from)), LinearMethod::multigrid);
    EXPECT_EQ(concrete_method(LinearMethod::cholesky, of(1 << 30)), LinearMethod::cholesky);
    EXPECT_EQ(concrete_method(LinearMethod::multigrid, of(3)), LinearMethod::multigrid);
  }
  // The dome as shipped (201 × 201 nodes, its perimeter held, a membrane) takes multigrid; the
  // 51 × 51 grid its continuation starts from, the factorisation. A node on the body keeps two
  // of its three unknowns.
  EXPECT_GE(2 * 199 * 199, kMembraneMultigridMinUnknowns);
  EXPECT_LT(3 * 49 * 49, kMembraneMultigridMinUnknowns);
  EXPECT_THROW(make_linear_solver(LinearMethod::automatic), std::invalid_argument);
}

TEST(LinearSolver, EveryMethodSolvesTheSameSystem) {
  const int side = 16;
  const Eigen::SparseMatrix<double> lower = test::grid_stiffness(side, 0.01);
  const Eigen::SparseMatrix<double> a = test::symmetric(lower);
  UnknownLayout mesh{test::xyz_components(lower.rows()), std::nullopt};
  UnknownLayout lattice{test::xyz_components(lower.rows()), test::grid_lattice(side)};
  Eigen::VectorXd b(lower.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = std::sin(0.1 * static_cast<double>(i));
  struct Case {
    LinearMethod method;
    const UnknownLayout* layout;
    std::string name;
  };
  for (const Case& c : {Case{LinearMethod::cholesky, &lattice, "cholesky"},
                        Case{LinearMethod::multigrid, &mesh, "multigrid (algebraic)"},
                        Case{LinearMethod::multigrid, &lattice, "multigrid (lattice)"}}) {
    const std::unique_ptr<LinearSolver> solver = make_linear_solver(c.method);
    EXPECT_EQ(solver->method(), c.method);
    ASSERT_TRUE(solver->set_matrix(lower, *c.layout));
    EXPECT_EQ(solver->name(), c.name);
    const double tolerance = 1e-5;
    const Eigen::VectorXd x = solver->solve(b, tolerance);
    const double residual = (b - a * x).norm() / b.norm();
    EXPECT_LE(residual, c.method == LinearMethod::cholesky ? 1e-12 : tolerance) << c.name;
    EXPECT_EQ(solver->iterations() > 0, c.method == LinearMethod::multigrid) << c.name;
  }
}

TEST(LinearSolver, CholeskyFindsAnIndefiniteMatrix) {
  Eigen::SparseMatrix<double> lower = test::grid_stiffness(5, 0.01);
  lower.coeffRef(7, 7) = -1.0;
  const std::unique_ptr<LinearSolver> solver = make_linear_solver(LinearMethod::cholesky);
  EXPECT_FALSE(solver->set_matrix(lower, UnknownLayout{test::xyz_components(lower.rows()), std::nullopt}));
}

}  // namespace
}  // namespace fabform::linear_solver_test
