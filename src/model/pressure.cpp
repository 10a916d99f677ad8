#include "fabform/model/pressure.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

#include <Eigen/Geometry>

namespace fabform {
namespace {

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

PressureLoad::PressureLoad(const Fabric& fabric, double pressure_Pa, const Eigen::Vector3d& reference)
    : pressure_Pa_(pressure_Pa), reference_(reference), triangles_at_(static_cast<std::size_t>(fabric.node_count())) {
  for (const Face& f : fabric.faces()) {
    const auto& c = f.corner;
    if (f.corners == 3) {
      triangles_.push_back({{c[0], c[1], c[2]}, 1.0});
      continue;
    }
    for (const std::array<int, 3> t : {std::array<int, 3>{c[0], c[1], c[2]}, {c[0], c[2], c[3]},
                                       {c[0], c[1], c[3]}, {c[1], c[2], c[3]}})
      triangles_.push_back({t, 0.5});
  }
  const auto side_of = [&](const Triangle& t, int corner) {
    const int a = t.node[static_cast<std::size_t>(corner)];
    const int b = t.node[static_cast<std::size_t>((corner + 1) % 3)];
    return std::array<int, 2>{std::min(a, b), std::max(a, b)};
  };
  std::map<std::array<int, 2>, int> side_index;  // sorted: Newton's matrix sums in this order
  for (std::size_t i = 0; i < triangles_.size(); ++i)
    for (int corner = 0; corner < 3; ++corner) {
      triangles_at_[static_cast<std::size_t>(triangles_[i].node[static_cast<std::size_t>(corner)])].push_back(static_cast<int>(i));
      side_index.emplace(side_of(triangles_[i], corner), 0);
    }
  for (auto& [side, index] : side_index) index = static_cast<int>(sides_.size()), sides_.push_back(side);
  for (Triangle& t : triangles_)
    for (int corner = 0; corner < 3; ++corner) t.side[static_cast<std::size_t>(corner)] = side_index[side_of(t, corner)];
}

std::string PressureLoad::describe(const Model& /*model*/) const {
  char text[200];
  std::snprintf(text, sizeof text,
                "pressure: %.6g Pa, a follower load normal to the fabric, pushing against warp x weft", pressure_Pa_);
  return text;
}

double PressureLoad::triangle_volume(const Triangle& t, const Positions& x, int moved,
                                     const Eigen::Vector3d& at) const {
  const auto p = [&](int c) -> Eigen::Vector3d {
    const int node = t.node[static_cast<std::size_t>(c)];
    return (node == moved ? at : x[static_cast<std::size_t>(node)]) - reference_;
  };
  return t.weight * p(0).dot(p(1).cross(p(2))) / 6.0;
}

Eigen::Vector3d PressureLoad::force_at(const Model& /*model*/, const Positions& x, int node,
                                       const Eigen::Vector3d& /*at*/) const {
  Eigen::Vector3d gradient = Eigen::Vector3d::Zero();  // ∂V/∂x_node
  for (const int i : triangles_at_[static_cast<std::size_t>(node)]) {
    const Triangle& t = triangles_[static_cast<std::size_t>(i)];
    const int c = static_cast<int>(std::find(t.node.begin(), t.node.end(), node) - t.node.begin());
    const Eigen::Vector3d next = x[static_cast<std::size_t>(t.node[static_cast<std::size_t>((c + 1) % 3)])] - reference_;
    const Eigen::Vector3d last = x[static_cast<std::size_t>(t.node[static_cast<std::size_t>((c + 2) % 3)])] - reference_;
    gradient += t.weight * next.cross(last) / 6.0;
  }
  return -pressure_Pa_ * gradient;
}

double PressureLoad::energy(const Model& /*model*/, const Positions& x) const {
  double volume = 0.0;
  for (const Triangle& t : triangles_) volume += triangle_volume(t, x, -1, Eigen::Vector3d::Zero());
  return pressure_Pa_ * volume;
}

double PressureLoad::node_energy_change(const Model& /*model*/, const Positions& x, int node,
                                        const Eigen::Vector3d& at) const {
  double change = 0.0;
  for (const int i : triangles_at_[static_cast<std::size_t>(node)]) {
    const Triangle& t = triangles_[static_cast<std::size_t>(i)];
    change += triangle_volume(t, x, node, at) - triangle_volume(t, x, -1, Eigen::Vector3d::Zero());
  }
  return pressure_Pa_ * change;
}

// ∂²V/∂x_a∂x_b = −[x_c − o]×/6 for a triangle (a, b, c) in its order (det is linear in each
// corner, so the diagonal blocks vanish); seen from b's side it is the transpose, [x_c − o]×/6.
std::vector<PressureCoupling> PressureLoad::couplings(const Positions& x) const {
  std::vector<PressureCoupling> out;
  out.reserve(sides_.size());
  for (const auto& side : sides_) out.push_back({side[0], side[1], Eigen::Vector3d::Zero()});
  for (const Triangle& t : triangles_)
    for (int corner = 0; corner < 3; ++corner) {
      const int a = t.node[static_cast<std::size_t>(corner)];
      const int b = t.node[static_cast<std::size_t>((corner + 1) % 3)];
      const Eigen::Vector3d c = x[static_cast<std::size_t>(t.node[static_cast<std::size_t>((corner + 2) % 3)])] - reference_;
      const double sign = a < b ? -1.0 : 1.0;
      out[static_cast<std::size_t>(t.side[static_cast<std::size_t>(corner)])].s += sign * t.weight * pressure_Pa_ / 6.0 * c;
    }
  return out;
}

// Each side's part of the Hessian, [[0, S], [Sᵀ, 0]] with S = [s]× skew, has eigenvalues ±|s|;
// its positive part is ½(H + |H|), |H| = |s|·(I − ŝŝᵀ) on both diagonal blocks.
void PressureLoad::add_stiffness(const Model& /*model*/, const Positions& x, StiffnessSink& sink) const {
  for (const PressureCoupling& c : couplings(x)) {
    const double length = c.s.norm();
    const Eigen::Matrix3d across =
        length > 0.0 ? Eigen::Matrix3d(0.5 * (length * Eigen::Matrix3d::Identity() - c.s * c.s.transpose() / length))
                     : Eigen::Matrix3d::Zero();
    sink.add(c.a, c.a, across);
    sink.add(c.b, c.b, across);
    sink.add(c.a, c.b, 0.5 * cross_matrix(c.s));
  }
}

}  // namespace fabform
