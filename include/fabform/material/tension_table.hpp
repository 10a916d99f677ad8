#pragma once
// A fabric direction's measured response: tension per unit width T (N/m) against engineering
// strain, piecewise linear (seed 003, Figure 5). Everything downstream works in N/m; a stress
// table is converted with its thickness when it is read.
#include <string>
#include <vector>

#include "fabform/material/compression_response.hpp"

namespace fabform {

struct TablePoint {
  double strain = 0.0;
  double tension_N_per_m = 0.0;
};

class TensionTable {
 public:
  /// Throws std::invalid_argument when the points are not a valid table: fewer than two,
  /// non-finite, strain not strictly increasing, or a tension-only table (no negative strain)
  /// that does not start at (0, 0).
  explicit TensionTable(std::vector<TablePoint> points, std::string name = "");

  /// Tension at a strain. Fabrics buckle rather than carry compression, so a table without
  /// negative strains gives zero below 0; outside the measured range the end segment extends.
  double tension(double strain) const;
  /// dT/dε, the slope of the segment the strain falls in (0 in the slack range).
  double slope(double strain) const;
  /// ∫₀^ε T dε (J/m²): the energy per unit rest area of a spring stretched to ε.
  double energy_density(double strain) const;

  /// The same three for a spring of rest length L (m): a tension-only table's compression
  /// response (set_compression) below zero strain, else exactly the table's own.
  double tension(double strain, double rest_length_m) const;
  double slope(double strain, double rest_length_m) const;
  double energy_density(double strain, double rest_length_m) const;

  /// What a tension-only table gives in compression (compression_response.hpp); B, the fabric's
  /// flexural rigidity (N·m), sets the buckling load. A table with measured compression keeps it.
  void set_compression(Compression mode, double flexural_rigidity_Nm = 0.0);
  /// The table with every tension multiplied by `factor` (> 0), its own compression response.
  TensionTable scaled(double factor) const;
  Compression compression() const { return compression_; }
  /// The law a spring of rest length L follows below zero strain.
  CompressionLaw compression_law(double rest_length_m) const;

  /// The steepest segment's slope (N/m per unit strain); a slack range has slope 0, and the
  /// extended end segments keep their slopes.
  double steepest_slope() const;
  bool tension_only() const { return tension_only_; }
  /// Whether the table is extrapolated at this strain (a slack tension-only spring is not).
  bool beyond_range(double strain) const {
    return strain > max_strain() || (!tension_only_ && strain < min_strain());
  }
  double min_strain() const { return points_.front().strain; }
  double max_strain() const { return points_.back().strain; }
  const std::vector<TablePoint>& points() const { return points_; }
  const std::string& name() const { return name_; }

 private:
  std::size_t segment_of(double strain) const;
  double energy_from_first_point(double strain) const;

  std::vector<TablePoint> points_;
  std::vector<double> energy_at_point_;  // ∫ T dε from the first point to every point
  double energy_at_zero_ = 0.0;
  std::string name_;
  bool tension_only_ = true;
  Compression compression_ = Compression::none;
  double flexural_rigidity_Nm_ = 0.0;
};

}  // namespace fabform
