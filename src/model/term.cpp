#include "fabform/model/term.hpp"

namespace fabform {

Eigen::Vector3d NodeFreedom::project(const Eigen::Vector3d& v) const {
  const Eigen::Vector3d free = remove_locked(v, locks);
  if (!contact_normal) return free;
  const Eigen::Vector3d normal = remove_locked(*contact_normal, locks);
  const double length2 = normal.squaredNorm();
  return length2 == 0.0 ? free : free - (free.dot(normal) / length2) * normal;
}

}  // namespace fabform
