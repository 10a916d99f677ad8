#include "fabform/geometry/rigid_body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdint>
#include <future>
#include <stdexcept>

#include "geometry/embree_scene.hpp"

namespace fabform {

struct EdgeCorner {
  int high;              // the edge's upper vertex (its lower one is the bucket's)
  std::uint32_t corner;  // 3 · triangle + corner
  bool operator<(const EdgeCorner& other) const { return high < other.high; }
};

namespace {

struct EdgeBuckets {
  std::vector<std::size_t> start;  // per vertex, and one past the last
  std::vector<EdgeCorner> corners;
};

void validate(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) throw std::invalid_argument("the mesh has no triangles");
  const int count = static_cast<int>(mesh.vertices.size());
  for (const auto& p : mesh.vertices)
    if (!p.allFinite()) throw std::invalid_argument("the mesh has a non-finite vertex");
  for (const auto& t : mesh.triangles)
    for (const int v : t)
      if (v < 0 || v >= count) throw std::invalid_argument("a triangle index is out of range");
}

double corner_angle(const Eigen::Vector3d& at, const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
  const Eigen::Vector3d u = p - at, v = q - at;
  const double nu = u.norm(), nv = v.norm();
  if (nu == 0.0 || nv == 0.0) return 0.0;
  return std::acos(std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0));
}

Eigen::Vector3d normalized_or_zero(const Eigen::Vector3d& v) {
  const double n = v.norm();
  return n > 0.0 ? Eigen::Vector3d(v / n) : Eigen::Vector3d::Zero();
}

// Every corner's edge (corner c of triangle t runs from vertex c to vertex c + 1), grouped by
// the edge's lower vertex: bucket v is corners[start[v], start[v + 1]).
EdgeBuckets bucket_edges(const std::vector<std::array<int, 3>>& triangles, std::size_t vertex_count) {
  EdgeBuckets buckets;
  buckets.start.assign(vertex_count + 1, 0);
  const auto ends = [&](std::size_t t, int c) {
    const int a = triangles[t][c], b = triangles[t][(c + 1) % 3];
    return std::pair<std::size_t, int>(static_cast<std::size_t>(std::min(a, b)), std::max(a, b));
  };
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) ++buckets.start[ends(t, c).first + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) buckets.start[v + 1] += buckets.start[v];
  buckets.corners.resize(3 * triangles.size());
  std::vector<std::size_t> next(buckets.start.begin(), buckets.start.end() - 1);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const auto [low, high] = ends(t, c);
      buckets.corners[next[low]++] = {high, static_cast<std::uint32_t>(3 * t + static_cast<std::size_t>(c))};
    }
  return buckets;
}

}  // namespace

RigidBody::RigidBody(std::string name, TriangleMesh mesh, double friction)
    : name_(std::move(name)), mesh_(std::move(mesh)), friction_(friction) {
  if (!(friction >= 0.0 && std::isfinite(friction)))
    throw std::invalid_argument("friction coefficient must be finite and not negative");
  validate(mesh_);
  box_ = bounding_box(mesh_.vertices);
  // The BVH and the pseudo-normals need only the mesh: build them side by side (a large
  // body's set-up is mostly these two).
  auto bvh = std::async(std::launch::async, [this] { return std::make_unique<EmbreeScene>(mesh_.vertices, mesh_.triangles); });
  compute_normals();
  bvh_ = bvh.get();
}

RigidBody::~RigidBody() = default;
RigidBody::RigidBody(RigidBody&&) noexcept = default;
RigidBody& RigidBody::operator=(RigidBody&&) noexcept = default;

// Angle-weighted pseudo-normals (Bærentzen & Aanæs 2005): the sign of (p − c)·n at the
// closest feature tells inside from outside, also at edges and vertices.
void RigidBody::compute_normals() {
  const auto& V = mesh_.vertices;
  const std::size_t count = mesh_.triangles.size();
  face_normals_.resize(count);
  vertex_normals_.assign(V.size(), Eigen::Vector3d::Zero());
  for (std::size_t t = 0; t < count; ++t) {
    const auto& tri = mesh_.triangles[t];
    const Eigen::Vector3d n = normalized_or_zero((V[tri[1]] - V[tri[0]]).cross(V[tri[2]] - V[tri[0]]));
    face_normals_[t] = n;
    for (int c = 0; c < 3; ++c) {
      const int a = tri[c], b = tri[(c + 1) % 3], o = tri[(c + 2) % 3];
      vertex_normals_[a] += corner_angle(V[a], V[b], V[o]) * n;
    }
  }
  for (auto& n : vertex_normals_) n = normalized_or_zero(n);
  compute_edge_normals();
}

