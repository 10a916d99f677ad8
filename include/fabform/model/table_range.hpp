#pragma once
// Beyond a table's last measured point fabform extends the last segment; a run says so,
// because the answer there is an extrapolation, not a measurement.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

/// One line per direction whose springs leave the measured range at positions x.
std::vector<std::string> table_range_warnings(const Model& model,
                                              const std::vector<Eigen::Vector3d>& x);

}  // namespace fabform
