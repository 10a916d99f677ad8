#pragma once
// The figures a run's results are written from, each computed once from the state written:
// result.json, fabric.vtk, bodies.vtk and a load step's files only write them
// (result_writer.hpp). Every state written has its StateFigures; the final state adds its
// cells' (CellFigures), which a load step's files do not carry.
#include "fabform/analysis/cell_deformation.hpp"
#include "fabform/analysis/contact_pressure.hpp"
#include "fabform/analysis/draw_in.hpp"
#include "fabform/analysis/fabric_figures.hpp"
#include "fabform/analysis/garment_ease.hpp"
#include "fabform/model/spring_strains.hpp"
#include "fabform/output/result_writer.hpp"

namespace fabform {

struct StateFigures {
  FabricFigures fabric;      // strain peaks and histogram, areas
  NodeStrains strains;       // per node
  DrawIn draw_in;
  ContactPressure pressure;  // on the nodes and on the bodies' vertices
  std::optional<GarmentEase> ease;  // a garment's, on a body
};

struct CellFigures {
  CellDeformation deformation;       // shear angle, thickness ratio and wrinkle risk per face
  CellDeformationOptions options;    // the locking angle the shear was judged by
  const char* locking_from = "";     // where that angle came from: "shear table", "scene" or "default"
};

/// The figures of the run's state, its contact as the run's check found it.
StateFigures state_figures(const RunRecord& run);

/// The cells of the run's state. The locking angle is the shear table's when it has one (it
/// stiffens), else the scene's fabric.locking_angle_deg, else CellDeformationOptions' default.
CellFigures cell_figures(const RunRecord& run);

}  // namespace fabform
