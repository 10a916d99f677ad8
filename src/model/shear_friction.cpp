#include "fabform/model/shear_friction.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "fabform/angles.hpp"
#include "fabform/model/model.hpp"
#include "fabform/model/rounded_abs.hpp"

namespace fabform {
namespace {

// A four-sided face's diagonals, corner 0 to 2 and 1 to 3, in the flat fabric and at x.
struct CellDiagonals {
  std::array<std::array<int, 2>, 2> ends{};
  std::array<double, 2> rest_length{};
  std::array<Eigen::Vector3d, 2> now{};
  double scale = 0.0;  // L₁·L₂ / (2·A): γ per unit of ε₁ − ε₂
  double area = 0.0;   // A = |d₁ × d₂| / 2 of the flat cell
};

CellDiagonals diagonals(const Model& model, const Face& face, const Positions& x, int moved, const Eigen::Vector3d& at) {
  const auto p = [&](int node) -> const Eigen::Vector3d& { return node == moved ? at : x[static_cast<std::size_t>(node)]; };
  CellDiagonals d;
  std::array<Eigen::Vector3d, 2> flat;
  for (std::size_t k = 0; k < 2; ++k) {
    d.ends[k] = {face.corner[k], face.corner[k + 2]};
    flat[k] = model.fabric.rest_position(d.ends[k][1]) - model.fabric.rest_position(d.ends[k][0]);
    d.rest_length[k] = flat[k].norm();
    d.now[k] = p(d.ends[k][1]) - p(d.ends[k][0]);
  }
  d.area = 0.5 * flat[0].cross(flat[1]).norm();
  d.scale = d.rest_length[0] * d.rest_length[1] / (2.0 * d.area);
  return d;
}

double shear_of(const CellDiagonals& d) {
  return d.scale * ((d.now[0].norm() / d.rest_length[0]) - (d.now[1].norm() / d.rest_length[1]));
}

// ∂γ/∂(the end `end` of diagonal k): ±s·n_k/L_k, the second diagonal's with the opposite sign.
// A diagonal crushed to a point has no direction: it then pulls nowhere.
Eigen::Vector3d shear_gradient(const CellDiagonals& d, std::size_t k, std::size_t end) {
  const double length = d.now[k].norm();
  if (length == 0.0) return Eigen::Vector3d::Zero();
  const double sign = (k == 0 ? 1.0 : -1.0) * (end == 1 ? 1.0 : -1.0);
  return sign * d.scale * d.now[k] / (length * d.rest_length[k]);
}

}  // namespace

ShearFriction::ShearFriction(double hysteresis_N_m, double rounding_rad)
    : hysteresis_N_m_(hysteresis_N_m), rounding_rad_(rounding_rad) {
  if (!(hysteresis_N_m > 0.0 && rounding_rad > 0.0))
    throw std::invalid_argument("shear friction: 2HG and the rounding angle must be positive");
}

double ShearFriction::shear_angle(const Model& model, int face, const Positions& x) const {
  const Face& f = model.fabric.faces()[static_cast<std::size_t>(face)];
  return shear_of(diagonals(model, f, x, -1, Eigen::Vector3d::Zero()));
}

double ShearFriction::cell_energy(const Model& model, int face, const Positions& x, int moved,
                                  const Eigen::Vector3d& at) const {
  const Face& f = model.fabric.faces()[static_cast<std::size_t>(face)];
  if (f.corners != 4) return 0.0;
  const CellDiagonals d = diagonals(model, f, x, moved, at);
  return d.area * 0.5 * hysteresis_N_m_ * rounded_abs(shear_of(d), rounding_rad_);
}

std::string ShearFriction::describe(const Model& model) const {
  std::size_t cells = 0;
  for (const Face& f : model.fabric.faces()) cells += f.corners == 4 ? 1 : 0;
  char text[300];
  std::snprintf(text, sizeof text,
                "shear friction: %zu cells shear against half the measured hysteresis 2HG (loading branch; 2HG %.6g "
                "N/m, rounded over %.6g°)",
                cells, hysteresis_N_m_, rounding_rad_ * kDegreesPerRadian);
  return text;
}

double ShearFriction::energy(const Model& model, const Positions& x) const {
  double energy = 0.0;
  for (std::size_t f = 0; f < model.fabric.faces().size(); ++f)
    energy += cell_energy(model, static_cast<int>(f), x, -1, Eigen::Vector3d::Zero());
  return energy;
}

Eigen::Vector3d ShearFriction::force_at(const Model& model, const Positions& x, int node,
                                        const Eigen::Vector3d& at) const {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (const int f : model.fabric.faces_at(node)) {
    const Face& face = model.fabric.faces()[static_cast<std::size_t>(f)];
    if (face.corners != 4) continue;
    const CellDiagonals d = diagonals(model, face, x, node, at);
    const double slope = d.area * 0.5 * hysteresis_N_m_ * rounded_abs_slope(shear_of(d), rounding_rad_);
    for (std::size_t k = 0; k < 2; ++k)
      for (std::size_t end = 0; end < 2; ++end)
        if (d.ends[k][end] == node) force -= slope * shear_gradient(d, k, end);
  }
  return force;
}

double ShearFriction::node_energy_change(const Model& model, const Positions& x, int node,
                                         const Eigen::Vector3d& at) const {
  double change = 0.0;
  for (const int f : model.fabric.faces_at(node))
    change += cell_energy(model, f, x, node, at) - cell_energy(model, f, x, node, x[static_cast<std::size_t>(node)]);
  return change;
}

void ShearFriction::add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const {
  const std::vector<Face>& faces = model.fabric.faces();
  sink.add_each(faces.size(), [&](std::size_t f, StiffnessSink& part) {
    if (faces[f].corners != 4) return;
    const CellDiagonals d = diagonals(model, faces[f], x, -1, Eigen::Vector3d::Zero());
    const double gamma = shear_of(d), friction = d.area * 0.5 * hysteresis_N_m_;
    std::array<int, 4> node{};
    std::array<Eigen::Vector3d, 4> g;
    for (std::size_t k = 0; k < 2; ++k)
      for (std::size_t end = 0; end < 2; ++end) {
        node[2 * k + end] = d.ends[k][end];
        g[2 * k + end] = shear_gradient(d, k, end);
      }
    // ρ''·g·gᵀ, inside the rounding only.
    if (const double curvature = friction * rounded_abs_curvature(gamma, rounding_rad_); curvature > 0.0)
      for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c <= r; ++c) part.add(node[r], node[c], curvature * g[r] * g[c].transpose());
    // ρ'·s·∂²ε_k: ∂²|d|/L over the diagonal's ends is ±(I − n·nᵀ)/(L·|d|); the first diagonal's
    // enters with ρ', the second's with −ρ': keep the one that is positive semi-definite.
    const double slope = friction * rounded_abs_slope(gamma, rounding_rad_);
    const std::size_t k = slope >= 0.0 ? 0 : 1;
    if (d.now[k].norm() == 0.0) return;
    const Eigen::Vector3d n = d.now[k].normalized();
    const Eigen::Matrix3d p = std::abs(slope) * d.scale / (d.rest_length[k] * d.now[k].norm()) *
                              (Eigen::Matrix3d::Identity() - n * n.transpose());
    part.add(d.ends[k][0], d.ends[k][0], p);
    part.add(d.ends[k][1], d.ends[k][1], p);
    part.add(d.ends[k][1], d.ends[k][0], -p);
  });
}

}  // namespace fabform
