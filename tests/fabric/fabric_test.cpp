// Fabric: nodes, springs, their rest lengths and widths, the per-node spring slots.
#include "fabform/fabric/fabric.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <utility>

namespace fabform::fabric_test {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

class FabricShapes : public ::testing::TestWithParam<FabricSpec> {};

TEST_P(FabricShapes, NodeCountsAndIndexing) {
  const FabricSpec spec = GetParam();
  const Fabric grid(spec);
  const int n = spec.divisions_warp + 1, m = spec.divisions_weft + 1;
  EXPECT_EQ(grid.nodes_warp(), n);
  EXPECT_EQ(grid.nodes_weft(), m);
  EXPECT_EQ(grid.node_count(), n * m);
  std::set<int> seen;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int k = grid.node(i, j);
      ASSERT_GE(k, 0);
      ASSERT_LT(k, grid.node_count());
      EXPECT_EQ(grid.i_of(k), i);
      EXPECT_EQ(grid.j_of(k), j);
      seen.insert(k);
    }
  EXPECT_EQ(static_cast<int>(seen.size()), n * m);  // node(i, j) is a bijection
}

TEST_P(FabricShapes, RestPositions) {
  const FabricSpec spec = GetParam();
  const Fabric grid(spec);
  EXPECT_DOUBLE_EQ(grid.spacing_warp(), spec.width_m / spec.divisions_warp);
  EXPECT_DOUBLE_EQ(grid.spacing_weft(), spec.height_m / spec.divisions_weft);
  // i·(W/(n−1)) is a product of two rounded numbers: a few ulps of the fabric size.
  const double tol = 4 * kEps * std::max(spec.width_m, spec.height_m);
  for (int k = 0; k < grid.node_count(); ++k) {
    const Eigen::Vector3d x = grid.rest_position(k);
    EXPECT_NEAR(x.x(), spec.width_m * grid.i_of(k) / spec.divisions_warp, tol);
    EXPECT_NEAR(x.y(), spec.height_m * grid.j_of(k) / spec.divisions_weft, tol);
    EXPECT_EQ(x.z(), 0.0);
  }
  EXPECT_NEAR(grid.rest_position(grid.node(grid.nodes_warp() - 1, grid.nodes_weft() - 1)).x(),
              spec.width_m, tol);
  EXPECT_NEAR(grid.rest_position(grid.node_count() - 1).y(), spec.height_m, tol);
}

TEST_P(FabricShapes, SpringsJoinNeighboursWithRestLengths) {
  const FabricSpec spec = GetParam();
  const Fabric grid(spec);
  const int n = grid.nodes_warp(), m = grid.nodes_weft();
  ASSERT_EQ(static_cast<int>(grid.springs().size()), (n - 1) * m + n * (m - 1));
  std::set<std::pair<int, int>> pairs;
  int warp = 0, weft = 0;
  for (const Spring& s : grid.springs()) {
    ASSERT_LT(s.a, s.b);  // a is the lower-index end
    pairs.insert({s.a, s.b});
    // The rest length equals the rest distance of its nodes (a few ulps of the spacing).
    const double distance = (grid.rest_position(s.b) - grid.rest_position(s.a)).norm();
    EXPECT_NEAR(s.rest_length, distance, 8 * kEps * std::max(spec.width_m, spec.height_m));
    if (s.kind == SpringKind::warp) {
      ++warp;
      EXPECT_EQ(grid.j_of(s.a), grid.j_of(s.b));
      EXPECT_EQ(grid.i_of(s.b), grid.i_of(s.a) + 1);
      EXPECT_DOUBLE_EQ(s.rest_length, spec.width_m / spec.divisions_warp);
    } else {
      ++weft;
      EXPECT_EQ(grid.i_of(s.a), grid.i_of(s.b));
      EXPECT_EQ(grid.j_of(s.b), grid.j_of(s.a) + 1);
      EXPECT_DOUBLE_EQ(s.rest_length, spec.height_m / spec.divisions_weft);
    }
  }
  EXPECT_EQ(warp, (n - 1) * m);
  EXPECT_EQ(weft, n * (m - 1));
  EXPECT_EQ(pairs.size(), grid.springs().size());  // no duplicates
}

