#include "fabform/study/result_figures.hpp"

#include <algorithm>

namespace fabform {
namespace {

// Strain peaks are objects; their figure is the strain.
const char* const kPeaks[] = {"figures.max_warp_strain", "figures.max_weft_strain", "figures.min_warp_strain",
                              "figures.min_weft_strain"};

bool is_peak(const std::string& path) {
  return std::find(std::begin(kPeaks), std::end(kPeaks), path) != std::end(kPeaks);
}

}  // namespace

std::vector<std::string> result_figure_paths(const Scene& scene) {
  std::vector<std::string> paths = {
      "iterations", "residual_N", "residual_recomputed_N", "tolerance_N", "force_scale_N", "tolerance_relative",
      "position_error_m",
      "residual_relative", "wall_seconds", "solve_seconds", "threads", "nodes", "contact_nodes",
      "max_penetration_m", "figures.area_flat_m2", "figures.area_formed_m2", "figures.contact_area_m2",
      "figures.draw_in_max_m", "figures.springs_cutting_bodies", "figures.springs_over_edges",
      "figures.deepest_spring_cut_m", "figures.sliding_nodes", "figures.stuck_nodes", "figures.shear_angle_max_deg",
      "figures.thickness_ratio_min", "figures.wrinkle_cells", "figures.locking_angle_deg", "figures.contact_pressure_max_Pa",
      "figures.contact_pressure_max_mmHg", "figures.contact_pressure_mean_Pa", "figures.contact_pressure_mean_mmHg",
      "fabric.nodes", "fabric.faces", "continuation_levels",
      "fabric.springs.warp", "fabric.springs.weft", "fabric.springs.shear", "fabric.springs.bend"};
  for (const char* peak : kPeaks) {
    paths.emplace_back(peak);
    paths.push_back(std::string(peak) + ".strain");
  }
  if (scene.solver.name == "newton") paths.emplace_back("linear_iterations");  // its linear solve's
  if (scene.drape.on)
    for (const char* p : {"drape_coefficient", "drape.coefficient", "drape.shadow_area_m2", "drape.specimen_area_m2",
                          "drape.support_area_m2", "drape.folds", "drape.shadow_pieces"})
      paths.emplace_back(p);
  if (scene.self_contact.on)
    for (const char* p : {"self_contact.thickness_m", "self_contact.contact_pairs", "self_contact.smallest_gap_m",
                          "self_contact.intersecting_triangle_pairs"})
      paths.emplace_back(p);
  if (std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const BodySpec& b) { return b.path.moves(); }))
    paths.emplace_back("load_steps");
  return paths;
}

std::string figure_pointer(const std::string& path) {
  std::string pointer = "/" + path;
  std::replace(pointer.begin(), pointer.end(), '.', '/');
  return is_peak(path) ? pointer + "/strain" : pointer;
}

}  // namespace fabform
