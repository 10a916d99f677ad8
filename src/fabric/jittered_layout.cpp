#include "fabform/fabric/fabric_layout.hpp"

#include <cstddef>
#include <vector>

#include "fabform/fabric/split_mix.hpp"

namespace fabform {
namespace {

// A point uniform in the unit disc, by rejection from the square around it: arithmetic alone, so
// the same on every machine (a sine's last bit may differ between maths libraries).
Eigen::Vector2d in_unit_disc(std::uint64_t* state) {
  for (;;) {
    const double x = symmetric_unit(state);
    const double y = symmetric_unit(state);
    if (x * x + y * y < 1.0) return {x, y};
  }
}

// Faces at each node: a lattice node with four is inside the fabric, one with fewer on its outline.
std::vector<int> faces_per_node(const FabricLayout& layout) {
  std::vector<int> count(layout.rest.size(), 0);
  for (const Face& f : layout.faces)
    for (int c = 0; c < f.corners; ++c) ++count[static_cast<std::size_t>(f.corner[static_cast<std::size_t>(c)])];
  return count;
}

}  // namespace

// Every lattice point of the square around the circle draws its move, in lattice order, so a
// node's move depends on the seed and its place alone, not on which cells the circle keeps. The
// outline's nodes keep their places: the specimen is cut as the quadrangular mesh's is.
FabricLayout jittered_layout(const FabricSpec& spec) {
  FabricLayout layout = circle_lattice_layout(spec);
  const int n = layout.lattice_size[0];
  std::vector<Eigen::Vector2d> move(static_cast<std::size_t>(n) * static_cast<std::size_t>(layout.lattice_size[1]));
  std::uint64_t state = spec.jitter_seed;
  for (Eigen::Vector2d& m : move) m = spec.jitter * layout.spacing[0] * in_unit_disc(&state);
  const std::vector<int> faces = faces_per_node(layout);
  for (std::size_t k = 0; k < layout.rest.size(); ++k) {
    if (faces[k] < 4) continue;
    const auto [i, j] = layout.lattice[k];
    layout.rest[k].head<2>() += move[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i)];
  }
  return layout;
}

}  // namespace fabform
