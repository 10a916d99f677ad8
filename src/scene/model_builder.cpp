#include "fabform/scene/model_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "fabform/geometry/nearby_queries.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "fabform/material/material_csv.hpp"
#include "fabform/model/clamp_frame.hpp"
#include "fabform/model/seam.hpp"
#include "fabform/model/self_contact.hpp"
#include "fabform/model/edge_contact.hpp"
#include "fabform/model/spring_contact.hpp"
#include "fabform/model/force_scale.hpp"
#include "fabform/model/gravity.hpp"
#include "fabform/model/hinge_bending.hpp"
#include "fabform/model/hinge_friction.hpp"
#include "fabform/model/pressure.hpp"
#include "fabform/model/shear_friction.hpp"
#include "fabform/model/wind.hpp"
#include "fabform/scene/fabric_plausibility.hpp"
#include "fabform/scene/memory_budget.hpp"
#include "fabform/thread_count.hpp"

namespace fabform {
namespace {

// Embree works in single precision and contact tolerances are relative to the scene; a
// coordinate beyond a thousand kilometres is a unit mistake, not a fabric.
constexpr double kMaxCoordinate_m = 1e6;

// A file named by the scene and missing is the scene's error: name its line and key.
void require_file(const std::string& path, const SourceLocation& where, const char* what) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(where, std::string("no such ") + what + " '" + path + "'");
}

bool within_range(const std::vector<Eigen::Vector3d>& points) {
  for (const auto& p : points)
    if (!(p.cwiseAbs().maxCoeff() <= kMaxCoordinate_m)) return false;
  return true;
}

// A table whose force falls with strain makes the fabric unstable where it does (a spring that
// softens snaps); most often it is a typing error, so the scene must say it is meant.
MaterialFile read_material(const Scene& scene, const std::string& path, const SourceLocation& where) {
  require_file(path, where, "material table");
  MaterialFile file = read_material_file(path);
  if (file.falling_line > 0 && !scene.softening)
    throw InputError({path, file.falling_line, ""},
                     "the tension falls with strain here (below the point before); if the fabric is meant to soften, "
                     "set softening = true under [fabric] in the scene");
  return file;
}

// The fabric's mass per area as its material files state it (one of them, or both alike), or
// as the scene does (fabric.areal_mass_g_m2), when it must agree with the files; none when
// nothing says.
std::optional<GivenValue> areal_mass(const Scene& scene, const MaterialFile& warp, const MaterialFile& weft) {
  const auto& a = warp.areal_density_kg_m2;
  const auto& b = weft.areal_density_kg_m2;
  // The same fabric written twice: the same decimal text reads as the same double.
  if (a && b && *a != *b) {
    char text[320];
    std::snprintf(text, sizeof text, "areal_density_kg_m2 %.17g differs from %.17g in the warp file %s",
                  *b, *a, scene.warp_path.c_str());
    throw InputError({scene.weft_path, weft.areal_density_line, ""}, text);
  }
  std::optional<GivenValue> files;
  if (a) files = GivenValue{*a, {scene.warp_path, warp.areal_density_line, ""}};
  else if (b) files = GivenValue{*b, {scene.weft_path, weft.areal_density_line, ""}};
  if (!scene.areal_mass_kg_m2) return files;
  // g/m² and kg/m² written for the same fabric differ by the decimal conversion's rounding only.
  if (files && std::abs(files->value - *scene.areal_mass_kg_m2) > 1e-9 * files->value) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "%.6g g/m² differs from the material file's %.6g g/m² (%s line %d: areal_density_kg_m2 %.6g): "
                  "give the fabric's mass in one place",
                  *scene.areal_mass_kg_m2 * 1e3, files->value * 1e3, files->where.file.c_str(), files->where.line,
                  files->value);
    throw InputError(scene.areal_mass_where, text);
  }
  return GivenValue{*scene.areal_mass_kg_m2, scene.areal_mass_where};
}

