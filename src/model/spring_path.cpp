#include "fabform/model/spring_path.hpp"

#include "fabform/fabric/spring.hpp"
#include "fabform/model/wrapped_spring.hpp"

namespace fabform {

std::optional<EdgeWrap> spring_wrap(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                                    const Eigen::Vector3d& xb) {
  if (spring.kind == SpringKind::bend) return std::nullopt;
  std::optional<EdgeWrap> longest;
  for (const RigidBody& body : model.bodies)
    if (body.wrap_angle_deg() > 0.0)
      if (auto w = body.wrap(xa, xb); w && (!longest || w->length > longest->length)) longest = w;
  return longest;
}

double spring_path_length(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                          const Eigen::Vector3d& xb) {
  const auto wrap = spring_wrap(model, spring, xa, xb);
  return wrap ? wrap->length : (xb - xa).norm();
}

double spring_path_strain(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                          const Eigen::Vector3d& xb) {
  return spring_path_length(model, spring, xa, xb) / spring.rest_length - 1.0;
}

double spring_path_energy(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                          const Eigen::Vector3d& xb) {
  const TensionTable& table = model.table(spring.kind);
  const auto wrap = spring_wrap(model, spring, xa, xb);
  return wrap ? wrapped_spring_energy(*wrap, spring, table) : spring_energy(xa, xb, spring, table);
}

Eigen::Vector3d spring_path_force(const Model& model, const Spring& spring, const Eigen::Vector3d& xa,
                                  const Eigen::Vector3d& xb, int end) {
  const TensionTable& table = model.table(spring.kind);
  const auto wrap = spring_wrap(model, spring, xa, xb);
  const Eigen::Vector3d& node = end == spring.a ? xa : xb;
  const Eigen::Vector3d& other = end == spring.a ? xb : xa;
  return wrap ? wrapped_spring_force(node, *wrap, spring, table) : spring_force_on_a(node, other, spring, table);
}

}  // namespace fabform