// Edges are matched through their lower vertex: corners are bucketed by it (a counting sort,
// linear time), and each bucket, a handful of edges, is sorted by the upper vertex. A full sort
// of three million edge records took most of a million-triangle body's set-up.
void RigidBody::compute_edge_normals() {
  const EdgeBuckets buckets = bucket_edges(mesh_.triangles, mesh_.vertices.size());
  edge_normals_.resize(mesh_.triangles.size());
  edge_on_rim_.assign(mesh_.triangles.size(), {false, false, false});
  vertex_on_rim_.assign(mesh_.vertices.size(), 0);
  std::vector<EdgeCorner> bucket;
  for (std::size_t low = 0; low < mesh_.vertices.size(); ++low) {
    bucket.assign(buckets.corners.begin() + buckets.start[low], buckets.corners.begin() + buckets.start[low + 1]);
    std::sort(bucket.begin(), bucket.end());
    for (std::size_t first = 0, last = 0; first < bucket.size(); first = last) {
      for (last = first; last < bucket.size() && bucket[last].high == bucket[first].high;) ++last;
      set_edge(bucket.data() + first, bucket.data() + last);
      if (last - first == 1) vertex_on_rim_[low] = vertex_on_rim_[static_cast<std::size_t>(bucket[first].high)] = 1;
    }
  }
}

// One edge, walked by the corners [first, last): its normal is the normalised sum of its
// faces' normals; it is on the rim when one face has it. Two faces that run it the same way
// (or one, or three) leave the surface not watertight.
void RigidBody::set_edge(const EdgeCorner* first, const EdgeCorner* last) {
  const auto runs_up = [&](const EdgeCorner* e) {
    const auto& tri = mesh_.triangles[e->corner / 3];
    return tri[e->corner % 3] < tri[(e->corner % 3 + 1) % 3];
  };
  if (last - first != 2 || runs_up(first) == runs_up(first + 1)) watertight_ = false;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const EdgeCorner* e = first; e != last; ++e) sum += face_normals_[e->corner / 3];
  const Eigen::Vector3d normal = normalized_or_zero(sum);
  for (const EdgeCorner* e = first; e != last; ++e) {
    edge_normals_[e->corner / 3][e->corner % 3] = normal;
    edge_on_rim_[e->corner / 3][e->corner % 3] = last - first == 1;
  }
}

// An open mesh (a dress form, a disc) has no inside beyond its rim: a point whose closest
// feature is a boundary edge or vertex is outside, whatever side of the face it is on.
bool RigidBody::on_rim(int triangle, TriangleFeature feature) const {
  const auto& tri = mesh_.triangles[triangle];
  switch (feature) {
    case TriangleFeature::face: return false;
    case TriangleFeature::edge01: return edge_on_rim_[triangle][0];
    case TriangleFeature::edge12: return edge_on_rim_[triangle][1];
    case TriangleFeature::edge20: return edge_on_rim_[triangle][2];
    case TriangleFeature::vertex0: return vertex_on_rim_[tri[0]] != 0;
    case TriangleFeature::vertex1: return vertex_on_rim_[tri[1]] != 0;
    case TriangleFeature::vertex2: return vertex_on_rim_[tri[2]] != 0;
  }
  return false;
}

double RigidBody::signed_volume() const {
  double six_volume = 0.0;
  for (const auto& t : mesh_.triangles)
    six_volume += mesh_.vertices[t[0]].dot(mesh_.vertices[t[1]].cross(mesh_.vertices[t[2]]));
  return six_volume / 6.0;
}

Eigen::Vector3d RigidBody::feature_normal(int triangle, TriangleFeature feature) const {
  const auto& tri = mesh_.triangles[triangle];
  switch (feature) {
    case TriangleFeature::face: return face_normals_[triangle];
    case TriangleFeature::edge01: return edge_normals_[triangle][0];
    case TriangleFeature::edge12: return edge_normals_[triangle][1];
    case TriangleFeature::edge20: return edge_normals_[triangle][2];
    case TriangleFeature::vertex0: return vertex_normals_[tri[0]];
    case TriangleFeature::vertex1: return vertex_normals_[tri[1]];
    case TriangleFeature::vertex2: return vertex_normals_[tri[2]];
  }
  return face_normals_[triangle];
}

