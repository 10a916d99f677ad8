// Whether a run's state has the energy its forces say: newton's line search trusts that moving a
// node along its force lowers Π by |R|·δ to first order, and a term whose energy jumps, or whose
// force is not its energy's derivative, stalls it there. From the checkpoint.bin of a run that
// stopped unconverged (a converged run keeps none),
// each free node (not on a body, its locked axes held) is moved δ = 1e-9 m along its force and
// against it, and half the difference of the changes of Π the two moves make (each term's own,
// node_energy_change) is compared with −|R|·δ: the stiffness's part, Kδ²/2 in each, cancels, and a
// jump on either side shows. Nodes where the two differ by more than half are listed with the
// term that differs most. Exit status 0: every node agrees; 1: some do not; 2: bad input.
//   build/fabform_energy_check SCENE RESULTS_DIR [KEY=VALUE ...]
// The KEY=VALUE pairs are the run's own --set overrides (the model must be the run's).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "fabform/error.hpp"
#include "fabform/model/model.hpp"
#include "fabform/model/potential_energy.hpp"
#include "fabform/output/checkpoint.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"

namespace {

using fabform::Model;
using fabform::Positions;

constexpr double kMoveM = 1e-9;
// Below this force the change over δ (1e-13 J) nears the rounding of the terms' energies
// (~1e-15 J on the CAD die: a node whose force is 1e-6 N "disagrees" by rounding alone).
constexpr double kSmallestForceN = 1e-4;
constexpr double kDisagreeShare = 0.5;

struct NodeCheck {
  int node = 0;
  double force_N = 0.0;
  double predicted_J = 0.0;  // −|R|·δ
  double measured_J = 0.0;   // half the difference of Π's changes at x ± δ along R
  std::string term;  // the term whose change differs most from its own force's prediction
};

// Half the difference of the changes `change(at)` makes at x ± δ·direction.
template <class Change>
double central_change(const Positions& x, int node, const Eigen::Vector3d& direction, const Change& change) {
  const Eigen::Vector3d& here = x[static_cast<std::size_t>(node)];
  const Eigen::Vector3d move = kMoveM * direction;
  return 0.5 * (change(Eigen::Vector3d(here + move)) - change(Eigen::Vector3d(here - move)));
}

// The term whose energy change along `direction` differs most from what its force predicts.
std::string worst_term(const Model& model, const Positions& x, int node, const Eigen::Vector3d& direction) {
  std::string worst;
  double largest = -1.0;
  for (const auto& term : model.terms) {
    const double predicted =
        -term->force_at(model, x, node, x[static_cast<std::size_t>(node)]).dot(direction) * kMoveM;
    const double measured = central_change(
        x, node, direction, [&](const Eigen::Vector3d& at) { return term->node_energy_change(model, x, node, at); });
    if (std::abs(measured - predicted) > largest) {
      largest = std::abs(measured - predicted);
      worst = term->describe(model);
    }
  }
  return worst.substr(0, worst.find(':'));
}

std::vector<NodeCheck> disagreeing_nodes(const Model& model, const fabform::SolverState& state, int* checked) {
  const std::vector<Eigen::Vector3d> forces = fabform::node_forces(model, state.x);
  std::vector<NodeCheck> found;
  for (int k = 0; k < model.node_count(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (state.contact[i].active()) continue;  // a node on a body moves along it, not along R
    Eigen::Vector3d force = forces[i];
    for (int axis = 0; axis < 3; ++axis)
      if (model.locks[i] & (1 << axis)) force[axis] = 0.0;
    if (!(force.norm() > kSmallestForceN)) continue;
    ++*checked;
    const Eigen::Vector3d direction = force.normalized();
    NodeCheck c{k, force.norm(), -force.norm() * kMoveM, 0.0, ""};
    c.measured_J = central_change(state.x, k, direction, [&](const Eigen::Vector3d& at) {
      return fabform::node_energy_change(model, state.x, k, at);
    });
    if (std::abs(c.measured_J - c.predicted_J) <= kDisagreeShare * std::abs(c.predicted_J)) continue;
    c.term = worst_term(model, state.x, k, direction);
    found.push_back(c);
  }
  std::sort(found.begin(), found.end(), [](const NodeCheck& a, const NodeCheck& b) {
    return std::abs(a.measured_J - a.predicted_J) > std::abs(b.measured_J - b.predicted_J);
  });
  return found;
}

int check(int argc, char** argv) {
  std::vector<fabform::SceneOverride> overrides;
  for (int a = 3; a < argc; ++a) overrides.push_back(fabform::parse_override(argv[a]));
  const fabform::Scene scene = fabform::load_scene(argv[1], overrides);
  const Model model = fabform::build_model(scene);
  const fabform::Checkpoint checkpoint = fabform::read_checkpoint(
      std::string(argv[2]) + "/checkpoint.bin", model.node_count(), static_cast<int>(model.bodies.size()));
  int checked = 0;
  const std::vector<NodeCheck> found = disagreeing_nodes(model, checkpoint.state, &checked);
  std::printf("energy_check: %d free nodes with a force above %g N moved %g m along it and against it; %zu disagree\n",
              checked, kSmallestForceN, kMoveM, found.size());
  for (std::size_t k = 0; k < found.size() && k < 10; ++k)
    std::printf("  node %d: |R| %.4g N, change of energy %.4g J against %.4g J predicted (%s)\n", found[k].node,
                found[k].force_N, found[k].measured_J, found[k].predicted_J, found[k].term.c_str());
  return found.empty() ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: fabform_energy_check SCENE RESULTS_DIR [KEY=VALUE ...]\n");
    return 2;
  }
  try {
    return check(argc, argv);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "fabform_energy_check: error: %s\n", error.what());
    return 2;
  }
}
