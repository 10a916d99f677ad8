#pragma once
// Newton's matrix: the sum of the model's terms' stiffness (term.hpp), each positive
// semi-definite, in the nodes' free directions (free_directions.hpp).
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "fabform/model/model.hpp"
#include "solver/free_directions.hpp"

namespace fabform {

/// Lower triangle only (what Eigen's SimplicialLDLT reads); every diagonal entry is stored,
/// so a regularisation can be added to it in place. `lagged` is a term Newton holds for one
/// iteration (friction), added to the model's own.
Eigen::SparseMatrix<double> reduced_hessian(const Model& model,
                                            const std::vector<Eigen::Vector3d>& x,
                                            const FreeDirections& directions,
                                            const Term* lagged = nullptr);

}  // namespace fabform
