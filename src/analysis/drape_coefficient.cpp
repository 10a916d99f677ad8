#include "fabform/analysis/drape_coefficient.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_with_holes_2.h>

namespace fabform {
namespace {

// Exact constructions: the union's corners where triangle edges cross are rational points, and
// its area is summed without rounding.
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using PolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

std::size_t at(int index) { return static_cast<std::size_t>(index); }

// Each node once, so that triangles sharing a node share its exact point.
std::vector<Point> projected_nodes(const std::vector<Eigen::Vector3d>& positions_m) {
  std::vector<Point> nodes;
  nodes.reserve(positions_m.size());
  for (std::size_t k = 0; k < positions_m.size(); ++k) {
    const Eigen::Vector3d& p = positions_m[k];
    if (!p.allFinite()) {
      std::ostringstream message;
      message << "fabric_shadow: node " << k << " has a non-finite position (" << p.x() << ", "
              << p.y() << ", " << p.z() << ")";
      throw std::invalid_argument(message.str());
    }
    nodes.emplace_back(p.x(), p.y());
  }
  return nodes;
}

void check_nodes_exist(const std::array<int, 3>& triangle, std::size_t index, std::size_t node_count) {
  for (const int node : triangle)
    if (node < 0 || at(node) >= node_count)
      throw std::invalid_argument("fabric_shadow: triangle " + std::to_string(index) + " names node " +
                                  std::to_string(node) + ", which does not exist (" +
                                  std::to_string(node_count) + " nodes)");
}

// The Boolean operations take simple counter-clockwise polygons only: a triangle seen edge-on
// (collinear corners) is left out, one seen from below is turned round.
std::vector<Polygon> projected_triangles(const std::vector<Point>& nodes,
                                         const std::vector<std::array<int, 3>>& triangles) {
  std::vector<Polygon> polygons;
  polygons.reserve(triangles.size());
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    check_nodes_exist(triangles[k], k, nodes.size());
    const Point& a = nodes[at(triangles[k][0])];
    const Point& b = nodes[at(triangles[k][1])];
    const Point& c = nodes[at(triangles[k][2])];
    const CGAL::Orientation turn = CGAL::orientation(a, b, c);
    if (turn == CGAL::COLLINEAR) continue;
    const std::array<Point, 3> counter_clockwise =
        turn == CGAL::LEFT_TURN ? std::array<Point, 3>{a, b, c} : std::array<Point, 3>{a, c, b};
    polygons.emplace_back(counter_clockwise.begin(), counter_clockwise.end());
  }
  return polygons;
}

// The corners of a boundary: points in the middle of a straight run (where a triangle's corner
// lies on another's edge, as along a grid's border) are not corners of the shadow.
std::vector<Eigen::Vector2d> corners(const Polygon& boundary) {
  std::vector<Eigen::Vector2d> out;
  const std::size_t n = boundary.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Point& p = boundary[k];
    if (CGAL::collinear(boundary[(k + n - 1) % n], p, boundary[(k + 1) % n])) continue;
    out.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  }
  return out;
}

}  // namespace

Shadow fabric_shadow(const std::vector<Eigen::Vector3d>& positions_m,
                     const std::vector<std::array<int, 3>>& triangles) {
  const std::vector<Polygon> polygons = projected_triangles(projected_nodes(positions_m), triangles);
  // The range join merges the triangles divide-and-conquer; one by one would be quadratic.
  // Tag_false keeps them segment polygons rather than converting each to a polyline.
  std::vector<PolygonWithHoles> pieces;
  CGAL::join(polygons.begin(), polygons.end(), std::back_inserter(pieces), CGAL::Tag_false());

  Shadow shadow;
  Kernel::FT area = 0;
  for (const PolygonWithHoles& piece : pieces) {
    area += piece.outer_boundary().area();
    for (const Polygon& hole : piece.holes()) area += hole.area();  // clockwise: negative
    shadow.holes += static_cast<int>(piece.number_of_holes());
    shadow.outlines.push_back(corners(piece.outer_boundary()));
    shadow.outline_vertices += static_cast<int>(shadow.outlines.back().size());
  }
  shadow.components = static_cast<int>(pieces.size());
  shadow.area_m2 = CGAL::to_double(CGAL::exact(area));  // rounded once, from the exact sum
  return shadow;
}

int count_folds(const std::vector<Eigen::Vector2d>& outline_m, const Eigen::Vector2d& centre_m,
                double min_depth_m) {
  if (!std::isfinite(min_depth_m) || min_depth_m < 0.0)
    throw std::invalid_argument("count_folds: the depth must be finite and non-negative, not " +
                                std::to_string(min_depth_m) + " m");
  const std::size_t n = outline_m.size();
  if (n < 3) return 0;
  std::vector<double> radius(n);
  for (std::size_t k = 0; k < n; ++k) radius[k] = (outline_m[k] - centre_m).norm();
  // Walk once round from the deepest point, so that every maximum has a valley on both sides.
  const auto start = static_cast<std::size_t>(std::min_element(radius.begin(), radius.end()) - radius.begin());
  int folds = 0;
  bool rising = true;
  double valley = radius[start], peak = radius[start];
  for (std::size_t step = 1; step <= n; ++step) {
    const double r = radius[(start + step) % n];
    if (rising) {
      peak = std::max(peak, r);
      if (peak - valley > min_depth_m && peak - r > min_depth_m) {  // past a maximum
        ++folds;
        rising = false;
        valley = r;
      }
    } else {
      valley = std::min(valley, r);
      if (r - valley > min_depth_m) {  // past a minimum
        rising = true;
        peak = r;
      }
    }
  }
  return folds;
}

double drape_coefficient(double shadow_area_m2, double specimen_area_m2, double disc_area_m2) {
  const auto fail = [](const auto&... parts) {
    std::ostringstream message;
    message << "drape_coefficient: ";
    (message << ... << parts);
    throw std::invalid_argument(message.str());
  };
  const auto check = [&](double area_m2, const char* name) {
    if (!std::isfinite(area_m2) || area_m2 < 0.0)
      fail("the ", name, " area must be finite and non-negative, not ", area_m2, " m^2");
  };
  check(shadow_area_m2, "shadow");
  check(specimen_area_m2, "specimen");
  check(disc_area_m2, "disc");
  if (!(specimen_area_m2 > disc_area_m2))
    fail("the specimen (", specimen_area_m2, " m^2) must be larger than the disc it lies on (",
         disc_area_m2, " m^2)");
  return (shadow_area_m2 - disc_area_m2) / (specimen_area_m2 - disc_area_m2);
}

}  // namespace fabform
