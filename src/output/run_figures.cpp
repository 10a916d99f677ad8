#include "fabform/output/run_figures.hpp"

#include <optional>
#include <utility>

#include "fabform/analysis/locking_angle.hpp"

namespace fabform {
namespace {

std::pair<CellDeformationOptions, const char*> deformation_options(const RunRecord& run) {
  CellDeformationOptions options;
  if (run.model.shear)
    if (const std::optional<double> locking = locking_angle_deg(*run.model.shear); locking && *locking > 0.0 && *locking < 90.0) {
      options.locking_angle_deg = *locking;
      return {options, "shear table"};
    }
  if (run.scene.locking_angle_deg) {
    options.locking_angle_deg = *run.scene.locking_angle_deg;
    return {options, "scene"};
  }
  return {options, "default"};
}

}  // namespace

StateFigures state_figures(const RunRecord& run) {
  const std::vector<Eigen::Vector3d>& x = run.state.x;
  return {fabric_figures(run.model, x, run.check.contact), node_strains(run.model, x), draw_in(run.model, x),
          contact_pressure(run.model, x, run.check.contact), garment_ease(run.model, x)};
}

CellFigures cell_figures(const RunRecord& run) {
  const auto [options, locking_from] = deformation_options(run);
  return {cell_deformation(run.model, run.state.x, options), options, locking_from};
}

}  // namespace fabform
