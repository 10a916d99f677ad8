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

/// [garment]: pattern (a GarmentCode *_specification.json), its panels' grain_deg; its panels
/// become the fabric's (which must be of shape "panels" and give none itself), its stitches seams.
void read_garment(TableReader garment, Scene* scene);

/// The [[seam]] tables, after the panels.
void read_seams(std::vector<TableReader> seams, Scene* scene);

/// The panels meshed once, so that a lattice too coarse for an outline is an error of the scene
/// (blamed on spacing_m); the fabric's extent then set from the lattice.
void mesh_panels(TableReader& fabric, Scene* scene);

}  // namespace fabform
