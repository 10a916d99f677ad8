#include "fabform/output/result_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "fabform/analysis/drape_figures.hpp"
#include "fabform/analysis/ply_figures.hpp"
#include "fabform/analysis/print_map.hpp"
#include "fabform/error.hpp"
#include "fabform/io/obj_text.hpp"
#include "fabform/io/png_image.hpp"
#include "fabform/model/force_scale.hpp"
#include "fabform/model/seam.hpp"
#include "fabform/number_text.hpp"
#include "fabform/output/checkpoint.hpp"
#include "fabform/output/print_map_files.hpp"
#include "fabform/output/results_folder.hpp"
#include "fabform/output/run_figures.hpp"
#include "fabform/solver/solver_registry.hpp"
#include "fabform/thread_count.hpp"
#include "linalg/parallel_failure.hpp"

namespace fabform {
namespace {

namespace fs = std::filesystem;

// JSON has no NaN or infinity; such values are written as null.
nlohmann::json number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

nlohmann::json vector_json(const Eigen::Vector3d& v) { return {number(v.x()), number(v.y()), number(v.z())}; }

nlohmann::json peak_json(const StrainPeak& p) {
  return {{"strain", number(p.strain)},
          {"spring_from_node", {p.i, p.j}},
          {"at_m", {number(p.at_m.x()), number(p.at_m.y()), number(p.at_m.z())}}};
}

nlohmann::json figures_json(const FabricFigures& f) {
  nlohmann::json histogram = {{"strain_edges", f.histogram.edges},
                              {"warp_area_m2", f.histogram.warp_area_m2},
                              {"weft_area_m2", f.histogram.weft_area_m2}};
  return {{"area_flat_m2", f.area_flat_m2},
          {"area_formed_m2", number(f.area_formed_m2)},
          {"contact_area_m2", number(f.contact_area_m2)},
          {"max_warp_strain", peak_json(f.max_warp)},
          {"max_weft_strain", peak_json(f.max_weft)},
          {"min_warp_strain", peak_json(f.min_warp)},
          {"min_weft_strain", peak_json(f.min_weft)},
          {"strain_histogram", histogram}};
}

nlohmann::json fabric_json(const Fabric& fabric) {
  nlohmann::json springs;
  for (const SpringKind kind : {SpringKind::warp, SpringKind::weft, SpringKind::shear, SpringKind::bend})
    springs[to_string(kind)] = std::count_if(fabric.springs().begin(), fabric.springs().end(),
                                             [&](const Spring& s) { return s.kind == kind; });
  nlohmann::json panels = nlohmann::json::array();  // a garment's: the order fabric.vtk's panel field numbers them
  for (const PanelMesh& p : fabric.panels()) panels.push_back({{"name", p.name}, {"first_node", p.first_node}, {"nodes", p.node_count}});
  return {{"shape", fabric.spec().tube != FabricSpec::Tube::none ? "tube" : to_string(fabric.spec().shape)},
          {"panels", panels.empty() ? nlohmann::json(nullptr) : panels},
          {"tube", fabric.spec().tube != FabricSpec::Tube::none ? nlohmann::json(to_string(fabric.spec().tube)) : nlohmann::json(nullptr)},
          {"mesh", to_string(fabric.spec().mesh)},
          {"nodes", fabric.node_count()},
          {"faces", fabric.faces().size()},
          {"springs", springs}};
}

// Why a drape figure is not a tester's reading: the run stopped short of a rest, or the shadow
// is smaller than the support, which no fabric hanging under its weight gives.
nlohmann::json drape_caveats(const RunRecord& run, double coefficient) {
  nlohmann::json caveats = nlohmann::json::array();
  if (!run.summary.converged())
    caveats.push_back("the run did not converge (" + to_string(run.summary.termination) +
                      "): the figure is where the solver stopped, not a rest");
  if (coefficient < 0.0)
    caveats.push_back("negative: the shadow is smaller than the support, which no real drape gives; "
                      "check the fabric's mass, bending and tables");
  return caveats;
}

// A drape test's figures; null where the state has no shadow (a position not finite).
nlohmann::json drape_json(const RunRecord& run) {
  const DrapeSpec& drape = run.scene.drape;
  double support = 0.0;
  for (const RigidBody& body : run.model.bodies)
    if (body.name() == drape.support) support = support_area(body.mesh());
  const double radius = run.scene.fabric.radius_m();
  try {
    const DrapeFigures f = drape_figures(run.model.fabric, run.state.x,
                                         run.scene.origin_m.head<2>() + Eigen::Vector2d(radius, radius), support);
    return {{"coefficient", f.coefficient},
            {"shadow_area_m2", f.shadow_area_m2},
            {"specimen_area_m2", f.specimen_area_m2},
            {"support", drape.support.empty() ? nlohmann::json("pin") : nlohmann::json(drape.support)},
            {"support_area_m2", f.support_area_m2},
            {"folds", f.folds},
            {"shadow_pieces", f.shadow_pieces},
            {"caveats", drape_caveats(run, f.coefficient)}};
  } catch (const std::invalid_argument&) {
    return nullptr;
  }
}

// What a forming engineer reads: shear, thinning, wrinkle risk and the pressure on the bodies.
void forming_json(const RunRecord& run, const CellFigures& cells, const ContactPressure& p, nlohmann::json& figures) {
  const CellDeformation& d = cells.deformation;
  const auto face_centre = [&](int f) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    const Face& face = run.model.fabric.faces()[static_cast<std::size_t>(f)];
    for (int c = 0; c < face.corners; ++c) sum += run.state.x[static_cast<std::size_t>(face.corner[static_cast<std::size_t>(c)])];
    return vector_json(sum / face.corners);
  };
  figures["shear_angle_max_deg"] = d.shear_angle_max_face < 0 ? nlohmann::json(nullptr) : number(d.shear_angle_max_deg);
  figures["shear_angle_max_at_m"] = d.shear_angle_max_face < 0 ? nlohmann::json(nullptr) : face_centre(d.shear_angle_max_face);
  figures["thickness_ratio_min"] = d.thickness_ratio_min_face < 0 ? nlohmann::json(nullptr) : number(d.thickness_ratio_min);
  figures["thickness_ratio_min_at_m"] =
      d.thickness_ratio_min_face < 0 ? nlohmann::json(nullptr) : face_centre(d.thickness_ratio_min_face);
  figures["wrinkle_cells"] = d.wrinkle_cells;
  figures["locking_angle_deg"] = cells.options.locking_angle_deg;
  figures["locking_angle_from"] = cells.locking_from;
  figures["contact_pressure_max_Pa"] = number(p.max_Pa);
  figures["contact_pressure_max_mmHg"] = number(p.max_Pa / kPascalPerMmHg);
  figures["contact_pressure_mean_Pa"] = number(p.mean_Pa);
  figures["contact_pressure_mean_mmHg"] = number(p.mean_Pa / kPascalPerMmHg);
  figures["contact_pressure_max_at_m"] =
      p.max_node < 0 ? nlohmann::json(nullptr) : vector_json(run.state.x[static_cast<std::size_t>(p.max_node)]);
}

std::string result_json(const RunRecord& run, const StateFigures& state, const CellFigures& cells) {
  const Summary& s = run.summary;
  nlohmann::json j;
  j["fabform_version"] = FABFORM_VERSION;
  j["scene"] = run.scene.name;
  j["scene_file"] = run.inputs.scene_file;
  j["scene_sha256"] = run.inputs.files.front().sha256;
  nlohmann::json overrides = nlohmann::json::array();
  for (const SceneOverride& o : run.inputs.overrides)
    overrides.push_back(o.unset ? nlohmann::json{{"key", o.key}, {"unset", true}} : nlohmann::json{{"key", o.key}, {"value", o.value}});
  j["overrides"] = overrides;
  nlohmann::json inputs = nlohmann::json::array();
  for (const InputFile& f : run.inputs.files)
    inputs.push_back({{"role", f.role}, {"path", f.path}, {"sha256", f.sha256}});
  j["inputs"] = inputs;
  j["solver"] = s.solver;
  j["threads"] = run.threads;
  j["huge_pages"] = run.huge_pages;
  j["converged"] = s.converged();
  j["termination"] = to_string(s.termination);
  j["message"] = s.message;
  j["iterations"] = s.iterations;
  j["residual_N"] = number(s.residual_N);
  j["tolerance_N"] = s.tolerance_N;
  // The same, relative to what a spring carries per unit strain at rest (force_scale.hpp).
  const double scale = spring_force_scale_N(run.model);
  j["force_scale_N"] = scale;
  j["tolerance_relative"] = scale > 0.0 ? number(s.tolerance_N / scale) : nlohmann::json(nullptr);
  j["residual_relative"] = scale > 0.0 ? number(s.residual_N / scale) : nlohmann::json(nullptr);
  j["residual_recomputed_N"] = number(run.check.max_residual_N);
  // How far the answer is from the exact rest, estimated (position_error.hpp), and which
  // tolerance stopped a converged run.
  j["position_error_m"] = number(s.position_error_m);
  j["position_error_estimate"] = solver_named(s.solver).position_error_estimate;
  j["tolerance_m"] = s.tolerance_m > 0.0 ? nlohmann::json(s.tolerance_m) : nlohmann::json(nullptr);
  j["converged_on"] = s.converged() ? nlohmann::json(to_string(s.converged_on)) : nlohmann::json(nullptr);
  // Newton's linear solve, and its iterations when it is multigrid's conjugate gradients.
  j["linear_solver"] = s.linear_solver.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.linear_solver);
  j["linear_iterations"] = s.linear_solver.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.linear_iterations);
  j["wall_seconds"] = run.wall_seconds;
  j["solve_seconds"] = s.seconds;
  j["nodes"] = run.model.node_count();
  j["grid"] = {run.model.fabric.nodes_warp(), run.model.fabric.nodes_weft()};
  j["contact_nodes"] = run.check.contact_nodes;
  j["max_penetration_m"] = number(run.check.max_penetration_m);
  j["figures"] = figures_json(state.fabric);
  const DrawIn& edge = state.draw_in;
  j["figures"]["draw_in_max_m"] = edge.max_node < 0 ? nlohmann::json(nullptr) : number(edge.max_m);
  j["figures"]["draw_in_max_node"] = edge.max_node < 0 ? nlohmann::json(nullptr) : nlohmann::json(run.model.fabric.node_name(edge.max_node));
  j["figures"]["springs_cutting_bodies"] = run.check.spring_cuts.springs;
  j["figures"]["springs_over_edges"] = run.check.spring_cuts.over_edges;
  j["figures"]["deepest_spring_cut_m"] = run.check.spring_cuts.deepest_m;
  j["figures"]["sliding_nodes"] = run.check.sliding_nodes;
  j["figures"]["stuck_nodes"] = run.check.stuck_nodes;
  forming_json(run, cells, state.pressure, j["figures"]);
  j["fabric"] = fabric_json(run.model.fabric);
  // Each seam's force per length (N/m) and how far it stands open (m).
  nlohmann::json seams = nlohmann::json::array();
  for (const SeamFigures& f : seam_figures(run.model, run.state.x))
    seams.push_back({{"name", f.name}, {"length_m", number(f.length_m)}, {"tension_mean_N_m", number(f.tension_mean_N_m)},
                     {"tension_max_N_m", number(f.tension_max_N_m)}, {"gap_max_m", number(f.gap_max_m)}});
  if (!seams.empty()) j["seams"] = seams;
  // A garment's ease per panel: how far it stands off the body, over its area and at most.
  if (state.ease) {
    nlohmann::json ease = nlohmann::json::array();
    for (const PanelEase& e : state.ease->panels)
      ease.push_back({{"panel", e.panel}, {"mean_m", number(e.mean_m)}, {"max_m", number(e.max_m)}});
    j["ease"] = ease;
  }
  if (const std::optional<PlyFigures> plies = ply_figures(run.model, run.state.x))
    j["self_contact"] = {{"thickness_m", plies->thickness_m},
                         {"contact_pairs", plies->contact_pairs},
                         {"smallest_gap_m", plies->smallest_gap_m ? number(*plies->smallest_gap_m) : nlohmann::json(nullptr)},
                         {"intersecting_triangle_pairs", plies->intersecting_triangle_pairs}};
  if (run.scene.drape.on) {
    j["drape"] = drape_json(run);
    j["drape_coefficient"] = j["drape"].is_null() ? nlohmann::json(nullptr) : j["drape"]["coefficient"];
  }
  j["modelled"] = run.model.modelled();
  j["materials"] = {{"warp", run.scene.warp_path}, {"weft", run.scene.weft_path}};
  if (run.scene.shear.on) j["materials"]["shear"] = run.scene.shear.material_path;
  nlohmann::json bodies = nlohmann::json::array();
  for (const RigidBody& b : run.model.bodies)
    bodies.push_back({{"name", b.name()}, {"triangles", b.mesh().triangles.size()}});
  j["bodies"] = bodies;
  nlohmann::json constraints = nlohmann::json::array();
  for (const ConstraintSpec& c : run.scene.constraints)
    constraints.push_back({{"nodes", c.nodes_text}, {"axes", axes_to_string(c.axes)}});
  j["constraints"] = constraints;
  j["warnings"] = run.warnings;
  // How many coarser grids were asked for, and who chose them (a scene's key, or fabform from
  // the fabric's size); "continuation" lists those solved.
  j["continuation_levels"] = run.scene.solver.continuation_levels;
  j["continuation_chosen_by"] = run.scene.solver.continuation_chosen ? "fabform" : "scene";
  if (run.continuation && !run.continuation->empty()) {
    // The top-level figures stay the scene's own grid's; these are the coarser grids before it.
    nlohmann::json levels = nlohmann::json::array();
    for (const ContinuationLevel& level : *run.continuation)
      levels.push_back({{"divisions", {level.divisions[0], level.divisions[1]}},
                        {"termination", to_string(level.summary.termination)},
                        {"iterations", level.summary.iterations},
                        {"residual_N", number(level.summary.residual_N)},
                        {"solve_seconds", level.summary.seconds}});
    j["continuation"] = levels;
  }
  if (run.model.load_steps() > 0) {
    j["load_steps"] = run.model.load_steps();
    nlohmann::json steps = nlohmann::json::array();
    for (const StepResult& step : run.steps ? *run.steps : std::vector<StepResult>{})
      steps.push_back(nlohmann::json::parse(step.json));
    j["steps"] = steps;
  }
  return j.dump(2) + "\n";
}

