#include "fabform/model/seam.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "fabform/model/model.hpp"

namespace fabform {
namespace {

// A stitch's gap x[node] − (1 − t)·x[first] − t·x[second] as Σ c_p x[p] over its distinct nodes,
// coefficients of a node named twice summed (a dart's point is its own partner) and zeros dropped.
struct Coefficients {
  std::array<int, 3> node{};
  std::array<double, 3> c{};
  int count = 0;
  void add(int n, double value) {
    for (int p = 0; p < count; ++p)
      if (node[static_cast<std::size_t>(p)] == n) {
        c[static_cast<std::size_t>(p)] += value;
        return;
      }
    node[static_cast<std::size_t>(count)] = n;
    c[static_cast<std::size_t>(count)] = value;
    ++count;
  }
};

Coefficients coefficients(const Stitch& s) {
  Coefficients k;
  k.add(s.node, 1.0);
  if (s.t < 1.0) k.add(s.first, -(1.0 - s.t));
  if (s.t > 0.0) k.add(s.second, -s.t);
  return k;
}

// The gap with `node` moved to `at` (none moved: node −1).
Eigen::Vector3d gap_moved(const Stitch& s, const Positions& x, int node, const Eigen::Vector3d& at) {
  const auto where = [&](int n) { return n == node ? at : x[static_cast<std::size_t>(n)]; };
  return where(s.node) - (1.0 - s.t) * where(s.first) - s.t * where(s.second);
}

Eigen::Vector3d gap(const Stitch& s, const Positions& x) { return gap_moved(s, x, -1, Eigen::Vector3d::Zero()); }

}  // namespace

double chain_length(const Fabric& fabric, const std::vector<int>& chain) {
  double length = 0.0;
  for (std::size_t k = 1; k < chain.size(); ++k) length += (fabric.rest_position(chain[k]) - fabric.rest_position(chain[k - 1])).norm();
  return length;
}

namespace {

// Each node's fraction of its chain's flat length.
std::vector<double> arc_fractions(const Fabric& fabric, const std::vector<int>& chain, double* length) {
  if (chain.size() < 2) throw std::invalid_argument("a seam's edge needs at least 2 nodes");
  std::vector<double> at(chain.size(), 0.0);
  for (std::size_t k = 1; k < chain.size(); ++k)
    at[k] = at[k - 1] + (fabric.rest_position(chain[k]) - fabric.rest_position(chain[k - 1])).norm();
  *length = at.back();
  if (!(*length > 0.0)) throw std::invalid_argument("a seam's edge has no length");
  for (double& f : at) f /= *length;
  return at;
}

// Every node of `from` held on the point of `onto` at its own fraction of the length.
void hold_on(const Fabric& fabric, const std::vector<int>& from, const std::vector<int>& onto,
             std::vector<Stitch>& out) {
  double from_length = 0.0, onto_length = 0.0;
  const std::vector<double> f = arc_fractions(fabric, from, &from_length);
  const std::vector<double> g = arc_fractions(fabric, onto, &onto_length);
  for (std::size_t k = 0; k < from.size(); ++k) {
    const auto upper = std::upper_bound(g.begin(), g.end(), f[k]);
    const std::size_t j = std::min<std::size_t>(static_cast<std::size_t>(std::max<std::ptrdiff_t>(upper - g.begin(), 1)) - 1,
                                                g.size() - 2);
    const double span = g[j + 1] - g[j];
    const double t = span > 0.0 ? std::clamp((f[k] - g[j]) / span, 0.0, 1.0) : 0.0;
    const double before = k > 0 ? f[k] - f[k - 1] : 0.0, after = k + 1 < from.size() ? f[k + 1] - f[k] : 0.0;
    // Half the node's share of its chain: the other chain's nodes hold the other half.
    out.push_back({from[k], onto[j], onto[j + 1], t, 0.25 * (before + after) * from_length});
  }
}

}  // namespace

std::vector<Stitch> stitches_by_arc_length(const Fabric& fabric, const std::vector<int>& first_edge,
                                           const std::vector<int>& second_edge) {
  std::vector<Stitch> stitches;
  hold_on(fabric, first_edge, second_edge, stitches);
  hold_on(fabric, second_edge, first_edge, stitches);
  return stitches;
}

SeamTerm::SeamTerm(std::vector<Seam> seams, double stiffness_N_m2, int node_count)
    : at_node_(static_cast<std::size_t>(node_count)), seams_(std::move(seams)), stiffness_(stiffness_N_m2) {
  if (!(stiffness_ > 0.0 && std::isfinite(stiffness_))) throw std::invalid_argument("a seam's stiffness must be positive");
  for (const Seam& seam : seams_)
    for (const Stitch& s : seam.stitches) {
      const Coefficients k = coefficients(s);
      for (int p = 0; p < k.count; ++p) at_node_[static_cast<std::size_t>(k.node[static_cast<std::size_t>(p)])].push_back(static_cast<int>(all_.size()));
      all_.push_back(s);
    }
}

std::vector<SeamFigures> SeamTerm::figures(const Positions& x) const {
  std::vector<SeamFigures> out;
  for (const Seam& seam : seams_) {
    SeamFigures f{seam.name, seam.length_m};
    double force = 0.0, length = 0.0;
    for (const Stitch& s : seam.stitches) {
      const double open = gap(s, x).norm();
      force += stiffness_ * s.length_m * open;
      length += s.length_m;
      f.tension_max_N_m = std::max(f.tension_max_N_m, stiffness_ * open);
      f.gap_max_m = std::max(f.gap_max_m, open);
    }
    f.tension_mean_N_m = length > 0.0 ? force / length : 0.0;
    out.push_back(f);
  }
  return out;
}

std::string SeamTerm::describe(const Model& /*model*/) const {
  char text[240];
  std::snprintf(text, sizeof text,
                "seams: %zu, %zu stitches holding each edge's nodes on the other edge by arc length, "
                "%.6g N/m of seam per metre of gap",
                seams_.size(), all_.size(), stiffness_);
  return text;
}

Eigen::Vector3d SeamTerm::force_at(const Model& /*model*/, const Positions& x, int node,
                                   const Eigen::Vector3d& at) const {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (const int id : at_node_[static_cast<std::size_t>(node)]) {
    const Stitch& s = all_[static_cast<std::size_t>(id)];
    const Coefficients k = coefficients(s);
    for (int p = 0; p < k.count; ++p)
      if (k.node[static_cast<std::size_t>(p)] == node)
        force -= stiffness_ * s.length_m * k.c[static_cast<std::size_t>(p)] * gap_moved(s, x, node, at);
  }
  return force;
}

double SeamTerm::energy(const Model& /*model*/, const Positions& x) const {
  double energy = 0.0;
  for (const Stitch& s : all_) energy += 0.5 * stiffness_ * s.length_m * gap(s, x).squaredNorm();
  return energy;
}

double SeamTerm::node_energy_change(const Model& /*model*/, const Positions& x, int node,
                                    const Eigen::Vector3d& at) const {
  double change = 0.0;
  for (const int id : at_node_[static_cast<std::size_t>(node)]) {
    const Stitch& s = all_[static_cast<std::size_t>(id)];
    change += 0.5 * stiffness_ * s.length_m * (gap_moved(s, x, node, at).squaredNorm() - gap(s, x).squaredNorm());
  }
  return change;
}

void SeamTerm::add_stiffness(const Model& /*model*/, const Positions& /*x*/, StiffnessSink& sink) const {
  for (const Stitch& s : all_) {
    const Coefficients k = coefficients(s);
    const double w = stiffness_ * s.length_m;
    for (int p = 0; p < k.count; ++p)
      for (int q = p; q < k.count; ++q)
        sink.add(k.node[static_cast<std::size_t>(p)], k.node[static_cast<std::size_t>(q)],
                 w * k.c[static_cast<std::size_t>(p)] * k.c[static_cast<std::size_t>(q)] * Eigen::Matrix3d::Identity());
  }
}

void SeamTerm::bound_stiffness(const Model& /*model*/, StiffnessBound& bound) const {
  for (const Stitch& s : all_) {
    const Coefficients k = coefficients(s);
    double sum = 0.0, squares = 0.0;
    for (int p = 0; p < k.count; ++p) {
      sum += std::abs(k.c[static_cast<std::size_t>(p)]);
      squares += k.c[static_cast<std::size_t>(p)] * k.c[static_cast<std::size_t>(p)];
    }
    // As a spring of stiffness w counts: w at each end, and w for the element (half its eigenvalue w·|c|²).
    const double w = stiffness_ * s.length_m;
    for (int p = 0; p < k.count; ++p)
      bound.per_node[static_cast<std::size_t>(k.node[static_cast<std::size_t>(p)])] +=
          0.5 * w * std::abs(k.c[static_cast<std::size_t>(p)]) * sum;
    bound.stiffest_element = std::max(bound.stiffest_element, 0.5 * w * squares);
  }
}

std::vector<SeamFigures> seam_figures(const Model& model, const Positions& x) {
  std::vector<SeamFigures> all;
  for (const SeamTerm* seams : terms_of<SeamTerm>(model))
    for (SeamFigures& f : seams->figures(x)) all.push_back(std::move(f));
  return all;
}

std::vector<int> sewn_representatives(const Model& model) {
  std::vector<int> root(static_cast<std::size_t>(model.node_count()));
  for (std::size_t k = 0; k < root.size(); ++k) root[k] = static_cast<int>(k);
  const auto find = [&](int n) {
    while (root[static_cast<std::size_t>(n)] != n) n = root[static_cast<std::size_t>(n)] = root[static_cast<std::size_t>(root[static_cast<std::size_t>(n)])];
    return n;
  };
  for (const SeamTerm* seams : terms_of<SeamTerm>(model))
    for (const Seam& seam : seams->seams())
      for (const Stitch& s : seam.stitches) {
        if (s.t != 0.0 && s.t != 1.0) continue;
        const int a = find(s.node), b = find(s.t == 0.0 ? s.first : s.second);
        root[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
      }
  for (std::size_t k = 0; k < root.size(); ++k) root[k] = find(static_cast<int>(k));
  return root;
}

double seam_stiffness_N_m2(const Model& model) {
  const double slope = std::max(model.warp.steepest_slope(), model.weft.steepest_slope());
  const double spacing = 0.5 * (model.fabric.spacing_warp() + model.fabric.spacing_weft());
  return kSeamStiffnessRatio * slope / spacing;
}

}  // namespace fabform
