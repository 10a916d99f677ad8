#include "fabform/model/edge_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include <Eigen/Geometry>

#include "fabform/model/contact_penalty.hpp"
#include "fabform/model/model.hpp"
#include "fabform/thread_count.hpp"
#include "model/sum_in_index_order.hpp"

namespace fabform {
namespace {

// κ over the softest spring's stiffness at rest (edge_contact.hpp says why so stiff).
constexpr double kStiffnessRatio = 1000.0;
// An edge's weight falls to 0 within this share of the mean spring's rest length past its ends.
constexpr double kMarginShare = 0.25;
// A spring whose direction is within this share of its length parallel to the bisecting plane
// runs along the edge: it reaches under it nowhere in particular.
constexpr double kParallelShare = 1e-9;

double smoothstep(double u) { return u * u * (3.0 - 2.0 * u); }
double smoothstep_slope(double u) { return 6.0 * u * (1.0 - u); }

using CellKey = std::int64_t;

CellKey cell_key(const Eigen::Vector3i& c) {
  const auto part = [](int v) { return static_cast<CellKey>(v & 0x1fffff); };
  return (part(c.x()) << 42) | (part(c.y()) << 21) | part(c.z());
}

// Whether the body goes on past an edge's end, within the edge's wedge: another edge there runs
// on between faces turned alike (a long CAD edge cut in pieces, along its cracks too; a fillet's
// facets), or a point just past the end and just under the edge lies inside the body (a pocket's
// rim round its corner); else the body ends there (a box's corner). Probed this share of the
// shorter of the edge and the margin away.
constexpr double kProbeShare = 0.05;
constexpr double kAlikeCos = 0.866;  // faces within 30° of each other's

bool continued_by(const SharpEdge& edge, bool from_end, const SharpEdge& other) {
  const auto alike = [](const Eigen::Vector3d& u, const Eigen::Vector3d& v) { return u.dot(v) > kAlikeCos; };
  const bool faces = (alike(edge.normal_a, other.normal_a) && alike(edge.normal_b, other.normal_b)) ||
                     (alike(edge.normal_a, other.normal_b) && alike(edge.normal_b, other.normal_a));
  const Eigen::Vector3d& end = from_end ? edge.from : edge.to;
  const Eigen::Vector3d past = from_end ? edge.from - edge.to : edge.to - edge.from;
  const Eigen::Vector3d on = other.from == end ? other.to - other.from : other.from - other.to;
  return faces && (other.from == end || other.to == end) && past.dot(on) > 0.0;
}

// The edges that end at each point, by its coordinates (a mesh's edges share their vertices').
using EdgesAt = std::map<std::array<double, 3>, std::vector<int>>;

std::array<double, 3> point_key(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

bool goes_on_past(const RigidBody& body, const std::vector<SharpEdge>& edges, const EdgesAt& at, int index,
                  bool from_end, double margin_m) {
  const SharpEdge& edge = edges[static_cast<std::size_t>(index)];
  const Eigen::Vector3d end = from_end ? edge.from : edge.to;
  for (const int other : at.at(point_key(end)))
    if (other != index && continued_by(edge, from_end, edges[static_cast<std::size_t>(other)])) return true;
  const Eigen::Vector3d past = (from_end ? edge.from - edge.to : edge.to - edge.from).normalized();
  const Eigen::Vector3d under = -(edge.normal_a + edge.normal_b).normalized();
  const double probe = kProbeShare * std::min((edge.to - edge.from).norm(), margin_m);
  return body.closest(body.pose() * (end + probe * (past + under))).signed_distance < 0.0;
}

std::vector<EdgeEnds> edge_ends(const RigidBody& body, const std::vector<SharpEdge>& edges, double margin_m) {
  EdgesAt at;
  for (int e = 0; e < static_cast<int>(edges.size()); ++e) {
    at[point_key(edges[static_cast<std::size_t>(e)].from)].push_back(e);
    at[point_key(edges[static_cast<std::size_t>(e)].to)].push_back(e);
  }
  std::vector<EdgeEnds> ends;
  for (int e = 0; e < static_cast<int>(edges.size()); ++e)
    ends.push_back({!goes_on_past(body, edges, at, e, true, margin_m), !goes_on_past(body, edges, at, e, false, margin_m),
                    margin_m});
  return ends;
}

}  // namespace

std::optional<EdgeReach> reach_under_edge(const SharpEdge& edge, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const EdgeEnds& ends) {
  const Eigen::Vector3d d = b - a;
  const Eigen::Vector3d beta = edge.normal_a - edge.normal_b;  // normal to the bisecting plane
  const double across = d.dot(beta);
  if (std::abs(across) <= kParallelShare * d.norm() * beta.norm()) return std::nullopt;
  const double s = (edge.from - a).dot(beta) / across;
  if (!(s > 0.0 && s < 1.0)) return std::nullopt;
  const Eigen::Vector3d p = a + s * d;
  // On the bisecting plane the depth below either face is the same.
  const double depth = -(p - edge.from).dot(edge.normal_a);
  if (!(depth > 0.0)) return std::nullopt;
  const Eigen::Vector3d line = edge.to - edge.from;
  const double length = line.norm();
  if (!(length > 0.0)) return std::nullopt;
  const Eigen::Vector3d axis = line / length;
  const double t = (p - edge.from).dot(axis);  // metres along the edge
  // The faces bound the body only near their edge: a segment between two nodes outside it
  // reaches under the edge within its own length of it (farther, it is under another part).
  if ((p - edge.from - t * axis).squaredNorm() > d.squaredNorm()) return std::nullopt;
  // Past a capped end the body has ended; past a continued one the next edge takes over as
  // the weight falls from 1 to 0 within the margin. `sign` is ∂beyond/∂t.
  double beyond = 0.0, sign = 0.0;
  if (t < 0.0) beyond = -t, sign = -1.0;
  if (t > length) beyond = t - length, sign = 1.0;
  const bool capped = sign < 0.0 ? ends.capped_from : ends.capped_to;
  if (beyond > 0.0 && (capped || beyond >= ends.margin_m)) return std::nullopt;
  // ∂t/∂a = (1 − s) h, ∂t/∂b = s h: p moves with its ends and along the spring as s changes.
  const Eigen::Vector3d h = axis - (d.dot(axis) / across) * beta;
  EdgeReach reach;
  reach.along = s;
  reach.depth = depth;
  reach.direction = edge.normal_a - (d.dot(edge.normal_a) / across) * beta;
  // Near a capped end (a corner) the body ends across the edge: no deeper than the end is far.
  if (ends.capped_from && t < reach.depth) reach.depth = t, reach.direction = -h;
  if (ends.capped_to && length - t < reach.depth) reach.depth = length - t, reach.direction = h;
  reach.weight = 1.0;
  if (beyond > 0.0) {
    const double u = beyond / ends.margin_m;
    reach.weight = 1.0 - smoothstep(u);
    const double slope = -smoothstep_slope(u) / ends.margin_m * sign;  // ∂w/∂t
    reach.weight_gradient_a = slope * (1.0 - s) * h;
    reach.weight_gradient_b = slope * s * h;
  }
  return reach;
}

EdgePenalty edge_penalty(const EdgeReach& reach, double stiffness_N_m, double onset_m) {
  const double w = reach.weight, s = reach.along;
  const OnsetPenalty phi = onset_penalty(reach.depth, stiffness_N_m, onset_m);
  EdgePenalty penalty;
  penalty.energy = w * phi.value;
  penalty.curvature = w * phi.curvature;
  // ∂δ/∂a = −(1 − s) g, ∂δ/∂b = −s g (edge_contact.hpp).
  penalty.gradient_a = phi.value * reach.weight_gradient_a - w * phi.slope * (1.0 - s) * reach.direction;
  penalty.gradient_b = phi.value * reach.weight_gradient_b - w * phi.slope * s * reach.direction;
  return penalty;
}

// One body's edges in its placed frame, hashed into cubic cells (each edge in every cell its box,
// widened by the margin, meets).
struct EdgeContact::BodyEdges {
  int body = 0;
  std::vector<SharpEdge> edges;
  std::vector<EdgeEnds> ends;  // per edge
  std::vector<Eigen::AlignedBox3d> boxes;  // per edge, widened by the margin
  mutable std::vector<NearEdges> cache;     // per spring (edges_near)
  double cell_m = 1.0;
  std::unordered_map<CellKey, std::vector<int>> cells;

  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const { return (p / cell_m).array().floor().cast<int>(); }

