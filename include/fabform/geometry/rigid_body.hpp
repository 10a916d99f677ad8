#pragma once
// A rigid forming body (a mold, a torso, a support disc): its placed triangle mesh, an Embree
// BVH over it, and the pseudo-normals that tell inside from outside. All answers are double.
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "fabform/angles.hpp"
#include "fabform/geometry/closest_point.hpp"
#include "fabform/geometry/edge_wrap.hpp"
#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

class EmbreeScene;
struct EdgeCorner;  // rigid_body.cpp: one corner's edge, while edges are matched

/// A point on the body's surface with its outward normal. For a query point p, distance is
/// |p − point| and signed_distance is negative when p is inside the body (never when the
/// closest point is on the rim of an open mesh).
struct SurfacePoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double distance = 0.0;
  double signed_distance = 0.0;
  int triangle = -1;
};

/// A face within this share of a body's size of a point on the surface meets it there (a
/// hundred times kOnSurfaceShare: a node projected onto an edge lies on both its faces to a
/// rounding error, as does one on a crack of a CAD tessellation).
constexpr double kCreaseShare = 1e-7;
/// Two faces whose normals turn by less than this are one plane for a node resting on them.
constexpr double kCreaseAngleDeg = 1.0;
/// Its cosine: faces whose normals' dot product exceeds it are one plane.
inline const double kCreaseAngleCos = std::cos(kCreaseAngleDeg * kRadiansPerDegree);

/// Where a point lies within this share of a body's size (its box's diagonal) of the surface, it
/// lies on it: a node resting on a facet is left a rounding error above or below it (by the
/// interpolation of a coarser grid's rest, say), a move that starts there starts on it, and a
/// spring lying on a face does not pass under an edge that ends there.
constexpr double kOnSurfaceShare = 1e-9;

class RigidBody {
 public:
  /// Throws std::invalid_argument for a mesh with no usable triangle or a bad index, or a
  /// friction coefficient that is negative or not finite.
  RigidBody(std::string name, TriangleMesh mesh, double friction = 0.0);
  ~RigidBody();
  RigidBody(RigidBody&&) noexcept;
  RigidBody& operator=(RigidBody&&) noexcept;

  /// Closest surface point to p (BVH candidates, exact double distances).
  SurfacePoint closest(const Eigen::Vector3d& p) const;
  /// The same, searched within p's distance to triangle `near_triangle` (say, a neighbouring
  /// point's closest), which bounds it: cheap when that triangle is near. -1: no such triangle.
  SurfacePoint closest(const Eigen::Vector3d& p, int near_triangle) const;
  /// The same, when the surface lies within `radius` of p; a small radius makes it cheap.
  std::optional<SurfacePoint> closest_within(const Eigen::Vector3d& p, double radius) const;

  /// Where a point on the surface lies in a valley (a concave crease: a pocket's floor meeting
  /// its wall, two facets of a hole), the normals of the two faces there that turn most from
  /// each other (by more than kCreaseAngleDeg) and each rise on the outer side of the other's
  /// plane, among the faces within kCreaseShare of the body's size of p: a node pressed into
  /// the valley rests on both. None on a face's inside, on a ridge (a convex edge, which edge
  /// contact keeps springs out of) or where the faces turn less. Faces are found by distance,
  /// not by shared edges, so a CAD tessellation's cracks count too.
  std::optional<std::array<Eigen::Vector3d, 2>> valley_normals(const Eigen::Vector3d& p) const;

  /// Where the straight move from → to first enters the body through its outside, if it does.
  /// Crossings of the inside of a face (leaving the body) are not entries.
  std::optional<SurfacePoint> first_entry(const Eigen::Vector3d& from,
                                          const Eigen::Vector3d& to) const;

