// The fabric's springs as terms: stretch (warp and weft), shear and bend springs, each checked
// on its own against its energy by central differences, on measured tables.
#include "fabform/model/spring_term.hpp"

#include <gtest/gtest.h>

#include <random>

#include "fabform/fabric/spring.hpp"
#include "fabform/material/material_csv.hpp"
#include "support/term_checks.hpp"
#include "test_paths.hpp"

namespace fabform::spring_term_test {
namespace {

// A free fabric of the shipped swimwear knit with shear and bend springs and their tables.
Model knit_with_every_spring(const FabricSpec& layout) {
  FabricSpec spec = layout;
  spec.shear_springs = spec.bend_springs = true;
  const Fabric fabric(spec);
  const auto table = [](const char* direction) {
    return read_material_table(test::source_path(std::string("materials/white-swim-solid_") + direction + ".csv"));
  };
  Model model{fabric, table("warp"), table("weft"),
              std::vector<AxisMask>(static_cast<std::size_t>(fabric.node_count()), 0), {}, {}};
  model.shear = table("shear");
  model.bend = TensionTable({{-1.0, -5.0}, {0.0, 0.0}, {1.0, 5.0}}, "bend");
  return model;
}

// Stretched by 8 % and jittered by a tenth of that: every spring in tension, away from its
// table's kinks, where the projected stiffness is the exact one.
Positions stretched(const Fabric& fabric, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-2e-4, 2e-4);
  Positions x;
  for (int k = 0; k < fabric.node_count(); ++k)
    x.push_back(1.08 * fabric.rest_position(k) + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng)));
  return x;
}

class SpringTermRoles : public testing::TestWithParam<SpringTerm::Role> {};

// h = 1e-7 m on 2.5 cm springs: truncation ~h²·F''' and rounding ~ε·E/h both below 1e-6 of
// the largest force or stiffness.
TEST_P(SpringTermRoles, AgreeWithTheirEnergyByFiniteDifferences) {
  const Model model = knit_with_every_spring({0.1, 0.08, 4, 3});
  const SpringTerm term(GetParam());
  const Positions x = stretched(model.fabric, 3u);
  test::expect_force_is_minus_the_gradient(model, term, x, 1e-7, 1e-6);
  test::expect_node_changes_are_the_whole(model, term, x, {0, model.fabric.node(2, 1), model.fabric.node(4, 3)},
                                          Eigen::Vector3d(1e-4, -2e-4, 3e-4));
  test::expect_stiffness_is_minus_the_force_derivative(model, term, x, 1e-7, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(SpringTerm, SpringTermRoles,
                         testing::Values(SpringTerm::Role::stretch, SpringTerm::Role::shear, SpringTerm::Role::bend));

// Each role takes its own springs and no other: the three forces sum to all springs' force.
TEST(SpringTerm, RolesPartitionTheSprings) {
  const Model model = knit_with_every_spring({0.1, 0.08, 4, 3});
  ASSERT_EQ(model.terms.size(), 3u) << "the model starts with a term per kind of spring it has";
  const Positions x = stretched(model.fabric, 4u);
  for (int k = 0; k < model.node_count(); ++k) {
    Eigen::Vector3d all = Eigen::Vector3d::Zero();
    for (const int s : model.fabric.springs_at(k)) {
      const Spring& spring = model.fabric.springs()[static_cast<std::size_t>(s)];
      all += spring_force_on_a(x[static_cast<std::size_t>(k)], x[static_cast<std::size_t>(spring.a == k ? spring.b : spring.a)],
                               spring, model.table(spring.kind));
    }
    EXPECT_LT((node_force(model, x, k) - all).norm(), 1e-12 * all.norm()) << k;
  }
  EXPECT_TRUE(SpringTerm(SpringTerm::Role::bend).resists_bending());
  EXPECT_FALSE(SpringTerm(SpringTerm::Role::stretch).resists_bending());
}

TEST(SpringTerm, SaysWhatItModels) {
  const Model model = knit_with_every_spring({0.1, 0.08, 4, 3});
  const std::vector<std::string> lines = model.modelled();
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "stretch: warp and weft springs of a rectangle of 20 nodes, tension-only piecewise-linear tables");
  EXPECT_NE(lines[1].find("white-swim-solid_shear.csv"), std::string::npos) << lines[1];
  EXPECT_EQ(lines[2], "bending: skip-one bend springs, linear in tension and compression, 5 N/m per width");
}

}  // namespace
}  // namespace fabform::spring_term_test
