#include "fabform/scene/continuation_grids.hpp"

#include <algorithm>

namespace fabform {

std::vector<std::array<int, 2>> continuation_grids(const Scene& scene) {
  std::vector<std::array<int, 2>> grids;
  std::array<int, 2> d = {scene.fabric.divisions_warp, scene.fabric.divisions_weft};
  for (int level = 0; level < scene.solver.continuation_levels; ++level) {
    if (std::min(d[0], d[1]) / 2 < kMinContinuationDivisions) break;
    d = {d[0] / 2, d[1] / 2};
    grids.insert(grids.begin(), d);
  }
  return grids;
}

int chosen_continuation_levels(const Scene& scene) {
  std::array<int, 2> d = {scene.fabric.divisions_warp, scene.fabric.divisions_weft};
  int levels = 0;
  while (d[0] % 2 == 0 && d[1] % 2 == 0 && std::min(d[0], d[1]) / 2 >= kChosenCoarsestDivisions)
    d = {d[0] / 2, d[1] / 2}, ++levels;
  if (levels == 0) return 0;
  Scene continued = scene;
  continued.solver.continuation_levels = levels;
  std::string key;
  return continuation_refusal(continued, &key).empty() ? levels : 0;
}

namespace {

// The first division count on the way down that does not halve, or 0.
int odd_divisions(const Scene& scene) {
  std::array<int, 2> d = {scene.fabric.divisions_warp, scene.fabric.divisions_weft};
  for (int level = 0; level < scene.solver.continuation_levels; ++level) {
    if (std::min(d[0], d[1]) / 2 < kMinContinuationDivisions) return 0;
    for (const int n : d)
      if (n % 2 != 0) return n;
    d = {d[0] / 2, d[1] / 2};
  }
  return 0;
}

}  // namespace

std::string continuation_refusal(const Scene& scene, std::string* key) {
  *key = "continuation_levels";
  if (scene.solver.continuation_levels == 0) return "";
  if (scene.solver.name != "newton") {
    *key = "name";
    return "grid continuation (solver.continuation_levels) runs newton only, not " + scene.solver.name;
  }
  for (const BodySpec& body : scene.bodies)
    if (body.path.moves())
      return "body '" + body.name + "' travels in load steps ([body.path]); grid continuation solves one rest, not steps";
  if (scene.fabric.mesh == FabricSpec::Mesh::arc)
    return "an arc mesh (rings on spokes) has no coarser lattice: grid continuation is not supported for it";
  if (scene.fabric.shape == FabricSpec::Shape::panels)
    return "panels' boundary nodes lie on their outlines, which a coarser lattice would meet elsewhere: grid continuation is not supported for them";
  for (std::size_t c = 0; c < scene.constraints.size(); ++c)
    if (scene.constraints[c].nodes.kind == NodeSetSpec::Kind::index)
      return "constraint " + std::to_string(c) + " names a node by its lattice index, which means another place on a coarser grid";
  if (const int n = odd_divisions(scene); n != 0) return std::to_string(n) + " divisions do not halve";
  return "";
}

}  // namespace fabform
