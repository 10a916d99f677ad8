#pragma once
// Seed 003's sewing force F_seams, a term of the model: a seam pairs two edges of the fabric, in
// order and direction, and holds every node of each on the point of the other at the same
// fraction of its length (arc length in the flat pattern), by a stiff zero-length spring per
// stitch. A spring rather than welded nodes: panels laid apart (a pattern placed round a body)
// are pulled together by the same term that then holds them, and the mesh never changes during a
// solve. Its stiffness, kSeamStiffnessRatio times the fabric's steepest tension slope per
// lattice spacing, leaves a closed seam open by at most spacing × strain / kSeamStiffnessRatio
// under the tension it carries, which the figures report as its gap. The energy is quadratic,
// so newton's step takes it exactly; relax and dynamic are refused (a stiffness a thousand times
// the fabric's would bound dynamic's time step, and relax moves one node against it at a time).
#include <string>
#include <vector>

#include "fabform/fabric/fabric.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

constexpr double kSeamStiffnessRatio = 1000.0;
// A seam's longer edge may be this many times its shorter one: ease and gathers, not a seam
// sewn to the wrong edge.
constexpr double kMaxSeamLengthRatio = 2.0;

/// One node of an edge held on a point of the other edge, (1 − t)·x[first] + t·x[second].
struct Stitch {
  int node = 0;
  int first = 0;
  int second = 0;
  double t = 0.0;
  double length_m = 0.0;  // the length of its own edge the stitch stands for (flat pattern)
};

struct Seam {
  std::string name;
  std::vector<Stitch> stitches;
  double length_m = 0.0;  // its first edge's length in the flat pattern
};

/// A chain of nodes' length in the flat fabric (m).
double chain_length(const Fabric& fabric, const std::vector<int>& chain);

/// The stitches of a seam between two chains of nodes (in order along the seam), matched by
/// arc length in the flat fabric: every node of each chain on the other chain's point at its
/// fraction of the length, each standing for half its share of its chain; the first chain's
/// stitches first, in its order. Throws
/// std::invalid_argument when a chain has fewer than 2 nodes or no length.
std::vector<Stitch> stitches_by_arc_length(const Fabric& fabric, const std::vector<int>& first_edge,
                                           const std::vector<int>& second_edge);

/// What a seam carries at positions x: its tension (the stitches' force per length of seam,
/// N/m), mean and largest, and its largest gap (m).
struct SeamFigures {
  std::string name;
  double length_m = 0.0;
  double tension_mean_N_m = 0.0;
  double tension_max_N_m = 0.0;
  double gap_max_m = 0.0;
};

class SeamTerm final : public Term {
 public:
  /// `stiffness_N_m2`: a stitch's force per length of seam per metre of gap (> 0).
  SeamTerm(std::vector<Seam> seams, double stiffness_N_m2, int node_count);

  const std::vector<Seam>& seams() const { return seams_; }
  double stiffness_N_m2() const { return stiffness_; }
  std::vector<SeamFigures> figures(const Positions& x) const;

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const override;
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;
  void bound_stiffness(const Model& model, StiffnessBound& bound) const override;
  /// What it needs of its solver; the scene reader asks the same of a scene that would have it.
  static constexpr SolverNeeds kNeeds = SolverNeed::stiff_penalty;
  SolverNeeds needs() const override { return kNeeds; }

 private:
  // Every stitch of every seam, and for each node the stitches it takes part in.
  std::vector<Stitch> all_;
  std::vector<std::vector<int>> at_node_;
  std::vector<Seam> seams_;
  double stiffness_;
};

/// The figures of every seam of the model's seam terms, at positions x (none without seams).
std::vector<SeamFigures> seam_figures(const Model& model, const Positions& x);

/// For every node, the lowest node it is sewn onto at a node of the other edge (t = 0 or 1),
/// directly or through others, or itself: sewn nodes are one point of the garment.
std::vector<int> sewn_representatives(const Model& model);

/// The stiffness a model's seams take: kSeamStiffnessRatio × the steepest slope of its warp and
/// weft tables (N/m) over the lattice's mean spacing (m).
double seam_stiffness_N_m2(const Model& model);

}  // namespace fabform
