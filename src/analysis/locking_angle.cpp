#include "fabform/analysis/locking_angle.hpp"

#include <algorithm>
#include <cmath>

#include "fabform/angles.hpp"

namespace fabform {
namespace {


double slope_of(const TablePoint& a, const TablePoint& b) {
  return (b.tension_N_per_m - a.tension_N_per_m) / (b.strain - a.strain);
}

}  // namespace

double shear_angle_of_diagonal_strain_deg(double diagonal_strain) {
  const double sine = (1.0 + diagonal_strain) * (1.0 + diagonal_strain) - 1.0;
  return kDegreesPerRadian * std::asin(std::clamp(sine, -1.0, 1.0));
}

std::optional<double> locking_angle_deg(const TensionTable& shear) {
  const std::vector<TablePoint>& p = shear.points();
  if (p.size() < 3) return std::nullopt;
  const TablePoint& a = p[0];
  const TablePoint& b = p[p.size() - 2];
  const double soft = slope_of(a, p[1]), stiff = slope_of(b, p.back());
  if (!(stiff > soft)) return std::nullopt;
  // soft·(e − e_a) + T_a = stiff·(e − e_b) + T_b
  const double e = (b.tension_N_per_m - a.tension_N_per_m + soft * a.strain - stiff * b.strain) / (soft - stiff);
  return shear_angle_of_diagonal_strain_deg(e);
}

}  // namespace fabform