// Gravity needs something to hang from: a node held in z, or a body to rest on.
void require_support(const Scene& scene, const Model& model) {
  if (!model.bodies.empty()) return;
  for (const AxisMask lock : model.locks)
    if (lock & kLockZ) return;
  throw InputError(scene.gravity.where,
                   "gravity with nothing to hold the fabric up: no node is held in z and the scene has no body");
}

// The mass is the model's when gravity weighs it or the scene gives it; dynamic then moves it.
void add_mass(const Scene& scene, const std::optional<GivenValue>& mass, Model* model) {
  if (mass && (scene.gravity.on || scene.areal_mass_kg_m2)) model->areal_density_kg_m2 = mass->value;
  if (!scene.gravity.on) return;
  require_support(scene, *model);
  if (!mass)
    throw InputError(scene.gravity.where,
                     "gravity needs the fabric's mass per area: give fabric.areal_mass_g_m2, or an "
                     "'areal_density_kg_m2,VALUE' line in a material file (" + scene.warp_path + ", " +
                         scene.weft_path + ")");
  model->terms.push_back(std::make_shared<Gravity>(model->fabric, mass->value, scene.gravity.acceleration_m_s2));
}

RigidBody body_of(const BodySpec& spec, TriangleMesh placed) {
  try {
    RigidBody body(spec.name, std::move(placed), spec.friction);
    if (spec.wrap_edges_deg > 0.0) body.wrap_edges_sharper_than(spec.wrap_edges_deg);
    return body;
  } catch (const std::invalid_argument& error) {
    throw InputError({spec.mesh_path, 0, ""}, error.what());
  }
}

RigidBody build_body(const BodySpec& spec, std::vector<std::string>* warnings) {
  require_file(spec.mesh_path, spec.mesh_where, "mesh");
  std::vector<std::string> read;
  TriangleMesh mesh = place(read_mesh(spec.mesh_path, &read), spec.placement);
  for (const std::string& w : read) warnings->push_back(spec.mesh_path + ": " + w);
  if (!within_range(mesh.vertices))
    throw InputError(spec.where, "the placed mesh reaches beyond 1e6 m: check units, scale and translation");
  return body_of(spec, std::move(mesh));
}

// The scene's bodies, read from their files (their warnings added), or, given a model of the
// same scene, from its meshes as placed (whose warnings that model holds).
std::vector<RigidBody> build_bodies(const Scene& scene, const Model* placed_from, std::vector<std::string>* warnings) {
  std::vector<RigidBody> bodies;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    bodies.push_back(placed_from ? body_of(scene.bodies[b], placed_from->bodies[b].mesh())
                                 : build_body(scene.bodies[b], warnings));
  return bodies;
}

// A turn is about the placed mesh's bounding box's centre unless the scene names a pivot.
std::vector<ToolPath> build_paths(const Scene& scene, const std::vector<RigidBody>& bodies) {
  std::vector<ToolPath> paths;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    ToolPath path = scene.bodies[b].path;
    if (!scene.bodies[b].pivot_given) path.pivot_m = 0.5 * (bodies[b].box().min + bodies[b].box().max);
    paths.push_back(path);
  }
  return paths;
}

Fabric build_fabric(const Scene& scene) {
  try {
    return Fabric(scene.fabric);
  } catch (const std::invalid_argument& error) {
    throw InputError(scene.fabric_where, error.what());
  }
}

std::string fabric_name(const Fabric& fabric) {
  if (fabric.spec().tube != FabricSpec::Tube::none)
    return "tube of " + std::to_string(fabric.nodes_warp()) + " x " + std::to_string(fabric.nodes_weft()) + " grid";
  if (fabric.spec().shape == FabricSpec::Shape::rectangle)
    return std::to_string(fabric.nodes_warp()) + " x " + std::to_string(fabric.nodes_weft()) + " grid";
  if (fabric.spec().shape == FabricSpec::Shape::panels)
    return std::to_string(fabric.panels().size()) + " panel(s) of " + std::to_string(fabric.node_count()) + " nodes";
  return std::string(to_string(fabric.spec().mesh)) + " circle of " + std::to_string(fabric.node_count()) +
         " nodes (a circle has no edges or corners)";
}

