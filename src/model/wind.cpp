#include "fabform/model/wind.hpp"

#include <cstddef>
#include <cstdio>
#include <stdexcept>

#include <Eigen/Geometry>

#include "fabform/model/model.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {
namespace {

constexpr double kFastestWind_m_s = 1000.0;

}  // namespace

std::string Wind::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (!velocity_m_s.allFinite()) return bad("velocity_m_s", "must be finite");
  if (velocity_m_s.squaredNorm() == 0.0) return bad("velocity_m_s", "wind without a direction: the velocity is zero");
  if (!(velocity_m_s.norm() <= kFastestWind_m_s)) return bad("velocity_m_s", "must be at most 1000 m/s in speed");
  if (!(coefficient_N_s_m3 > 0.0 && coefficient_N_s_m3 <= 1e6))
    return bad("coefficient_N_s_m3",
               "must be in (0, 1e6] N·s/m³ (force per area per m/s of wind across the fabric)");
  return "";
}

namespace {

// Twice the face's vector area, corner `moved` at `at`.
Eigen::Vector3d twice_vector_area(const Face& face, const std::vector<Eigen::Vector3d>& x, int moved,
                                  const Eigen::Vector3d& at) {
  const auto p = [&](int c) -> const Eigen::Vector3d& {
    const int node = face.corner[static_cast<std::size_t>(c)];
    return node == moved ? at : x[static_cast<std::size_t>(node)];
  };
  if (face.corners == 3) return (p(1) - p(0)).cross(p(2) - p(0));
  return (p(2) - p(0)).cross(p(3) - p(1));
}

}  // namespace

Eigen::Vector3d node_normal(const Fabric& fabric, const std::vector<Eigen::Vector3d>& x, int node,
                            const Eigen::Vector3d& at) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const int face : fabric.faces_at(node))
    sum += twice_vector_area(fabric.faces()[static_cast<std::size_t>(face)], x, node, at);
  const double length = sum.norm();
  return length > 0.0 ? Eigen::Vector3d(sum / length) : Eigen::Vector3d::Zero();
}

Eigen::Vector3d wind_force(const Wind& wind, double node_area_m2, const Eigen::Vector3d& normal,
                           const Eigen::Vector3d& velocity_m_s) {
  return wind.coefficient_N_s_m3 * node_area_m2 * normal.dot(wind.velocity_m_s - velocity_m_s) * normal;
}

Eigen::Vector3d after_wind_drag(double drag_step, const Eigen::Vector3d& normal, const Eigen::Vector3d& velocity_m_s) {
  return velocity_m_s - drag_step / (1.0 + drag_step * normal.squaredNorm()) * normal.dot(velocity_m_s) * normal;
}

WindLoad::WindLoad(const Wind& wind) : wind_(wind) {
  if (const std::string why = wind.invalid_reason(); !why.empty()) throw std::invalid_argument("wind: " + why);
}

std::string WindLoad::describe(const Model& /*model*/) const {
  const Eigen::Vector3d& v = wind_.velocity_m_s;
  char text[240];
  std::snprintf(text, sizeof text,
                "wind: seed 004's C·A·[n·(v_wind − v)]·n on each node, v_wind = (%.6g, %.6g, %.6g) m/s, "
                "C = %.6g N·s/m³ per area",
                v.x(), v.y(), v.z(), wind_.coefficient_N_s_m3);
  return text;
}

Eigen::Vector3d WindLoad::force_at(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const {
  return wind_force(wind_, model.fabric.node_areas()[static_cast<std::size_t>(node)],
                    node_normal(model.fabric, x, node, at), Eigen::Vector3d::Zero());
}

namespace {

class WindDrag final : public StepDrag {
 public:
  WindDrag(const Wind& wind, const Fabric& fabric, const Positions& x)
      : coefficient_(wind.coefficient_N_s_m3), areas_(fabric.node_areas()), normals_(x.size()) {
#pragma omp parallel for schedule(static) if (fabric.node_count() >= kMinParallelItems)
    for (int k = 0; k < fabric.node_count(); ++k) normals_[static_cast<std::size_t>(k)] = node_normal(fabric, x, k);
  }

  Eigen::Vector3d after(int node, double seconds, double mass_kg, const Eigen::Vector3d& velocity,
                        const NodeFreedom& freedom) const override {
    const auto k = static_cast<std::size_t>(node);
    return after_wind_drag(seconds * coefficient_ * areas_[k] / mass_kg, freedom.project(normals_[k]), velocity);
  }

 private:
  double coefficient_;
  const std::vector<double>& areas_;
  Positions normals_;
};

}  // namespace

std::unique_ptr<StepDrag> WindLoad::drag(const Model& model, const Positions& x) const {
  return std::make_unique<WindDrag>(wind_, model.fabric, x);
}

}  // namespace fabform
