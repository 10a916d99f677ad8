#include "fabform/scene/model_builder.hpp"

#include <cstdio>
#include <stdexcept>

#include "fabform/io/mesh_reader.hpp"
#include "fabform/material/material_csv.hpp"

namespace fabform {
namespace {

std::vector<RigidBody> build_bodies(const Scene& scene) {
  std::vector<RigidBody> bodies;
  for (const BodySpec& spec : scene.bodies) {
    TriangleMesh mesh = place(read_mesh(spec.mesh_path), spec.placement);
    try {
      bodies.emplace_back(spec.name, std::move(mesh));
    } catch (const std::invalid_argument& error) {
      throw InputError({spec.mesh_path, 0, ""}, error.what());
    }
  }
  return bodies;
}

std::vector<AxisMask> build_locks(const Scene& scene, const FabricGrid& grid) {
  std::vector<AxisMask> locks(static_cast<std::size_t>(grid.node_count()), 0);
  for (const ConstraintSpec& c : scene.constraints) {
    const std::vector<int> nodes = select_nodes(grid, c.nodes);
    if (nodes.empty())
      throw InputError(c.where, "node set " + c.nodes_text + " selects no node of the " +
                                    std::to_string(grid.nodes_warp()) + " x " +
                                    std::to_string(grid.nodes_weft()) + " grid");
    for (const int k : nodes)
      locks[static_cast<std::size_t>(k)] = static_cast<AxisMask>(locks[static_cast<std::size_t>(k)] | c.axes);
  }
  return locks;
}

std::string node_name(const FabricGrid& grid, int k) {
  return "node (" + std::to_string(grid.i_of(k)) + ", " + std::to_string(grid.j_of(k)) + ")";
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
                                                  body.name() + "' (" + depth +
                                                  " m deep); the initial shape must clear it");
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
  FabricGrid grid(scene.grid);
  Model model{grid,
              read_material_table(scene.warp_path),
              read_material_table(scene.weft_path),
              build_locks(scene, grid),
              build_bodies(scene),
              initial_positions(grid, scene.origin_m, scene.initial)};
  check_clear_start(scene, model);
  return model;
}

}  // namespace fabform
