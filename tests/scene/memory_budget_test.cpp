// A run too large for the machine is refused before it allocates, with the estimate and what the
// machine has; the node count it estimates from is the one the fabric then has.
#include "fabform/scene/memory_budget.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fabform/error.hpp"
#include "fabform/fabric/fabric.hpp"

namespace fabform::memory_budget_test {
namespace {

FabricSpec rectangle(int warp, int weft) {
  FabricSpec spec;
  spec.divisions_warp = warp, spec.divisions_weft = weft;
  return spec;
}

FabricSpec circle(FabricSpec::Mesh mesh, int divisions, int rings = 0, int spokes = 0) {
  FabricSpec spec;
  spec.shape = FabricSpec::Shape::circle;
  spec.mesh = mesh;
  spec.divisions_warp = spec.divisions_weft = divisions;
  spec.rings = rings, spec.spokes = spokes;
  return spec;
}

TEST(MemoryBudget, RectangleAndArcCountsAreExact) {
  for (const FabricSpec& spec : {rectangle(1, 1), rectangle(7, 3), rectangle(40, 40),
                                 circle(FabricSpec::Mesh::arc, 0, 1, 3), circle(FabricSpec::Mesh::arc, 0, 12, 40)})
    EXPECT_EQ(expected_nodes(spec), Fabric(spec).node_count());
}

// A circle's lattice points inside it: the disc's area in cells, within the boundary's cells.
TEST(MemoryBudget, CircleLatticeCountIsCloseToTheFabrics) {
  for (int divisions : {10, 24, 61, 120}) {
    const FabricSpec spec = circle(FabricSpec::Mesh::quadrangular, divisions);
    const double actual = Fabric(spec).node_count();
    EXPECT_NEAR(expected_nodes(spec), actual, 4.0 * (divisions + 1)) << divisions << " divisions";
  }
}

TEST(MemoryBudget, NewtonNeedsMoreThanTheExplicitSolvers) {
  EXPECT_GT(least_run_bytes(1e6, "newton"), least_run_bytes(1e6, "relax"));
  EXPECT_EQ(least_run_bytes(2e6, "relax"), 2.0 * least_run_bytes(1e6, "relax"));
  EXPECT_EQ(least_run_bytes(1e6, "dynamic"), least_run_bytes(1e6, "relax"));
}

TEST(MemoryBudget, MachineMemoryIsReadAndPlausible) {
  const double available = available_memory_bytes();
  EXPECT_GT(available, 1e6);
  EXPECT_LT(available, 1e15) << "no limit read where Linux has /proc/meminfo";
}

Scene scene_of(const FabricSpec& spec, const std::string& solver) {
  Scene scene;
  scene.fabric = spec;
  scene.fabric_where = {"scene.toml", 3, "fabric.divisions"};
  scene.solver.name = solver;
  return scene;
}

TEST(MemoryBudget, RefusesWhatCannotFitNamingTheKeyAndTheFigures) {
  const Scene huge = scene_of(rectangle(7000, 7000), "relax");  // 49 million nodes
  try {
    check_memory_budget(huge, 24e9);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where().line, 3);
    EXPECT_EQ(std::string(error.what()),
              "scene.toml:3: fabric.divisions: a fabric of 4.9e+07 nodes needs at least 36.8 GB with solver relax; "
              "this machine has 24.0 GB available: use fewer divisions");
  }
}

TEST(MemoryBudget, AcceptsWhatFits) {
  EXPECT_NO_THROW(check_memory_budget(scene_of(rectangle(1000, 1000), "newton"), 24e9));
  EXPECT_NO_THROW(check_memory_budget(scene_of(rectangle(200, 200), "relax"), 1e9));
  EXPECT_THROW(check_memory_budget(scene_of(rectangle(1000, 1000), "newton"), 1e9), InputError);
}

}  // namespace
}  // namespace fabform::memory_budget_test
