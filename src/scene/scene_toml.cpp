#include "fabform/scene/scene_toml.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "fabform/model/clamp_frame.hpp"
#include "fabform/model/edge_contact.hpp"
#include "fabform/model/spring_contact.hpp"
#include "fabform/model/gravity.hpp"
#include "fabform/model/hinge_friction.hpp"
#include "fabform/model/seam.hpp"
#include "fabform/model/self_contact.hpp"
#include "fabform/model/shear_friction.hpp"
#include "fabform/model/wind.hpp"
#include "fabform/scene/continuation_grids.hpp"
#include "fabform/solver/solver_registry.hpp"
#include "scene/garment_toml.hpp"
#include "scene/scene_overrides.hpp"
#include "scene/scene_values.hpp"
#include "scene/toml_table_reader.hpp"

namespace fabform {
namespace {

namespace fs = std::filesystem;
using namespace scene_values;

void read_rectangle(TableReader& r, Scene* scene) {
  const Eigen::Vector2d size = r.vector<2>("size_m", Eigen::Vector2d::Zero(), true);
  if (!(size.array() > 0.0).all()) r.fail("size_m", "both sides must be positive");
  if (size.maxCoeff() > kMaxLength_m) r.fail("size_m", "must be at most " + number_text(kMaxLength_m) + " m a side");
  const auto [n, m] = r.integer_pair("divisions", true);
  FabricSpec& f = scene->fabric;
  f.width_m = size.x(), f.height_m = size.y();
  f.divisions_warp = checked_int(r, "divisions", n, 1, 10000);
  f.divisions_weft = checked_int(r, "divisions", m, 1, 10000);
  scene->fabric_where = r.locate_key("divisions");
}

// A seamless tube: the rectangle of its circumference and length sewn to itself, the warp
// running round it or along it; divisions are [round, along].
void read_tube(TableReader& r, Scene* scene) {
  const double circumference = r.number("circumference_m", 0.0, true);
  check_size(r, "circumference_m", circumference);
  const double length = r.number("length_m", 0.0, true);
  check_size(r, "length_m", length);
  const auto [round, along] = r.integer_pair("divisions", true);
  const std::string warp_runs = r.text("warp_runs", "round");
  if (warp_runs != "round" && warp_runs != "along")
    r.fail("warp_runs", "must be round or along (got '" + shown(warp_runs) + "')");
  FabricSpec& f = scene->fabric;
  const bool warp_round = warp_runs == "round";
  f.tube = warp_round ? FabricSpec::Tube::warp_round : FabricSpec::Tube::warp_along;
  f.width_m = warp_round ? circumference : length;
  f.height_m = warp_round ? length : circumference;
  const int round_divisions = checked_int(r, "divisions", round, 3, 10000);
  const int along_divisions = checked_int(r, "divisions", along, 1, 10000);
  f.divisions_warp = warp_round ? round_divisions : along_divisions;
  f.divisions_weft = warp_round ? along_divisions : round_divisions;
  scene->fabric_where = r.locate_key("divisions");
}

// A jittered lattice's nodes move by up to this fraction of its spacing (kMaxJitter keeps its
// cells convex); its seed is the start's, [initial] seed, read later (parse_scene).
void read_jitter(TableReader& r, FabricSpec* f) {
  f->jitter = r.number("jitter", kMaxJitter);
  if (!(f->jitter > 0.0 && f->jitter <= kMaxJitter))
    r.fail("jitter", "must be in (0, 0.2], a fraction of the lattice spacing (more could turn a cell's corner inward)");
}

// Seed 000's circle: lattice points inside it (quadrangular, triangular, jittered) or rings on spokes.
void read_circle(TableReader& r, Scene* scene) {
  FabricSpec& f = scene->fabric;
  f.shape = FabricSpec::Shape::circle;
  f.width_m = f.height_m = r.number("diameter_m", 0.0, true);
  check_size(r, "diameter_m", f.width_m);
  const std::string mesh = r.text("mesh", "", true);
  if (mesh == "quadrangular" || mesh == "triangular" || mesh == "jittered") {
    f.mesh = mesh == "triangular" ? FabricSpec::Mesh::triangular
             : mesh == "jittered" ? FabricSpec::Mesh::jittered
                                  : FabricSpec::Mesh::quadrangular;
    f.divisions_warp = f.divisions_weft = checked_int(r, "divisions", r.integer("divisions", 0, true), 3, 10000);
    scene->fabric_where = r.locate_key("divisions");
    if (f.mesh == FabricSpec::Mesh::jittered) read_jitter(r, &f);
  } else if (mesh == "arc") {
    f.mesh = FabricSpec::Mesh::arc;
    f.rings = checked_int(r, "rings", r.integer("rings", 0, true), 1, 5000);
    f.spokes = checked_int(r, "spokes", r.integer("spokes", 0, true), 3, 10000);
    scene->fabric_where = r.locate_key("rings");
  } else {
    r.fail("mesh", "must be one of quadrangular, triangular, arc, jittered (got '" + shown(mesh) + "')");
  }
}

void read_fabric(TableReader& r, Scene* scene) {
  const std::string shape = r.text("shape", "rectangle");
  if (shape == "rectangle") read_rectangle(r, scene);
  else if (shape == "circle") read_circle(r, scene);
  else if (shape == "tube") read_tube(r, scene);
  else if (shape == "panels") read_panels(r, scene);
  else r.fail("shape", "must be rectangle, circle, tube or panels (got '" + shown(shape) + "')");
  scene->origin_m = r.vector<3>("origin_m", Eigen::Vector3d::Zero());
  scene->warp_path = resolve(scene->path, plain_text(r, "warp", "", true));
  scene->warp_where = r.locate_key("warp");
  scene->weft_path = resolve(scene->path, plain_text(r, "weft", "", true));
  scene->weft_where = r.locate_key("weft");
  scene->softening = r.flag("softening", false);
  if (r.has("areal_mass_g_m2")) {
    const double grams = r.number("areal_mass_g_m2", 0.0);
    if (!(grams > 0.0 && grams <= 1e5)) r.fail("areal_mass_g_m2", "must be in (0, 1e5] g/m²");
    scene->areal_mass_kg_m2 = grams * 1e-3;
    scene->areal_mass_where = r.locate_key("areal_mass_g_m2");
  }
  if (r.has("locking_angle_deg")) {
    scene->locking_angle_deg = r.number("locking_angle_deg", 45.0);
    if (!(*scene->locking_angle_deg > 0.0 && *scene->locking_angle_deg < 90.0))
      r.fail("locking_angle_deg", "must lie between 0 and 90 degrees");
  }
  const std::string compression = r.text("compression", "none");
  if (!parse_compression(compression, &scene->compression))
    r.fail("compression", "must be one of none, linear, buckling (got '" + shown(compression) + "')");
  scene->compression_where = r.locate_key("compression");
  if (shape == "rectangle")
    r.reject_unknown({"shape", "size_m", "divisions", "origin_m", "warp", "weft", "softening", "locking_angle_deg",
                     "areal_mass_g_m2", "compression"});
  else if (shape == "panels")
    r.reject_unknown({"shape", "spacing_m", "panel", "origin_m", "warp", "weft", "softening", "locking_angle_deg",
                      "areal_mass_g_m2", "compression"});
  else if (shape == "tube")
    r.reject_unknown({"shape", "circumference_m", "length_m", "divisions", "warp_runs", "origin_m", "warp", "weft",
                      "softening", "locking_angle_deg", "areal_mass_g_m2", "compression"});
  else if (scene->fabric.mesh == FabricSpec::Mesh::arc)
    r.reject_unknown({"shape", "diameter_m", "mesh", "rings", "spokes", "origin_m", "warp", "weft", "softening", "locking_angle_deg",
                     "areal_mass_g_m2", "compression"});
  else if (scene->fabric.mesh == FabricSpec::Mesh::jittered)
    r.reject_unknown({"shape", "diameter_m", "mesh", "divisions", "jitter", "origin_m", "warp", "weft", "softening",
                      "locking_angle_deg", "areal_mass_g_m2", "compression"});
  else
    r.reject_unknown({"shape", "diameter_m", "mesh", "divisions", "origin_m", "warp", "weft", "softening", "locking_angle_deg",
                     "areal_mass_g_m2", "compression"});
}

// A KES hysteresis is given in the lab's unit or in SI, not both; its rounding only with it.
// Returns the key that gives it, or "" for none.
std::string hysteresis_key(TableReader& r, const std::string& lab, const std::string& si, const std::string& rounding,
                           const std::string& kind, const std::string& what) {
  const bool in_lab = r.has(lab), in_si = r.has(si);
  if (in_lab && in_si) r.fail(lab, "give " + what + " once: " + lab + " or " + si + ", not both");
  if (!in_lab && !in_si && r.has(rounding))
    r.fail(rounding, "rounds the " + kind + " friction: give " + what + " as well (" + lab + ")");
  return in_lab ? lab : in_si ? si : "";
}

// KES-FB1 reports 2HG in gf/cm (× 0.980665 = N/m); the friction acts on four-sided cells.
void read_shear_hysteresis(TableReader& r, Scene* scene) {
  ShearSpec& s = scene->shear;
  const std::string key = hysteresis_key(r, "hysteresis_gf_cm", "hysteresis_N_m", "hysteresis_rounding_deg", "shear", "2HG");
  if (key.empty()) return;
  const bool in_gf = key == "hysteresis_gf_cm";
  const FabricSpec::Mesh mesh = scene->fabric.mesh;
  if (mesh == FabricSpec::Mesh::arc || mesh == FabricSpec::Mesh::jittered)
    r.fail(key, std::string("shear friction reads a cell's shear from its diagonals, which is exact on a lattice's "
                            "rectangular cells only: use mesh = \"quadrangular\" or \"triangular\", not \"") +
                    to_string(mesh) + "\"");
  const double value = r.number(key, 0.0, true);
  const double cap = in_gf ? 1e3 : 1e3 * kGramForcePerCentimetre_N_m;
  if (!(value > 0.0 && value <= cap)) r.fail(key, in_gf ? "must be in (0, 1000] gf/cm" : "must be in (0, 980.665] N/m");
  s.hysteresis_N_m = in_gf ? value * kGramForcePerCentimetre_N_m : value;
  s.hysteresis_where = r.locate_key(key);
  const double rounding_deg = r.number("hysteresis_rounding_deg", s.hysteresis_rounding_rad / kRadiansPerDegree);
  // At 1e-4° the stick is already a shear rigidity HG/γ₀ of 2.9e5 × 2HG per radian.
  if (!(rounding_deg >= 1e-4 && rounding_deg <= 10.0)) r.fail("hysteresis_rounding_deg", "must be in [0.0001, 10] degrees");
  s.hysteresis_rounding_rad = rounding_deg * kRadiansPerDegree;
}

// The diagonal springs follow a bias table (material) or a measured shear rigidity; one of them.
void read_shear(TableReader r, Scene* scene) {
  ShearSpec& s = scene->shear;
  s.on = true;
  s.where = r.where();
  const int given = int(r.has("material")) + int(r.has("rigidity_N_m")) + int(r.has("rigidity_gf_cm_deg"));
  if (given != 1)
    throw InputError(r.where(), "give one of material (a bias tension table), rigidity_N_m (G, N/m per radian, "
                                "as FAST gives it) or rigidity_gf_cm_deg (G as KES-FB1 gives it)");
  if (r.has("material")) {
    s.material_path = resolve(scene->path, plain_text(r, "material", "", true));
    s.material_where = r.locate_key("material");
  } else {
    const std::string key = r.has("rigidity_N_m") ? "rigidity_N_m" : "rigidity_gf_cm_deg";
    const double value = r.number(key, 0.0, true);
    // KES-FB1 gives G in gf/(cm·degree); fabform works in N/m per radian.
    s.rigidity_N_m = key == "rigidity_N_m" ? value : value * kGramForcePerCentimetre_N_m / kRadiansPerDegree;
    if (!(s.rigidity_N_m > 0.0 && s.rigidity_N_m <= 1e9)) r.fail(key, "must be positive, at most 1e9 N/m");
    s.rigidity_where = r.locate_key(key);
  }
  scene->fabric.shear_springs = true;
  read_shear_hysteresis(r, scene);
  r.reject_unknown({"material", "rigidity_N_m", "rigidity_gf_cm_deg", "hysteresis_gf_cm", "hysteresis_N_m",
                    "hysteresis_rounding_deg"});
}

// KES-FB reports 2HB in gf·cm/cm (1 gf·cm/cm = 9.80665e-3 N·m/m); only hinges have friction.
void read_bending_hysteresis(TableReader& r, BendingSpec* b) {
  const std::string key =
      hysteresis_key(r, "hysteresis_gf_cm_cm", "hysteresis_Nm_m", "hysteresis_rounding_per_m", "bending", "2HB");
  if (key.empty()) return;
  const bool in_gf = key == "hysteresis_gf_cm_cm";
  if (!b->hinges()) r.fail(key, "bending friction acts in hinges: give the rigidity (rigidity_uNm, rigidity_Nm or "
                                "bending_length_cm), not stiffness_N_m");
  const Eigen::Vector2d value = r.number_or_pair(key);
  if (!(value.minCoeff() >= 0.0 && value.maxCoeff() > 0.0 && value.maxCoeff() <= (in_gf ? 1e3 : 1e3 * kNewtonsPerGramForce)))
    r.fail(key, in_gf ? "must be in [0, 1000] gf·cm/cm, one of them positive"
                      : "must be in [0, 9.80665] N·m/m, one of them positive");
  b->hysteresis_N = in_gf ? kNewtonsPerGramForce * value : value;
  b->hysteresis_where = r.locate_key(key);
  b->hysteresis_rounding_per_m = r.number("hysteresis_rounding_per_m", b->hysteresis_rounding_per_m);
  // At 1e-3 1/m (a bend of radius 1 km) the stick is already a rigidity HB/κ_r of 500 m × 2HB.
  if (!(b->hysteresis_rounding_per_m >= 1e-3 && b->hysteresis_rounding_per_m <= 1e4))
    r.fail("hysteresis_rounding_per_m", "must be in [0.001, 1e4] 1/m");
}

// Hinges take the rigidity in N·m or µN·m, or the cantilever's bending length in cm, each a
// number or [warp, weft]; seed 004's bend springs a stiffness. One of the four.
void read_bending(TableReader r, Scene* scene) {
  BendingSpec& b = scene->bending;
  b.on = true;
  b.where = r.where();
  const std::vector<std::string> keys = {"stiffness_N_m", "rigidity_Nm", "rigidity_uNm", "bending_length_cm"};
  const std::string one_of = "give one of stiffness_N_m (seed 004's bend springs), rigidity_Nm or rigidity_uNm "
                             "(hinges with the fabric's flexural rigidity) or bending_length_cm (a cantilever test's)";
  std::string key;
  for (const std::string& k : keys)
    if (r.has(k)) {
      if (!key.empty()) throw InputError(b.where, one_of + ", not " + key + " and " + k);
      key = k;
    }
  if (key.empty()) throw InputError(b.where, one_of);
  b.value_where = r.locate_key(key);
  if (key == "stiffness_N_m") {
    b.stiffness_N_m = r.number("stiffness_N_m", 0.0, true);
    if (!(b.stiffness_N_m > 0.0 && b.stiffness_N_m <= 1e9)) r.fail("stiffness_N_m", "must be in (0, 1e9] N/m");
    scene->fabric.bend_springs = true;
  } else if (key == "bending_length_cm") {
    const Eigen::Vector2d c = r.number_or_pair(key);
    if (!(c.minCoeff() > 0.0 && c.maxCoeff() <= 1e3)) r.fail(key, "must be in (0, 1000] cm");
    b.bending_length_m = 0.01 * c;
    scene->fabric.hinges = true;
  } else {
    const bool micro = key == "rigidity_uNm";
    const Eigen::Vector2d value = r.number_or_pair(key);
    if (!(value.minCoeff() > 0.0 && value.maxCoeff() <= (micro ? 1e9 : 1e3)))
      r.fail(key, micro ? "must be in (0, 1e9] µN·m" : "must be in (0, 1e3] N·m");
    b.rigidity_Nm = micro ? 1e-6 * value : value;
    scene->fabric.hinges = true;
  }
  read_bending_hysteresis(r, &b);
  std::vector<std::string> known = keys;
  known.insert(known.end(), {"hysteresis_gf_cm_cm", "hysteresis_Nm_m", "hysteresis_rounding_per_m"});
  r.reject_unknown(known);
}

void read_wind(TableReader r, Scene* scene) {
  WindSpec& w = scene->wind;
  w.on = true;
  w.where = r.where();
  if (!r.has("velocity_m_s")) r.fail("velocity_m_s", "wind without a direction: give its velocity, [x, y, z] m/s");
  w.velocity_m_s = r.vector<3>("velocity_m_s", Eigen::Vector3d::Zero());
  w.coefficient_N_s_m3 = r.number("coefficient_N_s_m3", 0.0, true);
  std::string field;
  if (const std::string why = Wind{w.velocity_m_s, w.coefficient_N_s_m3}.invalid_reason(&field); !why.empty())
    r.fail(field, why);
  r.reject_unknown({"velocity_m_s", "coefficient_N_s_m3"});
}

void read_self_contact(TableReader r, Scene* scene) {
  SelfContactSpec& s = scene->self_contact;
  s.on = true;
  s.where = r.where();
  s.thickness_m = r.number("thickness_m", s.thickness_m);
  // A centimetre is a quilt; beyond, a unit mistake.
  if (!(s.thickness_m > 0.0 && s.thickness_m <= 0.01)) r.fail("thickness_m", "must be in (0, 0.01] m");
  r.reject_unknown({"thickness_m"});
}

void read_pressure(TableReader r, Scene* scene) {
  PressureSpec& p = scene->pressure;
  p.on = true;
  p.where = r.where();
  p.pressure_Pa = r.number("pressure_Pa", 0.0, true);
  // 1e7 Pa is a hundred atmospheres: beyond, a unit mistake.
  if (!(p.pressure_Pa != 0.0 && std::abs(p.pressure_Pa) <= 1e7))
    r.fail("pressure_Pa", "must be non-zero and within ±1e7 Pa");
  // A pressure follows the faces' normals, and a garment's panels face whichever way their
  // outlines run round (GarmentCode's back panels the other way from its fronts).
  if (scene->fabric.shape == FabricSpec::Shape::panels)
    r.fail("pressure_Pa", "a garment's panels do not all face out: a pressure on panels is not supported");
  r.reject_unknown({"pressure_Pa"});
}

void read_drape(TableReader r, Scene* scene) {
  DrapeSpec& d = scene->drape;
  d.on = true;
  d.where = r.where();
  d.support = plain_text(r, "support", "");
  d.support_where = r.locate_key("support");
  if (scene->fabric.shape != FabricSpec::Shape::circle)
    throw InputError(d.where, "a drape test needs a circular fabric ([fabric] shape = \"circle\")");
  if (r.has("clamp_radius_m")) {
    d.clamp_radius_m = r.number("clamp_radius_m", 0.0);
    d.clamp_where = r.locate_key("clamp_radius_m");
    if (!(d.clamp_radius_m > 0.0)) r.fail("clamp_radius_m", "must be positive");
    if (d.clamp_radius_m >= scene->fabric.radius_m())
      r.fail("clamp_radius_m", "is " + number_text(d.clamp_radius_m) + " m, not smaller than the specimen's radius " +
                                   number_text(scene->fabric.radius_m()) + " m: nothing would hang");
  }
  r.reject_unknown({"support", "clamp_radius_m"});
}

// [body.path]: the body's travel in load steps.
void read_path(TableReader r, BodySpec* body) {
  ToolPath& path = body->path;
  path.steps = checked_int(r, "steps", r.integer("steps", 0, true), 1, 100000);
  body->steps_where = r.locate_key("steps");
  path.translation_m = r.vector<3>("translation_m", Eigen::Vector3d::Zero());
  check_magnitude(r, "translation_m", path.translation_m.cwiseAbs().maxCoeff(), kMaxLength_m, "m");
  path.rotation_deg = angles<3>(r, "rotation_deg");
  body->pivot_given = r.has("pivot_m");
  path.pivot_m = r.vector<3>("pivot_m", Eigen::Vector3d::Zero());
  check_magnitude(r, "pivot_m", path.pivot_m.cwiseAbs().maxCoeff(), kMaxLength_m, "m");
  std::string field;
  if (const std::string why = path.invalid_reason(&field); !why.empty()) r.fail(field, why);
  r.reject_unknown({"steps", "translation_m", "rotation_deg", "pivot_m"});
}

// Every travelling body moves in the same load steps.
void check_steps_agree(const Scene& scene) {
  const BodySpec* first = nullptr;
  for (const BodySpec& body : scene.bodies) {
    if (!body.path.moves()) continue;
    if (!first) first = &body;
    else if (body.path.steps != first->path.steps)
      throw InputError(body.steps_where, "body '" + body.name + "' travels in " + std::to_string(body.path.steps) +
                                             " steps, body '" + first->name + "' in " +
                                             std::to_string(first->path.steps) + ": every path takes the same steps");
  }
}

BodySpec read_body(TableReader r, const std::string& scene_path, std::size_t index) {
  BodySpec body;
  body.where = r.where();
  body.name = plain_text(r, "name", "body" + std::to_string(index));
  body.mesh_path = resolve(scene_path, plain_text(r, "mesh", "", true));
  body.mesh_where = r.locate_key("mesh");
  body.units = r.text("units", "", true);
  if (!parse_length_unit(body.units, &body.placement.metres_per_unit))
    r.fail("units", "must be one of m, cm, mm, in (got '" + shown(body.units) + "')");
  body.placement.scale = r.number("scale", 1.0);
  body.placement.rotation_deg = angles<3>(r, "rotation_deg");
  body.placement.translation_m = r.vector<3>("translation_m", Eigen::Vector3d::Zero());
  body.friction = r.number("friction", 0.0);
  body.friction_where = r.locate_key("friction");
  if (!(body.friction >= 0.0 && body.friction <= 10.0))
    r.fail("friction", "Coulomb's coefficient must be in [0, 10] (0: frictionless)");
  if (r.has("wrap_edges_deg")) {
    body.wrap_edges_deg = r.number("wrap_edges_deg", 0.0);
    body.wrap_edges_where = r.locate_key("wrap_edges_deg");
    if (!(body.wrap_edges_deg >= 0.0 && body.wrap_edges_deg < 180.0))
      r.fail("wrap_edges_deg",
             "the angle between an edge's faces from which springs wrap it must be in (0, 180) degrees (0: none)");
  }
  if (r.has("edge_contact_deg")) {
    body.edge_contact_deg = r.number("edge_contact_deg", 0.0);
    body.edge_contact_where = r.locate_key("edge_contact_deg");
    if (!(body.edge_contact_deg >= 0.0 && body.edge_contact_deg < 180.0))
      r.fail("edge_contact_deg",
             "the angle between an edge's faces from which springs are kept from under it must be in (0, 180) "
             "degrees (0: none)");
    if (body.edge_contact_deg > 0.0 && body.wrap_edges_deg > 0.0)
      r.fail("edge_contact_deg", "a body's edges are either wrapped (wrap_edges_deg) or kept out of the springs "
                                 "(edge_contact_deg), not both");
  }
  if (r.has("spring_contact")) {
    body.spring_contact = r.flag("spring_contact", false);
    body.spring_contact_where = r.locate_key("spring_contact");
    if (body.spring_contact && (body.wrap_edges_deg > 0.0 || body.edge_contact_deg > 0.0))
      r.fail("spring_contact", "a body keeps springs out along their length (spring_contact) or wraps them over its "
                               "edges (wrap_edges_deg) or keeps them from under its edges (edge_contact_deg): one");
  }
  std::string field;
  if (const std::string why = body.placement.invalid_reason(&field); !why.empty()) r.fail(field, why);
  if (r.has("path")) read_path(r.table("path", false), &body);
  r.reject_unknown({"name", "mesh", "units", "scale", "rotation_deg", "translation_m", "friction", "wrap_edges_deg",
                    "edge_contact_deg", "spring_contact", "path"});
  return body;
}

// A node by grid index (one off the grid is reported by the model builder, which knows the grid).
NodeSetSpec read_node_index(TableReader& r, std::string* text) {
  const auto [i, j] = r.integer_pair("node", true);
  NodeSetSpec spec;
  spec.kind = NodeSetSpec::Kind::index;
  spec.i = checked_int(r, "node", i, 0, 100000);
  spec.j = checked_int(r, "node", j, 0, 100000);
  *text = "node [" + std::to_string(i) + ", " + std::to_string(j) + "]";
  return spec;
}

// "A point of the flat fabric", from its lower-left corner: a point off the fabric is usually
// written in scene coordinates (origin_m added) or in the wrong unit, and would silently pick
// whichever edge node is nearest.
NodeSetSpec read_nearest(TableReader& r, const FabricSpec& fabric, std::string* text) {
  NodeSetSpec spec;
  spec.kind = NodeSetSpec::Kind::nearest;
  spec.point = r.vector<2>("nearest_m", Eigen::Vector2d::Zero(), true);
  const Eigen::Vector2d& p = spec.point;
  if (fabric.shape == FabricSpec::Shape::circle) {
    const double radius = fabric.radius_m();
    if (!((p - Eigen::Vector2d(radius, radius)).norm() <= radius))
      r.fail("nearest_m", "must lie on the fabric: within " + number_text(radius) + " m of its centre [" +
                              number_text(radius) + ", " + number_text(radius) +
                              "] (points are from the lower-left corner of the circle's bounding square)");
  } else if (!(p.x() >= 0.0 && p.x() <= fabric.width_m && p.y() >= 0.0 && p.y() <= fabric.height_m)) {
    r.fail("nearest_m", "must lie on the fabric: x from 0 to " + number_text(fabric.width_m) +
                            ", y from 0 to " + number_text(fabric.height_m) +
                            " m from its lower-left corner");
  }
  *text = "nearest_m";
  return spec;
}

// A box may reach beyond the fabric (it selects the nodes inside), but its corners come in
// order: reversed, it would select nothing.
NodeSetSpec read_box(TableReader& r, std::string* text) {
  const toml::node* n = r.take("box_m");
  const toml::array* corners = n->as_array();
  if (!corners || corners->size() != 2) r.fail("box_m", "must be [[x0, y0], [x1, y1]]");
  NodeSetSpec spec;
  spec.kind = NodeSetSpec::Kind::box;
  spec.box_min = r.read_vector<2>((*corners)[0], "box_m");
  spec.box_max = r.read_vector<2>((*corners)[1], "box_m");
  if (!(spec.box_min.array() <= spec.box_max.array()).all())
    r.fail("box_m", "must be [[x0, y0], [x1, y1]] with x0 <= x1 and y0 <= y1");
  *text = "box_m";
  return spec;
}

NodeSetSpec read_selector(TableReader& r, const FabricSpec& fabric, std::string* text) {
  static const std::vector<std::string> selectors = {"nodes", "node", "nearest_m", "box_m"};
  int given = 0;
  for (const auto& s : selectors) given += r.has(s) ? 1 : 0;
  // None or several: the constraint as a whole is wrong, not one of its keys.
  if (given != 1) throw InputError(r.where(), "give exactly one of nodes, node, nearest_m, box_m");
  if (r.has("node")) return read_node_index(r, text);
  if (r.has("nearest_m")) return read_nearest(r, fabric, text);
  if (r.has("box_m")) return read_box(r, text);
  NodeSetSpec spec;
  *text = r.text("nodes", "");
  if (!parse_named_node_set(*text, &spec))
    r.fail("nodes", "unknown node set '" + shown(*text) +
                        "' (known: perimeter, corners, edge:left, edge:right, edge:bottom, "
                        "edge:top)");
  return spec;
}

ConstraintSpec read_constraint(TableReader r, const FabricSpec& fabric) {
  ConstraintSpec constraint;
  constraint.where = r.where();
  constraint.nodes = read_selector(r, fabric, &constraint.nodes_text);
  const std::string axes = r.text("axes", "xyz");
  if (!parse_axes(axes, &constraint.axes))
    r.fail("axes", "must name each of x, y, z at most once, e.g. \"xyz\" or \"xy\"");
  r.reject_unknown({"nodes", "node", "nearest_m", "box_m", "axes"});
  return constraint;
}

void read_clamp(TableReader r, Scene* scene) {
  ClampSpec& c = scene->clamp;
  c.on = true;
  c.where = r.where();
  if (r.has("width_m")) {
    for (const char* other : {"nodes", "node", "nearest_m", "box_m"})
      if (r.has(other)) throw InputError(c.where, "give one of width_m (a frame round the edge) or a node set, not both");
    c.nodes.kind = NodeSetSpec::Kind::frame;
    c.nodes.width_m = r.number("width_m", 0.0, true);
    if (!(c.nodes.width_m >= 0.0 && c.nodes.width_m <= kMaxLength_m))
      r.fail("width_m", "must be between 0 (the edge's nodes alone) and " + number_text(kMaxLength_m) + " m");
    c.nodes_text = "frame " + number_text(c.nodes.width_m) + " m wide";
  } else {
    c.nodes = read_selector(r, scene->fabric, &c.nodes_text);
  }
  c.force_N = r.number("force_N", 0.0, true);
  c.friction = r.number("friction", 0.0, true);
  std::string field;
  // The creep length is the solver's; here only the clamp's own values are checked.
  if (const std::string why = ClampOptions{c.force_N, c.friction, 1.0}.invalid_reason(&field); !why.empty())
    r.fail(field, why);
  r.reject_unknown({"width_m", "nodes", "node", "nearest_m", "box_m", "force_N", "friction"});
}

// A seeded jitter of the start along z (start_perturbation.hpp), of any initial shape.
void read_perturbation(TableReader& r, StartPerturbation* p) {
  p->amplitude_m = r.number("perturbation_m", 0.0);
  if (!(p->amplitude_m >= 0.0 && p->amplitude_m <= 0.1)) r.fail("perturbation_m", "must be in [0, 0.1] m");
  p->seed = static_cast<std::uint64_t>(checked_int(r, "seed", r.integer("seed", 1), 0, 2147483647));
}

void read_initial(TableReader r, Scene* scene) {
  scene->initial_where = r.where();
  const bool tube = scene->fabric.tube != FabricSpec::Tube::none;
  const bool panels = scene->fabric.shape == FabricSpec::Shape::panels;
  const std::string shape = r.text("shape", tube ? "tube" : panels ? "pattern" : "flat");
  if (!parse_initial_kind(shape, &scene->initial.kind))
    r.fail("shape", "must be one of flat, lift, bump, wrap, tube, fold, pattern (got '" + shown(shape) + "')");
  using Kind = InitialShape::Kind;
  if (scene->initial.kind == Kind::pattern && !panels)
    r.fail("shape", "a pattern start places panels: the fabric must be of panels ([fabric] shape = \"panels\")");
  if (tube != (scene->initial.kind == Kind::tube))
    r.fail("shape", tube ? "a tube fabric starts as a tube round the body (shape = \"tube\"), not " + shape
                         : std::string("a tube start needs a tube fabric ([fabric] shape = \"tube\")"));
  InitialShape& s = scene->initial;
  const bool raises = s.kind == Kind::lift || s.kind == Kind::bump || s.kind == Kind::fold;
  s.height_m = r.number("height_m", 0.0, raises);
  if (s.kind == Kind::wrap) {
    s.axis_xy_m = r.vector<2>("axis_m", Eigen::Vector2d::Zero(), true);
    s.radius_m = r.number("radius_m", 0.0, true);
    s.facing_deg = angle(r, "facing_deg", 0.0, true);
    s.span_deg = r.number("span_deg", 0.0, true);
  }
  if (s.kind == Kind::fold) {
    s.fold_at_m = r.number("fold_at_m", 0.0, true);
    if (scene->fabric.shape != FabricSpec::Shape::rectangle || s.fold_at_m >= scene->fabric.width_m)
      r.fail("fold_at_m", "must lie inside a rectangle's width (" + number_text(scene->fabric.width_m) + " m)");
  }
  if (s.kind == Kind::tube) {
    s.axis_xy_m = r.vector<2>("axis_m", Eigen::Vector2d::Zero(), true);
    s.radius_m = r.number("radius_m", 0.0, true);
    s.facing_deg = angle(r, "facing_deg", 0.0);
  }
  std::string field;
  if (const std::string why = s.invalid_reason(&field); !why.empty()) r.fail(field, why);
  read_perturbation(r, &scene->perturbation);
  std::vector<std::string> known = {"shape", "perturbation_m", "seed"};
  if (raises) known.push_back("height_m");
  if (s.kind == Kind::wrap || s.kind == Kind::tube) known.insert(known.end(), {"axis_m", "radius_m", "facing_deg"});
  if (s.kind == Kind::wrap) known.push_back("span_deg");
  if (s.kind == Kind::fold) known.push_back("fold_at_m");
  r.reject_unknown(known);
}

// e in newtons or relative to the fabric's force scale: a scene gives one; a command line that
// sets the other replaces the scene's.
void read_relative_tolerance(TableReader& r, SolverSpec* s) {
  if (!r.has("tolerance_relative")) return;
  const double relative = r.number("tolerance_relative", 0.0);
  if (!(relative > 0.0 && relative <= 1.0))
    r.fail("tolerance_relative", "must be in (0, 1]: ||R||inf over a spring's force per unit strain at rest");
  const bool from_command_line = r.locate_key("tolerance_relative").file == kOverrideSource;
  if (r.has("tolerance_N")) {
    const bool newtons_from_command_line = r.locate_key("tolerance_N").file == kOverrideSource;
    if (newtons_from_command_line == from_command_line)
      r.fail("tolerance_relative", "give one of tolerance_N (newtons) or tolerance_relative (of the fabric's force "
                                   "scale), not both");
    if (newtons_from_command_line) return;
  }
  s->tolerance_relative = relative;
}

// tolerance_N and max_iterations are every solver's; the other keys belong to one solver each
// and are validated whichever solver runs, so a scene stays valid when --solver switches it.
void read_solver(TableReader r, Scene* scene) {
  SolverSpec& s = scene->solver;
  s.name = r.text("name", "relax");
  if (!find_solver(s.name)) r.fail("name", "unknown solver '" + shown(s.name) + "' (see `fabform solvers`)");
  s.set_tolerance_N(r.number("tolerance_N", s.tolerance_N()));
  read_relative_tolerance(r, &s);
  if (r.has("tolerance_m")) {
    const double tolerance_m = r.number("tolerance_m", 0.0);
    if (!(std::isfinite(tolerance_m) && tolerance_m > 0.0))
      r.fail("tolerance_m", "must be a positive, finite distance from the rest in metres");
    s.set_tolerance_m(tolerance_m);
  }
  if (r.has("max_iterations"))
    s.set_max_iterations(checked_int(r, "max_iterations", r.integer("max_iterations", 0), 0, 1'000'000'000));
  s.relax.C = r.number("C", s.relax.C);
  s.newton.regularization = r.number("regularization", s.newton.regularization);
  s.newton.slack_stiffness = r.number("slack_stiffness", s.newton.slack_stiffness);
  s.newton.armijo = r.number("armijo", s.newton.armijo);
  s.newton.max_backtracks = checked_int(
      r, "max_backtracks", r.integer("max_backtracks", s.newton.max_backtracks), 1, 200);
  s.newton.friction_creep = r.number("friction_creep", s.newton.friction_creep);
  s.newton.linear_solver = r.text("linear_solver", s.newton.linear_solver);
  s.dynamic.areal_density_kg_m2 = r.number("areal_density_kg_m2", s.dynamic.areal_density_kg_m2);
  // Only a fabric without a mass of its own moves with this one; one that has a mass would
  // ignore it without a word.
  if (r.has("areal_density_kg_m2") && (scene->gravity.on || scene->areal_mass_kg_m2))
    r.fail("areal_density_kg_m2", std::string("is dynamic's mass for a fabric that has none; this fabric's comes from ") +
                                      (scene->areal_mass_kg_m2 ? "fabric.areal_mass_g_m2" : "its material files, as its weight does") +
                                      ": set it there");
  if (r.has("damping")) s.dynamic.damping = r.number("damping", 0.0);
  s.dynamic.time_step_fraction = r.number("time_step_fraction", s.dynamic.time_step_fraction);
  s.dynamic.stretch_limit = r.number("stretch_limit", s.dynamic.stretch_limit);
  s.threads = checked_int(r, "threads", r.integer("threads", 1), 1, 1024);
  s.continuation_levels = checked_int(r, "continuation_levels", r.integer("continuation_levels", 0), 0, 10);
  // How often a load step that does not converge is cut in half (load_steps.hpp); 0: never.
  s.max_step_cuts = checked_int(r, "max_step_cuts", r.integer("max_step_cuts", s.max_step_cuts), 0, 20);
  std::string field;
  for (const SolverEntry& solver : solvers())
    if (const std::string why = solver.invalid_reason(s, &field); !why.empty()) r.fail(field, why);
  r.reject_unknown({"name", "tolerance_N", "tolerance_relative", "tolerance_m", "max_iterations", "C", "regularization", "slack_stiffness", "armijo",
                    "max_backtracks", "areal_density_kg_m2", "damping", "time_step_fraction",
                    "stretch_limit", "threads", "friction_creep", "continuation_levels", "linear_solver",
                    "max_step_cuts"});
}

void read_gravity(TableReader r, Scene* scene) {
  GravitySpec& g = scene->gravity;
  g.on = true;
  g.where = r.where();
  g.acceleration_m_s2 = r.number("acceleration_m_s2", g.acceleration_m_s2);
  if (!(g.acceleration_m_s2 > 0.0 && g.acceleration_m_s2 <= 1000.0))
    r.fail("acceleration_m_s2", "must be in (0, 1000] m/s² (9.80665 on Earth)");
  r.reject_unknown({"acceleration_m_s2"});
}

void read_output(TableReader r, Scene* scene) {
  const std::string dir = plain_text(r, "dir", "");
  scene->output_dir = resolve(scene->path, dir);
  CheckpointSpec& c = scene->checkpoint;
  c.every_iterations = checked_int(
      r, "checkpoint_every_iterations",
      r.integer("checkpoint_every_iterations", c.every_iterations), 0, 1'000'000'000);
  c.every_minutes = r.number("checkpoint_every_minutes", c.every_minutes);
  if (!(c.every_minutes >= 0.0 && c.every_minutes <= 1e6))
    r.fail("checkpoint_every_minutes", "must be between 0 (off) and 1e6");
  r.reject_unknown({"dir", "checkpoint_every_iterations", "checkpoint_every_minutes"});
}

// ---------------------------------------------------------------------------------------------
// toml++ gives a syntax error's line but not its key (an integer beyond 64 bits, 1e999, a
// duplicate key). Where the line is a plain `key = value` under a [table] or [[array]] header,
// the dotted key is recovered, so the message names it like any other. A hand-written scan,
// not std::regex, whose recursion a fuzzed line of a megabyte would overflow.

bool is_bare_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
}

// The bare (possibly dotted) key starting at `from`, or "" when there is none.
std::string bare_key_at(std::string_view line, std::size_t from) {
  std::size_t end = from;
  while (end < line.size() && is_bare_key_char(line[end])) ++end;
  return std::string(line.substr(from, end - from));
}

std::size_t skip_blanks(std::string_view line, std::size_t at) {
  while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
  return at;
}

// A header's dotted name with the element of each array it lies in: [[fabric.panel.curve]] in the
// second panel is in "fabric.panel.1.curve", [body.path] in "body.1.path".
std::string within_elements(const std::string& name, const std::map<std::string, int>& arrays) {
  std::string resolved;
  for (std::size_t from = 0; from <= name.size();) {
    const std::size_t dot = std::min(name.find('.', from), name.size());
    resolved += (resolved.empty() ? "" : ".") + name.substr(from, dot - from);
    const auto element = arrays.find(resolved);
    if (dot < name.size() && element != arrays.end()) resolved += "." + std::to_string(element->second - 1);
    from = dot + 1;
  }
  return resolved;
}

// Follows [table] and [[array]] headers; `prefix` becomes "fabric", "body.1" or, for a table
// or an array inside an array's element, "body.1.path" or "fabric.panel.1.curve.0".
void follow_header(std::string_view line, std::map<std::string, int>* arrays, std::string* prefix) {
  std::size_t at = skip_blanks(line, 0);
  if (at >= line.size() || line[at] != '[') return;
  const bool array = at + 1 < line.size() && line[at + 1] == '[';
  const std::string name = within_elements(bare_key_at(line, skip_blanks(line, at + (array ? 2 : 1))), *arrays);
  *prefix = array ? name + "." + std::to_string((*arrays)[name]++) : name;
}

// The dotted key of a `key = value` line, or "" for any other line.
std::string key_of_line(std::string_view line, const std::string& prefix) {
  const std::size_t at = skip_blanks(line, 0);
  const std::string key = bare_key_at(line, at);
  const std::size_t equals = skip_blanks(line, at + key.size());
  if (key.empty() || equals >= line.size() || line[equals] != '=') return "";
  return prefix.empty() ? key : prefix + "." + key;
}

std::string key_on_line(std::string_view text, int line_number) {
  std::map<std::string, int> arrays;
  std::string prefix;
  std::size_t start = 0;
  for (int line = 1; start <= text.size(); ++line) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view here = text.substr(start, end - start);
    if (line == line_number) return key_of_line(here, prefix);
    follow_header(here, &arrays, &prefix);
    start = end + 1;
  }
  return "";
}

// Where a key was given, for a message: its line, or the command line's --set.
std::string said_at(const SourceLocation& where) {
  return where.line > 0 ? "line " + std::to_string(where.line) : std::string("from the command line");
}

// The friction in bending or shear a scene has (bending's first when both), and where it was given.
struct GivenHysteresis {
  std::string section;  // "bending" or "shear"; empty: none
  SourceLocation where;
};

GivenHysteresis given_hysteresis(const Scene& scene) {
  if (scene.bending.hysteresis_N.maxCoeff() > 0.0) return {"bending", scene.bending.hysteresis_where};
  if (scene.shear.hysteresis_N_m > 0.0) return {"shear", scene.shear.hysteresis_where};
  return {};
}

// Friction in bending or shear is modelled on the KES loops' loading branch alone: a fabric
// swinging back along it, as dynamic's would, would unbend or unshear elastically.
void refuse_hysteresis_without_loading_branch(const Scene& scene, TableReader& solver) {
  if (solver_gives(scene.solver.name, HingeFriction::kNeeds | ShearFriction::kNeeds)) return;
  const GivenHysteresis friction = given_hysteresis(scene);
  if (friction.section.empty()) return;
  solver.fail("name", "the scene has " + friction.section + " friction (" + said_at(friction.where) +
                          "), modelled on its loading branch alone, from which " + scene.solver.name +
                          "'s fabric would spring back: use " + solvers_giving(HingeFriction::kNeeds | ShearFriction::kNeeds));
}

// The same loading branch holds in load steps only while every hinge and cell keeps bending or
// shearing the way it began: one that the tool's travel straightens again would spring back
// along it elastically, as no fabric with friction does.
void refuse_hysteresis_in_load_steps(const Scene& scene) {
  const GivenHysteresis friction = given_hysteresis(scene);
  if (friction.section.empty()) return;
  for (const BodySpec& body : scene.bodies)
    if (body.path.moves())
      throw InputError(friction.where, friction.section + " friction is modelled on its loading branch from the flat "
                                           "start alone, and body '" + body.name + "' travels in load steps (" +
                                           said_at(body.steps_where) + "), in which a fabric that unbends would spring "
                                           "back along it: leave out the friction or the body's path");
}

// Friction needs the slip from where a node landed (kBodyFrictionNeeds). Seed 003's relaxation,
// the solver without it, moves a node along its unbalanced force, which a stuck node has
// whatever its history.
void refuse_friction_without_stick(const Scene& scene, TableReader& solver) {
  if (solver_gives(scene.solver.name, kBodyFrictionNeeds)) return;
  for (const BodySpec& body : scene.bodies)
    if (body.friction > 0.0)
      solver.fail("name", "body '" + body.name + "' has friction (" + said_at(body.friction_where) + "), which " +
                              scene.solver.name + " cannot carry (seed 003's rule has no stick or slip): use " +
                              solvers_giving(kBodyFrictionNeeds));
}

// A spring over an edge is as stiff across itself as its tension over its shorter leg, which
// no time step bounds as a node nears the edge: explicit dynamics cannot carry it.
void refuse_wrapped_edges_under_a_time_step(const Scene& scene, TableReader& solver) {
  if (solver_gives(scene.solver.name, kWrappedEdgeNeeds)) return;
  for (const BodySpec& body : scene.bodies)
    if (body.wrap_edges_deg > 0.0)
      solver.fail("name", "body '" + body.name + "' lets springs wrap its edges (" + said_at(body.wrap_edges_where) +
                              "), which " + scene.solver.name +
                              " cannot carry (no stable time step bounds a wrapped spring): use " +
                              solvers_giving(kWrappedEdgeNeeds));
}

// The edge penalty, self-contact's and a seam's stitches (a tube's, a garment's) are far stiffer
// than the fabric: only a solver that takes them into its step's matrix carries them.
void refuse_stiff_penalties_without_their_matrix(const Scene& scene, TableReader& solver) {
  const std::string& name = scene.solver.name;
  const std::string stitches = " takes in its step, not " + name;
  for (const BodySpec& body : scene.bodies)
    if (body.edge_contact_deg > 0.0 && !solver_gives(name, EdgeContact::kNeeds)) {
      const std::string who = solvers_giving(EdgeContact::kNeeds);
      solver.fail("name", "body '" + body.name + "' keeps springs from under its edges (" +
                              said_at(body.edge_contact_where) + "), a penalty only " + who + " carries: use " + who);
    }
  for (const BodySpec& body : scene.bodies)
    if (body.spring_contact && !solver_gives(name, SpringContact::kNeeds)) {
      const std::string who = solvers_giving(SpringContact::kNeeds);
      solver.fail("name", "body '" + body.name + "' keeps springs out along their length (" +
                              said_at(body.spring_contact_where) + "), a penalty only " + who + " carries: use " + who);
    }
  if (scene.self_contact.on && !solver_gives(name, SelfContact::kNeeds))
    solver.fail("name", "the scene has self-contact ([self_contact], line " + std::to_string(scene.self_contact.where.line) +
                            "), whose stiff penalty only " + solvers_giving(SelfContact::kNeeds) + stitches);
  if (scene.fabric.tube != FabricSpec::Tube::none && !solver_gives(name, SeamTerm::kNeeds))
    solver.fail("name", "the fabric is a tube (" + said_at(scene.fabric_where) + "), whose seam's stiff stitches only " +
                            solvers_giving(SeamTerm::kNeeds) + stitches);
  if (!scene.seams.empty() && !solver_gives(name, SeamTerm::kNeeds))
    solver.fail("name", "the garment has seams (" + said_at(scene.seams.front().where) + "), whose stiff stitches only " +
                            solvers_giving(SeamTerm::kNeeds) + stitches);
}

Scene read_scene(const toml::table& root, const std::string& path,
                 const OverriddenKeys& overridden) {
  Scene scene;
  scene.path = path;
  TableReader r(&root, "", path, overridden);
  TableReader info = r.table("scene", false);
  scene.name = read_scene_name(info, fs::path(path).stem().string());
  scene.description = info.text("description", "");
  info.reject_unknown({"name", "description"});
  TableReader fabric = r.table("fabric", true);
  read_fabric(fabric, &scene);
  if (r.has("garment")) read_garment(r.table("garment", false), &scene);
  if (scene.fabric.shape == FabricSpec::Shape::panels) check_panels(fabric, &scene);
  read_seams(r.tables("seam"), &scene);
  if (scene.fabric.shape == FabricSpec::Shape::panels) mesh_panels(fabric, &scene);
  const auto bodies = r.tables("body");
  for (std::size_t b = 0; b < bodies.size(); ++b) scene.bodies.push_back(read_body(bodies[b], path, b));
  check_steps_agree(scene);
  for (auto& c : r.tables("constraint")) scene.constraints.push_back(read_constraint(c, scene.fabric));
  if (r.has("gravity")) read_gravity(r.table("gravity", false), &scene);
  if (r.has("shear")) read_shear(r.table("shear", false), &scene);
  if (r.has("bending")) read_bending(r.table("bending", false), &scene);
  if (r.has("wind")) read_wind(r.table("wind", false), &scene);
  if (r.has("pressure")) read_pressure(r.table("pressure", false), &scene);
  if (r.has("clamp")) read_clamp(r.table("clamp", false), &scene);
  if (r.has("drape")) read_drape(r.table("drape", false), &scene);
  if (r.has("self_contact")) read_self_contact(r.table("self_contact", false), &scene);
  if (scene.fabric.mesh == FabricSpec::Mesh::triangular && !scene.shear.on)
    fabric.fail("mesh", "a triangular mesh has diagonal springs: name their bias table in a [shear] table "
                        "(material = FILE)");
  read_initial(r.table("initial", false), &scene);
  scene.fabric.jitter_seed = scene.perturbation.seed;  // one seed for the specimen's imperfections
  TableReader solver = r.table("solver", false);
  read_solver(solver, &scene);
  scene.tolerance_where = solver.locate_key("tolerance_relative");
  if (scene.wind.on && !solver_gives(scene.solver.name, WindLoad::kNeeds))
    solver.fail("name", "the scene has wind (" + said_at(scene.wind.where) +
                            "), which depends on the fabric's velocity (seed 004): only solver " +
                            solvers_giving(WindLoad::kNeeds) + " models it, not " + scene.solver.name);
  refuse_friction_without_stick(scene, solver);
  refuse_wrapped_edges_under_a_time_step(scene, solver);
  refuse_stiff_penalties_without_their_matrix(scene, solver);
  refuse_hysteresis_without_loading_branch(scene, solver);
  refuse_hysteresis_in_load_steps(scene);
  if (scene.clamp.on && !solver_gives(scene.solver.name, ClampFrame::kNeeds))
    solver.fail("name", "the scene has a blank holder ([clamp], line " + std::to_string(scene.clamp.where.line) +
                            "), whose friction only " + solvers_giving(ClampFrame::kNeeds) +
                            " models, not " + scene.solver.name);
  if (!solver.has("continuation_levels")) {
    scene.solver.continuation_levels = chosen_continuation_levels(scene);
    scene.solver.continuation_chosen = true;
  }
  std::string continuation_key;
  if (const std::string why = continuation_refusal(scene, &continuation_key); !why.empty())
    solver.fail(continuation_key, why);
  read_output(r.table("output", false), &scene);
  r.reject_unknown({"scene", "fabric", "body", "constraint", "gravity", "shear", "bending", "wind", "pressure", "clamp", "drape",
                    "self_contact", "garment", "seam", "initial", "solver", "output"});
  return scene;
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& path,
                  const std::vector<SceneOverride>& overrides) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& error) {
    const int line = static_cast<int>(error.source().begin.line);
    throw InputError({path, line, key_on_line(text, line)}, std::string(error.description()));
  }
  return read_scene(root, path, apply_overrides(root, overrides));
}

Scene load_scene(const std::string& path, const std::vector<SceneOverride>& overrides) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError({path, 0, ""}, "no such scene file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw InputError({path, 0, ""}, "cannot read the scene file");
  return parse_scene(text.str(), path, overrides);
}

}  // namespace fabform