// A run in load steps numbers its iterations within each step: a first column says which.
std::string convergence_csv(const Summary& s, bool in_steps) {
  NumberText out(10);
  out << (in_steps ? "step," : "") << "iteration,residual_N,seconds,contact_nodes\n";
  for (const IterationRecord& r : s.history) {
    if (in_steps) out << r.step << ',';
    out << r.iteration << ',' << r.residual_N << ',' << r.seconds << ',' << r.contact_nodes << '\n';
  }
  return out.str();
}

std::string fabric_obj(const RunRecord& run) {
  NumberText out(12);
  out << "# fabform " << FABFORM_VERSION << ": formed fabric of scene " << run.scene.name
      << " (metres)\n";
  for (const auto& x : run.state.x) out << "v " << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
  for (const Face& f : run.model.fabric.faces()) {
    out << 'f';
    for (int c = 0; c < f.corners; ++c) out << ' ' << f.corner[static_cast<std::size_t>(c)] + 1;
    out << '\n';
  }
  return out.str();
}

// Every body where it stands (placed, then moved along its path), in metres, in one mesh: what
// the fabric was formed over, for reports and ParaView.
TriangleMesh posed_bodies(const Model& model) {
  TriangleMesh all;
  for (const RigidBody& body : model.bodies) {
    const TriangleMesh mesh = body.posed_mesh();
    const int offset = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    for (const auto& t : mesh.triangles) all.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  return all;
}

std::string bodies_obj(const RunRecord& run) {
  return obj_text(posed_bodies(run.model), "fabform " FABFORM_VERSION ": the bodies of scene " + run.scene.name +
                                              " where the run left them (metres)");
}

void vtk_field(NumberText& out, const char* name, const std::vector<double>& values) {
  out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
  for (const double v : values) out << (std::isfinite(v) ? v : 0.0) << '\n';
}

using PointField = std::pair<const char*, std::vector<double>>;

// Each node's panel (its index in result.json's fabric.panels), for a garment.
std::vector<double> node_panels(const Fabric& fabric) {
  std::vector<double> panel(static_cast<std::size_t>(fabric.node_count()), 0.0);
  for (std::size_t p = 0; p < fabric.panels().size(); ++p)
    for (int k = 0; k < fabric.panels()[p].node_count; ++k)
      panel[static_cast<std::size_t>(fabric.panels()[p].first_node + k)] = static_cast<double>(p);
  return panel;
}

// What each node of the formed fabric carries into ParaView; a garment's also its panel and ease.
std::vector<PointField> fabric_fields(const RunRecord& run, const StateFigures& state) {
  std::vector<PointField> fields = {{"strain_warp", state.strains.warp},
                                    {"strain_weft", state.strains.weft},
                                    {"contact", std::vector<double>(run.check.contact.begin(), run.check.contact.end())},
                                    {"residual_N", run.check.residual_N},
                                    {"draw_in_m", state.draw_in.per_node_m},
                                    {"contact_pressure_Pa", state.pressure.node_Pa}};
  if (!run.model.fabric.panels().empty()) fields.push_back({"panel", node_panels(run.model.fabric)});
  if (state.ease) fields.push_back({"ease_m", state.ease->node_m});
  return fields;
}

// What each face of the formed fabric carries into ParaView.
std::vector<PointField> fabric_cell_fields(const CellDeformation& d) {
  return {{"shear_angle_deg", d.shear_angle_deg},
          {"thickness_ratio", d.thickness_ratio},
          {"wrinkle_risk", std::vector<double>(d.wrinkle_risk.begin(), d.wrinkle_risk.end())}};
}

std::string fabric_vtk(const RunRecord& run, const StateFigures& state, const CellFigures& cells) {
  NumberText out(12);
  const auto& x = run.state.x;
  const std::vector<Face>& faces = run.model.fabric.faces();
  out << "# vtk DataFile Version 3.0\nfabform " << run.scene.name << " formed fabric\nASCII\n"
      << "DATASET POLYDATA\nPOINTS " << x.size() << " double\n";
  for (const auto& p : x) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  std::size_t indices = 0;
  for (const Face& f : faces) indices += 1 + static_cast<std::size_t>(f.corners);
  out << "POLYGONS " << faces.size() << ' ' << indices << '\n';
  for (const Face& f : faces) {
    out << f.corners;
    for (int c = 0; c < f.corners; ++c) out << ' ' << f.corner[static_cast<std::size_t>(c)];
    out << '\n';
  }
  out << "POINT_DATA " << x.size() << '\n';
  for (const auto& [name, values] : fabric_fields(run, state)) vtk_field(out, name, values);
  out << "CELL_DATA " << faces.size() << '\n';
  for (const auto& [name, values] : fabric_cell_fields(cells.deformation)) vtk_field(out, name, values);
  return out.str();
}

// The bodies where the run left them (bodies.obj's vertices, in its order), with the pressure
// the fabric puts on each vertex.
std::string bodies_vtk(const RunRecord& run, const ContactPressure& on_bodies) {
  const TriangleMesh all = posed_bodies(run.model);
  std::vector<double> pressure;
  for (const std::vector<double>& body : on_bodies.body_vertex_Pa)
    pressure.insert(pressure.end(), body.begin(), body.end());
  NumberText out(12);
  out << "# vtk DataFile Version 3.0\nfabform " << run.scene.name << " bodies\nASCII\n"
      << "DATASET POLYDATA\nPOINTS " << all.vertices.size() << " double\n";
  for (const auto& p : all.vertices) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  out << "POLYGONS " << all.triangles.size() << ' ' << 4 * all.triangles.size() << '\n';
  for (const auto& t : all.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out << "POINT_DATA " << all.vertices.size() << '\n';
  vtk_field(out, "contact_pressure_Pa", pressure);
  return out.str();
}

// The flat blank where the scene lays it: the fabric's rest positions from the scene's origin.
std::vector<Eigen::Vector3d> flat_blank(const RunRecord& run) {
  std::vector<Eigen::Vector3d> flat;
  for (int k = 0; k < run.model.node_count(); ++k) flat.push_back(run.scene.origin_m + run.model.fabric.rest_position(k));
  return flat;
}

// A result file's name and what makes its bytes.
using FileMaker = std::pair<std::string, std::function<std::string()>>;

// The flat blank and its map to the formed state (print_map_files.hpp).
struct PrintMapParts {
  std::vector<Eigen::Vector3d> flat;
  PrintMap map;
};

// None for a state with NaN or infinity.
std::optional<PrintMapParts> print_map_parts(const RunRecord& run) {
  for (const auto& p : run.state.x)
    if (!p.allFinite()) return std::nullopt;
  std::vector<Eigen::Vector3d> flat = flat_blank(run);
  PrintMap map = print_map(run.model.fabric, flat, run.state.x);
  return PrintMapParts{std::move(flat), std::move(map)};
}

void add_print_map_makers(const RunRecord& run, const PrintMapParts& parts, std::vector<FileMaker>& makers) {
  makers.emplace_back("formed.obj", [&] { return formed_obj(parts.map, run.state.x); });
  makers.emplace_back("formed.mtl", [] { return map_mtl("formed"); });
  makers.emplace_back("blank.obj", [&] { return blank_obj(parts.map, parts.flat); });
  makers.emplace_back("blank.mtl", [] { return map_mtl("blank"); });
  makers.emplace_back("uv_grid.png", [] { return png_bytes(checkerboard(512, 512, 16)); });
}

// The files, made on every thread the run has when its fabric is large (a million nodes' text
// is half a gigabyte); each file is made the same way on any thread. In the makers' order.
std::vector<ResultFile> made_at_once(const std::vector<FileMaker>& makers, int nodes) {
  std::vector<ResultFile> files(makers.size());
  ParallelFailure failure;
  const auto count = static_cast<int>(makers.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_in_use()) if (nodes >= kMinParallelItems)
  for (int k = 0; k < count; ++k) {
    if (failure.caught()) continue;
    const auto i = static_cast<std::size_t>(k);
    try {
      files[i] = {makers[i].first, makers[i].second()};
    } catch (...) {
      failure.capture();
    }
  }
  failure.rethrow();
  return files;
}

// VTK's XML polygon data, ASCII: what a ParaView collection (.pvd) plays as a series. A value
// that is not finite is written as 0, as in fabric.vtk.
std::string vtp_text(const std::vector<Eigen::Vector3d>& points, const std::vector<std::vector<int>>& polygons,
                     const std::vector<PointField>& fields) {
  NumberText out(12);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<PolyData>\n<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfPolys=\"" << polygons.size() << "\">\n"
      << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : points) out << (std::isfinite(p.x()) ? p.x() : 0.0) << ' ' << (std::isfinite(p.y()) ? p.y() : 0.0)
                                   << ' ' << (std::isfinite(p.z()) ? p.z() : 0.0) << '\n';
  out << "</DataArray>\n</Points>\n<Polys>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& polygon : polygons) {
    for (const int v : polygon) out << v << ' ';
    out << '\n';
  }
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for (const auto& polygon : polygons) out << (offset += polygon.size()) << '\n';
  out << "</DataArray>\n</Polys>\n<PointData>\n";
  for (const auto& [name, values] : fields) {
    out << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (const double v : values) out << (std::isfinite(v) ? v : 0.0) << '\n';
    out << "</DataArray>\n";
  }
  out << "</PointData>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  return out.str();
}

