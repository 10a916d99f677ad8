#pragma once
// Turns a validated Scene into a Model: reads the material tables and meshes, places the
// bodies, selects the constrained nodes and lays out the initial deformation, checking that the
// fabric starts clear of every body (seed 003, §3.1).
#include "fabform/model/model.hpp"
#include "fabform/scene/scene.hpp"

namespace fabform {

/// Throws InputError naming the file, line and key of the first problem.
Model build_model(const Scene& scene);

}  // namespace fabform