TEST_P(FabricShapes, WidthsTileTheFabric) {
  // Each spring stands for a strip of fabric; edge springs for half a strip (seed 003,
  // Figure 3). The warp springs of one column (fixed i, all j) together span H; the weft
  // springs of one row (fixed j, all i) span W. Tolerance: a sum of m terms, each rounded.
  const FabricSpec spec = GetParam();
  const Fabric grid(spec);
  const int n = grid.nodes_warp(), m = grid.nodes_weft();
  std::vector<double> warp_column(static_cast<std::size_t>(n - 1), 0.0);
  std::vector<double> weft_row(static_cast<std::size_t>(m - 1), 0.0);
  for (const Spring& s : grid.springs()) {
    const bool edge = s.kind == SpringKind::warp
                          ? (grid.j_of(s.a) == 0 || grid.j_of(s.a) == m - 1)
                          : (grid.i_of(s.a) == 0 || grid.i_of(s.a) == n - 1);
    const double strip = s.kind == SpringKind::warp ? grid.spacing_weft() : grid.spacing_warp();
    // Widths are the cell's area over the spring's length: (a·b)/a, rounded twice.
    const double expected = edge ? 0.5 * strip : strip;
    EXPECT_NEAR(s.width, expected, 2.0 * kEps * expected);
    if (s.kind == SpringKind::warp)
      warp_column[static_cast<std::size_t>(grid.i_of(s.a))] += s.width;
    else
      weft_row[static_cast<std::size_t>(grid.j_of(s.a))] += s.width;
  }
  for (const double sum : warp_column) EXPECT_NEAR(sum, spec.height_m, 4.0 * m * kEps * spec.height_m);
  for (const double sum : weft_row) EXPECT_NEAR(sum, spec.width_m, 4.0 * n * kEps * spec.width_m);
}

// A node stands for the cells around it: one for an inner node, a half on an edge, a quarter at
// a corner; together they are the whole fabric. Tolerance: a sum of n·m terms, each rounded.
TEST_P(FabricShapes, NodeAreasTileTheFabric) {
  const FabricSpec spec = GetParam();
  const Fabric grid(spec);
  const std::vector<double> area = grid.node_areas();
  ASSERT_EQ(area.size(), static_cast<std::size_t>(grid.node_count()));
  const double cell = grid.spacing_warp() * grid.spacing_weft();
  double total = 0.0;
  for (int k = 0; k < grid.node_count(); ++k) {
    const int i = grid.i_of(k), j = grid.j_of(k);
    const int edges = (i == 0 || i == grid.nodes_warp() - 1) + (j == 0 || j == grid.nodes_weft() - 1);
    EXPECT_EQ(area[static_cast<std::size_t>(k)], cell / (1 << edges)) << k;  // sums of quarters
    total += area[static_cast<std::size_t>(k)];
  }
  const double whole = spec.width_m * spec.height_m;
  EXPECT_NEAR(total, whole, 8.0 * grid.node_count() * kEps * whole);
}

// springs_at lists each spring at both its ends, warp before weft, nothing else.
TEST_P(FabricShapes, SpringsAtNodes) {
  const Fabric grid(GetParam());
  std::vector<int> listed(grid.springs().size(), 0);
  for (int k = 0; k < grid.node_count(); ++k) {
    int previous = -1;
    for (const int s : grid.springs_at(k)) {
      ASSERT_GE(s, 0);
      ASSERT_LT(s, static_cast<int>(grid.springs().size()));
      const Spring& spring = grid.springs()[static_cast<std::size_t>(s)];
      EXPECT_TRUE(spring.a == k || spring.b == k) << "node " << k << " spring " << s;
      EXPECT_GT(s, previous);
      previous = s;
      ++listed[static_cast<std::size_t>(s)];
    }
  }
  for (const int count : listed) EXPECT_EQ(count, 2);
}

