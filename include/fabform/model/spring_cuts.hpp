#pragma once
// Springs that pass through a body. Contact is the nodes' (seed 003): a node is kept out of a
// body, a straight spring between two nodes is not, so over a sharp edge a spring may cut through
// the corner, unless the body lets springs wrap its edges (edge_wrap.hpp); a wrapped spring is
// checked leg by leg. A run reports how many springs do and how deep the deepest cuts, so that an engineer
// sees where the mesh is too coarse for the body's features (refine it, or round the edge).
// A chord between two nodes resting on a curved body always sinks into it, by L/(8R) of its
// length L on a curve of radius R: a spring counts as a cut when it reaches deeper than 1 % of
// its rest length, a feature sharper than a radius of 12.5 springs.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

struct SpringCuts {
  int springs = 0;           // warp, weft and shear springs that cut into a body
  double deepest_m = 0.0;    // how far inside a body the deepest of them reaches
  int deepest_spring = -1;   // index into the fabric's springs; -1 when none cuts
  int over_edges = 0;        // springs that run over a body's edge (edge_wrap.hpp)
};

/// A cut's depth is the deepest of 32 points along the spring, refined round it.
SpringCuts find_spring_cuts(const Model& model, const std::vector<Eigen::Vector3d>& x);

}  // namespace fabform