std::vector<AxisMask> build_locks(const Scene& scene, const Fabric& fabric) {
  std::vector<AxisMask> locks(static_cast<std::size_t>(fabric.node_count()), 0);
  for (const ConstraintSpec& c : scene.constraints) {
    const std::vector<int> nodes = select_nodes(fabric, c.nodes);
    if (nodes.empty())
      throw InputError(c.where, "node set " + c.nodes_text + " selects no node of the " + fabric_name(fabric));
    for (const int k : nodes) {
      auto& lock = locks[static_cast<std::size_t>(k)];
      lock = static_cast<AxisMask>(lock | c.axes);
    }
  }
  return locks;
}

std::vector<Eigen::Vector3d> build_start(const Scene& scene, const Fabric& fabric) {
  std::vector<Eigen::Vector3d> start = initial_positions(fabric, scene.origin_m, scene.initial);
  if (!within_range(start))
    throw InputError(scene.initial_where, "the fabric starts beyond 1e6 m: check origin_m and the initial shape");
  return start;
}

// An outward-oriented closed mesh encloses a positive volume; a negative one means the faces
// point inward, which makes everything outside look inside.
std::string orientation_hint(const RigidBody& body) {
  return body.signed_volume() < 0.0
             ? "; the mesh's faces point inward (negative enclosed volume): flip its orientation"
             : "; the initial shape must clear it";
}

// The first of `count` items (in order) for which `fails` holds, or -1; the items are tried in
// parallel, so the answer is the serial loop's whatever the thread count.
template <class Fails>
int first_failing(int count, const Fails& fails) {
  std::vector<unsigned char> failed(static_cast<std::size_t>(count), 0);
#pragma omp parallel for schedule(dynamic, 256) if (count >= kMinParallelItems)
  for (int i = 0; i < count; ++i) failed[static_cast<std::size_t>(i)] = fails(i) ? 1 : 0;
  const auto first = std::find(failed.begin(), failed.end(), 1);
  return first == failed.end() ? -1 : static_cast<int>(first - failed.begin());
}

// How deep each node starts inside body `body`: 0 on its surface, negative outside it (−∞
// where that is known without asking how far).
std::vector<double> start_depths(const Model& model, int body) {
  std::vector<double> depth(model.start.size());
  for_each_nearby(model.node_count(), model.bodies, [&](int k, NearbyQueries& queries) {
    const auto i = static_cast<std::size_t>(k);
    depth[i] = queries.surely_outside(body, model.start[i], 0.0)
                   ? -std::numeric_limits<double>::infinity()
                   : -queries.closest(body, model.start[i]).signed_distance;
  });
  return depth;
}

// Seed 003 starts from a deformation with "no contact or intersection" with the body.
void check_clear_start(const Scene& scene, const Model& model) {
  const auto at = [&](int k) -> const Eigen::Vector3d& { return model.start[static_cast<std::size_t>(k)]; };
  const std::vector<Spring>& springs = model.fabric.springs();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const RigidBody& body = model.bodies[b];
    const std::vector<double> depths = start_depths(model, static_cast<int>(b));
    const auto inside = std::find_if(depths.begin(), depths.end(), [](double d) { return d >= 0.0; });
    if (inside != depths.end()) {
      char depth[64];
      std::snprintf(depth, sizeof depth, "%.3g", *inside);
      const std::string node = model.fabric.node_name(static_cast<int>(inside - depths.begin()));
      throw InputError(scene.initial_where, node + " starts inside body '" + body.name() + "' (" + depth + " m deep)" +
                                                orientation_hint(body));
    }
    const int through = first_failing(static_cast<int>(springs.size()), [&](int s) {
      const Spring& spring = springs[static_cast<std::size_t>(s)];
      return body.segment_crosses(at(spring.a), at(spring.b));
    });
    if (through >= 0) {
      const Spring& spring = springs[static_cast<std::size_t>(through)];
      throw InputError(scene.initial_where, "the spring from " + model.fabric.node_name(spring.a) + " to " +
                                                model.fabric.node_name(spring.b) + " passes through body '" +
                                                body.name() + "'; the initial shape must clear it");
    }
  }
}

