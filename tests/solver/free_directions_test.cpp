// Newton's unknowns: one slot per free axis whatever the contact set, so that the matrix's
// pattern (and CHOLMOD's ordering of it) survives nodes landing on and leaving bodies, while a
// contact normal still takes its direction out of the step exactly.
#include "solver/free_directions.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "solver/reduced_hessian.hpp"
#include "support/clamped_fabric.hpp"

namespace fabform::free_directions_test {
namespace {

// Every third interior node presses on a body whose normal leans off the axes (so the tangent
// basis mixes all three), and one interior column is held in x.
struct Touching {
  Model model = test::clamped_fabric(6, 0.05);
  std::vector<NodeContact> free, touching;
  int touching_nodes = 0;

  Touching() {
    test::lift_interior(model, 0.01);
    for (int j = 1; j < 6; ++j) model.locks[static_cast<std::size_t>(model.fabric.node(2, j))] = kLockX;
    free.resize(model.start.size());
    touching = free;
    for (int k = 0; k < model.node_count(); ++k)
      if (!model.fabric.on_perimeter(k) && k % 3 == 0) {
        touching[static_cast<std::size_t>(k)] = NodeContact{0, Eigen::Vector3d(0.3, -0.2, 1.0).normalized()};
        ++touching_nodes;
      }
  }
};

TEST(FreeDirections, LayoutDependsOnTheLocksAlone) {
  const Touching t;
  const FreeDirections apart = free_directions(t.model, t.free);
  const FreeDirections pressed = free_directions(t.model, t.touching);
  EXPECT_EQ(apart.offset, pressed.offset);
  EXPECT_EQ(apart.used, apart.unknowns());
  ASSERT_GT(t.touching_nodes, 0);
  EXPECT_EQ(pressed.used, apart.used - t.touching_nodes);  // each loses its normal
}

// A contact node's used columns are orthonormal and tangent; the slot it lost is a zero column.
TEST(FreeDirections, ContactEmptiesTheNormalsSlot) {
  const Touching t;
  const FreeDirections d = free_directions(t.model, t.touching);
  for (int k = 0; k < t.model.node_count(); ++k) {
    const NodeContact& c = t.touching[static_cast<std::size_t>(k)];
    if (!c.active()) continue;
    const Eigen::Matrix3d& b = d.of(k);
    const int used = d.count(k) - 1;
    ASSERT_GE(used, 1) << "node " << k;
    EXPECT_EQ(b.col(used).norm(), 0.0) << "node " << k;
    for (int i = 0; i < used; ++i) {
      EXPECT_NEAR(b.col(i).norm(), 1.0, 1e-14) << "node " << k;
      EXPECT_NEAR(b.col(i).dot(c.normal), 0.0, 1e-14) << "node " << k;
    }
  }
}

// The pattern CHOLMOD orders is the same with and without contact, entry for entry; only values
// differ, and an emptied slot's row and column hold exact zeros.
TEST(FreeDirections, NewtonsPatternSurvivesContact) {
  const Touching t;
  const FreeDirections apart = free_directions(t.model, t.free);
  const FreeDirections pressed = free_directions(t.model, t.touching);
  Eigen::SparseMatrix<double> a = reduced_hessian(t.model, t.model.start, apart);
  Eigen::SparseMatrix<double> b = reduced_hessian(t.model, t.model.start, pressed);
  a.makeCompressed();
  b.makeCompressed();
  ASSERT_EQ(a.nonZeros(), b.nonZeros());
  EXPECT_TRUE(std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()));
  EXPECT_TRUE(std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr()));
  const Eigen::MatrixXd dense = Eigen::MatrixXd(b);
  for (int k = 0; k < t.model.node_count(); ++k) {
    if (!t.touching[static_cast<std::size_t>(k)].active()) continue;
    const int empty = pressed.offset[static_cast<std::size_t>(k) + 1] - 1;
    EXPECT_EQ(dense.row(empty).norm() + dense.col(empty).norm(), 0.0) << "node " << k;
  }
}

// A step's value in an emptied slot moves nothing, and the force there reads zero: the normal
// stays out of the step whatever the linear solver leaves in it.
TEST(FreeDirections, EmptySlotsCarryNothing) {
  const Touching t;
  const FreeDirections d = free_directions(t.model, t.touching);
  std::vector<Eigen::Vector3d> forces(t.model.start.size(), Eigen::Vector3d(1.0, 2.0, 3.0));
  const Eigen::VectorXd reduced = reduced_forces(d, forces);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(d.unknowns());
  const std::vector<Eigen::Vector3d> steps = node_steps(d, ones);
  for (int k = 0; k < t.model.node_count(); ++k) {
    const NodeContact& c = t.touching[static_cast<std::size_t>(k)];
    if (!c.active()) continue;
    EXPECT_EQ(reduced[d.offset[static_cast<std::size_t>(k) + 1] - 1], 0.0) << "node " << k;
    EXPECT_NEAR(steps[static_cast<std::size_t>(k)].dot(c.normal), 0.0, 1e-14) << "node " << k;
  }
}

}  // namespace
}  // namespace fabform::free_directions_test
