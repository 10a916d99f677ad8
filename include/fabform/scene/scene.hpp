#pragma once
// A scene as fabform runs it: validated, in SI units, with every path resolved against the
// scene file's folder and every value remembering where it was written (for error messages).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/angles.hpp"
#include "fabform/error.hpp"
#include "fabform/fabric/fabric.hpp"
#include "fabform/fabric/initial_shape.hpp"
#include "fabform/fabric/node_set.hpp"
#include "fabform/fabric/start_perturbation.hpp"
#include "fabform/geometry/placement.hpp"
#include "fabform/geometry/tool_path.hpp"
#include "fabform/material/compression_response.hpp"
#include "fabform/model/gravity.hpp"
#include "fabform/solver/solver_registry.hpp"

namespace fabform {

struct BodySpec {
  std::string name;
  std::string mesh_path;
  SourceLocation mesh_where;
  std::string units;  // as written: m, cm, mm or in
  Placement placement;
  double friction = 0.0;  // Coulomb's μ between the fabric and this body; 0: frictionless
  SourceLocation friction_where;
  // Springs wrap the body's convex edges whose faces turn by at least this much (degrees); 0, the
  // default: contact is the nodes' alone, as in seed 003.
  double wrap_edges_deg = 0.0;
  SourceLocation wrap_edges_where;
  // The fabric's springs are kept out from under the body's convex edges whose faces turn by at
  // least this much (degrees), by a smooth penalty (edge_contact.hpp); 0, the default: none.
  double edge_contact_deg = 0.0;
  SourceLocation edge_contact_where;
  // The fabric's springs are kept out of the body along their length, by a penalty on how deep
  // points along them lie inside it (spring_contact.hpp); false, the default: the nodes alone.
  bool spring_contact = false;
  SourceLocation spring_contact_where;
  ToolPath path;               // [body.path]: its travel in load steps (steps 0: it stays put)
  bool pivot_given = false;    // else the turn is about the placed mesh's bounding box's centre
  SourceLocation steps_where;  // path.steps, for messages
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

// [shear]: the diagonal springs (seed 000's triangular mesh, seed 004's shear springs), following
// the material file of their bias tension or a measured shear rigidity G (KES, FAST).
struct ShearSpec {
  bool on = false;
  SourceLocation where;
  std::string material_path;  // "" when the rigidity is given instead
  SourceLocation material_where;
  double rigidity_N_m = 0.0;  // G, shear force per width per radian (N/m); 0: from the table
  SourceLocation rigidity_where;
  // KES-FB1's shear hysteresis 2HG (force per width, N/m), the cells' friction
  // (shear_friction.hpp); 0: none. It rounds in over this shear angle (0.1°).
  double hysteresis_N_m = 0.0;
  double hysteresis_rounding_rad = 0.1 * kRadiansPerDegree;
  SourceLocation hysteresis_where;
};

// [bending]: seed 004's bend springs (stiffness_N_m) or hinges with the fabric's flexural
// rigidity, given in N·m or µN·m or as a cantilever's bending length; one of them. Index 0 is
// the warp's (a strip cut along the warp, bent along its length), 1 the weft's.
struct BendingSpec {
  bool on = false;
  double stiffness_N_m = 0.0;  // bend springs' tension per width per unit strain; 0: none
  Eigen::Vector2d rigidity_Nm = Eigen::Vector2d::Zero();  // B, moment per width per unit curvature
  // Cantilever bending lengths c (m), BS 3356 / ASTM D1388: B = m·g₀·c³ with the fabric's areal
  // mass m, so the model builder, which knows m, turns them into rigidities. 0: not given.
  Eigen::Vector2d bending_length_m = Eigen::Vector2d::Zero();
  // KES-FB's bending hysteresis 2HB (moment per width, N·m/m) along warp and weft, the hinges'
  // friction (hinge_friction.hpp); 0: none. The friction moment rounds in over this curvature.
  Eigen::Vector2d hysteresis_N = Eigen::Vector2d::Zero();
  double hysteresis_rounding_per_m = 10.0;
  SourceLocation hysteresis_where;
  bool hinges() const { return rigidity_Nm.maxCoeff() > 0.0 || bending_length_m.maxCoeff() > 0.0; }
  SourceLocation where;
  SourceLocation value_where;  // the key that gave the rigidity or bending length
};

// [wind]: seed 004's wind, velocity_m_s (required: a wind has a direction) and its strength
// coefficient_N_s_m3 (C per area of fabric). Only solver dynamic models it.
struct WindSpec {
  bool on = false;
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
  double coefficient_N_s_m3 = 0.0;
  SourceLocation where;
};

// [pressure]: a uniform pressure on the fabric (vacuum forming), a follower load; positive
// pushes against warp × weft (down, for a fabric laid face up). The fabric's edge must be held.
struct PressureSpec {
  bool on = false;
  double pressure_Pa = 0.0;
  SourceLocation where;
};

// [clamp]: a blank holder gripping a frame round the blank's edge (width_m) or a node set, with
// its whole normal force and the friction of its faces (clamp_frame.hpp).
struct ClampSpec {
  bool on = false;
  NodeSetSpec nodes;
  std::string nodes_text;  // the region as written, for reports
  double force_N = 0.0;
  double friction = 0.0;
  SourceLocation where;
};

// [drape]: the scene is a drape test of a circular fabric; its result gives the drape
// coefficient, with the named body as the support disc (none: over a pin, A_disc = 0).
// clamp_radius_m: the tester's clamp, two discs of that radius holding the specimen's centre
// (BS 5058, ISO 9073-9): its nodes are held in x, y and z.
struct DrapeSpec {
  bool on = false;
  std::string support;  // a body's name, or ""
  SourceLocation support_where;
  double clamp_radius_m = 0.0;  // 0: no clamp (the scene holds the specimen by its constraints)
  SourceLocation clamp_where;
  SourceLocation where;
};

// [self_contact]: the fabric meets itself (folds, plies, a garment's front and back) with a
// thickness; material files give none, so the scene does, or 0.5 mm (self_contact.hpp).
struct SelfContactSpec {
  bool on = false;
  double thickness_m = 0.5e-3;
  SourceLocation where;
};

// [[seam]]: two panel edges sewn together (seam.hpp), their points matched by arc length. A
// pattern sews edges that run opposite ways round their panels (right side to right side), so
// the second edge is taken from its end unless same_direction; edge lengths may differ (ease,
// gathers) up to kMaxSeamLengthRatio.
struct SeamSpec {
  std::string name;
  std::array<int, 2> panel = {0, 0};  // indices into FabricSpec::panels
  std::array<int, 2> edge = {0, 0};   // edges of their outlines
  bool same_direction = false;
  SourceLocation where;
};

struct Scene {
  std::string path;
  std::string name;
  std::string description;
  FabricSpec fabric;
  SourceLocation fabric_where;  // the key that sets the fabric's divisions (or rings)
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();  // the flat fabric's bounding box's lower-left corner
  std::string warp_path;
  SourceLocation warp_where;
  std::string weft_path;
  SourceLocation weft_where;
  bool softening = false;  // [fabric] softening: tension tables may fall with strain, as meant
  std::optional<double> locking_angle_deg;  // [fabric]: where a cell locks, without a stiffening shear table
  Compression compression = Compression::none;  // [fabric]: what tension-only tables give in compression
  SourceLocation compression_where;
  // [fabric] areal_mass_g_m2, in kg/m²: the fabric's mass per area, when the scene gives it rather
  // than (or as well as, and then alike) its material files.
  std::optional<double> areal_mass_kg_m2;
  SourceLocation areal_mass_where;
  std::vector<BodySpec> bodies;
  std::vector<ConstraintSpec> constraints;
  GravitySpec gravity;
  ShearSpec shear;
  BendingSpec bending;
  WindSpec wind;
  PressureSpec pressure;
  ClampSpec clamp;
  DrapeSpec drape;
  SelfContactSpec self_contact;
  std::vector<SeamSpec> seams;
  std::string pattern_path;  // [garment] pattern: the sewing pattern the panels and seams came from, or ""
  InitialShape initial;
  SourceLocation initial_where;
  StartPerturbation perturbation;  // [initial] perturbation_m, seed: a seeded jitter of the start in z
  SolverSpec solver;
  SourceLocation tolerance_where;  // solver.tolerance_relative, for messages
  std::string output_dir;  // "" when the scene names none
  CheckpointSpec checkpoint;
};

}  // namespace fabform