// A closest-point query first looks this share of the body's size around the point.
constexpr double kNearShare = 0.02;

SurfacePoint RigidBody::surface_point_on(int triangle, const Eigen::Vector3d& p) const {
  const auto& tri = mesh_.triangles[triangle];
  const auto& V = mesh_.vertices;
  return surface_point_from(triangle, p, closest_point_on_triangle(p, V[tri[0]], V[tri[1]], V[tri[2]]));
}

SurfacePoint RigidBody::surface_point_from(int triangle, const Eigen::Vector3d& p, const TriangleClosest& c) const {
  SurfacePoint s;
  s.point = c.point;
  s.triangle = triangle;
  s.normal = feature_normal(triangle, c.feature);
  if (s.normal.isZero()) s.normal = face_normals_[triangle];
  s.distance = (p - c.point).norm();
  const bool inside = !on_rim(triangle, c.feature) && (p - c.point).dot(s.normal) < 0.0;
  s.signed_distance = inside ? -s.distance : s.distance;
  return s;
}

void RigidBody::move_to(const Eigen::Isometry3d& pose) {
  pose_ = pose;
  inverse_ = pose.inverse();
  moved_ = !pose.isApprox(Eigen::Isometry3d::Identity(), 0.0);
}

TriangleMesh RigidBody::posed_mesh() const {
  TriangleMesh posed = mesh_;
  if (moved_)
    for (Eigen::Vector3d& v : posed.vertices) v = pose_ * v;
  return posed;
}

SurfacePoint RigidBody::to_posed(SurfacePoint s) const {
  if (!moved_) return s;
  s.point = pose_ * s.point;
  s.normal = pose_.linear() * s.normal;
  return s;
}

SurfacePoint RigidBody::closest(const Eigen::Vector3d& p) const {
  // An unbounded query visits candidates until a close one shrinks it; most points asked about
  // lie near the surface, where a bounded query sees only the few triangles around them.
  if (auto near = closest_within(p, kNearShare * box_.diagonal())) return *near;
  if (auto found = closest_within(p, std::numeric_limits<double>::infinity())) return *found;
  return to_posed(surface_point_on(0, to_placed(p)));  // only if Embree found no candidate at all
}

SurfacePoint RigidBody::closest(const Eigen::Vector3d& p, int near_triangle) const {
  if (near_triangle < 0 || near_triangle >= static_cast<int>(mesh_.triangles.size())) return closest(p);
  const Eigen::Vector3d q = to_placed(p);
  const auto& tri = mesh_.triangles[static_cast<std::size_t>(near_triangle)];
  const auto& V = mesh_.vertices;
  const double bound = (q - closest_point_on_triangle(q, V[tri[0]], V[tri[1]], V[tri[2]]).point).norm();
  // The hinted triangle lies within the bound, so the search finds it or a closer one, unless p
  // is not finite (Embree is not asked then): closest() answers that case.
  if (auto found = closest_within_placed(q, bound)) return to_posed(*found);
  return closest(p);
}

std::optional<SurfacePoint> RigidBody::closest_within(const Eigen::Vector3d& p, double radius) const {
  auto found = closest_within_placed(to_placed(p), radius);
  if (found) *found = to_posed(*found);
  return found;
}

std::optional<SurfacePoint> RigidBody::closest_within_placed(const Eigen::Vector3d& p,
                                                             double radius) const {
  // Embree culls with float boxes and a float query point, each off by an ulp or so: keep a
  // margin so no candidate that could be closest is culled.
  const double float_error = 4.0 * std::numeric_limits<float>::epsilon() *
                             (p.cwiseAbs().maxCoeff() + box_.max.cwiseAbs().maxCoeff() +
                              (std::isfinite(radius) ? radius : 0.0));
  const double margin = 1e-6 * box_.diagonal() + float_error + 1e-12;
  // Candidates are many and only the closest is kept: each gets its distance alone, and the
  // closest its normal and side once, at the end.
  int best = -1;
  TriangleClosest best_point;
  double best_distance = std::numeric_limits<double>::infinity();
  const auto& V = mesh_.vertices;
  bvh_->visit_near(p, radius + margin, [&](int triangle) {
    const auto& tri = mesh_.triangles[static_cast<std::size_t>(triangle)];
    const TriangleClosest c = closest_point_on_triangle(p, V[tri[0]], V[tri[1]], V[tri[2]]);
    if (const double distance = (p - c.point).norm(); distance < best_distance)
      best = triangle, best_point = c, best_distance = distance;
    return std::min(radius, best_distance) + margin;
  });
  if (best < 0 || best_distance > radius) return std::nullopt;
  return surface_point_from(best, p, best_point);
}

