#include "fabform/geometry/panel_outline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fabform/angles.hpp"

namespace fabform {
namespace {

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Vec2 left_normal(const Vec2& d) { return {-d.y(), d.x()}; }

// An arc's centre and the angles of its two ends, the end's angle reached from the start's by
// turning the arc's way.
struct ArcFrame {
  Vec2 centre;
  double start_angle;
  double sweep;  // signed, radians
};

ArcFrame arc_frame(const Vec2& a, const Vec2& b, const OutlineEdge& e) {
  const Vec2 chord = b - a;
  const double half = 0.5 * chord.norm();
  const double offset = std::sqrt(std::max(0.0, e.radius_m * e.radius_m - half * half));
  // Turning counter-clockwise the short way round, the centre lies left of the chord.
  const bool centre_left = e.counter_clockwise != e.large_arc;
  const Vec2 centre = 0.5 * (a + b) + (centre_left ? 1.0 : -1.0) * offset * left_normal(chord).normalized();
  const double start = std::atan2(a.y() - centre.y(), a.x() - centre.x());
  double sweep = std::atan2(b.y() - centre.y(), b.x() - centre.x()) - start;
  if (e.counter_clockwise) {
    while (sweep <= 0.0) sweep += 2.0 * kPi;
  } else {
    while (sweep >= 0.0) sweep -= 2.0 * kPi;
  }
  return {centre, start, sweep};
}

std::size_t controls_needed(OutlineEdge::Kind kind) {
  return kind == OutlineEdge::Kind::quadratic ? 1 : kind == OutlineEdge::Kind::cubic ? 2 : 0;
}

// Whether segments pq and rs share a point (touching and overlapping included).
bool segments_meet(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  const double d1 = cross(q - p, r - p), d2 = cross(q - p, s - p);
  const double d3 = cross(s - r, p - r), d4 = cross(s - r, q - r);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  const auto on = [](const Vec2& a, const Vec2& b, const Vec2& c, double d) {
    return d == 0.0 && std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) &&
           std::min(a.y(), b.y()) <= c.y() && c.y() <= std::max(a.y(), b.y());
  };
  return on(p, q, r, d1) || on(p, q, s, d2) || on(r, s, p, d3) || on(r, s, q, d4);
}

// Whether the closed polyline crosses itself: any two segments that are not neighbours meet.
// Quadratic in the points, which a panel's few hundred keep small.
bool crosses_itself(const std::vector<Vec2>& points) {
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segments_meet(points[i], points[(i + 1) % n], points[j], points[(j + 1) % n])) return true;
    }
  return false;
}

// A bound on edge k's length: an arc's own, a Bézier curve's control polygon (never shorter
// than the curve).
double edge_length_bound(const PanelOutline& outline, int k) {
  const Vec2& a = outline.vertices[static_cast<std::size_t>(k)];
  const Vec2& b = outline.vertices[(static_cast<std::size_t>(k) + 1) % outline.vertices.size()];
  const OutlineEdge& e = outline.edges[static_cast<std::size_t>(k)];
  if (e.kind == OutlineEdge::Kind::arc) return std::abs(arc_frame(a, b, e).sweep) * e.radius_m;
  double length = 0.0;
  Vec2 previous = a;
  for (const Vec2& c : e.controls) length += (c - previous).norm(), previous = c;
  return length + (b - previous).norm();
}

// The number of segments a curve is traced with: enough that none is longer than max_segment,
// at least 8 (and, as a guard, at most kMaxSegments: callers bound the ratio well below).
constexpr double kMaxSegments = 1e8;

int segments_for(const PanelOutline& outline, int k, double max_segment) {
  return static_cast<int>(std::clamp(std::ceil(edge_length_bound(outline, k) / max_segment), 8.0, kMaxSegments));
}

}  // namespace

std::string PanelOutline::invalid_reason() const {
  if (vertices.size() < 3) return "an outline needs at least 3 vertices";
  if (edges.size() != vertices.size()) return "an outline has one edge per vertex";
  double size = 0.0;
  for (const Vec2& v : vertices) {
    if (!v.allFinite()) return "a vertex is not finite";
    size = std::max(size, v.cwiseAbs().maxCoeff());
  }
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const OutlineEdge& e = edges[k];
    const std::string edge = "edge " + std::to_string(k);
    const Vec2 chord = vertices[(k + 1) % vertices.size()] - vertices[k];
    if (chord.norm() <= 1e-9 * std::max(size, 1e-3)) return edge + " has no length (its two vertices coincide)";
    if (e.controls.size() != controls_needed(e.kind))
      return edge + " needs " + std::to_string(controls_needed(e.kind)) + " control point(s)";
    for (const Vec2& c : e.controls)
      if (!c.allFinite()) return edge + " has a control point that is not finite";
    if (e.kind == OutlineEdge::Kind::arc && !std::isfinite(e.radius_m)) return edge + " is an arc whose radius is not finite";
    if (e.kind == OutlineEdge::Kind::arc && !(e.radius_m >= 0.5 * chord.norm() * (1.0 - 1e-9)))
      return edge + " is an arc whose radius is shorter than half the distance between its ends";
  }
  // Traced in at most a few thousand segments, as the check is quadratic in them.
  double extent = 0.0;
  for (const Vec2& v : vertices) extent = std::max(extent, (v - vertices[0]).norm());
  const std::vector<Vec2> points = trace_outline(*this, std::max(extent / 256.0, length_bound() / 4096.0)).points;
  for (const Vec2& p : points)
    if (!p.allFinite()) return "the outline's curves reach beyond finite numbers";
  if (crosses_itself(points)) return "the outline crosses itself";
  return "";
}

