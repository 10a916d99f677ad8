#include "fabform/model/spring_contact.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "fabform/geometry/nearby_queries.hpp"
#include "fabform/model/contact_penalty.hpp"
#include "fabform/model/model.hpp"
#include "model/sum_in_index_order.hpp"

namespace fabform {
namespace {

// κ over the softest spring's stiffness at rest (default_stiffness says why so stiff).
constexpr double kSpringContactStiffnessRatio = 1e5;
// Below this share of a spring's length a sample lies on the surface: its direction into the
// body is the surface's normal, not the direction to the closest point.
constexpr double kOnSurfaceOfSpring = 1e-12;

}  // namespace

SpringContact::SpringContact(const Model& model, std::vector<int> bodies, double stiffness_N_m)
    : bodies_(std::move(bodies)),
      stiffness_N_m_(stiffness_N_m),
      onset_m_(contact_onset_m(model.fabric)) {
  if (!(std::isfinite(stiffness_N_m) && stiffness_N_m > 0.0))
    throw std::invalid_argument("spring contact: the penalty's stiffness must be positive and finite");
  for (const int b : bodies_)
    if (b < 0 || b >= static_cast<int>(model.bodies.size()))
      throw std::invalid_argument("spring contact: no body " + std::to_string(b));
}

double SpringContact::default_stiffness(const Model& model) { return contact_stiffness(model, kSpringContactStiffnessRatio); }

std::string SpringContact::describe(const Model& model) const {
  std::string names;
  for (const int b : bodies_) names += (names.empty() ? "" : ", ") + model.bodies[static_cast<std::size_t>(b)].name();
  char text[160];
  std::snprintf(text, sizeof text, " (%d points a spring); penalty stiffness %.6g N/m", kSamples, stiffness_N_m_);
  return "spring contact: warp, weft and shear springs kept out of " + names + text;
}

std::vector<SampleDepth> SpringContact::samples_inside(NearbyQueries& queries, const Eigen::Vector3d& a,
                                                       const Eigen::Vector3d& b, const double* a_distances,
                                                       const double* b_distances) const {
  std::vector<SampleDepth> inside;
  const double length = (b - a).norm();
  if (!a.allFinite() || !b.allFinite()) return inside;  // a broken state, being measured
  for (std::size_t listed = 0; listed < bodies_.size(); ++listed) {
    const int body = bodies_[listed];
    // The signed distance changes no faster than the point moves, so a segment whose ends' distances
    // add up to more than its length has no point inside.
    if (a_distances) {
      if (a_distances[listed] + b_distances[listed] > length) continue;
    } else if (queries.clearance_bound(body, a) + queries.clearance_bound(body, b) > length ||
               queries.closest(body, a).signed_distance + queries.closest(body, b).signed_distance > length) {
      continue;
    }
    for (int i = 0; i < kSamples; ++i) {
      const double t = (i + 0.5) / kSamples;
      const Eigen::Vector3d p = a + t * (b - a);
      const SurfacePoint q = queries.closest(body, p);
      if (!(q.signed_distance < 0.0)) continue;
      const Eigen::Vector3d inward = q.distance > kOnSurfaceOfSpring * length
                                         ? Eigen::Vector3d((p - q.point) / q.distance)
                                         : Eigen::Vector3d(-q.normal);
      inside.push_back({body, t, -q.signed_distance, inward});
    }
  }
  return inside;
}

SpringContact::Penalty SpringContact::penalty(const std::vector<SampleDepth>& samples) const {
  Penalty total;
  for (const SampleDepth& s : samples) {
    const OnsetPenalty phi = onset_penalty(s.depth, stiffness_N_m_, onset_m_);
    total.energy += phi.value / kSamples;
    total.gradient_a += (phi.slope / kSamples * (1.0 - s.along)) * s.inward;
    total.gradient_b += (phi.slope / kSamples * s.along) * s.inward;
  }
  return total;
}

std::vector<std::vector<SampleDepth>> SpringContact::every_spring(const Model& model, const Positions& x) const {
  // Each node's signed distance to each listed body, once, rather than twice a spring.
  const std::size_t listed = bodies_.size();
  std::vector<double> distance(x.size() * listed);
  for_each_nearby(static_cast<int>(x.size()), model.bodies, [&](int k, NearbyQueries& queries) {
    const auto node = static_cast<std::size_t>(k);
    for (std::size_t b = 0; b < listed; ++b)
      distance[node * listed + b] = x[node].allFinite() ? queries.closest(bodies_[b], x[node]).signed_distance : 0.0;
  });
  const std::vector<Spring>& springs = model.fabric.springs();
  std::vector<std::vector<SampleDepth>> samples(springs.size());
  for_each_nearby(static_cast<int>(springs.size()), model.bodies, [&](int i, NearbyQueries& queries) {
    const Spring& s = springs[static_cast<std::size_t>(i)];
    if (!stretches_surface(s.kind)) return;
    const auto a = static_cast<std::size_t>(s.a), b = static_cast<std::size_t>(s.b);
    samples[static_cast<std::size_t>(i)] =
        samples_inside(queries, x[a], x[b], &distance[a * listed], &distance[b * listed]);
  });
  return samples;
}

Eigen::Vector3d SpringContact::force_at(const Model& model, const Positions& x, int node,
                                        const Eigen::Vector3d& at) const {
  NearbyQueries queries(model.bodies);
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for_each_surface_spring_at(model.fabric, x, node, at,
                             [&](int, const Eigen::Vector3d& a, const Eigen::Vector3d& b, bool is_a) {
    const Penalty p = penalty(samples_inside(queries, a, b));
    force -= is_a ? p.gradient_a : p.gradient_b;
  });
  return force;
}

void SpringContact::add_forces(const Model& model, const Positions& x, std::vector<Eigen::Vector3d>& forces) const {
  const std::vector<Spring>& springs = model.fabric.springs();
  const std::vector<std::vector<SampleDepth>> samples = every_spring(model, x);
  for (std::size_t i = 0; i < springs.size(); ++i) {
    if (samples[i].empty()) continue;
    const Penalty p = penalty(samples[i]);
    forces[static_cast<std::size_t>(springs[i].a)] -= p.gradient_a;
    forces[static_cast<std::size_t>(springs[i].b)] -= p.gradient_b;
  }
}

double SpringContact::energy(const Model& model, const Positions& x) const {
  const std::vector<std::vector<SampleDepth>> samples = every_spring(model, x);
  return sum_in_index_order(static_cast<std::ptrdiff_t>(samples.size()), [&](std::ptrdiff_t i) {
    return samples[static_cast<std::size_t>(i)].empty() ? 0.0 : penalty(samples[static_cast<std::size_t>(i)]).energy;
  });
}

double SpringContact::node_energy_change(const Model& model, const Positions& x, int node,
                                         const Eigen::Vector3d& at) const {
  NearbyQueries queries(model.bodies);
  double change = 0.0;
  for_each_surface_spring_at(model.fabric, x, node, at,
                             [&](int s, const Eigen::Vector3d& a, const Eigen::Vector3d& b, bool) {
    const Spring& spring = model.fabric.springs()[static_cast<std::size_t>(s)];
    const double before = penalty(samples_inside(queries, x[static_cast<std::size_t>(spring.a)],
                                                 x[static_cast<std::size_t>(spring.b)])).energy;
    change += penalty(samples_inside(queries, a, b)).energy - before;
  });
  return change;
}

// The samples inside at the step's start, against which each trial's are measured.
class SpringContact::DepthGrowth final : public StepCheck {
 public:
  DepthGrowth(const SpringContact& term, std::vector<std::vector<SampleDepth>> before)
      : term_(term), before_(std::move(before)) {}

