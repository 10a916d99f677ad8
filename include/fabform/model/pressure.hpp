#pragma once
// A uniform pressure on the fabric (vacuum forming, or air pressure on a blank), a term of the
// model: a follower load, normal to the fabric as it deforms. Positive P pushes along −n, n the
// faces' normal by the right-hand rule from warp to weft (+z for a fabric laid flat in the x–y
// plane), so a positive pressure presses a blank down onto a mold below it.
// Its potential is Π_p = P·V, V the volume of the cones from a fixed point o to the fabric's
// triangles (a four-sided face is both its splittings into triangles, each at half weight, so
// neither diagonal is preferred). At a node inside the fabric −∂Π_p/∂x is exactly the follower
// load, −P times a third of its triangles' vector areas, and does not depend on o; on an edge
// it would, which is why a scene with pressure must hold the fabric's edge (a clamped blank).
// Its Hessian couples the two ends of each side by a skew block; Newton takes it made positive
// semi-definite side by side (closed form, pressure.cpp).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fabform/fabric/fabric.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

/// The skew coupling ∂²Π_p/∂x_a∂x_b = [s]× between two nodes a < b that share a triangle.
struct PressureCoupling {
  int a = -1;
  int b = -1;
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
};

class PressureLoad final : public Term {
 public:
  /// `reference` is o: any fixed point near the fabric (it keeps the volumes' digits).
  PressureLoad(const Fabric& fabric, double pressure_Pa, const Eigen::Vector3d& reference);

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override;
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;
  bool external() const override { return true; }

  /// The exact Hessian's couplings at x, one per pair of nodes that share a triangle.
  std::vector<PressureCoupling> couplings(const Positions& x) const;

 private:
  struct Triangle {
    std::array<int, 3> node;
    double weight;  // 1, or 1/2 for each of a four-sided face's four triangles
    std::array<int, 3> side = {-1, -1, -1};  // sides_ index of corner → next corner
  };
  double triangle_volume(const Triangle& t, const Positions& x, int moved, const Eigen::Vector3d& at) const;

  double pressure_Pa_;
  Eigen::Vector3d reference_;
  std::vector<Triangle> triangles_;
  std::vector<std::vector<int>> triangles_at_;  // per node: indices into triangles_
  std::vector<std::array<int, 2>> sides_;       // pairs a < b sharing a triangle, sorted
};

}  // namespace fabform
