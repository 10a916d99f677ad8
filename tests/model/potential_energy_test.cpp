// The total potential energy and the node forces every solver uses are one model: with the
// stretch of measured tables, seed 004's shear and bend springs and the fabric's weight,
// −∂Π/∂x_k is node_force at every node, checked by central differences.
#include "fabform/model/potential_energy.hpp"

#include <gtest/gtest.h>

#include <initializer_list>
#include <memory>
#include <random>
#include <string>

#include "fabform/material/material_csv.hpp"
#include "fabform/model/gravity.hpp"
#include "fabform/model/hinge_bending.hpp"
#include "fabform/model/spring_term.hpp"
#include "test_paths.hpp"

namespace fabform::potential_energy_test {
namespace {

// A free fabric of a shipped material, weighed with its density.
Model weighed_fabric(const Fabric& grid, const std::string& fabric, double density_kg_m2) {
  Model model{grid,
              read_material_table(test::source_path("materials/" + fabric + "_warp.csv")),
              read_material_table(test::source_path("materials/" + fabric + "_weft.csv")),
              std::vector<AxisMask>(static_cast<std::size_t>(grid.node_count()), 0),
              {},
              {}};
  model.terms.push_back(std::make_shared<Gravity>(grid, density_kg_m2, kStandardGravity_m_s2));
  return model;
}

// −∂Π/∂x_k against node_force at every node and axis. h: truncation error ~h²·Π''' and
// rounding ~ε·Π/h balance near 1e-7 m for these forces; the tolerance is relative to the
// largest force, 1e-6.
void expect_forces_are_minus_the_gradient(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  const double h = 1e-7;
  double largest = 0.0;
  for (int k = 0; k < model.node_count(); ++k) largest = std::max(largest, node_force(model, x, k).norm());
  ASSERT_GT(largest, 0.0);
  for (int k = 0; k < model.node_count(); ++k) {
    const Eigen::Vector3d force = node_force(model, x, k);
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<Eigen::Vector3d> plus = x, minus = x;
      plus[static_cast<std::size_t>(k)][axis] += h, minus[static_cast<std::size_t>(k)][axis] -= h;
      const double slope = (potential_energy(model, plus) - potential_energy(model, minus)) / (2 * h);
      EXPECT_NEAR(-slope, force[axis], 1e-6 * largest) << "node " << k << " axis " << axis;
    }
  }
}

// Stretched by 5–15 %, away from the tables' kinks at 0 strain, and crumpled out of plane.
std::vector<Eigen::Vector3d> stretched_and_crumpled(const Fabric& fabric, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.001, 0.001);
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < fabric.node_count(); ++k)
    x.push_back(1.1 * fabric.rest_position(k) + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng)));
  return x;
}

// Moving one node changes Π by node_energy_change: the same number relax judges its steps by.
// The whole's difference carries the rounding of Π (~1e-16 of it); the node's does not.
void expect_node_changes_are_the_whole(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                       std::initializer_list<int> nodes) {
  for (const int node : nodes) {
    const Eigen::Vector3d at = x[static_cast<std::size_t>(node)] + Eigen::Vector3d(0.001, -0.0005, -0.002);
    std::vector<Eigen::Vector3d> moved = x;
    moved[static_cast<std::size_t>(node)] = at;
    const double whole = potential_energy(model, moved) - potential_energy(model, x);
    EXPECT_NEAR(node_energy_change(model, x, node, at), whole, 1e-9 * std::abs(whole)) << node;
  }
}

TEST(PotentialEnergy, MinusItsGradientIsTheNodeForceWithGravity) {
  const Fabric grid({0.1, 0.08, 6, 4});
  expect_forces_are_minus_the_gradient(weighed_fabric(grid, "white-swim-solid", 0.204),
                                       stretched_and_crumpled(grid, 11u));
}

