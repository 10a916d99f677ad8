// Panels meshed on the lattice: a rectangle is today's rectangle exactly, a curved panel's
// boundary nodes lie on its outline and its cells tile it, the grain turns the lattice, and a
// lattice too coarse for an outline is refused by name.
#include "fabform/fabric/fabric.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include <Eigen/Geometry>

#include "fabform/angles.hpp"

namespace fabform::panel_layout_test {
namespace {

using Vec2 = Eigen::Vector2d;

OutlineEdge straight() { return {}; }

PanelSpec rectangle_panel(double width, double height) {
  PanelSpec p;
  p.name = "rectangle";
  p.outline = {{{0, 0}, {width, 0}, {width, height}, {0, height}}, {straight(), straight(), straight(), straight()}};
  return p;
}

FabricSpec panels_spec(std::vector<PanelSpec> panels, double spacing) {
  FabricSpec spec;
  spec.shape = FabricSpec::Shape::panels;
  spec.panels = std::move(panels);
  spec.panel_spacing_m = {spacing, spacing};
  return spec;
}

// GarmentCode's shirt_mean front torso panel (left half), in metres: straight sides, a quadratic
// shoulder, a cubic armhole and a cubic neckline, as the pattern draws it.
PanelSpec shirt_front() {
  PanelSpec p;
  p.name = "left_ftorso";
  const std::vector<Vec2> v = {{0.0, 0.0}, {0.0, 0.4058}, {0.1285, 0.4590}, {0.1723, 0.4416},
                               {0.1729, 0.4341}, {0.2622, 0.2614}, {0.2622, 0.0}};
  p.outline.vertices = v;
  p.outline.edges.assign(7, straight());
  const auto relative = [&](int k, double along, double across) {
    const Vec2 a = v[static_cast<std::size_t>(k)], b = v[(static_cast<std::size_t>(k) + 1) % v.size()];
    const Vec2 d = b - a;
    return Vec2(a + along * d + across * Vec2(-d.y(), d.x()));
  };
  p.outline.edges[1].kind = OutlineEdge::Kind::quadratic;
  p.outline.edges[1].controls = {relative(1, 0.15, -0.1)};
  p.outline.edges[4].kind = OutlineEdge::Kind::cubic;
  p.outline.edges[4].controls = {relative(4, 0.4935, -0.2068), relative(4, 0.7926, -0.3511)};
  return p;
}

TEST(PanelLayout, ARectanglePanelIsTheRectangle) {
  FabricSpec rectangle;
  rectangle.width_m = 0.3, rectangle.height_m = 0.2;
  rectangle.divisions_warp = 30, rectangle.divisions_weft = 20;
  FabricSpec panel = panels_spec({rectangle_panel(0.3, 0.2)}, 0.0);
  panel.panel_spacing_m = {0.3 / 30, 0.2 / 20};
  const Fabric a(rectangle), b(panel);
  ASSERT_EQ(a.node_count(), b.node_count());
  for (int k = 0; k < a.node_count(); ++k) {
    EXPECT_EQ(a.rest_position(k), b.rest_position(k)) << k;
    EXPECT_EQ(a.i_of(k), b.i_of(k));
    EXPECT_EQ(a.j_of(k), b.j_of(k));
    EXPECT_TRUE(b.on_lattice(k));
  }
  ASSERT_EQ(a.springs().size(), b.springs().size());
  for (std::size_t s = 0; s < a.springs().size(); ++s) {
    const Spring &p = a.springs()[s], &q = b.springs()[s];
    EXPECT_EQ(p.a, q.a);
    EXPECT_EQ(p.b, q.b);
    EXPECT_EQ(p.kind, q.kind);
    EXPECT_EQ(p.rest_length, q.rest_length);
    EXPECT_EQ(p.width, q.width);
  }
  EXPECT_EQ(a.flat_area(), b.flat_area());
  EXPECT_EQ(a.node_areas(), b.node_areas());
  // Its four edges are the rectangle's sides, from vertex to vertex.
  const PanelMesh& mesh = b.panels().at(0);
  ASSERT_EQ(mesh.edge_nodes.size(), 4u);
  EXPECT_EQ(mesh.edge_nodes[0].front(), a.node(0, 0));
  EXPECT_EQ(mesh.edge_nodes[0].back(), a.node(30, 0));
  EXPECT_EQ(mesh.edge_nodes[1].back(), a.node(30, 20));
  EXPECT_EQ(mesh.edge_nodes[2].back(), a.node(0, 20));
  EXPECT_EQ(mesh.edge_nodes[3].size(), 21u);
}

// Run clockwise, the same rectangle gives the same mesh; its edges follow the outline's way.
TEST(PanelLayout, AClockwiseOutlineGivesItsEdgesItsWay) {
  PanelSpec p = rectangle_panel(0.3, 0.2);
  const Fabric counter(panels_spec({p}, 0.01));
  p.outline.vertices = {{0, 0}, {0, 0.2}, {0.3, 0.2}, {0.3, 0}};
  const Fabric f(panels_spec({p}, 0.01));
  ASSERT_EQ(f.node_count(), counter.node_count());
  for (int n = 0; n < f.node_count(); ++n) EXPECT_EQ(f.rest_position(n), counter.rest_position(n));
  ASSERT_EQ(f.faces().size(), counter.faces().size());
  for (std::size_t k = 0; k < f.faces().size(); ++k) EXPECT_EQ(f.faces()[k].corner, counter.faces()[k].corner);
  const PanelMesh& mesh = f.panels().at(0);
  EXPECT_EQ(mesh.edge_nodes[0].front(), f.node(0, 0));
  EXPECT_EQ(mesh.edge_nodes[0].back(), f.node(0, 20));
  EXPECT_EQ(mesh.edge_nodes[0][1], f.node(0, 1));
  EXPECT_EQ(mesh.edge_nodes[3].back(), f.node(0, 0));
}

// The curved panel: every edge's nodes lie on its curve, in order, from vertex to vertex; the
// cells tile the polygon of the boundary nodes (their areas sum to its shoelace area), which is
// the outline's area less the slivers its chords cut off.
TEST(PanelLayout, ACurvedPanelsBoundaryNodesLieOnItsOutline) {
  const PanelSpec panel = shirt_front();
  const double h = 0.01;
  const Fabric f(panels_spec({panel}, h));
  const PanelMesh& mesh = f.panels().at(0);
  const TracedOutline exact = trace_outline(panel.outline, 1e-5);
  std::set<int> boundary;
  double shoelace = 0.0;
  for (std::size_t k = 0; k < mesh.edge_nodes.size(); ++k) {
    const std::vector<int>& chain = mesh.edge_nodes[k];
    EXPECT_TRUE(mesh.plane_point(f.rest_position(chain.front())).isApprox(panel.outline.vertices[k], 1e-12));
    double previous = -1.0;
    for (std::size_t c = 0; c + 1 < chain.size(); ++c) {
      const Vec2 p = mesh.plane_point(f.rest_position(chain[c]));
      const double s = exact.nearest_s(static_cast<int>(k), p);
      EXPECT_LT((exact.at(static_cast<int>(k), s) - p).norm(), 1e-7) << "edge " << k << " node " << c;
      EXPECT_GT(s, previous);
      previous = s;
      const Vec2 q = mesh.plane_point(f.rest_position(chain[c + 1]));
      shoelace += 0.5 * (p.x() * q.y() - p.y() * q.x());
      boundary.insert(chain[c]);
    }
  }
  for (int n = 0; n < f.node_count(); ++n)
    if (f.on_perimeter(n)) {
      EXPECT_TRUE(boundary.count(n)) << "perimeter node " << n << " is on no edge";
    }
  // The pattern runs clockwise: its shoelace area is negative, as the outline's.
  EXPECT_NEAR(f.flat_area(), std::abs(shoelace), 1e-12);
  // Chords between nodes at most ~1.5 spacings apart on curves of radius ≥ 5 cm: each cuts off
  // at most (2/3)·l·l²/(8 r); ~150 chords round the panel.
  const double l = 1.5 * h, sliver = 2.0 / 3.0 * l * l * l / (8.0 * 0.05);
  EXPECT_NEAR(shoelace, exact.signed_area(), 150 * sliver);
  // Every face turns counter-clockwise in the flat layout: both triangles of its split at
  // corner 0 have positive signed area.
  for (const Face& face : f.faces()) {
    const auto at = [&](int c) { return Eigen::Vector2d(f.rest_position(face.corner[static_cast<std::size_t>(c)]).head<2>()); };
    const auto twice = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
      const Eigen::Vector2d u = b - a, w = c - a;
      return u.x() * w.y() - u.y() * w.x();
    };
    EXPECT_GT(twice(at(0), at(1), at(2)), 0.0);
    if (face.corners == 4) {
      EXPECT_GT(twice(at(0), at(2), at(3)), 0.0);
    }
  }
}

// A 45° edge through the lattice's nodes drops staircase corners to triangles whose three nodes
// stay on the lattice: each is half a cell, and its chord is √2 spacings long, as measured.
TEST(PanelLayout, TrianglesAlongADiagonalAreHalfCellsWithTheirChordsLength) {
  PanelSpec triangle;
  triangle.name = "gusset";
  triangle.outline = {{{0, 0}, {0.1, 0}, {0.1, 0.1}}, {straight(), straight(), straight()}};
  const Fabric f(panels_spec({triangle}, 0.01));
  EXPECT_NEAR(f.flat_area(), 0.005, 1e-15);
  int chords = 0;
  for (const Spring& s : f.springs()) {
    const double length = (f.rest_position(s.b) - f.rest_position(s.a)).norm();
    EXPECT_NEAR(s.rest_length, length, 1e-15);
    chords += std::abs(length - std::sqrt(2.0) * 0.01) < 1e-12;
  }
  EXPECT_GT(chords, 0);
}

// Cut with the grain at 30° in the pattern's plane, a rectangle turned by 30° is the upright one.
TEST(PanelLayout, TheGrainTurnsTheLattice) {
  PanelSpec upright = rectangle_panel(0.3, 0.2);
  PanelSpec turned = upright;
  const double angle = 30.0 * kPi / 180.0;
  for (Vec2& v : turned.outline.vertices) v = Eigen::Rotation2Dd(angle) * v;
  turned.grain_deg = 30.0;
  const Fabric a(panels_spec({upright}, 0.01)), b(panels_spec({turned}, 0.01));
  ASSERT_EQ(a.node_count(), b.node_count());
  for (int k = 0; k < a.node_count(); ++k) EXPECT_TRUE(a.rest_position(k).isApprox(b.rest_position(k), 1e-12) ||
                                                       (a.rest_position(k) - b.rest_position(k)).norm() < 1e-14);
  const PanelMesh& mesh = b.panels().at(0);
  EXPECT_TRUE(mesh.plane_point(b.rest_position(mesh.edge_nodes[1].front())).isApprox(turned.outline.vertices[1], 1e-12));
}

// Two panels share the lattice side by side, each with its own nodes and edges.
TEST(PanelLayout, PanelsLieSideBySide) {
  PanelSpec left = rectangle_panel(0.1, 0.2), right = rectangle_panel(0.1, 0.2);
  left.name = "left", right.name = "right";
  const Fabric f(panels_spec({left, right}, 0.01));
  ASSERT_EQ(f.panels().size(), 2u);
  EXPECT_EQ(f.panels()[0].node_count, 11 * 21);
  EXPECT_EQ(f.panels()[1].first_node, 11 * 21);
  EXPECT_EQ(f.node_count(), 2 * 11 * 21);
  for (const Spring& s : f.springs())
    EXPECT_EQ(s.a < 231, s.b < 231) << "a spring joins the two panels";
  const PanelMesh& r = f.panels()[1];
  EXPECT_TRUE(r.plane_point(f.rest_position(r.first_node)).isApprox(Vec2(0, 0), 1e-12));
  EXPECT_NEAR(f.flat_area(), 0.04, 1e-15);
}

TEST(PanelLayout, ALatticeTooCoarseForTheOutlineIsRefused) {
  PanelSpec strip = rectangle_panel(0.3, 0.004);
  strip.name = "waistband";
  try {
    Fabric f(panels_spec({strip}, 0.01));
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("panel 'waistband': ", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("finer lattice spacing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fabform::panel_layout_test
