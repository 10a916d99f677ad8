#include "fabform/scene/model_builder.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "fabform/io/mesh_reader.hpp"
#include "fabform/material/material_csv.hpp"

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

MaterialFile read_material(const std::string& path, const SourceLocation& where) {
  require_file(path, where, "material table");
  return read_material_file(path);
}

// The fabric's mass per area, as its material files state it: one of them, or both alike.
double areal_density(const Scene& scene, const MaterialFile& warp, const MaterialFile& weft) {
  const auto& a = warp.areal_density_kg_m2;
  const auto& b = weft.areal_density_kg_m2;
  if (!a && !b)
    throw InputError(scene.gravity.where,
                     "gravity needs the fabric's mass per area: neither material file (" +
                         scene.warp_path + ", " + scene.weft_path +
                         ") has an 'areal_density_kg_m2,VALUE' line");
  // The same fabric written twice: the same decimal text reads as the same double.
  if (a && b && *a != *b) {
    char text[320];
    std::snprintf(text, sizeof text, "areal_density_kg_m2 %.17g differs from %.17g in the warp file %s",
                  *b, *a, scene.warp_path.c_str());
    throw InputError({scene.weft_path, weft.areal_density_line, ""}, text);
  }
  return a ? *a : *b;
}

// Gravity needs something to hang from: a node held in z, or a body to rest on.
void require_support(const Scene& scene, const Model& model) {
  if (!model.bodies.empty()) return;
  for (const AxisMask lock : model.locks)
    if (lock & kLockZ) return;
  throw InputError(scene.gravity.where,
                   "gravity with nothing to hold the fabric up: no node is held in z and the scene has no body");
}

std::string gravity_term(double density_kg_m2, double acceleration_m_s2) {
  char text[160];
  std::snprintf(text, sizeof text,
                "gravity: %.6g m/s² along -z on an areal density of %.6g kg/m² (material files)",
                acceleration_m_s2, density_kg_m2);
  return text;
}

void add_gravity(const Scene& scene, const MaterialFile& warp, const MaterialFile& weft, Model* model) {
  if (!scene.gravity.on) return;
  require_support(scene, *model);
  const double density = areal_density(scene, warp, weft);
  model->loads = gravity_loads(model->grid, density, scene.gravity.acceleration_m_s2);
  model->modelled.push_back(gravity_term(density, scene.gravity.acceleration_m_s2));
}

RigidBody build_body(const BodySpec& spec) {
  require_file(spec.mesh_path, spec.mesh_where, "mesh");
  TriangleMesh mesh = place(read_mesh(spec.mesh_path), spec.placement);
  if (!within_range(mesh.vertices))
    throw InputError(spec.where, "the placed mesh reaches beyond 1e6 m: check units, scale and translation");
  try {
    return RigidBody(spec.name, std::move(mesh));
  } catch (const std::invalid_argument& error) {
    throw InputError({spec.mesh_path, 0, ""}, error.what());
  }
}

std::vector<RigidBody> build_bodies(const Scene& scene) {
  std::vector<RigidBody> bodies;
  for (const BodySpec& spec : scene.bodies) bodies.push_back(build_body(spec));
  return bodies;
}

FabricGrid build_grid(const Scene& scene) {
  try {
    return FabricGrid(scene.grid);
  } catch (const std::invalid_argument& error) {
    throw InputError(scene.grid_where, error.what());
  }
}

std::vector<AxisMask> build_locks(const Scene& scene, const FabricGrid& grid) {
  std::vector<AxisMask> locks(static_cast<std::size_t>(grid.node_count()), 0);
  for (const ConstraintSpec& c : scene.constraints) {
    const std::vector<int> nodes = select_nodes(grid, c.nodes);
    if (nodes.empty())
      throw InputError(c.where, "node set " + c.nodes_text + " selects no node of the " +
                                    std::to_string(grid.nodes_warp()) + " x " +
                                    std::to_string(grid.nodes_weft()) + " grid");
    for (const int k : nodes) {
      auto& lock = locks[static_cast<std::size_t>(k)];
      lock = static_cast<AxisMask>(lock | c.axes);
    }
  }
  return locks;
}

std::vector<Eigen::Vector3d> build_start(const Scene& scene, const FabricGrid& grid) {
  std::vector<Eigen::Vector3d> start = initial_positions(grid, scene.origin_m, scene.initial);
  if (!within_range(start))
    throw InputError(scene.initial_where, "the fabric starts beyond 1e6 m: check origin_m and the initial shape");
  return start;
}

std::string node_name(const FabricGrid& grid, int k) {
  return "node (" + std::to_string(grid.i_of(k)) + ", " + std::to_string(grid.j_of(k)) + ")";
}

// An outward-oriented closed mesh encloses a positive volume; a negative one means the faces
// point inward, which makes everything outside look inside.
std::string orientation_hint(const RigidBody& body) {
  return body.signed_volume() < 0.0
             ? "; the mesh's faces point inward (negative enclosed volume): flip its orientation"
             : "; the initial shape must clear it";
}

// Seed 003 starts from a deformation with "no contact or intersection" with the body.
void check_clear_start(const Scene& scene, const Model& model) {
  for (const RigidBody& body : model.bodies) {
    for (int k = 0; k < model.node_count(); ++k) {
      const SurfacePoint s = body.closest(model.start[static_cast<std::size_t>(k)]);
      if (s.signed_distance <= 0.0) {
        char depth[64];
        std::snprintf(depth, sizeof depth, "%.3g", -s.signed_distance);
        throw InputError(scene.initial_where, node_name(model.grid, k) + " starts inside body '" +
                                                  body.name() + "' (" + depth + " m deep)" +
                                                  orientation_hint(body));
      }
    }
    for (const Spring& spring : model.grid.springs())
      if (body.segment_crosses(model.start[static_cast<std::size_t>(spring.a)],
                               model.start[static_cast<std::size_t>(spring.b)]))
        throw InputError(scene.initial_where,
                         "the spring from " + node_name(model.grid, spring.a) + " to " +
                             node_name(model.grid, spring.b) + " passes through body '" +
                             body.name() + "'; the initial shape must clear it");
  }
}

}  // namespace

Model build_model(const Scene& scene) {
  FabricGrid grid = build_grid(scene);
  const MaterialFile warp = read_material(scene.warp_path, scene.warp_where);
  const MaterialFile weft = read_material(scene.weft_path, scene.weft_where);
  Model model{grid,
              warp.table,
              weft.table,
              build_locks(scene, grid),
              build_bodies(scene),
              build_start(scene, grid),
              {},  // loads: add_gravity's, when the scene has [gravity]
              {"stretch: warp and weft springs, tension-only piecewise-linear tables"}};
  add_gravity(scene, warp, weft, &model);
  check_clear_start(scene, model);
  return model;
}

}  // namespace fabform
