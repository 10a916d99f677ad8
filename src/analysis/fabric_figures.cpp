#include "fabform/analysis/fabric_figures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fabform/model/spring_path.hpp"

namespace fabform {
namespace {

FormedCell formed_cell(const Model& model, const Face& face, const std::vector<Eigen::Vector3d>& x) {
  const Fabric& fabric = model.fabric;
  double sum[2] = {0.0, 0.0};
  int count[2] = {0, 0};
  for (int c = 0; c < face.corners; ++c) {
    const int s = stretch_spring_between(fabric, face.corner[static_cast<std::size_t>(c)],
                                 face.corner[static_cast<std::size_t>((c + 1) % face.corners)]);
    if (s < 0) continue;
    const Spring& spring = fabric.springs()[static_cast<std::size_t>(s)];
    const int kind = spring.kind == SpringKind::warp ? 0 : 1;
    sum[kind] += spring_path_strain(model, spring, x[static_cast<std::size_t>(spring.a)],
                                    x[static_cast<std::size_t>(spring.b)]);
    ++count[kind];
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {face_area(face, x), count[0] ? sum[0] / count[0] : nan, count[1] ? sum[1] / count[1] : nan};
}

// The most stretched (sign +1) or most compressed (sign −1) spring of a kind.
StrainPeak peak_of(const Model& model, const std::vector<Eigen::Vector3d>& x, SpringKind kind, double sign) {
  StrainPeak peak;
  peak.strain = -sign * std::numeric_limits<double>::infinity();
  for (const Spring& s : model.fabric.springs()) {
    if (s.kind != kind) continue;
    const double strain = spring_path_strain(model, s, x[s.a], x[s.b]);
    if (sign * strain > sign * peak.strain)
      peak = {strain, model.fabric.i_of(s.a), model.fabric.j_of(s.a), 0.5 * (x[s.a] + x[s.b])};
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

StrainHistogram histogram_of(const std::vector<FormedCell>& cells) {
  StrainHistogram h;
  if (cells.empty()) return h;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const FormedCell& c : cells)
    for (const double strain : {c.warp_strain, c.weft_strain})
      if (!std::isnan(strain)) lo = std::min(lo, strain), hi = std::max(hi, strain);
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
  for (const FormedCell& c : cells) {
    if (!std::isnan(c.warp_strain)) h.warp_area_m2[bin_of(c.warp_strain)] += c.area_m2;
    if (!std::isnan(c.weft_strain)) h.weft_area_m2[bin_of(c.weft_strain)] += c.area_m2;
  }
  return h;
}

// Each face's area split equally among its corners; the corners on a body add up.
double contact_area(const Fabric& fabric, const std::vector<FormedCell>& cells,
                    const std::vector<unsigned char>& contact) {
  double area = 0.0;
  for (std::size_t f = 0; f < cells.size(); ++f) {
    const Face& face = fabric.faces()[f];
    for (int c = 0; c < face.corners; ++c)
      if (contact[static_cast<std::size_t>(face.corner[static_cast<std::size_t>(c)])])
        area += cells[f].area_m2 / face.corners;
  }
  return area;
}

}  // namespace

int stretch_spring_between(const Fabric& fabric, int p, int q) {
  for (const int s : fabric.springs_at(p)) {
    const Spring& spring = fabric.springs()[static_cast<std::size_t>(s)];
    if ((spring.a == q || spring.b == q) && spring.kind <= SpringKind::weft) return s;
  }
  return -1;
}

std::vector<FormedCell> formed_cells(const Model& model, const std::vector<Eigen::Vector3d>& x) {
  std::vector<FormedCell> cells;
  cells.reserve(model.fabric.faces().size());
  for (const Face& face : model.fabric.faces()) cells.push_back(formed_cell(model, face, x));
  return cells;
}

FabricFigures fabric_figures(const Model& model, const std::vector<Eigen::Vector3d>& x,
                             const std::vector<unsigned char>& contact) {
  const std::vector<FormedCell> cells = formed_cells(model, x);
  FabricFigures f;
  f.area_flat_m2 = model.fabric.flat_area();
  for (const FormedCell& c : cells) f.area_formed_m2 += c.area_m2;
  f.contact_area_m2 = contact_area(model.fabric, cells, contact);
  f.max_warp = peak_of(model, x, SpringKind::warp, 1.0);
  f.max_weft = peak_of(model, x, SpringKind::weft, 1.0);
  f.min_warp = peak_of(model, x, SpringKind::warp, -1.0);
  f.min_weft = peak_of(model, x, SpringKind::weft, -1.0);
  f.histogram = histogram_of(cells);
  return f;
}

}  // namespace fabform
