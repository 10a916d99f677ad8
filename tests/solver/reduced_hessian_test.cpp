// Newton's matrix against central differences of the node forces, on a taut fabric (every
// spring stretched, so projecting a spring's stiffness changes nothing) with hinges bent out of
// its plane: springs and hinges together, in the free directions of the unlocked nodes; and an
// assembler kept from step to step against a fresh one.
#include "solver/reduced_hessian.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "fabform/model/hinge_bending.hpp"
#include "fabform/thread_count.hpp"
#include "support/clamped_fabric.hpp"
#include "support/sparse_matrices.hpp"
#include "support/threads_restored.hpp"

namespace fabform::reduced_hessian_test {
namespace {

Model bent_hinged_fabric(int divisions = 4) {
  FabricSpec spec{0.1, 0.1, divisions, divisions};
  spec.hinges = true;
  Model model = test::clamped_fabric(divisions, 0.05);
  model.fabric = Fabric(spec);
  model.terms.push_back(std::make_shared<HingeBending>(2e-3));
  std::mt19937 rng(11u);
  std::uniform_real_distribution<double> lift(-0.002, 0.002);
  for (int k = 0; k < model.node_count(); ++k)
    if (!model.fabric.on_perimeter(k)) model.start[static_cast<std::size_t>(k)].z() += lift(rng);
  return model;
}

Eigen::VectorXd forces_at(const Model& model, const FreeDirections& d, const std::vector<Eigen::Vector3d>& x) {
  std::vector<Eigen::Vector3d> f;
  for (int k = 0; k < model.node_count(); ++k) f.push_back(node_force(model, x, k));
  return reduced_forces(d, f);
}

// Step 1e-7 m on node spacings of 2.5 cm: truncation ~h²·f''' and rounding ~ε·f/h both stay
// below 1e-6 of the matrix's largest entry.
TEST(ReducedHessian, IsMinusTheDerivativeOfTheNodeForces) {
  const Model model = bent_hinged_fabric();
  const std::vector<Eigen::Vector3d>& x = model.start;
  const FreeDirections d = free_directions(model, std::vector<NodeContact>(x.size()));
  ASSERT_GT(d.unknowns(), 0);
  const Eigen::MatrixXd lower(reduced_hessian(model, x, d));
  const Eigen::MatrixXd h = lower + lower.transpose() - Eigen::MatrixXd(lower.diagonal().asDiagonal());
  const double scale = h.cwiseAbs().maxCoeff();
  const double step = 1e-7;
  for (int k = 0; k < model.node_count(); ++k)
    for (int c = 0; c < d.count(k); ++c) {
      std::vector<Eigen::Vector3d> plus = x, minus = x;
      plus[static_cast<std::size_t>(k)] += step * d.of(k).col(c);
      minus[static_cast<std::size_t>(k)] -= step * d.of(k).col(c);
      const Eigen::VectorXd column = -(forces_at(model, d, plus) - forces_at(model, d, minus)) / (2.0 * step);
      EXPECT_LT((column - h.col(d.offset[static_cast<std::size_t>(k)] + c)).cwiseAbs().maxCoeff(), 1e-6 * scale)
          << "node " << k << " direction " << c;
    }
}

// Without hinges the springs alone; the hinges add to it (a check that they are in at all).
TEST(ReducedHessian, HingesAddTheirStiffness) {
  Model model = bent_hinged_fabric();
  const FreeDirections d = free_directions(model, std::vector<NodeContact>(model.start.size()));
  const Eigen::MatrixXd with(reduced_hessian(model, model.start, d));
  model.terms.pop_back();
  const Eigen::MatrixXd without(reduced_hessian(model, model.start, d));
  EXPECT_GT((with - without).cwiseAbs().maxCoeff(), 1e-3 * without.cwiseAbs().maxCoeff());
}

// Newton keeps one assembler from step to step. Kept over new positions, nodes pressed on a body
// (a slot emptied), a term that couples pairs the earlier assemblies lacked (found in a second
// pass of the terms) and a model of another size, it gives what a fresh one gives, entry for
// entry, and a pattern that only grows.
TEST(ReducedHessian, AKeptAssemblerGivesWhatAFreshOneGives) {
  Model hinged = bent_hinged_fabric();
  Model springs_only = bent_hinged_fabric();  // the same fabric and positions
  springs_only.terms.pop_back();
  std::vector<NodeContact> pressed(hinged.start.size());
  for (int k = 0; k < hinged.node_count(); k += 4)
    pressed[static_cast<std::size_t>(k)] = NodeContact{0, Eigen::Vector3d(0.3, -0.2, 1.0).normalized()};
  std::vector<Eigen::Vector3d> moved = hinged.start;
  for (Eigen::Vector3d& p : moved) p.z() += 0.3 * p.x() * p.y();
  const Model other_size = test::clamped_fabric(6, 0.05);
  struct Case {
    const char* what;
    const Model* model;
    const std::vector<Eigen::Vector3d>* x;
    std::vector<NodeContact> contact;
  };
  const std::vector<Case> cases{
      {"springs", &springs_only, &springs_only.start, std::vector<NodeContact>(hinged.start.size())},
      {"hinges too", &hinged, &hinged.start, std::vector<NodeContact>(hinged.start.size())},
      {"moved", &hinged, &moved, std::vector<NodeContact>(hinged.start.size())},
      {"pressed", &hinged, &moved, pressed},
      {"springs again", &springs_only, &moved, pressed},
      {"another size", &other_size, &other_size.start, std::vector<NodeContact>(other_size.start.size())}};
  ReducedHessian kept;
  Eigen::Index last_entries = 0;
  for (const Case& c : cases) {
    const FreeDirections d = free_directions(*c.model, c.contact);
    const Eigen::SparseMatrix<double> again = kept.assemble(*c.model, *c.x, d);
    const Eigen::SparseMatrix<double> fresh = reduced_hessian(*c.model, *c.x, d);
    EXPECT_EQ(Eigen::MatrixXd(again), Eigen::MatrixXd(fresh)) << c.what;
    if (c.model != &other_size) {
      EXPECT_GE(again.nonZeros(), last_entries) << c.what;
    }
    last_entries = again.nonZeros();
  }
}

// From 8192 springs or hinges the pairs' sums are shared among the threads by column node; each
// pair's blocks still sum in the terms' order, so 2 and 3 threads (ranges of unequal sizes)
// give one thread's matrix bit for bit, in a fresh assembler (its pairs found in the shared
// pass) and a kept one, with nodes of 1, 2 and 3 free directions.
TEST(ReducedHessian, SameBitsOnAnyThreadCount) {
  const Model model = bent_hinged_fabric(70);
  ASSERT_GE(model.fabric.springs().size(), static_cast<std::size_t>(kMinParallelItems));
  ASSERT_GE(model.fabric.hinges().size(), static_cast<std::size_t>(kMinParallelItems));
  std::vector<NodeContact> pressed(model.start.size());
  for (int k = 0; k < model.node_count(); k += 3)
    pressed[static_cast<std::size_t>(k)] = NodeContact{0, Eigen::Vector3d(0.3, -0.2, 1.0).normalized()};
  const FreeDirections d = free_directions(model, pressed);
  const test::ThreadsRestored restored;
  use_threads(1);
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  const RowMatrix one(reduced_hessian(model, model.start, d));
  for (const int threads : {2, 3}) {
    use_threads(threads);
    ReducedHessian kept;
    const RowMatrix fresh(kept.assemble(model, model.start, d));
    const RowMatrix again(kept.assemble(model, model.start, d));
    EXPECT_TRUE(test::same_bits(fresh, one)) << threads << " threads";
    EXPECT_TRUE(test::same_bits(again, one)) << threads << " threads, kept";
  }
}

}  // namespace
}  // namespace fabform::reduced_hessian_test
