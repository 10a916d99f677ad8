#pragma once
// Turns a validated Scene into a Model: reads the material tables and meshes, places the
// bodies, selects the constrained nodes and lays out the initial deformation, checking that the
// fabric starts clear of every body (seed 003, §3.1).
#include "fabform/model/model.hpp"
#include "fabform/scene/scene.hpp"

namespace fabform {

/// Throws InputError naming the file, line and key of the first problem.
Model build_model(const Scene& scene);

/// The same, with the bodies made from `placed_from`'s meshes as placed instead of read again:
/// for a model of the same scene on another grid (run/coarse_grid_start.cpp), whose bodies do not
/// travel. `placed_from` may be null (read them).
Model build_model(const Scene& scene, const Model* placed_from);

/// The scene with its solver's e in newtons: a tolerance relative to the fabric's force scale
/// (solver.tolerance_relative) times that scale. Throws InputError at the key when the model's
/// fabric has no force scale (stretch tables that start slack).
Scene with_tolerance_in_newtons(Scene scene, const Model& model);

}  // namespace fabform
