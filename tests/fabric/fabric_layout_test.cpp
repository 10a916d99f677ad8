// Seed 000's circles (quadrangular, triangular, arc), the jittered lattice and seed 004's shear
// and bend springs on every layout: geometry against closed forms, areas that tile, springs where
// they belong, and node colours that no spring crosses.
#include "fabform/fabric/fabric.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>

namespace fabform::fabric_layout_test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kEps = std::numeric_limits<double>::epsilon();

FabricSpec circle(FabricSpec::Mesh mesh, double diameter, int divisions) {
  FabricSpec spec{diameter, diameter, divisions, divisions};
  spec.shape = FabricSpec::Shape::circle;
  spec.mesh = mesh;
  return spec;
}

FabricSpec arc(double diameter, int rings, int spokes) {
  FabricSpec spec = circle(FabricSpec::Mesh::arc, diameter, 0);
  spec.rings = rings;
  spec.spokes = spokes;
  return spec;
}

FabricSpec jittered(double diameter, int divisions, double jitter, std::uint64_t seed) {
  FabricSpec spec = circle(FabricSpec::Mesh::jittered, diameter, divisions);
  spec.jitter = jitter;
  spec.jitter_seed = seed;
  return spec;
}

FabricSpec with_springs(FabricSpec spec, bool shear, bool bend) {
  spec.shear_springs = shear;
  spec.bend_springs = bend;
  return spec;
}

double spring_area(const Fabric& fabric, SpringKind kind) {
  double sum = 0.0;
  for (const Spring& s : fabric.springs())
    if (s.kind == kind) sum += s.width * s.rest_length;
  return sum;
}

int count_of(const Fabric& fabric, SpringKind kind) {
  int count = 0;
  for (const Spring& s : fabric.springs()) count += s.kind == kind;
  return count;
}

// Invariants every layout keeps, with or without shear and bend springs.
class EveryLayout : public ::testing::TestWithParam<FabricSpec> {};

TEST_P(EveryLayout, NodesLieOnTheFabricAndFacesAreCounterClockwise) {
  const Fabric fabric(GetParam());
  const double r = GetParam().radius_m(), size = GetParam().width_m;
  for (int k = 0; k < fabric.node_count(); ++k) {
    const Eigen::Vector3d p = fabric.rest_position(k);
    EXPECT_EQ(p.z(), 0.0);
    if (GetParam().shape == FabricSpec::Shape::circle) {
      EXPECT_LE(std::hypot(p.x() - r, p.y() - r), r * (1.0 + 1e-12)) << fabric.node_name(k);
    }
    EXPECT_EQ(fabric.node(fabric.i_of(k), fabric.j_of(k)), k);
  }
  std::vector<Eigen::Vector3d> rest;
  for (int k = 0; k < fabric.node_count(); ++k) rest.push_back(fabric.rest_position(k));
  for (const Face& f : fabric.faces()) {
    const Eigen::Vector3d a = rest[static_cast<std::size_t>(f.corner[0])];
    const Eigen::Vector3d b = rest[static_cast<std::size_t>(f.corner[1])];
    const Eigen::Vector3d c = rest[static_cast<std::size_t>(f.corner[2])];
    EXPECT_GT((b - a).cross(c - a).z(), 1e-6 * size * size / fabric.node_count());
  }
}

// Each family of sides tiles the fabric once (seed 003's strips), so the warp and weft springs
// together stand for twice its area; the node areas for it once. Sums of thousands of rounded
// terms: a relative 1e-12.
TEST_P(EveryLayout, AreasTile) {
  const Fabric fabric(GetParam());
  const double area = fabric.flat_area();
  EXPECT_NEAR(spring_area(fabric, SpringKind::warp) + spring_area(fabric, SpringKind::weft), 2.0 * area, 1e-12 * area);
  double nodes = 0.0;
  for (const double a : fabric.node_areas()) {
    EXPECT_GT(a, 0.0);
    nodes += a;
  }
  EXPECT_NEAR(nodes, area, 1e-12 * area);
}

