#pragma once
// A scene as fabform runs it: validated, in SI units, with every path resolved against the
// scene file's folder and every value remembering where it was written (for error messages).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/error.hpp"
#include "fabform/fabric/grid.hpp"
#include "fabform/fabric/initial_shape.hpp"
#include "fabform/fabric/node_set.hpp"
#include "fabform/geometry/placement.hpp"
#include "fabform/model/external_loads.hpp"
#include "fabform/solver/solve.hpp"

namespace fabform {

struct BodySpec {
  std::string name;
  std::string mesh_path;
  SourceLocation mesh_where;
  std::string units;  // as written: m, cm, mm or in
  Placement placement;
  SourceLocation where;
};

struct ConstraintSpec {
  NodeSetSpec nodes;
  std::string nodes_text;  // the selector as written, for reports
  AxisMask axes = kLockX | kLockY | kLockZ;
  SourceLocation where;
};

// When a run writes its state so that `fabform run --resume` can go on from there: every K
// iterations and every M minutes, whichever comes first (0 turns either off).
struct CheckpointSpec {
  int every_iterations = 0;
  double every_minutes = 10.0;
};

// [gravity]: the fabric's weight along −z, its mass per area from the material files.
struct GravitySpec {
  bool on = false;  // the scene has a [gravity] table
  double acceleration_m_s2 = kStandardGravity_m_s2;
  SourceLocation where;
};

struct Scene {
  std::string path;
  std::string name;
  std::string description;
  GridSpec grid;
  SourceLocation grid_where;
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();  // the flat fabric's lower-left corner
  std::string warp_path;
  SourceLocation warp_where;
  std::string weft_path;
  SourceLocation weft_where;
  std::vector<BodySpec> bodies;
  std::vector<ConstraintSpec> constraints;
  GravitySpec gravity;
  InitialShape initial;
  SourceLocation initial_where;
  SolverSpec solver;
  std::string output_dir;  // "" when the scene names none
  CheckpointSpec checkpoint;
};

/// The solver names fabform knows, in the order `fabform solvers` lists them.
const std::vector<std::string>& solver_names();

}  // namespace fabform
