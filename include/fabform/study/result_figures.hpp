#pragma once
// The figures a study can collect: result.json's numbers by their dotted path (the schema
// src/output/result_writer.cpp writes), known before any case runs, so that a path no result
// has is refused at once.
#include <string>
#include <vector>

#include "fabform/scene/scene.hpp"

namespace fabform {

/// The dotted paths of the numbers the run of `scene` writes into result.json: those of every
/// run, and a drape test's or a run in load steps' own. A strain peak
/// (figures.max_warp_strain) stands for its strain.
std::vector<std::string> result_figure_paths(const Scene& scene);

/// The JSON pointer of a figure's number: "/figures/max_warp_strain/strain" for the path
/// "figures.max_warp_strain".
std::string figure_pointer(const std::string& path);

}  // namespace fabform