// Seed 004's shear springs follow the fabric's bias response, read like a warp or weft table;
// the fabric has them, so the model has their term. From a measured shear rigidity G they are
// linear both ways with k = 2·G: a cell sheared by γ stretches one diagonal by γ/2 and shortens
// the other as much, and the two, each standing for the cell's area A, store
// 2·A·k·(γ/2)²/2 = A·G·γ²/2, the continuum's shear energy. KES-FB1's 2HG adds the cells' friction.
void add_shear(const Scene& scene, Model* model) {
  if (!scene.shear.on) return;
  if (scene.shear.rigidity_N_m > 0.0) {
    const double k = 2.0 * scene.shear.rigidity_N_m;
    model->shear = TensionTable({{-1.0, -k}, {0.0, 0.0}, {1.0, k}}, "shear rigidity");
  } else {
    model->shear = read_material(scene, scene.shear.material_path, scene.shear.material_where).table;
  }
  if (scene.shear.hysteresis_N_m > 0.0)
    model->terms.push_back(std::make_shared<ShearFriction>(scene.shear.hysteresis_N_m, scene.shear.hysteresis_rounding_rad));
}

// A cantilever's bending length c gives the rigidity B = m·g₀·c³ (BS 3356, ASTM D1388: the
// strip's own weight m·g₀ per area bends it to the standard's angle), g₀ the standard gravity
// the test was made under.
Eigen::Vector2d hinge_rigidity(const Scene& scene, const std::optional<GivenValue>& mass) {
  const BendingSpec& b = scene.bending;
  if (b.bending_length_m.maxCoeff() <= 0.0) return b.rigidity_Nm;
  if (!mass)
    throw InputError(b.value_where, "a bending length gives the rigidity only with the fabric's mass (B = m·g·c³): "
                                    "give fabric.areal_mass_g_m2, or an 'areal_density_kg_m2,VALUE' line in a "
                                    "material file");
  return mass->value * kStandardGravity_m_s2 * b.bending_length_m.array().cube().matrix();
}

// Bending: hinges with the fabric's flexural rigidity, or seed 004's bend springs (the fabric
// has them, so the model has their term), which resist the shortening a fold brings as much as
// stretching: a table linear through zero in both directions, T = k·ε per width. Returns the
// hinges' rigidities along warp and weft (zero without hinges).
Eigen::Vector2d add_bending(const Scene& scene, const std::optional<GivenValue>& mass, Model* model) {
  if (!scene.bending.on) return Eigen::Vector2d::Zero();
  if (scene.bending.hinges()) {
    const Eigen::Vector2d rigidity = hinge_rigidity(scene, mass);
    model->terms.push_back(std::make_shared<HingeBending>(rigidity.x(), rigidity.y()));
    const BendingSpec& b = scene.bending;
    if (b.hysteresis_N.maxCoeff() > 0.0)
      model->terms.push_back(
          std::make_shared<HingeFriction>(b.hysteresis_N.x(), b.hysteresis_N.y(), b.hysteresis_rounding_per_m));
    return rigidity;
  }
  const double k = scene.bending.stiffness_N_m;
  model->bend = TensionTable({{-1.0, -k}, {0.0, 0.0}, {1.0, k}}, "bending");
  return Eigen::Vector2d::Zero();
}