std::string fabric_vtp(const RunRecord& run, const StateFigures& state) {
  std::vector<std::vector<int>> polygons;
  for (const Face& f : run.model.fabric.faces()) polygons.emplace_back(f.corner.begin(), f.corner.begin() + f.corners);
  return vtp_text(run.state.x, polygons, fabric_fields(run, state));
}

std::string bodies_vtp(const Model& model) {
  const TriangleMesh all = posed_bodies(model);
  std::vector<std::vector<int>> polygons;
  for (const auto& t : all.triangles) polygons.push_back({t[0], t[1], t[2]});
  return vtp_text(all.vertices, polygons, {});
}

std::string step_file(const char* what, int step) {
  char name[64];
  std::snprintf(name, sizeof name, "%s_step_%03d.vtp", what, step);
  return name;
}

// The collection ParaView opens to play the steps: the fabric and the bodies at each.
std::string steps_pvd(const std::vector<StepResult>& steps) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const StepResult& s : steps)
    for (const auto& [part, what] : {std::pair<int, const char*>{0, "fabric"}, {1, "bodies"}})
      out << "<DataSet timestep=\"" << s.step << "\" part=\"" << part << "\" file=\"" << step_file(what, s.step) << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  return out.str();
}

}  // namespace

void write_results(const std::string& dir, const RunRecord& run) {
  const bool in_steps = run.model.load_steps() > 0;
  const StateFigures state = state_figures(run);
  const CellFigures cells = cell_figures(run);
  // The largest files first (fabric.vtk, then the print map's), so that the last file a thread
  // takes is a small one.
  std::vector<FileMaker> makers = {{"fabric.vtk", [&] { return fabric_vtk(run, state, cells); }}};
  const Termination t = run.summary.termination;
  std::optional<PrintMapParts> map;
  if (t != Termination::running) map = print_map_parts(run);
  if (map) add_print_map_makers(run, *map, makers);
  makers.emplace_back("fabric.obj", [&] { return fabric_obj(run); });
  makers.emplace_back("convergence.csv", [&] { return convergence_csv(run.summary, in_steps); });
  makers.emplace_back("result.json", [&] { return result_json(run, state, cells); });
  if (t != Termination::converged && t != Termination::numerical_failure)
    makers.emplace_back("checkpoint.bin", [&] { return checkpoint_bytes(run.state, run.summary); });
  if (t != Termination::running && !run.model.bodies.empty()) {  // checkpoints stay light
    makers.emplace_back("bodies.obj", [&] { return bodies_obj(run); });
    makers.emplace_back("bodies.vtk", [&] { return bodies_vtk(run, state.pressure); });
  }
  if (in_steps && run.steps) {
    for (const StepResult& step : *run.steps) {
      makers.emplace_back(step_file("fabric", step.step), [&step] { return step.fabric_vtp; });
      makers.emplace_back(step_file("bodies", step.step), [&step] { return step.bodies_vtp; });
    }
    makers.emplace_back("fabric_steps.pvd", [&] { return steps_pvd(*run.steps); });
  }
  publish_results(dir, made_at_once(makers, run.model.node_count()));
}