TEST_P(EveryLayout, SpringsHaveTheirNodesRestDistance) {
  const Fabric fabric(GetParam());
  std::set<std::pair<int, int>> pairs;
  for (const Spring& s : fabric.springs()) {
    ASSERT_LT(s.a, s.b);
    EXPECT_TRUE(pairs.insert({s.a, s.b}).second) << "duplicate spring " << s.a << "-" << s.b;
    const double distance = (fabric.rest_position(s.b) - fabric.rest_position(s.a)).norm();
    EXPECT_NEAR(s.rest_length, distance, 8 * kEps * GetParam().width_m);
    EXPECT_GT(s.width, 0.0);
  }
}

TEST_P(EveryLayout, NoSpringJoinsTwoNodesOfOneColour) {
  const Fabric fabric(GetParam());
  std::vector<int> colour(static_cast<std::size_t>(fabric.node_count()), -1);
  for (std::size_t c = 0; c < fabric.colours().size(); ++c)
    for (const int k : fabric.colours()[c]) {
      EXPECT_EQ(colour[static_cast<std::size_t>(k)], -1) << "node in two colours";
      colour[static_cast<std::size_t>(k)] = static_cast<int>(c);
    }
  for (const int c : colour) EXPECT_GE(c, 0);
  for (const Spring& s : fabric.springs())
    EXPECT_NE(colour[static_cast<std::size_t>(s.a)], colour[static_cast<std::size_t>(s.b)]);
}

// Hinges: one across every side two faces share, its wings the faces' far sides; relax moves
// the nodes of a colour at once, so no hinge may reach two of them.
TEST_P(EveryLayout, HingesJoinTheTwoFacesOfEachInnerSideAndCrossColours) {
  FabricSpec spec = GetParam();
  spec.hinges = true;
  const Fabric fabric(spec);
  std::map<std::pair<int, int>, int> faces_at_side;
  for (const Face& f : fabric.faces())
    for (int c = 0; c < f.corners; ++c) {
      const int p = f.corner[static_cast<std::size_t>(c)], q = f.corner[static_cast<std::size_t>((c + 1) % f.corners)];
      ++faces_at_side[{std::min(p, q), std::max(p, q)}];
    }
  std::set<std::pair<int, int>> inner;
  for (const auto& [side, count] : faces_at_side)
    if (count == 2) inner.insert(side);
  std::set<std::pair<int, int>> hinged;
  for (const Hinge& h : fabric.hinges()) hinged.insert({h.edge[0], h.edge[1]});
  EXPECT_EQ(hinged, inner);
  EXPECT_EQ(fabric.hinges().size(), inner.size());
  std::vector<int> colour(static_cast<std::size_t>(fabric.node_count()), -1);
  for (std::size_t c = 0; c < fabric.colours().size(); ++c)
    for (const int k : fabric.colours()[c]) colour[static_cast<std::size_t>(k)] = static_cast<int>(c);
  for (const Hinge& h : fabric.hinges()) {
    EXPECT_GT(h.shape_factor, 0.0);
    const std::set<int> reach = {h.edge[0], h.edge[1], h.wing[0][0], h.wing[0][1], h.wing[1][0], h.wing[1][1]};
    std::set<int> colours;
    for (const int k : reach) colours.insert(colour[static_cast<std::size_t>(k)]);
    EXPECT_EQ(colours.size(), reach.size()) << "hinge " << h.edge[0] << "-" << h.edge[1];
    for (const int k : reach) {
      const auto at = fabric.hinges_at(k);
      EXPECT_NE(std::find_if(at.begin(), at.end(), [&](int i) { return &fabric.hinges()[static_cast<std::size_t>(i)] == &h; }),
                at.end());
    }
  }
}

// Shear: both diagonals of each four-sided face, each family tiling those faces once.
TEST_P(EveryLayout, ShearSpringsAreTheFacesDiagonals) {
  const Fabric fabric(with_springs(GetParam(), true, false));
  double quads = 0.0;
  int four_sided = 0;
  std::vector<Eigen::Vector3d> rest;
  for (int k = 0; k < fabric.node_count(); ++k) rest.push_back(fabric.rest_position(k));
  for (const Face& f : fabric.faces())
    if (f.corners == 4) quads += face_area(f, rest), ++four_sided;
  EXPECT_EQ(count_of(fabric, SpringKind::shear), 2 * four_sided);
  EXPECT_NEAR(spring_area(fabric, SpringKind::shear), 2.0 * quads, 1e-12 * quads);
}