// A tester's clamp holds the specimen's centre between two discs: every node within its radius
// is held where it starts, in x, y and z.
void add_drape_clamp(const Scene& scene, Model* model) {
  const DrapeSpec& d = scene.drape;
  if (!d.on || d.clamp_radius_m <= 0.0) return;
  NodeSetSpec disc;
  disc.kind = NodeSetSpec::Kind::disc;
  disc.point = Eigen::Vector2d::Constant(scene.fabric.radius_m());
  disc.width_m = d.clamp_radius_m;
  const std::vector<int> nodes = select_nodes(model->fabric, disc);
  if (nodes.empty())
    throw InputError(d.clamp_where, "the clamp holds no node of the " + fabric_name(model->fabric) + ": refine the mesh");
  for (const int k : nodes) model->locks[static_cast<std::size_t>(k)] = kLockX | kLockY | kLockZ;
}

// A table's small-strain slope (N/m): of the first segment that carries tension.
double small_strain_slope(const TensionTable& table) {
  for (const TablePoint& p : table.points())
    if (p.strain > 0.0 && table.tension(p.strain) > 0.0) return table.tension(p.strain) / p.strain;
  return 0.0;
}

// What the plausibility check reads: each property as the model uses it, and where it was given.
FabricValues fabric_values(const Scene& scene, const Model& model, const std::optional<GivenValue>& mass,
                           const Eigen::Vector2d& rigidity) {
  FabricValues v;
  if (mass && (scene.gravity.on || scene.areal_mass_kg_m2)) v.areal_mass_kg_m2 = mass;
  if (rigidity.maxCoeff() > 0.0) {
    v.rigidity_warp_Nm = GivenValue{rigidity.x(), scene.bending.value_where};
    v.rigidity_weft_Nm = GivenValue{rigidity.y(), scene.bending.value_where};
  }
  if (const double k = small_strain_slope(model.warp); k > 0.0) v.tensile_warp_N_m = GivenValue{k, {scene.warp_path, 0, ""}};
  if (const double k = small_strain_slope(model.weft); k > 0.0) v.tensile_weft_N_m = GivenValue{k, {scene.weft_path, 0, ""}};
  if (scene.shear.rigidity_N_m > 0.0) {
    v.shear_rigidity_N_m = GivenValue{scene.shear.rigidity_N_m, scene.shear.rigidity_where};
  } else if (model.shear) {
    // A tension-only diagonal stretched by γ/2 stands for the cell alone: G = k/4; both
    // diagonals carrying: G = k/2 (add_shear, add_compression).
    const double k = small_strain_slope(*model.shear);
    const bool both_ways = !model.shear->tension_only() || model.shear->compression() != Compression::none;
    if (k > 0.0) v.shear_rigidity_N_m = GivenValue{both_ways ? k / 2 : k / 4, {scene.shear.material_path, 0, ""}};
  }
  // A direction given 2HB = 0 has no friction to check.
  const Eigen::Vector2d& hb = scene.bending.hysteresis_N;
  if (hb.x() > 0.0) v.bending_hysteresis_warp_N = GivenValue{hb.x(), scene.bending.hysteresis_where};
  if (hb.y() > 0.0) v.bending_hysteresis_weft_N = GivenValue{hb.y(), scene.bending.hysteresis_where};
  if (scene.shear.hysteresis_N_m > 0.0)
    v.shear_hysteresis_N_m = GivenValue{scene.shear.hysteresis_N_m, scene.shear.hysteresis_where};
  return v;
}