std::optional<std::array<Eigen::Vector3d, 2>> RigidBody::valley_normals(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d q = to_placed(p);
  const double radius = kCreaseShare * box_.diagonal();
  std::vector<int> near;
  const auto& V = mesh_.vertices;
  bvh_->visit_near(q, radius, [&](int triangle) {
    const auto& tri = mesh_.triangles[static_cast<std::size_t>(triangle)];
    if (!face_normals_[triangle].isZero() &&
        (q - closest_point_on_triangle(q, V[tri[0]], V[tri[1]], V[tri[2]]).point).norm() <= radius)
      near.push_back(triangle);
    return radius;
  });
  // A valley: each face rises on the outer side of the other's plane (a ridge falls away).
  const auto centre = [&](int triangle) {
    const auto& tri = mesh_.triangles[static_cast<std::size_t>(triangle)];
    return Eigen::Vector3d((V[tri[0]] + V[tri[1]] + V[tri[2]]) / 3.0);
  };
  const auto valley = [&](int a, int b) {
    return face_normals_[a].dot(centre(b) - q) > 0.0 && face_normals_[b].dot(centre(a) - q) > 0.0;
  };
  // The widest pair, in the order the triangles are numbered, so the answer does not depend on
  // the order Embree visits them in.
  std::sort(near.begin(), near.end());
  double widest = kCreaseAngleCos;
  std::optional<std::array<Eigen::Vector3d, 2>> pair;
  for (std::size_t a = 0; a < near.size(); ++a)
    for (std::size_t b = a + 1; b < near.size(); ++b)
      if (const double c = face_normals_[near[a]].dot(face_normals_[near[b]]); c < widest && valley(near[a], near[b]))
        widest = c, pair = std::array<Eigen::Vector3d, 2>{pose_.linear() * face_normals_[near[a]],
                                                          pose_.linear() * face_normals_[near[b]]};
  return pair;
}

std::optional<SurfacePoint> RigidBody::first_entry(const Eigen::Vector3d& from,
                                                   const Eigen::Vector3d& to) const {
  auto found = first_entry_placed(to_placed(from), to_placed(to));
  if (found) *found = to_posed(*found);
  return found;
}

std::optional<SurfacePoint> RigidBody::first_entry_placed(const Eigen::Vector3d& from,
                                                          const Eigen::Vector3d& to) const {
  const Eigen::Vector3d direction = to - from;
  if (direction.isZero()) return std::nullopt;
  double t_near = 0.0;
  // Step past faces crossed from the inside; a handful is plenty for real meshes.
  for (int attempt = 0; attempt < 16 && t_near <= 1.0; ++attempt) {
    const auto hit = bvh_->first_hit(from, direction, t_near, 1.0);
    if (!hit) return std::nullopt;
    const auto& tri = mesh_.triangles[hit->triangle];
    const auto& V = mesh_.vertices;
    if (face_normals_[hit->triangle].dot(direction) < 0.0) {
      const double t = segment_plane_crossing(from, to, V[tri[0]], V[tri[1]], V[tri[2]])
                           .value_or(std::clamp(hit->t, 0.0, 1.0));
      return surface_point_on(hit->triangle, from + t * direction);
    }
    t_near = std::nextafter(static_cast<float>(hit->t), 2.0f);
  }
  return std::nullopt;
}