// Bend springs span two side springs in line: from the node before to the node after, through
// exactly one middle node.
TEST_P(EveryLayout, BendSpringsSpanTwoSpringsInLine) {
  const Fabric fabric(with_springs(GetParam(), false, true));
  for (const Spring& s : fabric.springs()) {
    if (s.kind != SpringKind::bend) continue;
    int middles = 0;
    for (const int t : fabric.springs_at(s.a)) {
      const Spring& first = fabric.springs()[static_cast<std::size_t>(t)];
      if (first.kind > SpringKind::weft) continue;
      const int middle = first.a == s.a ? first.b : first.a;
      for (const int u : fabric.springs_at(middle)) {
        const Spring& second = fabric.springs()[static_cast<std::size_t>(u)];
        const double path = first.rest_length + second.rest_length;
        // > 120° apart; near the arc mesh's centre a second, bent path joins the same two nodes.
        if (second.kind <= SpringKind::weft && (second.a == s.b || second.b == s.b) && s.rest_length > 0.85 * path) {
          ++middles;
          if (GetParam().spaced_exactly()) {
            EXPECT_NEAR(s.rest_length, path, 1e-12);  // straight on
          }
        }
      }
    }
    EXPECT_EQ(middles, 1) << s.a << "-" << s.b;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Layouts, EveryLayout,
    ::testing::Values(FabricSpec{0.1, 0.08, 7, 5}, FabricSpec{0.3, 0.3, 1, 1},
                      circle(FabricSpec::Mesh::quadrangular, 0.3, 3), circle(FabricSpec::Mesh::quadrangular, 0.3, 24),
                      circle(FabricSpec::Mesh::quadrangular, 0.3, 25), circle(FabricSpec::Mesh::triangular, 0.3, 16),
                      arc(0.3, 1, 3), arc(0.3, 6, 32), arc(0.24, 5, 17), jittered(0.3, 24, 0.2, 1),
                      jittered(0.3, 25, 0.1, 2)));

TEST(CircleLattice, ApproachesTheCircleFromInside) {
  const double r = 0.15;
  double previous_gap = kPi * r * r;
  for (const int divisions : {8, 32, 128}) {
    const Fabric fabric(circle(FabricSpec::Mesh::quadrangular, 2 * r, divisions));
    const double gap = kPi * r * r - fabric.flat_area();
    EXPECT_GT(gap, 0.0);
    EXPECT_LT(gap, previous_gap);
    EXPECT_LT(gap, 8.0 * (2 * kPi * r) * (2 * r / divisions));  // within a band of a few cells
    previous_gap = gap;
  }
}

TEST(CircleLattice, EvenDivisionsPutANodeAtTheCentre) {
  const Fabric fabric(circle(FabricSpec::Mesh::quadrangular, 0.3, 30));
  const int centre = fabric.node(15, 15);
  ASSERT_GE(centre, 0);
  EXPECT_NEAR((fabric.rest_position(centre) - Eigen::Vector3d(0.15, 0.15, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_FALSE(fabric.on_perimeter(centre));
  EXPECT_EQ(fabric.node(0, 0), -1);  // the bounding square's corner is off the circle
}

TEST(CircleLattice, TriangularIsTheQuadrangularWithDiagonalsOfRestLengthRootTwoL) {
  const Fabric quad(circle(FabricSpec::Mesh::quadrangular, 0.3, 20));
  const Fabric tri(circle(FabricSpec::Mesh::triangular, 0.3, 20));
  EXPECT_EQ(quad.node_count(), tri.node_count());
  EXPECT_EQ(count_of(quad, SpringKind::shear), 0);
  EXPECT_EQ(count_of(tri, SpringKind::shear), 2 * static_cast<int>(tri.faces().size()));
  for (const Spring& s : tri.springs())
    if (s.kind == SpringKind::shear) {
      EXPECT_NEAR(s.rest_length, std::sqrt(2.0) * 0.3 / 20, 1e-15);
    }
}

// The arc mesh is a regular P-gon of radius R cut by rings and spokes.
TEST(ArcMesh, RingsOnSpokes) {
  const int c = 6, p = 32;
  const double r = 0.15;
  const Fabric fabric(arc(2 * r, c, p));
  EXPECT_EQ(fabric.node_count(), 1 + c * p);
  EXPECT_EQ(static_cast<int>(fabric.faces().size()), c * p);
  EXPECT_NEAR(fabric.flat_area(), 0.5 * p * r * r * std::sin(2 * kPi / p), 1e-14);
  EXPECT_EQ(static_cast<int>(fabric.springs().size()), c * p + c * p);  // radial, ring
  for (const Spring& s : fabric.springs()) {
    const int ra = fabric.i_of(s.a), rb = fabric.i_of(s.b);
    const double expected = ra == rb ? 2.0 * (r * ra / c) * std::sin(kPi / p) : r / c;
    EXPECT_NEAR(s.rest_length, expected, 1e-15);
  }
  int perimeter = 0;
  for (int k = 0; k < fabric.node_count(); ++k) {
    EXPECT_EQ(fabric.on_perimeter(k), fabric.i_of(k) == c);
    perimeter += fabric.on_perimeter(k);
  }
  EXPECT_EQ(perimeter, p);
  EXPECT_EQ(fabric.node_name(1 + p + 3), "node (ring 2, spoke 3)");
  EXPECT_EQ(fabric.divisions_across(), 2 * c);
}

// Bend springs on the arc mesh: along each ring, along each spoke, and across the centre from a
// spoke to the one opposite.
TEST(ArcMesh, BendSprings) {
  const int c = 4, p = 16;
  const Fabric fabric(with_springs(arc(0.3, c, p), false, true));
  EXPECT_EQ(count_of(fabric, SpringKind::bend), c * p + (c - 1) * p + p / 2);
}

TEST(RectangleSprings, ShearAndBendCountsAndLengths) {
  const FabricSpec spec{0.1, 0.08, 10, 8};
  const Fabric fabric(with_springs(spec, true, true));
  const int n = 11, m = 9;
  EXPECT_EQ(count_of(fabric, SpringKind::shear), 2 * 10 * 8);
  EXPECT_EQ(count_of(fabric, SpringKind::bend), (n - 2) * m + n * (m - 2));
  for (const Spring& s : fabric.springs())
    if (s.kind == SpringKind::bend) {
      EXPECT_NEAR(s.rest_length, 0.02, 1e-15);  // 2 spacings either way
    }
}

TEST(RectangleColours, WarpAndWeftAloneGiveTheCheckerboard) {
  const Fabric fabric(FabricSpec{0.1, 0.1, 9, 6});
  ASSERT_EQ(fabric.colours().size(), 2u);
  for (const int k : fabric.colours()[0]) EXPECT_EQ((fabric.i_of(k) + fabric.j_of(k)) % 2, 0);
}

class InvalidCircle : public ::testing::TestWithParam<FabricSpec> {};

TEST_P(InvalidCircle, Throws) { EXPECT_THROW(Fabric{GetParam()}, std::invalid_argument); }

FabricSpec oval() {
  FabricSpec spec = circle(FabricSpec::Mesh::quadrangular, 0.3, 10);
  spec.height_m = 0.2;
  return spec;
}

FabricSpec triangular_rectangle() {
  FabricSpec spec{0.1, 0.1, 4, 4};
  spec.mesh = FabricSpec::Mesh::triangular;
  return spec;
}

INSTANTIATE_TEST_SUITE_P(Specs, InvalidCircle,
                         ::testing::Values(oval(), circle(FabricSpec::Mesh::quadrangular, 0.3, 2),
                                           circle(FabricSpec::Mesh::triangular, 0.3, 0), arc(0.3, 0, 8),
                                           arc(0.3, 4, 2), arc(0.3, 10000, 10000), arc(-0.3, 2, 8),
                                           triangular_rectangle()));

}  // namespace
}  // namespace fabform::fabric_layout_test