  bool admits(const Model& model, const Positions& to) const override {
    const std::vector<std::vector<SampleDepth>> after = term_.every_spring(model, to);
    for (std::size_t i = 0; i < after.size(); ++i)
      for (const SampleDepth& sample : after[i])
        if (sample.depth - depth_before(i, sample) > term_.onset_m_) return false;
    return true;
  }

 private:
  double depth_before(std::size_t spring, const SampleDepth& sample) const {
    for (const SampleDepth& s : before_[spring])
      if (s.body == sample.body && s.along == sample.along) return s.depth;
    return 0.0;
  }

  const SpringContact& term_;
  std::vector<std::vector<SampleDepth>> before_;
};

std::unique_ptr<StepCheck> SpringContact::step_check(const Model& model, const Positions& from) const {
  return std::make_unique<DepthGrowth>(*this, every_spring(model, from));
}

void SpringContact::add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const {
  const std::vector<Spring>& springs = model.fabric.springs();
  const std::vector<std::vector<SampleDepth>> samples = every_spring(model, x);
  sink.add_each(springs.size(), [&](std::size_t i, StiffnessSink& part) {
    for (const SampleDepth& s : samples[i]) {
      const double curvature = onset_penalty(s.depth, stiffness_N_m_, onset_m_).curvature / kSamples;
      const Eigen::Matrix3d nnT = curvature * s.inward * s.inward.transpose();
      const double t = s.along;
      part.add(springs[i].a, springs[i].a, (1.0 - t) * (1.0 - t) * nnT);
      part.add(springs[i].b, springs[i].b, t * t * nnT);
      part.add(springs[i].a, springs[i].b, t * (1.0 - t) * nnT);
    }
  });
}

}  // namespace fabform
