#include "fabform/material/tension_table.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fabform {
namespace {

void validate(const std::vector<TablePoint>& points) {
  if (points.size() < 2) throw std::invalid_argument("a table needs at least two points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(points[i].strain) || !std::isfinite(points[i].tension_N_per_m))
      throw std::invalid_argument("point " + std::to_string(i + 1) + " is not finite");
    if (i > 0 && !(points[i].strain > points[i - 1].strain))
      throw std::invalid_argument("strain must increase strictly (point " + std::to_string(i + 1) +
                                  ")");
  }
  const bool tension_only = points.front().strain >= 0.0;
  if (tension_only && (points.front().strain != 0.0 || points.front().tension_N_per_m != 0.0))
    throw std::invalid_argument(
        "a table without negative strains is tension-only and must start at strain 0, value 0");
}

// Area under the segment from a to b, integrated from a.strain to e.
double trapezoid(const TablePoint& a, const TablePoint& b, double e) {
  const double s = (b.tension_N_per_m - a.tension_N_per_m) / (b.strain - a.strain);
  const double d = e - a.strain;
  return a.tension_N_per_m * d + 0.5 * s * d * d;
}

}  // namespace

TensionTable::TensionTable(std::vector<TablePoint> points, std::string name)
    : points_(std::move(points)), name_(std::move(name)) {
  validate(points_);
  tension_only_ = points_.front().strain >= 0.0;
  energy_at_point_.assign(points_.size(), 0.0);
  for (std::size_t k = 0; k + 1 < points_.size(); ++k)
    energy_at_point_[k + 1] =
        energy_at_point_[k] + trapezoid(points_[k], points_[k + 1], points_[k + 1].strain);
  // Energy is measured from strain 0, where the fabric is at rest.
  energy_at_zero_ = tension_only_ ? 0.0 : energy_from_first_point(0.0);
}

std::size_t TensionTable::segment_of(double strain) const {
  const auto it = std::upper_bound(points_.begin(), points_.end(), strain,
                                   [](double e, const TablePoint& p) { return e < p.strain; });
  const auto index = static_cast<std::size_t>(it - points_.begin());
  return std::clamp<std::size_t>(index == 0 ? 0 : index - 1, 0, points_.size() - 2);
}

double TensionTable::tension(double strain) const {
  if (tension_only_ && strain <= 0.0) return 0.0;
  const std::size_t k = segment_of(strain);
  const TablePoint& a = points_[k];
  const TablePoint& b = points_[k + 1];
  return a.tension_N_per_m +
         (b.tension_N_per_m - a.tension_N_per_m) * (strain - a.strain) / (b.strain - a.strain);
}

double TensionTable::steepest_slope() const {
  double steepest = 0.0;
  for (std::size_t i = 1; i < points_.size(); ++i)
    steepest = std::max(steepest, (points_[i].tension_N_per_m - points_[i - 1].tension_N_per_m) /
                                      (points_[i].strain - points_[i - 1].strain));
  return steepest;
}

double TensionTable::slope(double strain) const {
  if (tension_only_ && strain <= 0.0) return 0.0;
  const std::size_t k = segment_of(strain);
  const TablePoint& a = points_[k];
  const TablePoint& b = points_[k + 1];
  return (b.tension_N_per_m - a.tension_N_per_m) / (b.strain - a.strain);
}

double TensionTable::energy_from_first_point(double strain) const {
  const std::size_t k = segment_of(strain);
  return energy_at_point_[k] + trapezoid(points_[k], points_[k + 1], strain);
}

double TensionTable::energy_density(double strain) const {
  if (tension_only_ && strain <= 0.0) return 0.0;
  return energy_from_first_point(strain) - energy_at_zero_;
}

TensionTable TensionTable::scaled(double factor) const {
  std::vector<TablePoint> points = points_;
  for (TablePoint& p : points) p.tension_N_per_m *= factor;
  TensionTable table(std::move(points), name_);
  table.set_compression(compression_, flexural_rigidity_Nm_);
  return table;
}

void TensionTable::set_compression(Compression mode, double flexural_rigidity_Nm) {
  compression_ = mode;
  flexural_rigidity_Nm_ = flexural_rigidity_Nm;
}

CompressionLaw TensionTable::compression_law(double rest_length_m) const {
  const TablePoint& a = points_[0];
  const TablePoint& b = points_[1];
  // A first segment that falls (a softening table's) would push apart a compressed spring: 0.
  const double first_slope = std::max((b.tension_N_per_m - a.tension_N_per_m) / (b.strain - a.strain), 0.0);
  return {tension_only_ ? compression_ : Compression::none, first_slope,
          compression_ == Compression::buckling ? euler_buckling_tension(flexural_rigidity_Nm_, rest_length_m) : 0.0};
}

// Strain 0 itself belongs to the compression law when there is one: its slope there is k₀, not
// the slack side's 0, so that newton sees the stiffness a spring at rest has.
double TensionTable::tension(double strain, double rest_length_m) const {
  if (strain > 0.0 || !tension_only_ || compression_ == Compression::none) return tension(strain);
  return compression_law(rest_length_m).tension(strain);
}

double TensionTable::slope(double strain, double rest_length_m) const {
  if (strain > 0.0 || !tension_only_ || compression_ == Compression::none) return slope(strain);
  return compression_law(rest_length_m).slope(strain);
}

double TensionTable::energy_density(double strain, double rest_length_m) const {
  if (strain > 0.0 || !tension_only_ || compression_ == Compression::none) return energy_density(strain);
  return compression_law(rest_length_m).energy_density(strain);
}

}  // namespace fabform
