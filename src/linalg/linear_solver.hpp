#pragma once
// Newton's linear solve behind one interface: a sparse Cholesky factorisation (sparse_cholesky.hpp),
// exact, whose time and memory grow as the unknowns' 1.5th power on a fabric grid; or conjugate
// gradients preconditioned by multigrid, to a tolerance, whose cost grows linearly: geometric on
// a fabric's lattice (lattice_multigrid.hpp), algebraic on an arc mesh
// (amg_conjugate_gradient.hpp). `automatic` takes the factorisation on small grids and multigrid
// beyond (the sizes: below).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "linalg/lattice_prolongation.hpp"

namespace fabform {

enum class LinearMethod { automatic, cholesky, multigrid };

/// "auto", "cholesky", "multigrid"; the names a scene's solver.linear_solver takes.
std::string to_string(LinearMethod method);
/// The method a name gives; false for an unknown name.
bool linear_method_named(const std::string& name, LinearMethod* method);

/// From this many unknowns `automatic` takes multigrid. On a lattice it is geometric: for a
/// membrane (no bending term) from 10 000 (on the dome 1.8 × faster than the factorisation at
/// 201 × 201 nodes, and at 101 × 101 too; README), below which the shipped scenes keep the
/// factorisation their goldens were made with (there multigrid was 4 × slower on the Cusick
/// drape and at most 1.2 × faster elsewhere); for a fabric that bends from 200 000, as bending's
/// fourth-order stiffness is what line smoothing and bilinear interpolation serve worst (the
/// Cusick drape at 80 divisions: 3.6 × slower). Elsewhere it is BoomerAMG, no faster than the
/// factorisation below a million.
constexpr int kMembraneMultigridMinUnknowns = 10'000;
constexpr int kLatticeMultigridMinUnknowns = 200'000;
constexpr int kAlgebraicMultigridMinUnknowns = 1'000'000;

/// What `automatic` chooses by.
struct LinearSystemShape {
  int unknowns = 0;
  bool lattice = false;  // the nodes lie on a lattice (multigrid would be geometric)
  bool bending = false;  // the model has a bending term
};

/// The method `method` stands for with a system of this shape (itself unless automatic).
LinearMethod concrete_method(LinearMethod method, const LinearSystemShape& shape);

/// What a solver may know of the unknowns besides the matrix.
struct UnknownLayout {
  std::vector<int> component;              // per unknown: its place in its node's displacement (0, 1, 2)
  std::optional<LatticeUnknowns> lattice;  // when the nodes lie on a lattice: multigrid is geometric
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Takes a symmetric matrix by its lower triangle, every diagonal entry stored. False when the
  /// matrix is found not to be positive definite.
  virtual bool set_matrix(const Eigen::SparseMatrix<double>& lower, const UnknownLayout& layout) = 0;
  /// x with A x = b: exactly, or with ‖b − A x‖₂ ≤ relative_tolerance · ‖b‖₂ for an iterative
  /// method, whose every iterate is a descent direction for ½x'Ax − b'x.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b, double relative_tolerance) = 0;
  virtual LinearMethod method() const = 0;
  /// The method as result.json names it: "cholesky", "multigrid (lattice)" for the geometric
  /// hierarchy, "multigrid (algebraic)" for BoomerAMG's.
  virtual std::string name() const = 0;
  /// Inner iterations over every solve so far (0 for a direct method).
  virtual long iterations() const = 0;
};

/// A solver of a concrete method (not automatic).
std::unique_ptr<LinearSolver> make_linear_solver(LinearMethod method);

}  // namespace fabform