// [fabric] compression: what the in-plane springs' tension-only tables give below zero strain
// (compression_response.hpp). A buckling spring bows along its own length, so the warp's take
// the warp's flexural rigidity, the weft's the weft's and the diagonals' their mean (the hinges'
// B_warp·cos²ψ + B_weft·sin²ψ at ψ = 45°). A tension-only shear table stands for the cell through
// its stretched diagonal alone (k_d = 4·G); once the compressed diagonal pushes back as well, each
// carries half the table: the same G in pure shear, and a cell squeezed along its bias resists it
// (with slack diagonals only the warp and weft did, at half their strain, and a drape gathered at
// the four bias directions whatever the fabric).
void add_compression(const Scene& scene, const Eigen::Vector2d& rigidity, Model* model) {
  if (scene.compression == Compression::none) return;
  if (scene.compression == Compression::buckling && !(rigidity.minCoeff() > 0.0))
    throw InputError(scene.compression_where, "buckling needs the fabric's flexural rigidity: give it in [bending] "
                                              "(rigidity_uNm, rigidity_Nm or bending_length_cm, the hinges')");
  model->warp.set_compression(scene.compression, rigidity.x());
  model->weft.set_compression(scene.compression, rigidity.y());
  if (model->shear && model->shear->tension_only()) {
    model->shear = model->shear->scaled(0.5);
    model->shear->set_compression(scene.compression, rigidity.mean());
  }
}

// The blank holder grips its nodes in z (locks) and resists their draw-in by friction; its creep
// length is the one newton gives friction on bodies.
void add_clamp(const Scene& scene, Model* model) {
  if (!scene.clamp.on) return;
  const ClampSpec& c = scene.clamp;
  std::vector<int> nodes = select_nodes(model->fabric, c.nodes);
  if (nodes.empty())
    throw InputError(c.where, "the clamp's region (" + c.nodes_text + ") selects no node of the " + fabric_name(model->fabric));
  for (const int k : nodes) {
    auto& lock = model->locks[static_cast<std::size_t>(k)];
    lock = static_cast<AxisMask>(lock | kLockZ);
  }
  const ClampOptions options{c.force_N, c.friction, friction_creep_m(model->fabric, scene.solver.newton.friction_creep)};
  model->terms.push_back(std::make_shared<ClampFrame>(model->fabric, std::move(nodes), options, model->start));
}

// The pressure's potential is the follower load inside the fabric (pressure.hpp); on its edge
// the gradient differs from it by (x_k − o) × (the edge's chord at k) / 6, which a held node
// does not feel, and which points along z, where a clamped rim is held, when the rim and the
// reference point o lie in one horizontal plane. So the edge must be held in z, and where it
// may draw in (not held in x and y), it must start in one horizontal plane, o its centroid.
Eigen::Vector3d pressure_reference(const Scene& scene, const Model& model) {
  const AxisMask all = kLockX | kLockY | kLockZ;
  Eigen::Vector3d rim = Eigen::Vector3d::Zero();
  int count = 0, first_rim = -1;
  bool draws_in = false;
  for (int k = 0; k < model.node_count(); ++k) {
    if (!model.fabric.on_perimeter(k)) continue;
    const AxisMask lock = model.locks[static_cast<std::size_t>(k)];
    if (!(lock & kLockZ))
      throw InputError(scene.pressure.where, "a pressure needs the fabric's edge held in z (a clamped blank): " +
                                                 model.fabric.node_name(k) + " is not");
    draws_in = draws_in || lock != all;
    if (first_rim < 0) first_rim = k;
    rim += model.start[static_cast<std::size_t>(k)], ++count;
  }
  if (!draws_in) {  // a held edge: o the fabric's centroid, as before the edge could draw in
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : model.start) centre += p;
    return centre / static_cast<double>(model.node_count());
  }
  rim /= static_cast<double>(count);
  rim.z() = model.start[static_cast<std::size_t>(first_rim)].z();  // exactly the plane, not a mean's rounding
  for (int k = 0; k < model.node_count(); ++k)
    if (model.fabric.on_perimeter(k) && model.start[static_cast<std::size_t>(k)].z() != rim.z())
      throw InputError(scene.pressure.where, "a pressure on a blank whose edge draws in needs the edge to start in one "
                                             "horizontal plane: " + model.fabric.node_name(k) + " does not");
  return rim;
}