// faces_at lists, on every mesh, each face at each of its corners once, in face order.
TEST(Fabric, FacesAtNodes) {
  FabricSpec arc{0.2, 0.2, 0, 0, FabricSpec::Shape::circle, FabricSpec::Mesh::arc};
  arc.rings = 3, arc.spokes = 7;
  for (const FabricSpec& spec : {FabricSpec{0.1, 0.05, 4, 2}, FabricSpec{0.2, 0.2, 6, 6, FabricSpec::Shape::circle},
                                 FabricSpec{0.2, 0.2, 6, 6, FabricSpec::Shape::circle, FabricSpec::Mesh::triangular},
                                 arc}) {
    const Fabric fabric(spec);
    std::vector<int> listed(fabric.faces().size(), 0);
    for (int k = 0; k < fabric.node_count(); ++k) {
      int previous = -1;
      for (const int f : fabric.faces_at(k)) {
        ASSERT_GE(f, 0);
        ASSERT_LT(f, static_cast<int>(fabric.faces().size()));
        const Face& face = fabric.faces()[static_cast<std::size_t>(f)];
        EXPECT_NE(std::find(face.corner.begin(), face.corner.begin() + face.corners, k), face.corner.begin() + face.corners);
        EXPECT_GT(f, previous);
        previous = f;
        ++listed[static_cast<std::size_t>(f)];
      }
    }
    for (std::size_t f = 0; f < listed.size(); ++f) EXPECT_EQ(listed[f], fabric.faces()[f].corners) << f;
  }
}

TEST_P(FabricShapes, Perimeter) {
  const Fabric grid(GetParam());
  const int n = grid.nodes_warp(), m = grid.nodes_weft();
  int count = 0;
  for (int k = 0; k < grid.node_count(); ++k) {
    const int i = grid.i_of(k), j = grid.j_of(k);
    const bool expected = i == 0 || j == 0 || i == n - 1 || j == m - 1;
    EXPECT_EQ(grid.on_perimeter(k), expected) << i << "," << j;
    count += expected;
    // A perimeter node is exactly one with fewer than four springs.
    EXPECT_EQ(grid.on_perimeter(k), grid.springs_at(k).size() < 4);
  }
  EXPECT_EQ(count, n * m - std::max(n - 2, 0) * std::max(m - 2, 0));
}

INSTANTIATE_TEST_SUITE_P(Specs, FabricShapes,
                         ::testing::Values(FabricSpec{0.1, 0.1, 40, 40}, FabricSpec{0.3, 0.2, 5, 3},
                                           FabricSpec{1.0, 2.0, 1, 1}, FabricSpec{0.5, 0.01, 1, 7},
                                           FabricSpec{0.5, 0.01, 9, 1}, FabricSpec{2.5e-3, 7.0, 2, 2},
                                           FabricSpec{1e3, 1e-3, 13, 6}));

TEST(Fabric, StoresSpec) {
  const FabricSpec spec{0.4, 0.3, 8, 6};
  const Fabric grid(spec);
  EXPECT_EQ(grid.spec().width_m, 0.4);
  EXPECT_EQ(grid.spec().height_m, 0.3);
  EXPECT_EQ(grid.spec().divisions_warp, 8);
  EXPECT_EQ(grid.spec().divisions_weft, 6);
}

class FabricInvalid : public ::testing::TestWithParam<FabricSpec> {};

TEST_P(FabricInvalid, Throws) { EXPECT_THROW(Fabric{GetParam()}, std::invalid_argument); }

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

INSTANTIATE_TEST_SUITE_P(
    Specs, FabricInvalid,
    ::testing::Values(FabricSpec{0.0, 0.1, 4, 4}, FabricSpec{0.1, 0.0, 4, 4}, FabricSpec{-0.1, 0.1, 4, 4},
                      FabricSpec{0.1, -1e-9, 4, 4}, FabricSpec{kNaN, 0.1, 4, 4},
                      FabricSpec{0.1, kNaN, 4, 4}, FabricSpec{kInf, 0.1, 4, 4},
                      FabricSpec{0.1, kInf, 4, 4}, FabricSpec{0.1, 0.1, 0, 4},
                      FabricSpec{0.1, 0.1, 4, 0}, FabricSpec{0.1, 0.1, -3, 4},
                      FabricSpec{0.1, 0.1, 4, INT_MIN},
                      // More than 50 million nodes.
                      FabricSpec{0.1, 0.1, 10000, 10000}, FabricSpec{0.1, 0.1, 50'000'000, 1}));

// Divisions near INT_MAX must be refused, not overflow while counting nodes.
TEST(Fabric, HugeDivisionsThrow) {
  EXPECT_THROW(Fabric(FabricSpec{0.1, 0.1, INT_MAX, 1}), std::invalid_argument);
  EXPECT_THROW(Fabric(FabricSpec{0.1, 0.1, 1, INT_MAX}), std::invalid_argument);
}

}  // namespace
}  // namespace fabform::fabric_test
