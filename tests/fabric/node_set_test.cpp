// Node sets a scene constrains, the axis-lock parser and remove_locked.
#include "fabform/fabric/node_set.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace fabform::node_set_test {
namespace {

using Kind = NodeSetSpec::Kind;

// 6 × 4 nodes over 0.5 m × 0.3 m: spacing 0.1 m both ways.
Fabric test_grid() { return Fabric(FabricSpec{0.5, 0.3, 5, 3}); }

// Brute force: every node for which the predicate on (i, j) holds, in increasing order.
std::vector<int> nodes_where(const Fabric& grid, const std::function<bool(int, int)>& pred) {
  std::vector<int> nodes;
  for (int k = 0; k < grid.node_count(); ++k)
    if (pred(grid.i_of(k), grid.j_of(k))) nodes.push_back(k);
  return nodes;
}

NodeSetSpec spec_of(Kind kind) {
  NodeSetSpec spec;
  spec.kind = kind;
  return spec;
}

TEST(NodeSet, NamedSetsMatchBruteForce) {
  for (const FabricSpec& g : {FabricSpec{0.5, 0.3, 5, 3}, FabricSpec{1.0, 1.0, 1, 1}, FabricSpec{0.2, 0.7, 1, 6}}) {
    const Fabric grid(g);
    const int li = grid.nodes_warp() - 1, lj = grid.nodes_weft() - 1;
    struct Named {
      Kind kind;
      std::function<bool(int, int)> pred;
    };
    const Named cases[] = {
        {Kind::perimeter, [&](int i, int j) { return i == 0 || j == 0 || i == li || j == lj; }},
        {Kind::edge_left, [&](int i, int) { return i == 0; }},
        {Kind::edge_right, [&](int i, int) { return i == li; }},
        {Kind::edge_bottom, [&](int, int j) { return j == 0; }},
        {Kind::edge_top, [&](int, int j) { return j == lj; }},
        {Kind::corners, [&](int i, int j) { return (i == 0 || i == li) && (j == 0 || j == lj); }},
    };
    for (const Named& c : cases) {
      SCOPED_TRACE(static_cast<int>(c.kind));
      const std::vector<int> nodes = select_nodes(grid, spec_of(c.kind));
      EXPECT_EQ(nodes, nodes_where(grid, c.pred));
      EXPECT_TRUE(std::is_sorted(nodes.begin(), nodes.end()));
      EXPECT_FALSE(nodes.empty());
    }
  }
}

TEST(NodeSet, Counts) {
  const Fabric grid = test_grid();  // 6 × 4
  EXPECT_EQ(select_nodes(grid, spec_of(Kind::perimeter)).size(), 2u * 6 + 2u * 4 - 4);
  EXPECT_EQ(select_nodes(grid, spec_of(Kind::edge_left)).size(), 4u);
  EXPECT_EQ(select_nodes(grid, spec_of(Kind::edge_bottom)).size(), 6u);
  EXPECT_EQ(select_nodes(grid, spec_of(Kind::corners)),
            (std::vector<int>{grid.node(0, 0), grid.node(5, 0), grid.node(0, 3), grid.node(5, 3)}));
}

TEST(NodeSet, IndexInAndOutOfRange) {
  const Fabric grid = test_grid();
  NodeSetSpec spec = spec_of(Kind::index);
  for (int j = 0; j < grid.nodes_weft(); ++j)
    for (int i = 0; i < grid.nodes_warp(); ++i) {
      spec.i = i;
      spec.j = j;
      EXPECT_EQ(select_nodes(grid, spec), std::vector<int>{grid.node(i, j)});
    }
  const int big = std::numeric_limits<int>::max(), small = std::numeric_limits<int>::min();
  for (const auto& [i, j] : std::vector<std::pair<int, int>>{
           {-1, 0}, {0, -1}, {6, 0}, {0, 4}, {6, 4}, {-1, -1}, {big, 0}, {0, big}, {small, small}, {5, 4}, {6, 3}}) {
    spec.i = i;
    spec.j = j;
    EXPECT_TRUE(select_nodes(grid, spec).empty()) << i << "," << j;
  }
}

TEST(NodeSet, NearestMatchesBruteForce) {
  const Fabric grid = test_grid();
  std::mt19937 rng(7);
  // Points over and well beyond the fabric (0.5 × 0.3 m).
  std::uniform_real_distribution<double> x(-1.0, 1.5), y(-1.0, 1.3);
  NodeSetSpec spec = spec_of(Kind::nearest);
  for (int sample = 0; sample < 2000; ++sample) {
    spec.point = {x(rng), y(rng)};
    std::vector<double> d;
    for (int k = 0; k < grid.node_count(); ++k)
      d.push_back((grid.rest_position(k).head<2>() - spec.point).norm());
    const auto best = std::min_element(d.begin(), d.end());
    const std::vector<int> nodes = select_nodes(grid, spec);
    ASSERT_EQ(nodes.size(), 1u);
    // Ties (points on a bisector) may pick either node: compare distances, 1e-12 m.
    EXPECT_NEAR(d[static_cast<std::size_t>(nodes[0])], *best, 1e-12)
        << spec.point.transpose();
  }
  // Exactly on a node, and clearly closest to a corner from far outside.
  spec.point = grid.rest_position(grid.node(3, 2)).head<2>();
  EXPECT_EQ(select_nodes(grid, spec), std::vector<int>{grid.node(3, 2)});
  spec.point = {100.0, -100.0};
  EXPECT_EQ(select_nodes(grid, spec), std::vector<int>{grid.node(5, 0)});
}

TEST(NodeSet, BoxMatchesBruteForceAndIsInclusive) {
  const Fabric grid = test_grid();
  NodeSetSpec spec = spec_of(Kind::box);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x(-0.2, 0.7), y(-0.2, 0.5);
  for (int sample = 0; sample < 500; ++sample) {
    const double x0 = x(rng), x1 = x(rng), y0 = y(rng), y1 = y(rng);
    spec.box_min = {std::min(x0, x1), std::min(y0, y1)};
    spec.box_max = {std::max(x0, x1), std::max(y0, y1)};
    const auto expected = nodes_where(grid, [&](int i, int j) {
      const Eigen::Vector3d p = grid.rest_position(grid.node(i, j));
      return p.x() >= spec.box_min.x() && p.x() <= spec.box_max.x() && p.y() >= spec.box_min.y() &&
             p.y() <= spec.box_max.y();
    });
    EXPECT_EQ(select_nodes(grid, spec), expected);
  }
  // A degenerate box exactly at a node's rest position selects that node (inclusive).
  const Eigen::Vector2d p = grid.rest_position(grid.node(2, 1)).head<2>();
  spec.box_min = spec.box_max = p;
  EXPECT_EQ(select_nodes(grid, spec), std::vector<int>{grid.node(2, 1)});
  // The whole fabric (a margin: the last node's i·spacing may round above W or H).
  spec.box_min = {-1e-9, -1e-9};
  spec.box_max = {0.5 + 1e-9, 0.3 + 1e-9};
  EXPECT_EQ(select_nodes(grid, spec).size(), static_cast<std::size_t>(grid.node_count()));
}

TEST(NodeSet, BoxSelectingNothingIsEmpty) {
  const Fabric grid = test_grid();
  NodeSetSpec spec = spec_of(Kind::box);
  const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> boxes = {
      {{1.0, 1.0}, {2.0, 2.0}},      // beyond the fabric
      {{-1.0, -1.0}, {-0.01, 0.3}},  // left of it
      {{0.01, 0.01}, {0.09, 0.29}},  // between node columns
      {{0.3, 0.2}, {0.1, 0.0}},      // min > max
  };
  for (const auto& [lo, hi] : boxes) {
    spec.box_min = lo;
    spec.box_max = hi;
    EXPECT_TRUE(select_nodes(grid, spec).empty()) << lo.transpose() << " .. " << hi.transpose();
  }
}

TEST(NodeSet, ParseNamedNodeSet) {
  const std::pair<const char*, Kind> valid[] = {
      {"perimeter", Kind::perimeter}, {"corners", Kind::corners},
      {"edge:left", Kind::edge_left}, {"edge:right", Kind::edge_right},
      {"edge:bottom", Kind::edge_bottom}, {"edge:top", Kind::edge_top}};
  for (const auto& [name, kind] : valid) {
    NodeSetSpec spec = spec_of(Kind::box);
    EXPECT_TRUE(parse_named_node_set(name, &spec)) << name;
    EXPECT_EQ(spec.kind, kind) << name;
  }
  for (const char* name : {"", "edge", "edge:", "edge:middle", "Perimeter", "perimeter ", " corners",
                           "edge:LEFT", "edge left", "index", "nearest", "box", "corner"}) {
    NodeSetSpec spec;
    EXPECT_FALSE(parse_named_node_set(name, &spec)) << "'" << name << "'";
  }
}

TEST(NodeSet, ParseAxes) {
  const std::pair<const char*, AxisMask> valid[] = {
      {"x", kLockX}, {"y", kLockY}, {"z", kLockZ}, {"xy", kLockX | kLockY},
      {"yx", kLockX | kLockY}, {"xz", kLockX | kLockZ}, {"zy", kLockY | kLockZ},
      {"xyz", kLockX | kLockY | kLockZ}, {"zxy", kLockX | kLockY | kLockZ}};
  for (const auto& [text, mask] : valid) {
    AxisMask parsed = 0;
    EXPECT_TRUE(parse_axes(text, &parsed)) << text;
    EXPECT_EQ(parsed, mask) << text;
  }
  for (const char* text : {"", "xx", "w", "xyzx", "X", " x", "x,y", "xyw", "zz", "x "}) {
    AxisMask parsed = 0;
    EXPECT_FALSE(parse_axes(text, &parsed)) << "'" << text << "'";
  }
}

TEST(NodeSet, AxesRoundTrip) {
  for (unsigned m = 1; m < 8; ++m) {
    const auto mask = static_cast<AxisMask>(m);
    AxisMask parsed = 0;
    ASSERT_TRUE(parse_axes(axes_to_string(mask), &parsed)) << m;
    EXPECT_EQ(parsed, mask);
  }
  EXPECT_EQ(axes_to_string(kLockX | kLockZ), "xz");
  EXPECT_EQ(axes_to_string(0), "");
}

TEST(NodeSet, RemoveLocked) {
  const Eigen::Vector3d v(1.5, -2.0, 3.25);
  for (unsigned m = 0; m < 8; ++m) {
    const auto mask = static_cast<AxisMask>(m);
    const Eigen::Vector3d free = remove_locked(v, mask);
    EXPECT_EQ(free.x(), (mask & kLockX) ? 0.0 : v.x()) << m;
    EXPECT_EQ(free.y(), (mask & kLockY) ? 0.0 : v.y()) << m;
    EXPECT_EQ(free.z(), (mask & kLockZ) ? 0.0 : v.z()) << m;
  }
}

}  // namespace
}  // namespace fabform::node_set_test