void add_edge_contact(const Scene& scene, Model* model) {
  std::vector<double> angles;
  for (const BodySpec& body : scene.bodies) angles.push_back(body.edge_contact_deg);
  if (std::none_of(angles.begin(), angles.end(), [](double a) { return a > 0.0; })) return;
  const double stiffness = EdgeContact::default_stiffness(*model);
  if (!(stiffness > 0.0))
    throw InputError(scene.warp_where, "edge contact needs the fabric's stiffness at rest, and its warp and weft "
                                       "tables start slack");
  model->terms.push_back(std::make_shared<EdgeContact>(*model, angles, stiffness));
}

void add_spring_contact(const Scene& scene, Model* model) {
  std::vector<int> bodies;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b)
    if (scene.bodies[b].spring_contact) bodies.push_back(static_cast<int>(b));
  if (bodies.empty()) return;
  const double stiffness = SpringContact::default_stiffness(*model);
  if (!(stiffness > 0.0))
    throw InputError(scene.warp_where, "spring contact needs the fabric's stiffness at rest, and its warp and weft "
                                       "tables start slack");
  model->terms.push_back(std::make_shared<SpringContact>(*model, bodies, stiffness));
}

void add_pressure(const Scene& scene, Model* model) {
  if (!scene.pressure.on) return;
  const Eigen::Vector3d reference = pressure_reference(scene, *model);
  model->terms.push_back(std::make_shared<PressureLoad>(model->fabric, scene.pressure.pressure_Pa, reference));
}

void add_wind(const Scene& scene, Model* model) {
  if (!scene.wind.on) return;
  model->terms.push_back(std::make_shared<WindLoad>(Wind{scene.wind.velocity_m_s, scene.wind.coefficient_N_s_m3}));
}

// A tube's seam: its two edges across the round direction, node for node.
std::optional<Seam> tube_seam(const Scene& scene, const Fabric& fabric) {
  const FabricSpec::Tube tube = scene.fabric.tube;
  if (tube == FabricSpec::Tube::none) return std::nullopt;
  const bool round_warp = tube == FabricSpec::Tube::warp_round;
  NodeSetSpec first, second;
  first.kind = round_warp ? NodeSetSpec::Kind::edge_left : NodeSetSpec::Kind::edge_bottom;
  second.kind = round_warp ? NodeSetSpec::Kind::edge_right : NodeSetSpec::Kind::edge_top;
  return Seam{"tube", stitches_by_arc_length(fabric, select_nodes(fabric, first), select_nodes(fabric, second)),
              round_warp ? scene.fabric.height_m : scene.fabric.width_m};
}

// A garment's seam: two panel edges, the second from its end unless sewn the same way.
Seam panel_seam(const SeamSpec& spec, const Fabric& fabric) {
  const auto chain = [&](int side) {
    return fabric.panels()[static_cast<std::size_t>(spec.panel[static_cast<std::size_t>(side)])]
        .edge_nodes[static_cast<std::size_t>(spec.edge[static_cast<std::size_t>(side)])];
  };
  std::vector<int> first = chain(0), second = chain(1);
  if (!spec.same_direction) std::reverse(second.begin(), second.end());
  return Seam{spec.name, stitches_by_arc_length(fabric, first, second), chain_length(fabric, first)};
}

// Seed 003's F_seams: a tube's seam or a garment's, one term for them all.
void add_seams(const Scene& scene, Model* model) {
  std::vector<Seam> seams;
  if (std::optional<Seam> tube = tube_seam(scene, model->fabric)) seams.push_back(std::move(*tube));
  for (const SeamSpec& spec : scene.seams) seams.push_back(panel_seam(spec, model->fabric));
  if (seams.empty()) return;
  model->terms.push_back(std::make_shared<SeamTerm>(std::move(seams), seam_stiffness_N_m2(*model), model->node_count()));
}