StepResult step_result(const RunRecord& run, int step, const StepCuts& cuts) {
  const Summary& s = run.summary;
  const StateFigures state = state_figures(run);
  const FabricFigures& f = state.fabric;
  const DrawIn& edge = state.draw_in;
  nlohmann::json travel = nlohmann::json::array();
  for (std::size_t b = 0; b < run.model.paths.size(); ++b)
    if (const ToolPath& path = run.model.paths[b]; path.moves())
      travel.push_back({{"body", run.model.bodies[b].name()},
                        {"translation_m", vector_json(path.translation_at(step))},
                        {"rotation_deg", vector_json(path.rotation_deg_at(step))}});
  const nlohmann::json j = {{"step", step},
                            {"travel", travel},
                            {"converged", s.converged()},
                            {"iterations", s.iterations},
                            {"cuts", cuts.cuts},
                            {"smallest_fraction", cuts.smallest_fraction},
                            {"residual_N", number(s.residual_N)},
                            {"seconds", s.seconds},
                            {"contact_nodes", run.check.contact_nodes},
                            {"max_warp_strain", number(f.max_warp.strain)},
                            {"max_weft_strain", number(f.max_weft.strain)},
                            {"min_warp_strain", number(f.min_warp.strain)},
                            {"min_weft_strain", number(f.min_weft.strain)},
                            {"draw_in_max_m", edge.max_node < 0 ? nlohmann::json(nullptr) : number(edge.max_m)},
                            {"sliding_nodes", run.check.sliding_nodes},
                            {"stuck_nodes", run.check.stuck_nodes},
                            {"fabric_file", step_file("fabric", step)},
                            {"bodies_file", step_file("bodies", step)}};
  return {step, cuts, j.dump(), fabric_vtp(run, state), bodies_vtp(run.model)};
}

namespace {

std::string read_whole(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path.string(), 0, ""}, "missing: a finished load step's file, needed to resume");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::vector<StepResult> read_step_results(const std::string& dir) {
  const fs::path json_path = fs::path(dir) / "result.json";
  std::vector<StepResult> steps;
  try {
    const nlohmann::json j = nlohmann::json::parse(read_whole(json_path));
    if (!j.contains("steps")) return steps;
    for (const nlohmann::json& step : j.at("steps")) {
      const int k = step.at("step").get<int>();
      const StepCuts cuts{step.value("cuts", 0), step.value("smallest_fraction", 1.0)};  // a folder from before cuts has none
      steps.push_back({k, cuts, step.dump(), read_whole(fs::path(dir) / step_file("fabric", k)),
                       read_whole(fs::path(dir) / step_file("bodies", k))});
    }
  } catch (const nlohmann::json::exception& error) {
    throw InputError({json_path.string(), 0, "steps"}, std::string("cannot read the finished load steps: ") + error.what());
  }
  return steps;
}

}  // namespace fabform
