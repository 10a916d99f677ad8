#pragma once
// Everything a solver needs, in SI, validated: the fabric and the tables of its springs, the
// per-node axis locks, the rigid bodies, the starting positions and the constant loads.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/fabric/node_set.hpp"
#include "fabform/geometry/rigid_body.hpp"
#include "fabform/material/tension_table.hpp"
#include "fabform/model/wind.hpp"

namespace fabform {

struct Model {
  Fabric fabric;
  TensionTable warp;
  TensionTable weft;
  std::vector<AxisMask> locks;  // one per node
  std::vector<RigidBody> bodies;
  std::vector<Eigen::Vector3d> start;  // one per node
  std::vector<Eigen::Vector3d> loads = {};  // N, one per node (the fabric's weight); empty: none
  std::vector<std::string> modelled = {};   // each term of the model, said for result.json
  double areal_density_kg_m2 = 0.0;         // the fabric's, when its weight is modelled; else 0
  std::optional<double> bending_rigidity_Nm = {};  // B of the fabric's hinges, when it has them
  std::optional<TensionTable> shear = {};   // the shear springs' table, when the fabric has them
  std::optional<TensionTable> bend = {};    // the bend springs' table, when the fabric has them
  std::optional<Wind> wind = {};             // seed 004's wind, when the scene has one (dynamic only)

  /// The table a kind of spring follows; the model builder makes sure the fabric's kinds have one.
  const TensionTable& table(SpringKind kind) const {
    switch (kind) {
      case SpringKind::warp: return warp;
      case SpringKind::weft: return weft;
      case SpringKind::shear: return shear.value();
      case SpringKind::bend: return bend.value();
    }
    return warp;
  }
  int node_count() const { return fabric.node_count(); }
};

}  // namespace fabform
