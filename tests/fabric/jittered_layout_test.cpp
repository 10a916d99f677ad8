// The jittered circle (issue 22, item 4): the quadrangular lattice's cut with its inner nodes
// moved by a seeded draw. The moves keep their bound, repeat per seed, leave every cell convex
// and every side in its lattice family, and the springs take the moved distances as rest lengths.
#include "fabform/fabric/fabric.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace fabform::jittered_layout_test {
namespace {

FabricSpec jittered(int divisions, std::uint64_t seed, double jitter = kMaxJitter) {
  FabricSpec spec{0.3, 0.3, divisions, divisions};
  spec.shape = FabricSpec::Shape::circle;
  spec.mesh = FabricSpec::Mesh::jittered;
  spec.jitter = jitter;
  spec.jitter_seed = seed;
  spec.shear_springs = true;
  return spec;
}

FabricSpec lattice_of(FabricSpec spec) {
  spec.mesh = FabricSpec::Mesh::quadrangular;
  return spec;
}

TEST(JitteredLayout, IsTheLatticesCutWithItsInnerNodesMovedWithinTheBound) {
  const FabricSpec spec = jittered(24, 3);
  const Fabric moved(spec), lattice(lattice_of(spec));
  ASSERT_EQ(moved.node_count(), lattice.node_count());
  ASSERT_EQ(moved.faces().size(), lattice.faces().size());
  const double bound = spec.jitter * lattice.spacing_warp();
  double largest = 0.0;
  for (int k = 0; k < moved.node_count(); ++k) {
    ASSERT_EQ(moved.i_of(k), lattice.i_of(k));
    ASSERT_EQ(moved.j_of(k), lattice.j_of(k));
    const double move = (moved.rest_position(k) - lattice.rest_position(k)).norm();
    EXPECT_EQ(moved.rest_position(k).z(), 0.0);
    if (lattice.on_perimeter(k)) {
      EXPECT_EQ(move, 0.0) << moved.node_name(k);  // the cut stays the lattice's
    }
    EXPECT_LE(move, bound * (1.0 + 1e-12)) << moved.node_name(k);
    largest = std::max(largest, move);
  }
  EXPECT_GT(largest, 0.8 * bound);  // a draw uniform in the disc reaches near its rim among ~350 nodes
}

TEST(JitteredLayout, RepeatsForASeedAndDiffersBetweenSeeds) {
  const Fabric first(jittered(16, 2)), again(jittered(16, 2)), other(jittered(16, 3));
  double differs = 0.0;
  for (int k = 0; k < first.node_count(); ++k) {
    EXPECT_EQ(first.rest_position(k), again.rest_position(k));
    differs = std::max(differs, (first.rest_position(k) - other.rest_position(k)).norm());
  }
  EXPECT_GT(differs, 0.1 * kMaxJitter * first.spacing_warp());
}

// The jitter scales the seed's moves: half of it moves each node half as far the same way.
TEST(JitteredLayout, HalfTheJitterHalvesTheSameMoves) {
  const FabricSpec spec = jittered(16, 5);
  const Fabric full(spec), half(jittered(16, 5, 0.5 * kMaxJitter)), lattice(lattice_of(spec));
  for (int k = 0; k < full.node_count(); ++k) {
    const Eigen::Vector3d move = full.rest_position(k) - lattice.rest_position(k);
    const Eigen::Vector3d half_move = half.rest_position(k) - lattice.rest_position(k);
    EXPECT_LT((half_move - 0.5 * move).norm(), 1e-15) << full.node_name(k);
  }
}

// Every cell's corners turn left, each at least 0.1 of the spacing clear of the diagonal
// through its neighbours (kMaxJitter's margin): no cell is inverted, degenerate or concave.
TEST(JitteredLayout, EveryCellStaysConvex) {
  for (const std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    const Fabric fabric(jittered(40, seed));
    const double h = fabric.spacing_warp();
    for (const Face& f : fabric.faces())
      for (int c = 0; c < 4; ++c) {
        const Eigen::Vector3d before = fabric.rest_position(f.corner[static_cast<std::size_t>((c + 3) % 4)]);
        const Eigen::Vector3d at = fabric.rest_position(f.corner[static_cast<std::size_t>(c)]);
        const Eigen::Vector3d after = fabric.rest_position(f.corner[static_cast<std::size_t>((c + 1) % 4)]);
        const double clearance = (after - before).cross(at - before).z() / (after - before).norm();
        EXPECT_LT(clearance, -0.1 * h) << "seed " << seed << ", corner at " << fabric.node_name(f.corner[static_cast<std::size_t>(c)]);
      }
  }
}

TEST(JitteredLayout, SpringsRestAtTheMovedDistancesAndKeepTheirLatticeFamily) {
  const Fabric fabric(jittered(24, 1));
  for (const Spring& s : fabric.springs()) {
    const double distance = (fabric.rest_position(s.b) - fabric.rest_position(s.a)).norm();
    EXPECT_NEAR(s.rest_length, distance, 1e-15);
    const int di = std::abs(fabric.i_of(s.b) - fabric.i_of(s.a)), dj = std::abs(fabric.j_of(s.b) - fabric.j_of(s.a));
    const std::array<int, 2> expected = s.kind == SpringKind::warp   ? std::array<int, 2>{1, 0}
                                        : s.kind == SpringKind::weft ? std::array<int, 2>{0, 1}
                                                                     : std::array<int, 2>{1, 1};
    EXPECT_EQ((std::array<int, 2>{di, dj}), expected) << to_string(s.kind) << " spring " << s.a << "-" << s.b;
  }
}

// The specimen's area is its moved cells', which differ from the lattice's by the moves alone.
TEST(JitteredLayout, AreaIsTheMovedCells) {
  const Fabric moved(jittered(24, 2)), lattice(lattice_of(jittered(24, 2)));
  std::vector<Eigen::Vector3d> rest;
  for (int k = 0; k < moved.node_count(); ++k) rest.push_back(moved.rest_position(k));
  double sum = 0.0;
  for (const Face& f : moved.faces()) sum += face_area(f, rest);
  EXPECT_NEAR(moved.flat_area(), sum, 1e-12 * sum);
  // Inner nodes move within the outline: the total area is the lattice's.
  EXPECT_NEAR(moved.flat_area(), lattice.flat_area(), 1e-12 * lattice.flat_area());
}

TEST(JitteredLayout, RefusesAJitterOutsideItsBound) {
  for (const double jitter : {0.0, -0.1, 0.21, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_FALSE(jittered(24, 1, jitter).invalid_reason().empty()) << jitter;
  }
  EXPECT_TRUE(jittered(24, 1, kMaxJitter).invalid_reason().empty());
}

}  // namespace
}  // namespace fabform::jittered_layout_test