  Eigen::Vector3i lowest = Eigen::Vector3i::Constant(std::numeric_limits<int>::max());
  Eigen::Vector3i highest = Eigen::Vector3i::Constant(std::numeric_limits<int>::min());

  void add(int index, double margin_m) {
    const SharpEdge& e = edges[static_cast<std::size_t>(index)];
    boxes.emplace_back(Eigen::Vector3d(e.from.cwiseMin(e.to).array() - margin_m),
                       Eigen::Vector3d(e.from.cwiseMax(e.to).array() + margin_m));
    const Eigen::Vector3i lo = cell_of(boxes.back().min());
    const Eigen::Vector3i hi = cell_of(boxes.back().max());
    lowest = lowest.cwiseMin(lo);
    highest = highest.cwiseMax(hi);
    for (int i = lo.x(); i <= hi.x(); ++i)
      for (int j = lo.y(); j <= hi.y(); ++j)
        for (int k = lo.z(); k <= hi.z(); ++k) cells[cell_key({i, j, k})].push_back(index);
  }

  // The edges whose widened boxes meet the box lo–hi, each once, in index order.
  std::vector<int> near(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const {
    std::vector<int> found;
    const Eigen::AlignedBox3d box(lo, hi);
    // Cells past the edges' own hold none; a box over more cells than there are edges (a trial
    // step gone far) is answered by every edge.
    const Eigen::Array3d low = (lo / cell_m).array().floor().max(lowest.cast<double>().array());
    const Eigen::Array3d high = (hi / cell_m).array().floor().min(highest.cast<double>().array());
    if ((low > high).any()) return found;
    if ((high - low + 1.0).prod() > static_cast<double>(edges.size())) {
      for (std::size_t e = 0; e < edges.size(); ++e)
        if (boxes[e].intersects(box)) found.push_back(static_cast<int>(e));
      return found;
    }
    const Eigen::Vector3i from = low.cast<int>(), to = high.cast<int>();
    for (int i = from.x(); i <= to.x(); ++i)
      for (int j = from.y(); j <= to.y(); ++j)
        for (int k = from.z(); k <= to.z(); ++k)
          if (const auto it = cells.find(cell_key({i, j, k})); it != cells.end())
            for (const int e : it->second)
              if (boxes[static_cast<std::size_t>(e)].intersects(box)) found.push_back(e);
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  }
};

EdgeContact::EdgeContact(const Model& model, const std::vector<double>& angles_deg, double stiffness_N_m)
    : stiffness_N_m_(stiffness_N_m),
      margin_m_(kMarginShare * mean_surface_spring_length(model.fabric)),
      onset_m_(contact_onset_m(model.fabric)) {
  if (!(std::isfinite(stiffness_N_m) && stiffness_N_m > 0.0))
    throw std::invalid_argument("edge contact: the penalty's stiffness must be positive and finite");
  const double spring = mean_surface_spring_length(model.fabric);
  for (std::size_t b = 0; b < model.bodies.size() && b < angles_deg.size(); ++b) {
    if (!(angles_deg[b] > 0.0)) continue;
    BodyEdges body;
    body.body = static_cast<int>(b);
    body.edges = model.bodies[b].convex_edges(angles_deg[b]);
    body.cell_m = spring > 0.0 ? 2.0 * spring : model.bodies[b].box().diagonal();
    body.ends = edge_ends(model.bodies[b], body.edges, margin_m_);
    body.cache.resize(model.fabric.springs().size());
    for (int e = 0; e < static_cast<int>(body.edges.size()); ++e) body.add(e, margin_m_);
    bodies_.push_back(std::move(body));
  }
}

EdgeContact::~EdgeContact() = default;

double EdgeContact::default_stiffness(const Model& model) { return contact_stiffness(model, kStiffnessRatio); }

int EdgeContact::edge_count() const {
  int count = 0;
  for (const BodyEdges& body : bodies_) count += static_cast<int>(body.edges.size());
  return count;
}

std::string EdgeContact::describe(const Model& model) const {
  std::string bodies;
  for (const BodyEdges& body : bodies_)
    bodies += (bodies.empty() ? "" : ", ") + model.bodies[static_cast<std::size_t>(body.body)].name() + " (" +
              std::to_string(body.edges.size()) + " edges)";
  char text[160];
  std::snprintf(text, sizeof text, "; penalty stiffness %.6g N/m", stiffness_N_m_);
  return "edge contact: warp, weft and shear springs kept out from under the convex edges of " + bodies + text;
}

// The edges a spring may reach under are looked up once per Newton step (add_stiffness), in a
// box wider by kSlackShare of its length on every side; until either end has moved farther than
// that from where it was, the list holds every edge a fresh lookup would find (and a few more,
// which reach under nothing), in the same order, so the sums are the same to the bit.
constexpr double kSlackShare = 0.25;

const std::vector<int>& EdgeContact::edges_near(const BodyEdges& body, int spring, const Eigen::Vector3d& pa,
                                                const Eigen::Vector3d& pb, bool refresh,
                                                std::vector<int>& fresh) const {
  fresh.clear();
  if (!pa.allFinite() || !pb.allFinite()) return fresh;  // a broken state, being measured
  const double length = (pb - pa).norm();
  NearEdges& cached = body.cache[static_cast<std::size_t>(spring)];
  if (!refresh && cached.valid && (pa - cached.a).norm() <= cached.slack && (pb - cached.b).norm() <= cached.slack)
    return cached.edges;
  // The deepest point of a cut lies within the spring's length of it.
  double reach_m = std::max(length, margin_m_);
  const double slack = refresh ? kSlackShare * length : 0.0;
  reach_m += 3.0 * slack;  // covers a spring up to 2·slack longer, its ends `slack` away
  fresh = body.near(pa.cwiseMin(pb).array() - reach_m, pa.cwiseMax(pb).array() + reach_m);
  if (!refresh) return fresh;
  cached = NearEdges{pa, pb, slack, true, fresh};
  return cached.edges;
}

EdgeContact::SpringPenalty EdgeContact::spring_penalty(const Model& model, int spring, const Eigen::Vector3d& a,
                                                       const Eigen::Vector3d& b, std::vector<EdgeReach>* reaches) const {
  SpringPenalty total;
  std::vector<int> fresh;
  for (const BodyEdges& body : bodies_) {
    const RigidBody& rigid = model.bodies[static_cast<std::size_t>(body.body)];
    // Edges are kept where the body was placed; the spring is carried there, the answer back.
    const Eigen::Isometry3d to_placed = rigid.pose().inverse();
    const Eigen::Vector3d pa = to_placed * a, pb = to_placed * b;
    const Eigen::Matrix3d turn = rigid.pose().linear();
    for (const int e : edges_near(body, spring, pa, pb, reaches != nullptr, fresh)) {
      const auto k = static_cast<std::size_t>(e);
      auto reach = reach_under_edge(body.edges[k], pa, pb, body.ends[k]);
      if (!reach) continue;
      reach->direction = turn * reach->direction;
      reach->weight_gradient_a = turn * reach->weight_gradient_a;
      reach->weight_gradient_b = turn * reach->weight_gradient_b;
      const EdgePenalty p = edge_penalty(*reach, stiffness_N_m_, onset_m_);
      total.energy += p.energy;
      total.gradient_a += p.gradient_a;
      total.gradient_b += p.gradient_b;
      if (reaches) reaches->push_back(*reach);
    }
  }
  return total;
}

Eigen::Vector3d EdgeContact::force_at(const Model& model, const Positions& x, int node,
                                      const Eigen::Vector3d& at) const {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for_each_surface_spring_at(model.fabric, x, node, at,
                             [&](int s, const Eigen::Vector3d& a, const Eigen::Vector3d& b, bool is_a) {
    const SpringPenalty p = spring_penalty(model, s, a, b);
    force -= is_a ? p.gradient_a : p.gradient_b;
  });
  return force;
}

double EdgeContact::energy(const Model& model, const Positions& x) const {
  const std::vector<Spring>& springs = model.fabric.springs();
  return sum_in_index_order(static_cast<std::ptrdiff_t>(springs.size()), [&](std::ptrdiff_t i) {
    const Spring& s = springs[static_cast<std::size_t>(i)];
    if (!stretches_surface(s.kind)) return 0.0;
    return spring_penalty(model, static_cast<int>(i), x[static_cast<std::size_t>(s.a)], x[static_cast<std::size_t>(s.b)])
        .energy;
  });
}

double EdgeContact::node_energy_change(const Model& model, const Positions& x, int node,
                                       const Eigen::Vector3d& at) const {
  double change = 0.0;
  for_each_surface_spring_at(model.fabric, x, node, at,
                             [&](int s, const Eigen::Vector3d& a, const Eigen::Vector3d& b, bool) {
    const Spring& spring = model.fabric.springs()[static_cast<std::size_t>(s)];
    const double before = spring_penalty(model, s, x[static_cast<std::size_t>(spring.a)],
                                         x[static_cast<std::size_t>(spring.b)]).energy;
    change += spring_penalty(model, s, a, b).energy - before;
  });
  return change;
}

void EdgeContact::add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const {
  const std::vector<Spring>& springs = model.fabric.springs();
  // Each spring's reaches found in parallel, their blocks added in spring order.
  std::vector<std::vector<EdgeReach>> reaches(springs.size());
#pragma omp parallel for schedule(dynamic, 256) if (springs.size() >= kMinParallelItems)
  for (std::ptrdiff_t i = 0; i < static_cast<std::ptrdiff_t>(springs.size()); ++i) {
    const Spring& s = springs[static_cast<std::size_t>(i)];
    if (stretches_surface(s.kind))
      spring_penalty(model, static_cast<int>(i), x[static_cast<std::size_t>(s.a)], x[static_cast<std::size_t>(s.b)],
                     &reaches[static_cast<std::size_t>(i)]);
  }
  sink.add_each(springs.size(), [&](std::size_t i, StiffnessSink& part) {
    for (const EdgeReach& r : reaches[i]) {
      const Eigen::Matrix3d ggT = edge_penalty(r, stiffness_N_m_, onset_m_).curvature * r.direction * r.direction.transpose();
      const double s = r.along;
      part.add(springs[i].a, springs[i].a, (1.0 - s) * (1.0 - s) * ggT);
      part.add(springs[i].b, springs[i].b, s * s * ggT);
      part.add(springs[i].a, springs[i].b, s * (1.0 - s) * ggT);
    }
  });
}

}  // namespace fabform
