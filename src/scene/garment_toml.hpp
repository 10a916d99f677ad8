#pragma once
// A garment in a scene: [fabric] shape = "panels" with its lattice spacing and its panels, given
// as [[fabric.panel]] tables or read from a sewing pattern ([garment] pattern), and [[seam]]
// tables sewing panel edges (the pattern's stitches too). Internal to the scene parser.
#include <vector>

#include "fabform/scene/scene.hpp"
#include "scene/toml_table_reader.hpp"

namespace fabform {

/// [fabric] of shape "panels": spacing_m and the [[fabric.panel]] tables, if any.
void read_panels(TableReader& fabric, Scene* scene);

/// [garment]: pattern (a GarmentCode *_specification.json), its panels' grain_deg and the turn
/// of its world into the scene's (rotation_deg); its panels become the fabric's (which must be
/// of shape "panels" and give none itself), its stitches seams.
void read_garment(TableReader garment, Scene* scene);

/// A fabric of panels has some, each within kMaxCellsAcross cells of the spacing across it (a
/// spacing in the wrong unit is refused before anything is traced), and a pattern's stitches sew
/// edges of about one length.
void check_panels(TableReader& fabric, Scene* scene);

/// The [[seam]] tables, after the panels are checked.
void read_seams(std::vector<TableReader> seams, Scene* scene);

/// The panels meshed, so that a lattice too coarse for an outline is an error of the scene
/// (blamed on spacing_m), not of the model built from it; the fabric's extent then set from the
/// lattice.
void mesh_panels(TableReader& fabric, Scene* scene);

}  // namespace fabform