// Fabric–fabric contact, after the seams: nodes sewn together are one point to it.
void add_self_contact(const Scene& scene, Model* model) {
  if (!scene.self_contact.on) return;
  model->terms.push_back(std::make_shared<SelfContact>(model->fabric, sewn_representatives(*model),
                                                       scene.self_contact.thickness_m,
                                                       self_contact_stiffness_N_m(*model)));
}

// A drape test's support must lie under the specimen: every point of the named body, seen from
// above, within the placed circle.
void check_drape_support(const Scene& scene, const Model& model) {
  if (!scene.drape.on || scene.drape.support.empty()) return;
  const auto body = std::find_if(model.bodies.begin(), model.bodies.end(),
                                 [&](const RigidBody& b) { return b.name() == scene.drape.support; });
  if (body == model.bodies.end())
    throw InputError(scene.drape.support_where, "no body named '" + scene.drape.support + "' in the scene");
  const double radius = scene.fabric.radius_m();
  const Eigen::Vector2d centre = scene.origin_m.head<2>() + Eigen::Vector2d(radius, radius);
  double reach = 0.0;
  for (const Eigen::Vector3d& v : body->mesh().vertices) reach = std::max(reach, (v.head<2>() - centre).norm());
  if (reach >= radius) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "the %.4g m circle does not cover body '%s': the body reaches %.4g m from the circle's "
                  "centre, the circle %.4g m",
                  2 * radius, body->name().c_str(), reach, radius);
    throw InputError(scene.drape.support_where, text);
  }
}

}  // namespace

Scene with_tolerance_in_newtons(Scene scene, const Model& model) {
  if (scene.solver.tolerance_relative <= 0.0) return scene;
  const double scale = spring_force_scale_N(model);
  if (!(scale > 0.0))
    throw InputError(scene.tolerance_where, "the fabric's warp and weft tables start slack (no tension just above "
                                            "zero strain): a tolerance relative to their force scale means nothing; "
                                            "give tolerance_N");
  scene.solver.set_tolerance_N(scene.solver.tolerance_relative * scale);
  return scene;
}

Model build_model(const Scene& scene) { return build_model(scene, nullptr); }

Model build_model(const Scene& scene, const Model* placed_from) {
  check_memory_budget(scene);
  Fabric fabric = build_fabric(scene);
  const MaterialFile warp = read_material(scene, scene.warp_path, scene.warp_where);
  const MaterialFile weft = read_material(scene, scene.weft_path, scene.weft_where);
  std::vector<std::string> read_warnings;
  Model model{fabric, warp.table, weft.table, build_locks(scene, fabric), build_bodies(scene, placed_from, &read_warnings),
              build_start(scene, fabric)};
  model.read_warnings = std::move(read_warnings);
  model.paths = build_paths(scene, model.bodies);
  add_drape_clamp(scene, &model);
  const std::optional<GivenValue> mass = areal_mass(scene, warp, weft);
  add_shear(scene, &model);
  const Eigen::Vector2d rigidity = add_bending(scene, mass, &model);
  add_compression(scene, rigidity, &model);
  add_mass(scene, mass, &model);
  add_wind(scene, &model);
  add_clamp(scene, &model);
  perturb_start(scene.perturbation, model.locks, &model.start);  // after every lock is known
  add_pressure(scene, &model);
  add_edge_contact(scene, &model);
  add_spring_contact(scene, &model);
  add_seams(scene, &model);
  add_self_contact(scene, &model);
  check_drape_support(scene, model);
  check_clear_start(scene, model);
  for (std::string& w : plausibility_warnings(fabric_values(scene, model, mass, rigidity)))
    model.read_warnings.push_back(std::move(w));
  return model;
}

}  // namespace fabform
