#include "fabform/solver/contact_move.hpp"

#include <limits>
#include <optional>

namespace fabform {
namespace {

// A free node that comes to rest in a valley of the body rests on both its faces, where it may.
NodeContact resting(const RigidBody& body, int b, const SurfacePoint& on, const Eigen::Vector3d& anchor,
                    Valleys valleys) {
  NodeContact contact{b, on.normal, anchor};
  if (valleys == Valleys::one_face) return contact;
  if (const auto faces = body.valley_normals(on.point)) contact.normal = (*faces)[0], contact.crease = (*faces)[1];
  return contact;
}

// A move along one face past a valley (a concave crease) ends inside the body behind the other
// face, whose nearest point is on that face, never on the crease: a node pressed into the valley
// would hop from face to face for ever. It stops on the crease instead, where both faces' planes
// meet nearest `to` (from `from` on the first face's plane), if the surface is there.
std::optional<Eigen::Vector3d> on_valley(const RigidBody& body, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                         const Eigen::Vector3d& first, const SurfacePoint& second) {
  const double c = first.dot(second.normal);
  if (second.signed_distance >= 0.0 || c > kCreaseAngleCos) return std::nullopt;
  // to + α n₁ + β n₂ on both planes.
  const double r1 = -first.dot(to - from), r2 = -second.normal.dot(to - second.point);
  const double alpha = (r1 - c * r2) / (1.0 - c * c), beta = (r2 - c * r1) / (1.0 - c * c);
  const Eigen::Vector3d on = to + alpha * first + beta * second.normal;
  const auto check = body.closest_within(on, kCreaseShare * body.box().diagonal());
  if (!check) return std::nullopt;
  return check->point;
}

// A contact node moved on the tangent plane is projected back onto the surface (Fig. 8).
// The node was on the surface, so the surface is within the step's length of `to`.
NodeMove slide(const Model& model, const Eigen::Vector3d& from, const Eigen::Vector3d& to, const NodeContact& contact,
               Valleys valleys) {
  const RigidBody& surface = model.bodies[static_cast<std::size_t>(contact.body)];
  const double step_length = (to - from).norm();
  const auto s = surface.closest_within(to, 2.0 * step_length + 1e-6 * surface.box().diagonal());
  SurfacePoint projected = s ? *s : surface.closest(to);
  if (valleys == Valleys::both_faces)
    if (const auto valley = on_valley(surface, from, to, contact.normal, projected)) projected.point = *valley;
  return {projected.point, resting(surface, contact.body, projected, contact.anchor, valleys)};
}

// Entry points are snapped onto their triangle, which can move them by a rounding error;
// a held coordinate must not move at all.
Eigen::Vector3d keep_locked(Eigen::Vector3d point, const Eigen::Vector3d& reference,
                            AxisMask locks) {
  for (int axis = 0; axis < 3; ++axis)
    if (locks & (1 << axis)) point[axis] = reference[axis];
  return point;
}

// A node held on some axes cannot be projected to the closest surface point: that would move
// it along them. It returns to the surface along the free part of the normal instead, or, if
// the surface fell away further than the step, it is free. The reach is never shorter than
// Embree's single-precision slip (as in entry_point): a short step near the rest would search a
// ray that ends within a rounding error of the surface, miss it and release the node.
NodeMove slide_locked(const Model& model, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                      const NodeContact& contact, AxisMask locks) {
  const Eigen::Vector3d along = remove_locked(contact.normal, locks).normalized();
  const RigidBody& body = model.bodies[static_cast<std::size_t>(contact.body)];
  const double reach = 2.0 * (to - from).norm() + 1e-6 * body.box().diagonal();
  const auto s = body.first_entry(to + reach * along, to - reach * along);
  if (!s) return {to, NodeContact{}};
  return {keep_locked(s->point, to, locks), NodeContact{contact.body, s->normal, contact.anchor}};
}

// Embree's single-precision rays can slip through a shared edge (by ~1e-7 of the body's
// size), and a ray starting on the surface may not count it as entered; a move that ends
// inside the body, no deeper than the move is long plus such a slip, entered it too and stops
// on the surface: at the closest point, or, for a node held on some axes, where the free part
// of the normal leads back out (keep_locked then restores the held coordinates).
std::optional<SurfacePoint> entry_point(const RigidBody& body, const Eigen::Vector3d& from,
                                        const Eigen::Vector3d& to, AxisMask locks) {
  if (auto entry = body.first_entry(from, to)) return entry;
  const double reach = (to - from).norm() + 1e-6 * body.box().diagonal();
  const auto s = body.closest_within(to, reach);
  if (!s || s->signed_distance >= 0.0) return std::nullopt;
  if (locks == 0) return s;
  const Eigen::Vector3d along = remove_locked(s->normal, locks);
  if (along.squaredNorm() == 0.0) return std::nullopt;
  return body.first_entry(to + 2.0 * reach * along.normalized(), to);
}

// A free node moves straight; if the move enters a body, it stops on the surface there. A node
// held on no axis that starts on the surface (released there because its force pointed out of
// the body, while the step still leans a hair into it) would stop where it is, step after
// step: it lands and slides the step along the surface instead, as a node on the body does.
NodeMove fly(const Model& model, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
             AxisMask locks, Valleys valleys) {
  NodeMove result{to, NodeContact{}};
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const auto entry = entry_point(model.bodies[b], from, to, locks);
    if (entry && (entry->point - from).norm() < nearest) {
      nearest = (entry->point - from).norm();
      const Eigen::Vector3d landed = keep_locked(entry->point, to, locks);
      result = {landed, locks == 0 ? resting(model.bodies[b], static_cast<int>(b), *entry, landed, valleys)
                                   : NodeContact{static_cast<int>(b), entry->normal, landed}};
    }
  }
  if (!result.contact.active() || locks != 0) return result;
  const RigidBody& body = model.bodies[static_cast<std::size_t>(result.contact.body)];
  if (nearest > body.on_surface_distance()) return result;
  return slide(model, result.x, to, result.contact, valleys);
}

}  // namespace

NodeMove move_node(const Model& model, int node, const Eigen::Vector3d& from,
                   const Eigen::Vector3d& step, const NodeContact& contact, Valleys valleys) {
  const AxisMask locks = model.locks[static_cast<std::size_t>(node)];
  const Eigen::Vector3d to = from + remove_locked(step, locks);
  if (!contact.active()) return fly(model, from, to, locks, valleys);
  if (locks == 0) return slide(model, from, to, contact, valleys);
  return slide_locked(model, from, to, contact, locks);
}

}  // namespace fabform
