#include "fabform/model/term.hpp"

#include "fabform/thread_count.hpp"

namespace fabform {

void Term::add_forces(const Model& model, const Positions& x, std::vector<Eigen::Vector3d>& forces) const {
  const int nodes = static_cast<int>(x.size());
#pragma omp parallel for schedule(static) if (nodes >= kMinParallelItems)
  for (int k = 0; k < nodes; ++k)
    forces[static_cast<std::size_t>(k)] += force_at(model, x, k, x[static_cast<std::size_t>(k)]);
}

Eigen::Vector3d NodeFreedom::project(const Eigen::Vector3d& v) const {
  const Eigen::Vector3d free = remove_locked(v, locks);
  if (!contact_normal) return free;
  const Eigen::Vector3d normal = remove_locked(*contact_normal, locks);
  const double length2 = normal.squaredNorm();
  return length2 == 0.0 ? free : free - (free.dot(normal) / length2) * normal;
}

}  // namespace fabform
