#pragma once
// What a triangle mesh from CAD is: counts, bounding box, open or closed, boundary loops,
// degenerate and duplicate elements, self-intersections and orientation. Lengths are in the
// mesh's own units. Topology is by vertex index, as the contact code sees it: two vertices at
// the same position are counted as duplicates, not joined.
#include <string>
#include <vector>

#include "fabform/geometry/triangle_mesh.hpp"

namespace fabform {

struct InspectOptions {
  // Look for self-intersecting triangle pairs (exact predicates; O(n log n + pairs)).
  bool self_intersections = true;
  // Stop counting self-intersecting pairs at this many: a badly broken mesh can have
  // quadratically many, and the count only has to say that there are some.
  int max_self_intersection_pairs = 1000;
  // Triangles that meet only within this distance of both their edges (relative to the
  // bounding box diagonal) touch, they do not cross: CAD cracks and T-junctions whose vertices
  // differ by the export's float rounding (~1e-7 of the size).
  double touch_tolerance = 1e-6;
  // Skip the self-intersection search above this many triangles, and say so.
  int max_self_intersection_triangles = 2'000'000;
};

enum class MeshOrientation {
  consistent_open,  // every shared edge is walked both ways; open, so no inside or outside
  outward,          // closed, consistent, bounds a volume (normals point out)
  inward,           // closed, consistent, every component's normals point in
  mixed,            // closed, consistent, some components point in, some out
  inconsistent,     // some neighbours disagree; a consistent orientation exists (repairable)
  non_orientable,   // no consistent orientation exists (a Möbius band, say)
};

std::string to_string(MeshOrientation orientation);

struct MeshReport {
  int vertices = 0;
  int triangles = 0;
  BoundingBox box;  // of all vertices

  int bad_indices = 0;         // triangles naming a vertex that does not exist (then nothing else is counted)
  int isolated_vertices = 0;   // used by no triangle
  int duplicate_vertices = 0;  // same coordinates as another vertex, counted beyond the first

  int degenerate_triangles = 0;      // zero area, including the next count
  int repeated_index_triangles = 0;  // a vertex index used twice in one triangle
  int duplicate_triangles = 0;       // same vertex set as another triangle, beyond the first

  int edges = 0;               // distinct undirected edges of the non-repeated-index triangles
  int boundary_edges = 0;      // used by one triangle
  int boundary_loops = 0;      // closed chains of boundary edges (an open chain counts as one)
  int non_manifold_edges = 0;  // used by more than two triangles
  bool closed = false;         // no boundary edge (and at least one triangle)
  int components = 0;          // triangles connected through shared vertices

  int inconsistent_edges = 0;  // shared by two triangles that walk it the same way
  MeshOrientation orientation = MeshOrientation::consistent_open;
  double signed_volume = 0.0;  // Σ det/6 over all triangles; the enclosed volume when closed and outward

  bool self_intersections_checked = false;
  bool self_intersections_complete = false;  // false when counting stopped at the cap
  int self_intersecting_pairs = 0;           // pairs of distinct, non-duplicate triangles that cross or overlap
  int touching_pairs = 0;  // pairs that only touch along edges they do not share (cracks, T-junctions), not counted above
  std::string self_intersection_note;        // why it was not checked or not complete, or ""

  /// Whether fabform's contact can use the mesh as it is; `why` gets the reason when not.
  /// Open meshes are fine; inconsistent or inverted orientation is not.
  bool usable_for_contact(std::string* why = nullptr) const;
  /// Whether `repair_mesh` can fix what `usable_for_contact` rejects.
  bool repairable() const;
  /// The one verdict `fabform check` and `fabform run` both give on a mesh contact cannot use
  /// as it is: why, and that `fabform check --repair` fixes it when it does ("" when usable).
  std::string contact_refusal() const;
  /// What a usable mesh should still be warned about, one line each: self-intersections. Never
  /// that the mesh is open.
  std::vector<std::string> contact_warnings() const;
};

/// Inspects a mesh. Never throws for a bad mesh: bad indices are counted and stop the rest.
MeshReport inspect_mesh(const TriangleMesh& mesh, const InspectOptions& options = {});

}  // namespace fabform