  /// Whether the segment crosses the surface at all, in either direction.
  bool segment_crosses(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;

  /// Lets springs wrap the body's convex edges whose two faces turn by at least `angle_deg`
  /// (edge_wrap.hpp): a CAD part's sharp edges, or a fillet's facets when the angle is below
  /// theirs. Throws std::invalid_argument for an angle outside (0, 180).
  void wrap_edges_sharper_than(double angle_deg);
  /// The body's convex edges whose two faces turn by at least `angle_deg`, in the placed frame
  /// (move them by pose()), with the edges along a CAD tessellation's cracks, whose second face
  /// meets them in T-junctions. Throws std::invalid_argument for an angle outside (0, 180).
  std::vector<SharpEdge> convex_edges(double angle_deg) const;
  /// The angle springs wrap edges from; 0 when they wrap none (contact is the nodes' alone).
  double wrap_angle_deg() const { return wrap_angle_deg_; }
  /// How many edges springs may wrap.
  int sharp_edge_count() const { return static_cast<int>(sharp_edges_.size()); }
  /// The segment a–b's wrap over a wrappable edge it passes under, where the body now is (near a
  /// corner, the shortest whose legs pass under no other edge); none when it passes under none.
  std::optional<EdgeWrap> wrap(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;

  /// Moves the body rigidly to `pose` (a rotation and translation of its mesh as placed): a
  /// tool travelling along its path. Every query above answers for the body where it now is;
  /// the BVH stays as built, queries are carried into the placed frame and back.
  void move_to(const Eigen::Isometry3d& pose);
  /// Where the body is, relative to its placement (the identity until it moves).
  const Eigen::Isometry3d& pose() const { return pose_; }
  /// The mesh where the body now is (the placed mesh moved by pose()), for output.
  TriangleMesh posed_mesh() const;

  const std::string& name() const { return name_; }
  /// Coulomb's μ between the fabric and this body's surface (0: frictionless).
  double friction() const { return friction_; }
  /// The mesh as placed by the scene, before any travel (see posed_mesh()).
  const TriangleMesh& mesh() const { return mesh_; }
  /// The placed mesh's bounding box (its size holds wherever the body travels).
  const BoundingBox& box() const { return box_; }
  /// How near its surface a point lies on it: kOnSurfaceShare of the box's diagonal.
  double on_surface_distance() const { return kOnSurfaceShare * box_.diagonal(); }
  /// Whether every edge joins exactly two faces that run it in opposite directions: a closed,
  /// consistently oriented surface, whose signed distance then changes no faster than the
  /// point moves (it is zero only on the surface).
  bool watertight() const { return watertight_; }
  /// Volume enclosed, positive when the faces are oriented outward (meaningful when closed).
  double signed_volume() const;
  /// Outward unit normal of a triangle (zero for a degenerate one).
  const Eigen::Vector3d& face_normal(int triangle) const { return face_normals_[triangle]; }

 private:
  void compute_normals();
  void visit_convex_edges(double angle_deg, const std::function<void(const SharpEdge&, int, int)>& visit) const;
  void add_crack_edges(double cos_limit, std::vector<SharpEdge>& edges) const;
  void compute_edge_normals();
  void set_edge(const EdgeCorner* first, const EdgeCorner* last);
  Eigen::Vector3d feature_normal(int triangle, TriangleFeature feature) const;
  bool on_rim(int triangle, TriangleFeature feature) const;
  SurfacePoint surface_point_on(int triangle, const Eigen::Vector3d& p) const;
  SurfacePoint surface_point_from(int triangle, const Eigen::Vector3d& p, const TriangleClosest& c) const;
  std::optional<SurfacePoint> closest_within_placed(const Eigen::Vector3d& p, double radius) const;
  std::optional<SurfacePoint> first_entry_placed(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;
  Eigen::Vector3d to_placed(const Eigen::Vector3d& p) const { return moved_ ? Eigen::Vector3d(inverse_ * p) : p; }
  SurfacePoint to_posed(SurfacePoint s) const;
  std::optional<EdgeWrap> choose_wrap(const std::vector<int>& edges, const Eigen::Vector3d& a,
                                      const Eigen::Vector3d& b) const;

  std::string name_;
  TriangleMesh mesh_;
  double friction_;
  BoundingBox box_;
  std::vector<Eigen::Vector3d> face_normals_;
  std::vector<std::array<Eigen::Vector3d, 3>> edge_normals_;  // per triangle: 01, 12, 20
  std::vector<Eigen::Vector3d> vertex_normals_;
  std::vector<std::array<bool, 3>> edge_on_rim_;  // per triangle: edge used by this face only
  std::vector<unsigned char> vertex_on_rim_;
  bool watertight_ = true;
  std::vector<SharpEdge> sharp_edges_;              // in the placed frame
  std::vector<std::array<int, 3>> sharp_edge_at_;   // per triangle: 01, 12, 20's index there, or -1
  double wrap_angle_deg_ = 0.0;
  std::unique_ptr<EmbreeScene> bvh_;
  Eigen::Isometry3d pose_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d inverse_ = Eigen::Isometry3d::Identity();
  bool moved_ = false;  // a body that never moves answers without the two transforms
};

}  // namespace fabform