double PanelOutline::length_bound() const {
  double length = 0.0;
  for (std::size_t k = 0; k < edges.size(); ++k) length += edge_length_bound(*this, static_cast<int>(k));
  return length;
}

Vec2 PanelOutline::point(int edge, double t) const {
  const auto k = static_cast<std::size_t>(edge);
  const Vec2& a = vertices[k];
  const Vec2& b = vertices[(k + 1) % vertices.size()];
  const OutlineEdge& e = edges[k];
  const double u = 1.0 - t;
  switch (e.kind) {
    case OutlineEdge::Kind::straight: return u * a + t * b;
    case OutlineEdge::Kind::quadratic: return u * u * a + 2.0 * u * t * e.controls[0] + t * t * b;
    case OutlineEdge::Kind::cubic:
      return u * u * u * a + 3.0 * u * u * t * e.controls[0] + 3.0 * u * t * t * e.controls[1] + t * t * t * b;
    case OutlineEdge::Kind::arc: {
      if (t == 0.0) return a;
      if (t == 1.0) return b;
      const ArcFrame f = arc_frame(a, b, e);
      const double angle = f.start_angle + t * f.sweep;
      return f.centre + e.radius_m * Vec2(std::cos(angle), std::sin(angle));
    }
  }
  return a;
}

TracedOutline trace_outline(const PanelOutline& outline, double max_segment_m) {
  TracedOutline traced;
  traced.outline = outline;
  const int edges = static_cast<int>(outline.edges.size());
  for (int k = 0; k < edges; ++k) {
    const int n = segments_for(outline, k, max_segment_m);
    traced.edge_first.push_back(static_cast<int>(traced.points.size()));
    double s = 0.0;
    Vec2 previous = outline.point(k, 0.0);
    for (int i = 0; i < n; ++i) {
      const double t = static_cast<double>(i) / n;
      const Vec2 p = outline.point(k, t);
      s += (p - previous).norm();
      previous = p;
      traced.points.push_back(p);
      traced.edge.push_back(k);
      traced.t.push_back(t);
      traced.s.push_back(s);
    }
    traced.edge_length.push_back(s + (outline.point(k, 1.0) - previous).norm());
  }
  return traced;
}

std::pair<std::size_t, std::size_t> TracedOutline::edge_points(int k) const {
  const auto e = static_cast<std::size_t>(k);
  return {static_cast<std::size_t>(edge_first[e]),
          e + 1 < edge_first.size() ? static_cast<std::size_t>(edge_first[e + 1]) : points.size()};
}

double TracedOutline::signed_area() const {
  double twice = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) twice += cross(points[i], points[(i + 1) % points.size()]);
  return 0.5 * twice;
}

bool TracedOutline::contains(const Vec2& p) const {
  bool inside = false;
  for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++) {
    const Vec2& a = points[i];
    const Vec2& b = points[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < a.x() + (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()))
      inside = !inside;
  }
  return inside;
}

Vec2 TracedOutline::at(int k, double s_at) const {
  const auto e = static_cast<std::size_t>(k);
  const double length = edge_length[e];
  s_at = std::clamp(s_at, 0.0, length);
  const auto [first, end] = edge_points(k);
  // The traced points of the edge and its end vertex (t = 1, s = length) bracket s_at.
  double s0 = 0.0, t0 = 0.0;
  for (std::size_t i = first; i < end; ++i) {
    if (s[i] > s_at) {
      const double w = (s_at - s0) / (s[i] - s0);
      return outline.point(k, t0 + w * (t[i] - t0));
    }
    s0 = s[i], t0 = t[i];
  }
  const double w = length > s0 ? (s_at - s0) / (length - s0) : 1.0;
  return outline.point(k, t0 + w * (1.0 - t0));
}

double TracedOutline::nearest_s(int k, const Vec2& p) const {
  const auto e = static_cast<std::size_t>(k);
  const auto [first, end] = edge_points(k);
  double best = std::numeric_limits<double>::infinity(), best_s = 0.0;
  for (std::size_t i = first; i < end; ++i) {
    const Vec2& a = points[i];
    const Vec2& b = points[(i + 1) % points.size()];
    const double sb = i + 1 < end ? s[i + 1] : edge_length[e];
    const Vec2 d = b - a;
    const double w = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    const double distance = (a + w * d - p).squaredNorm();
    if (distance < best) best = distance, best_s = s[i] + w * (sb - s[i]);
  }
  return best_s;
}

}  // namespace fabform
