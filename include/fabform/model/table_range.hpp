#pragma once
// Beyond a table's last measured point fabform extends the last segment; a run says so,
// because the answer there is an extrapolation, not a measurement. And where springs of a
// tension-only table are compressed to less than half their length, the fabric has folded
// flat (nothing in the model resists it): a run says that too, as its rest is degenerate.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

/// One line per direction whose springs leave the measured range at positions x, and one per
/// direction whose tension-only springs are compressed below −50 %.
std::vector<std::string> table_range_warnings(const Model& model,
                                              const std::vector<Eigen::Vector3d>& x);

}  // namespace fabform
