#include "fabform/output/fabric_figures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fabform/fabric/spring.hpp"

namespace fabform {
namespace {

// A cell of the grid: corners (i, j), (i+1, j), (i+1, j+1), (i, j+1).
struct Cell {
  double area_m2;
  double warp_strain;  // mean of its two warp edges
  double weft_strain;  // mean of its two weft edges
};

double triangle_area(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

std::vector<Cell> formed_cells(const FabricGrid& grid, const std::vector<Eigen::Vector3d>& x) {
  std::vector<Cell> cells;
  const double warp_rest = grid.spacing_warp(), weft_rest = grid.spacing_weft();
  for (int j = 0; j + 1 < grid.nodes_weft(); ++j)
    for (int i = 0; i + 1 < grid.nodes_warp(); ++i) {
      const auto& a = x[grid.node(i, j)];
      const auto& b = x[grid.node(i + 1, j)];
      const auto& c = x[grid.node(i + 1, j + 1)];
      const auto& d = x[grid.node(i, j + 1)];
      cells.push_back({triangle_area(a, b, c) + triangle_area(a, c, d),
                       0.5 * (spring_strain(a, b, warp_rest) + spring_strain(d, c, warp_rest)),
                       0.5 * (spring_strain(a, d, weft_rest) + spring_strain(b, c, weft_rest))});
    }
  return cells;
}

StrainPeak peak_of(const Model& model, const std::vector<Eigen::Vector3d>& x, Direction direction) {
  StrainPeak peak;
  peak.strain = -std::numeric_limits<double>::infinity();
  for (const Spring& s : model.grid.springs()) {
    if (s.direction != direction) continue;
    const double strain = spring_strain(x[s.a], x[s.b], s.rest_length);
    if (strain > peak.strain)
      peak = {strain, model.grid.i_of(s.a), model.grid.j_of(s.a), 0.5 * (x[s.a] + x[s.b])};
  }
  return peak;
}

// A round bin width, step / per (step 1, 2 or 5, per a power of ten), giving at most 20 bins
// over [lo, hi]. Edges are integers divided by `per`, so they print as the round numbers they are.
struct BinWidth {
  double step;
  double per;
  double value() const { return step / per; }
};

BinWidth bin_width(double lo, double hi) {
  const double span = std::max(hi - lo, 1e-6);
  for (double per = 1e6;; per /= 10.0)
    for (const double step : {1.0, 2.0, 5.0})
      if (span * per / step <= 20.0) return {step, per};
}

StrainHistogram histogram_of(const std::vector<Cell>& cells) {
  StrainHistogram h;
  if (cells.empty()) return h;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Cell& c : cells)
    lo = std::min({lo, c.warp_strain, c.weft_strain}), hi = std::max({hi, c.warp_strain, c.weft_strain});
  if (!std::isfinite(lo) || !std::isfinite(hi)) return h;  // a broken state has no histogram
  const BinWidth width = bin_width(lo, hi);
  const double first = std::floor(lo / width.value());  // in widths
  const auto bins = static_cast<std::size_t>(std::floor(hi / width.value() - first)) + 1;
  for (std::size_t b = 0; b <= bins; ++b) h.edges.push_back((first + static_cast<double>(b)) * width.step / width.per);
  h.warp_area_m2.assign(bins, 0.0);
  h.weft_area_m2.assign(bins, 0.0);
  const auto bin_of = [&](double strain) {
    const double at = std::floor(strain / width.value() - first);
    return std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, at)));
  };
  for (const Cell& c : cells) {
    h.warp_area_m2[bin_of(c.warp_strain)] += c.area_m2;
    h.weft_area_m2[bin_of(c.weft_strain)] += c.area_m2;
  }
  return h;
}

// Each cell's area split equally among its four corners; the corners on a body add up.
double contact_area(const FabricGrid& grid, const std::vector<Cell>& cells,
                    const std::vector<unsigned char>& contact) {
  double area = 0.0;
  std::size_t cell = 0;
  for (int j = 0; j + 1 < grid.nodes_weft(); ++j)
    for (int i = 0; i + 1 < grid.nodes_warp(); ++i, ++cell)
      for (const int k : {grid.node(i, j), grid.node(i + 1, j), grid.node(i + 1, j + 1), grid.node(i, j + 1)})
        if (contact[static_cast<std::size_t>(k)]) area += 0.25 * cells[cell].area_m2;
  return area;
}

}  // namespace

FabricFigures fabric_figures(const Model& model, const std::vector<Eigen::Vector3d>& x,
                             const std::vector<unsigned char>& contact) {
  const std::vector<Cell> cells = formed_cells(model.grid, x);
  FabricFigures f;
  f.area_flat_m2 = model.grid.spec().width_m * model.grid.spec().height_m;
  for (const Cell& c : cells) f.area_formed_m2 += c.area_m2;
  f.contact_area_m2 = contact_area(model.grid, cells, contact);
  f.max_warp = peak_of(model, x, Direction::warp);
  f.max_weft = peak_of(model, x, Direction::weft);
  f.histogram = histogram_of(cells);
  return f;
}

}  // namespace fabform