void RigidBody::visit_convex_edges(double angle_deg,
                                   const std::function<void(const SharpEdge&, int, int)>& visit) const {
  const double cos_limit = std::cos(angle_deg * M_PI / 180.0);
  const auto& V = mesh_.vertices;
  const auto& T = mesh_.triangles;
  const EdgeBuckets buckets = bucket_edges(T, V.size());
  for (std::size_t low = 0; low < V.size(); ++low) {
    std::vector<EdgeCorner> bucket(buckets.corners.begin() + buckets.start[low],
                                   buckets.corners.begin() + buckets.start[low + 1]);
    std::sort(bucket.begin(), bucket.end());
    for (std::size_t first = 0, last = 0; first < bucket.size(); first = last) {
      for (last = first; last < bucket.size() && bucket[last].high == bucket[first].high;) ++last;
      if (last - first != 2) continue;  // a rim, or more than two faces: no wedge
      const std::uint32_t c1 = bucket[first].corner, c2 = bucket[first + 1].corner;
      const Eigen::Vector3d& n1 = face_normals_[c1 / 3];
      const Eigen::Vector3d& n2 = face_normals_[c2 / 3];
      if (n1.isZero() || n2.isZero() || n1.dot(n2) > cos_limit) continue;
      // Convex where the second face's far corner lies behind the first face.
      const Eigen::Vector3d& far = V[T[c2 / 3][(c2 % 3 + 2) % 3]];
      if ((far - V[low]).dot(n1) >= 0.0) continue;
      visit({V[low], V[static_cast<std::size_t>(bucket[first].high)], n1, n2}, static_cast<int>(c1), static_cast<int>(c2));
    }
  }
}

void RigidBody::wrap_edges_sharper_than(double angle_deg) {
  if (!(angle_deg > 0.0 && angle_deg < 180.0)) throw std::invalid_argument("an edge's angle must be in (0, 180) degrees");
  sharp_edges_.clear();
  sharp_edge_at_.assign(mesh_.triangles.size(), {-1, -1, -1});
  visit_convex_edges(angle_deg, [&](const SharpEdge& edge, int c1, int c2) {
    const int index = static_cast<int>(sharp_edges_.size());
    sharp_edges_.push_back(edge);
    sharp_edge_at_[static_cast<std::size_t>(c1 / 3)][static_cast<std::size_t>(c1 % 3)] =
        sharp_edge_at_[static_cast<std::size_t>(c2 / 3)][static_cast<std::size_t>(c2 % 3)] = index;
  });
  wrap_angle_deg_ = angle_deg;
}

std::vector<SharpEdge> RigidBody::convex_edges(double angle_deg) const {
  if (!(angle_deg > 0.0 && angle_deg < 180.0)) throw std::invalid_argument("an edge's angle must be in (0, 180) degrees");
  std::vector<SharpEdge> edges;
  visit_convex_edges(angle_deg, [&](const SharpEdge& edge, int, int) { edges.push_back(edge); });
  add_crack_edges(std::cos(angle_deg * M_PI / 180.0), edges);
  return edges;
}

// A CAD tessellation leaves cracks where two faces of the part meet: a rim edge on one side, the
// other side's triangles ending on the same line in other vertices (T-junctions). Such an edge is
// still the part's edge: its second face is the triangle on the other side whose edge runs along
// it through its middle.
void RigidBody::add_crack_edges(double cos_limit, std::vector<SharpEdge>& edges) const {
  const auto& V = mesh_.vertices;
  const auto& T = mesh_.triangles;
  const double near = 1e-6 * box_.diagonal();
  for (std::size_t t = 0; t < T.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      if (!edge_on_rim_[t][static_cast<std::size_t>(c)]) continue;
      const Eigen::Vector3d& a = V[static_cast<std::size_t>(T[t][static_cast<std::size_t>(c)])];
      const Eigen::Vector3d& b = V[static_cast<std::size_t>(T[t][static_cast<std::size_t>((c + 1) % 3)])];
      const Eigen::Vector3d& n1 = face_normals_[t];
      const Eigen::Vector3d middle = 0.5 * (a + b), along = (b - a).normalized();
      int partner = -1;
      Eigen::Vector3d side_from, side_to;  // the partner's side along this edge
      bvh_->visit_near(middle, near, [&](int other) {
        if (partner >= 0 || other == static_cast<int>(t)) return near;
        const auto& o = T[static_cast<std::size_t>(other)];
        for (int k = 0; k < 3 && partner < 0; ++k) {
          const Eigen::Vector3d& p = V[static_cast<std::size_t>(o[static_cast<std::size_t>(k)])];
          const Eigen::Vector3d& q = V[static_cast<std::size_t>(o[static_cast<std::size_t>((k + 1) % 3)])];
          const Eigen::Vector3d side = q - p;
          const bool collinear = side.normalized().cross(along).norm() < 1e-6 &&
                                 (middle - p).cross(side).norm() <= near * side.norm();
          if (collinear && (middle - p).dot(side) > 0.0 && (middle - q).dot(side) < 0.0)
            partner = other, side_from = p, side_to = q;
        }
        return near;
      });
      if (partner < 0) continue;
      // A crack is added from one side only, lest its line carry the penalty twice: where one
      // side's edge holds the other's (a T-junction: short edges along one long one), the short
      // edges; where they are staggered, the side of the lower-numbered triangle.
      const auto within = [&](const Eigen::Vector3d& x, const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
        const Eigen::Vector3d span = to - from;
        const double at = (x - from).dot(span) / span.squaredNorm();
        return at >= -1e-9 && at <= 1.0 + 1e-9;
      };
      const bool short_side = within(a, side_from, side_to) && within(b, side_from, side_to);
      const bool long_side = within(side_from, a, b) && within(side_to, a, b);
      if (!short_side && (long_side || partner < static_cast<int>(t))) continue;
      const Eigen::Vector3d& n2 = face_normals_[static_cast<std::size_t>(partner)];
      if (n1.isZero() || n2.isZero() || n1.dot(n2) > cos_limit) continue;
      const auto& o = T[static_cast<std::size_t>(partner)];
      const Eigen::Vector3d centre = (V[static_cast<std::size_t>(o[0])] + V[static_cast<std::size_t>(o[1])] +
                                      V[static_cast<std::size_t>(o[2])]) / 3.0;
      if ((centre - a).dot(n1) >= 0.0) continue;  // concave
      edges.push_back({a, b, n1, n2});
    }
}

