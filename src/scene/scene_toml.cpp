#include "fabform/scene/scene_toml.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/scene_overrides.hpp"
#include "scene/toml_table_reader.hpp"

namespace fabform {
namespace {

namespace fs = std::filesystem;

std::string resolve(const std::string& scene_path, const std::string& path) {
  if (path.empty() || fs::path(path).is_absolute()) return path;
  return (fs::path(scene_path).parent_path() / path).lexically_normal().string();
}

int checked_int(TableReader& r, const std::string& key, long long value, long long lo, long long hi) {
  if (value < lo || value > hi)
    r.fail(key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi));
  return static_cast<int>(value);
}

void read_fabric(TableReader r, Scene* scene) {
  const Eigen::Vector2d size = r.vector<2>("size_m", Eigen::Vector2d::Zero(), true);
  if (!(size.array() > 0.0).all()) r.fail("size_m", "both sides must be positive");
  const auto [n, m] = r.integer_pair("divisions", true);
  scene->grid = {size.x(), size.y(), checked_int(r, "divisions", n, 1, 10000),
                 checked_int(r, "divisions", m, 1, 10000)};
  scene->grid_where = r.locate_key("divisions");
  scene->origin_m = r.vector<3>("origin_m", Eigen::Vector3d::Zero());
  scene->warp_path = resolve(scene->path, r.text("warp", "", true));
  scene->warp_where = r.locate_key("warp");
  scene->weft_path = resolve(scene->path, r.text("weft", "", true));
  scene->weft_where = r.locate_key("weft");
  r.reject_unknown({"size_m", "divisions", "origin_m", "warp", "weft"});
}

BodySpec read_body(TableReader r, const std::string& scene_path, std::size_t index) {
  BodySpec body;
  body.where = r.where();
  body.name = r.text("name", "body" + std::to_string(index));
  body.mesh_path = resolve(scene_path, r.text("mesh", "", true));
  body.mesh_where = r.locate_key("mesh");
  body.units = r.text("units", "", true);
  if (!parse_length_unit(body.units, &body.placement.metres_per_unit))
    r.fail("units", "must be one of m, cm, mm, in (got '" + body.units + "')");
  body.placement.scale = r.number("scale", 1.0);
  body.placement.rotation_deg = r.vector<3>("rotation_deg", Eigen::Vector3d::Zero());
  body.placement.translation_m = r.vector<3>("translation_m", Eigen::Vector3d::Zero());
  std::string field;
  if (const std::string why = body.placement.invalid_reason(&field); !why.empty()) r.fail(field, why);
  r.reject_unknown({"name", "mesh", "units", "scale", "rotation_deg", "translation_m"});
  return body;
}

NodeSetSpec read_selector(TableReader& r, std::string* text) {
  static const std::vector<std::string> selectors = {"nodes", "node", "nearest_m", "box_m"};
  int given = 0;
  for (const auto& s : selectors) given += r.has(s) ? 1 : 0;
  if (given != 1) r.fail("nodes", "give exactly one of nodes, node, nearest_m, box_m");
  NodeSetSpec spec;
  if (r.has("nodes")) {
    *text = r.text("nodes", "");
    if (!parse_named_node_set(*text, &spec))
      r.fail("nodes", "unknown node set '" + *text +
                          "' (known: perimeter, corners, edge:left, edge:right, edge:bottom, "
                          "edge:top)");
  } else if (r.has("node")) {
    const auto [i, j] = r.integer_pair("node", true);
    spec.kind = NodeSetSpec::Kind::index;
    spec.i = checked_int(r, "node", i, 0, 100000);
    spec.j = checked_int(r, "node", j, 0, 100000);
    *text = "node [" + std::to_string(i) + ", " + std::to_string(j) + "]";
  } else if (r.has("nearest_m")) {
    spec.kind = NodeSetSpec::Kind::nearest;
    spec.point = r.vector<2>("nearest_m", Eigen::Vector2d::Zero(), true);
    *text = "nearest_m";
  } else {
    const toml::node* n = r.take("box_m");
    const toml::array* corners = n->as_array();
    if (!corners || corners->size() != 2) r.fail("box_m", "must be [[x0, y0], [x1, y1]]");
    spec.kind = NodeSetSpec::Kind::box;
    spec.box_min = r.read_vector<2>((*corners)[0], "box_m");
    spec.box_max = r.read_vector<2>((*corners)[1], "box_m");
    *text = "box_m";
  }
  return spec;
}

ConstraintSpec read_constraint(TableReader r) {
  ConstraintSpec constraint;
  constraint.where = r.where();
  constraint.nodes = read_selector(r, &constraint.nodes_text);
  const std::string axes = r.text("axes", "xyz");
  if (!parse_axes(axes, &constraint.axes))
    r.fail("axes", "must name each of x, y, z at most once, e.g. \"xyz\" or \"xy\"");
  r.reject_unknown({"nodes", "node", "nearest_m", "box_m", "axes"});
  return constraint;
}

void read_initial(TableReader r, Scene* scene) {
  scene->initial_where = r.where();
  const std::string shape = r.text("shape", "flat");
  if (!parse_initial_kind(shape, &scene->initial.kind))
    r.fail("shape", "must be one of flat, lift, bump, wrap (got '" + shape + "')");
  using Kind = InitialShape::Kind;
  InitialShape& s = scene->initial;
  const bool raises = s.kind == Kind::lift || s.kind == Kind::bump;
  s.height_m = r.number("height_m", 0.0, raises);
  if (s.kind == Kind::wrap) {
    s.axis_xy_m = r.vector<2>("axis_m", Eigen::Vector2d::Zero(), true);
    s.radius_m = r.number("radius_m", 0.0, true);
    s.facing_deg = r.number("facing_deg", 0.0, true);
    s.span_deg = r.number("span_deg", 0.0, true);
  }
  std::string field;
  if (const std::string why = s.invalid_reason(&field); !why.empty()) r.fail(field, why);
  r.reject_unknown({"shape", "height_m", "axis_m", "radius_m", "facing_deg", "span_deg"});
}

// tolerance_N and max_iterations are every solver's; the other keys belong to one solver each
// and are validated whichever solver runs, so a scene stays valid when --solver switches it.
void read_solver(TableReader r, Scene* scene) {
  SolverSpec& s = scene->solver;
  s.name = r.text("name", "relax");
  bool known = false;
  for (const auto& name : solver_names()) known = known || name == s.name;
  if (!known) r.fail("name", "unknown solver '" + s.name + "' (see `fabform solvers`)");
  s.relax.tolerance_N = s.newton.tolerance_N = s.dynamic.tolerance_N =
      r.number("tolerance_N", s.relax.tolerance_N);
  if (r.has("max_iterations"))
    s.relax.max_iterations = s.newton.max_iterations = s.dynamic.max_iterations = checked_int(
        r, "max_iterations", r.integer("max_iterations", 0), 0, 1'000'000'000);
  s.relax.C = r.number("C", s.relax.C);
  s.newton.regularization = r.number("regularization", s.newton.regularization);
  s.newton.armijo = r.number("armijo", s.newton.armijo);
  s.newton.max_backtracks = checked_int(
      r, "max_backtracks", r.integer("max_backtracks", s.newton.max_backtracks), 1, 200);
  s.dynamic.areal_density_kg_m2 = r.number("areal_density_kg_m2", s.dynamic.areal_density_kg_m2);
  if (r.has("damping")) s.dynamic.damping = r.number("damping", 0.0);
  s.dynamic.time_step_fraction = r.number("time_step_fraction", s.dynamic.time_step_fraction);
  s.dynamic.stretch_limit = r.number("stretch_limit", s.dynamic.stretch_limit);
  s.threads = checked_int(r, "threads", r.integer("threads", 1), 1, 1024);
  std::string field;
  if (const std::string why = s.relax.invalid_reason(&field); !why.empty()) r.fail(field, why);
  if (const std::string why = s.newton.invalid_reason(&field); !why.empty()) r.fail(field, why);
  if (const std::string why = s.dynamic.invalid_reason(&field); !why.empty()) r.fail(field, why);
  r.reject_unknown({"name", "tolerance_N", "max_iterations", "C", "regularization", "armijo",
                    "max_backtracks", "areal_density_kg_m2", "damping", "time_step_fraction",
                    "stretch_limit", "threads"});
}

void read_output(TableReader r, Scene* scene) {
  const std::string dir = r.text("dir", "");
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

Scene read_scene(const toml::table& root, const std::string& path,
                 const OverriddenKeys& overridden) {
  Scene scene;
  scene.path = path;
  TableReader r(&root, "", path, overridden);
  TableReader info = r.table("scene", false);
  scene.name = info.text("name", fs::path(path).stem().string());
  scene.description = info.text("description", "");
  info.reject_unknown({"name", "description"});
  read_fabric(r.table("fabric", true), &scene);
  const auto bodies = r.tables("body");
  for (std::size_t b = 0; b < bodies.size(); ++b) scene.bodies.push_back(read_body(bodies[b], path, b));
  for (auto& c : r.tables("constraint")) scene.constraints.push_back(read_constraint(c));
  read_initial(r.table("initial", false), &scene);
  read_solver(r.table("solver", false), &scene);
  read_output(r.table("output", false), &scene);
  r.reject_unknown({"scene", "fabric", "body", "constraint", "initial", "solver", "output"});
  return scene;
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& path,
                  const std::vector<SceneOverride>& overrides) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& error) {
    throw InputError({path, static_cast<int>(error.source().begin.line), ""},
                     std::string(error.description()));
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