// Seed 004's shear springs (the knit's measured bias table) and bend springs (linear in tension
// and compression, as the model builder makes them), on seed 000's circles.
TEST(PotentialEnergy, MinusItsGradientIsTheNodeForceWithShearAndBendSprings) {
  FabricSpec lattice{0.1, 0.1, 6, 6};
  lattice.shape = FabricSpec::Shape::circle;
  FabricSpec arc = lattice;
  arc.mesh = FabricSpec::Mesh::arc, arc.rings = 3, arc.spokes = 8;
  for (FabricSpec spec : {lattice, arc}) {
    spec.shear_springs = true;
    spec.bend_springs = true;
    const Fabric fabric(spec);
    Model model = weighed_fabric(fabric, "white-swim-solid", 0.204);
    model.shear = read_material_table(test::source_path("materials/white-swim-solid_shear.csv"));
    model.bend = TensionTable({{-1.0, -5.0}, {0.0, 0.0}, {1.0, 5.0}}, "bend");
    SCOPED_TRACE(spec.mesh == FabricSpec::Mesh::arc ? "arc" : "lattice");
    expect_forces_are_minus_the_gradient(model, stretched_and_crumpled(fabric, 12u));
  }
}

// Hinges with a measured flexural rigidity, crumpled enough that they bend.
TEST(PotentialEnergy, MinusItsGradientIsTheNodeForceWithHinges) {
  FabricSpec spec{0.1, 0.1, 0, 0};
  spec.shape = FabricSpec::Shape::circle, spec.mesh = FabricSpec::Mesh::arc, spec.rings = 3, spec.spokes = 8;
  spec.hinges = true;
  const Fabric fabric(spec);
  Model model = weighed_fabric(fabric, "white-swim-solid", 0.204);
  const auto hinges = std::make_shared<HingeBending>(5.56e-5);
  model.terms.push_back(hinges);
  std::vector<Eigen::Vector3d> x = stretched_and_crumpled(fabric, 13u);
  for (auto& p : x) p.z() += 0.2 * (p.x() - 0.05) * (p.x() - 0.05) / 0.05;  // and curved
  ASSERT_GT(hinges->energy(model, x), 1e-3 * energy_baseline(model, x).stored);
  expect_forces_are_minus_the_gradient(model, x);
}

// Relax judges a node's step by its own energy change; with hinges that includes theirs.
TEST(PotentialEnergy, NodeEnergyChangeIsTheChangeOfTheWholeWithHinges) {
  FabricSpec spec{0.1, 0.08, 5, 4};
  spec.hinges = true;
  const Fabric grid(spec);
  Model model = weighed_fabric(grid, "ivory-rib-knit", 0.276);
  model.terms.push_back(std::make_shared<HingeBending>(4e-5));
  const std::vector<Eigen::Vector3d> x = stretched_and_crumpled(grid, 14u);
  expect_node_changes_are_the_whole(model, x, {0, grid.node(2, 1), grid.node(4, 3)});
}

TEST(PotentialEnergy, NodeEnergyChangeIsTheChangeOfTheWhole) {
  const Fabric grid({0.1, 0.08, 5, 4});
  const Model model = weighed_fabric(grid, "ivory-rib-knit", 0.276);
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < grid.node_count(); ++k) x.push_back(1.08 * grid.rest_position(k));
  expect_node_changes_are_the_whole(model, x, {0, grid.node(2, 1), grid.node(4, 3)});
}

TEST(PotentialEnergy, WithoutLoadsItIsTheStretchEnergy) {
  const Fabric grid({0.1, 0.1, 2, 2});
  const TensionTable table({{0.0, 0.0}, {1.0, 100.0}}, "linear");
  Model model{grid, table, table, std::vector<AxisMask>(9, 0), {}, {}};
  std::vector<Eigen::Vector3d> x;
  for (int k = 0; k < grid.node_count(); ++k) x.push_back(1.2 * grid.rest_position(k));
  EXPECT_EQ(potential_energy(model, x), SpringTerm(SpringTerm::Role::stretch).energy(model, x));
  EXPECT_GT(potential_energy(model, x), 0.0);
}

}  // namespace
}  // namespace fabform::potential_energy_test