std::optional<EdgeWrap> RigidBody::wrap(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
  if (sharp_edges_.empty()) return std::nullopt;
  const Eigen::Vector3d pa = to_placed(a), pb = to_placed(b);
  // A segment under an edge passes through the body, so it crosses its surface; stretched by a
  // millionth at each end so that a node resting on a face still counts the crossing there. One
  // ray rules out most springs before any edge is looked at.
  const Eigen::Vector3d margin = 1e-6 * (pb - pa);
  if (!bvh_->first_hit(pa - margin, pb - pa + 2.0 * margin, 0.0, 1.0)) return std::nullopt;
  // An edge a segment wraps lies within its length of the segment (wrap_over), so within 1.5
  // lengths of its middle.
  const double radius = 1.5 * (pb - pa).norm();
  std::vector<int> near;
  bvh_->visit_near(0.5 * (pa + pb), radius, [&](int triangle) {
    for (const int e : sharp_edge_at_[static_cast<std::size_t>(triangle)])
      if (e >= 0 && std::find(near.begin(), near.end(), e) == near.end()) near.push_back(e);
    return radius;
  });
  std::sort(near.begin(), near.end());  // the same choice whatever order the BVH visits in
  auto found = choose_wrap(near, pa, pb);
  if (found && moved_) {
    found->point = pose_ * found->point;
    found->axis = pose_.linear() * found->axis;
  }
  return found;
}

// Near a corner a segment may pass under several edges. The string takes the shortest way over
// one of them whose two legs pass under none of the others (over a box's top edge rather than
// round its vertical edge below); where every way cuts another edge, the longest, the one that
// gives back most of the corner.
std::optional<EdgeWrap> RigidBody::choose_wrap(const std::vector<int>& edges, const Eigen::Vector3d& a,
                                               const Eigen::Vector3d& b) const {
  const double on_surface = on_surface_distance();
  std::optional<EdgeWrap> shortest_clear, longest;
  for (const int e : edges) {
    const auto w = wrap_over(sharp_edges_[static_cast<std::size_t>(e)], a, b, on_surface);
    if (!w) continue;
    if (!longest || w->length > longest->length) longest = w;
    const bool clear = std::none_of(edges.begin(), edges.end(), [&](int other) {
      const SharpEdge& edge = sharp_edges_[static_cast<std::size_t>(other)];
      return other != e && (wrap_over(edge, a, w->point, on_surface) || wrap_over(edge, w->point, b, on_surface));
    });
    if (clear && (!shortest_clear || w->length < shortest_clear->length)) shortest_clear = w;
  }
  return shortest_clear ? shortest_clear : longest;
}

bool RigidBody::segment_crosses(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const {
  const Eigen::Vector3d start = to_placed(from);
  const Eigen::Vector3d direction = to_placed(to) - start;
  return !direction.isZero() && bvh_->first_hit(start, direction, 0.0, 1.0).has_value();
}

}  // namespace fabform
