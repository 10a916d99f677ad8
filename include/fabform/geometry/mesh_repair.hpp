#pragma once
// Cleans a triangle mesh from CAD so that contact can use it: merges vertices at the same
// position, drops degenerate and duplicate triangles and unused vertices, and orients the
// triangles consistently (outward where the mesh is closed). Coordinates are not moved, and no
// vertex is split: what a file cannot hold (two vertices at one position) is never made, so the
// written mesh reads back as repaired. Non-manifold edges and a non-orientable surface stay.
#include <string>
#include <vector>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

struct RepairResult {
  TriangleMesh mesh;
  int merged_vertices = 0;          // vertices joined to another at the same position
  int removed_degenerate = 0;       // zero-area triangles dropped (after merging)
  int removed_duplicate = 0;        // triangles with the same vertex set as another, dropped
  int removed_isolated_vertices = 0;
  int reversed_triangles = 0;       // triangles now walked the other way round than in the input

  bool changed() const;
  /// One line per change ("merged 24 duplicate vertices"), empty when nothing changed.
  std::vector<std::string> changes() const;
};

/// Repairs a mesh (CGAL's polygon-soup repair and orientation). Throws std::invalid_argument
/// when a triangle names a vertex that does not exist.
RepairResult repair_mesh(const TriangleMesh& mesh);

}  // namespace fabform
