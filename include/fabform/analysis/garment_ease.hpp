#pragma once
// A garment's ease, the figure a fitter reads: how far each node of its panels stands off the
// body, the distance to the nearest body's surface (0 where it touches, negative inside), and
// per panel its mean over the panel's area and its largest. Only a fabric of panels has it.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

struct PanelEase {
  std::string panel;
  double mean_m = 0.0;  // weighted by the nodes' flat areas
  double max_m = 0.0;
};

struct GarmentEase {
  std::vector<double> node_m;  // per node
  std::vector<PanelEase> panels;
};

/// The ease at positions x, or none for a fabric that is no garment's panels or a scene
/// without a body.
std::optional<GarmentEase> garment_ease(const Model& model, const std::vector<Eigen::Vector3d>& x);

}  // namespace fabform
