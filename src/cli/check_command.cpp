// fabform check MESH [--units U] [--repair OUT.obj]: what a mesh is, whether contact can use
// it, and (with --repair) a cleaned copy. Exit 0 when the mesh (or the repaired copy) is usable,
// 2 with one line on stderr when it cannot be read or used.
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/guarded.hpp"
#include "fabform/error.hpp"
#include "fabform/geometry/mesh_repair.hpp"
#include "fabform/geometry/mesh_report.hpp"
#include "fabform/geometry/placement.hpp"
#include "fabform/io/mesh_reader.hpp"
#include "fabform/io/obj_text.hpp"
#include "fabform/output/atomic_file.hpp"

namespace fabform::cli {
namespace {

struct CheckArguments {
  std::string mesh;
  std::optional<std::string> units;
  std::optional<std::string> repair_out;
};

bool ends_with_obj(const std::string& path) {
  if (path.size() < 4) return false;
  std::string tail = path.substr(path.size() - 4);
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ".obj";
}

CheckArguments read_check_arguments(const CLI::App& command) {
  refuse_leftovers(command, "only one mesh can be checked at a time");
  CheckArguments parsed;
  if (const std::string* v = given(command, "MESH")) parsed.mesh = *v;
  if (const std::string* v = given(command, "--units")) parsed.units = *v;
  if (const std::string* v = given(command, "--repair")) parsed.repair_out = *v;
  if (parsed.mesh.empty()) throw usage_error("MESH", "missing: fabform check MESH [--units U] [--repair OUT.obj]");
  double unused = 0.0;
  if (parsed.units && !parse_length_unit(*parsed.units, &unused))
    throw usage_error("--units", "unknown unit '" + *parsed.units + "' (m, cm, mm or in)");
  if (parsed.repair_out && !ends_with_obj(*parsed.repair_out))
    throw usage_error("--repair", "the repaired mesh is written as OBJ: name it *.obj");
  return parsed;
}

// ---------------------------------------------------------------------------------------------
// The report

void line(const char* name, const std::string& value) { std::printf("  %-19s %s\n", name, value.c_str()); }

std::string format(const char* pattern, double a, double b, double c) {
  char text[128];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

std::string count(int n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

std::string surface_text(const MeshReport& r) {
  if (r.closed) return "closed (every edge has a triangle on both sides)";
  return "open: " + count(r.boundary_edges, "boundary edge", "boundary edges") + " in " +
         count(r.boundary_loops, "boundary loop", "boundary loops");
}

std::string self_intersection_text(const MeshReport& r) {
  if (!r.self_intersections_checked) return r.self_intersection_note;
  std::string text = (r.self_intersections_complete ? "" : "at least ") +
                     count(r.self_intersecting_pairs, "pair of triangles", "pairs of triangles");
  if (!r.self_intersections_complete) text += " (" + r.self_intersection_note + ")";
  if (r.touching_pairs > 0)
    text += "; " + std::to_string(r.touching_pairs) + " more only touch along edges they do not share (cracks, T-junctions)";
  return text;
}

void print_report(const MeshReport& r, double metres_per_unit) {
  const double m = metres_per_unit;
  line("vertices", std::to_string(r.vertices));
  line("triangles", std::to_string(r.triangles));
  line("bounding box (m)", format("min (%.6g, %.6g, %.6g)", r.box.min.x() * m, r.box.min.y() * m, r.box.min.z() * m) +
                               format(" max (%.6g, %.6g, %.6g)", r.box.max.x() * m, r.box.max.y() * m, r.box.max.z() * m));
  const Eigen::Vector3d size = (r.box.max - r.box.min) * m;
  line("size (m)", format("%.6g x %.6g x %.6g", size.x(), size.y(), size.z()));
  if (r.bad_indices > 0) {
    line("bad triangles", count(r.bad_indices, "triangle names", "triangles name") + " a missing vertex");
    return;
  }
  line("surface", surface_text(r));
  line("non-manifold edges", std::to_string(r.non_manifold_edges) + " (used by more than two triangles)");
  line("components", std::to_string(r.components));
  line("degenerate", count(r.degenerate_triangles, "triangle", "triangles") + " of zero area (" +
                         std::to_string(r.repeated_index_triangles) + " with a repeated vertex)");
  line("duplicate triangles", std::to_string(r.duplicate_triangles));
  line("duplicate vertices", std::to_string(r.duplicate_vertices));
  line("unused vertices", std::to_string(r.isolated_vertices));
  line("self-intersections", self_intersection_text(r));
  std::string orientation = to_string(r.orientation);
  if (r.inconsistent_edges > 0) orientation += ": " + count(r.inconsistent_edges, "edge", "edges") + " between triangles facing opposite ways";
  line("orientation", orientation);
  if (r.closed) line("enclosed volume", format("%.6g m^3 (signed)", r.signed_volume * m * m * m, 0, 0));
}

// Problems that do not stop contact but that the user should know about.
std::vector<std::string> remarks(const MeshReport& r) {
  std::vector<std::string> out;
  if (!r.closed && r.bad_indices == 0)
    out.push_back("open mesh: fine for contact, its rim counts as outside");
  if (r.self_intersecting_pairs > 0) out.push_back("self-intersections: contact near them may be wrong");
  if (r.non_manifold_edges > 0) out.push_back("non-manifold edges: inside and outside are ambiguous along them");
  if (r.degenerate_triangles > 0 || r.duplicate_triangles > 0 || r.duplicate_vertices > 0)
    out.push_back("degenerate or duplicate elements: --repair OUT.obj drops them");
  return out;
}

// ---------------------------------------------------------------------------------------------
// Repair

int repair(const CheckArguments& args, const TriangleMesh& mesh, double metres_per_unit) {
  const RepairResult repaired = repair_mesh(mesh);
  std::printf("repair:\n");
  const auto changes = repaired.changes();
  if (changes.empty()) std::printf("  nothing to change\n");
  for (const auto& change : changes) std::printf("  %s\n", change.c_str());
  const MeshReport after = inspect_mesh(repaired.mesh);
  std::printf("after repair:\n");
  print_report(after, metres_per_unit);
  std::string why;
  if (!after.usable_for_contact(&why)) {
    std::fprintf(stderr, "fabform: error: %s: even after repair, %s; nothing written\n", args.mesh.c_str(), why.c_str());
    return kExitBadInput;
  }
  write_file_atomically(*args.repair_out,
                        obj_text(repaired.mesh, "repaired by fabform check from " + args.mesh + " (coordinates in its units)"));
  std::printf("written: %s (OBJ, in the input's units)\n", args.repair_out->c_str());
  return kExitDone;
}

int check(const CheckArguments& args) {
  double metres_per_unit = 1.0;
  if (args.units) parse_length_unit(*args.units, &metres_per_unit);
  std::vector<std::string> warnings;
  const TriangleMesh mesh = read_mesh(args.mesh, &warnings);
  const MeshReport report = inspect_mesh(mesh);
  std::printf("mesh: %s\n", args.mesh.c_str());
  for (const auto& warning : warnings) std::printf("  warning: %s\n", warning.c_str());
  line("units", args.units ? *args.units + " (given); lengths below in metres" : "not given, assumed m");
  print_report(report, metres_per_unit);
  for (const auto& remark : remarks(report)) std::printf("  note: %s\n", remark.c_str());
  std::string why;
  const bool usable = report.usable_for_contact(&why);
  std::printf("verdict: %s\n", usable ? "usable for contact" : ("not usable for contact: " + why).c_str());
  if (args.repair_out) return repair(args, mesh, metres_per_unit);
  if (usable) return kExitDone;
  std::fprintf(stderr, "fabform: error: %s: %s\n", args.mesh.c_str(), report.contact_refusal().c_str());
  return kExitBadInput;
}

}  // namespace

Command add_check_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("check", "report whether a mesh can be a body: its size, defects and what contact needs");
  command->add_option("MESH", "STL, OBJ, PLY, OFF or VRML97 file");
  command->add_option("--units", "the file's unit: m, cm, mm or in")->type_name("U");
  command->add_option("--repair", "write the mesh repaired (merged, oriented, cracks closed) as OBJ")->type_name("OUT.obj");
  command->allow_extras();
  auto args = std::make_shared<CheckArguments>();
  return {command, [command, args] { *args = read_check_arguments(*command); }, [args] { return check(*args); }};
}

}  // namespace fabform::cli
