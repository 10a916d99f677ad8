#pragma once
// The fabric's springs as terms of the model: each spring of rest length L and width w carries
// w·T(ε) along itself and stores w·L·∫₀^ε T (spring.hpp), T its kind's table. Three roles, each
// its own term: stretch (the warp and weft springs, seed 003's Eq. 1), shear (seed 004's
// diagonal springs, the bias response) and bend (seed 004's skip-one springs).
#include <string>

#include "fabform/fabric/fabric.hpp"
#include "fabform/model/term.hpp"

namespace fabform {

class SpringTerm final : public Term {
 public:
  enum class Role { stretch, shear, bend };
  explicit SpringTerm(Role role) : role_(role) {}

  Role role() const { return role_; }
  /// Whether a spring of this kind is one of the term's.
  bool covers(SpringKind kind) const;

  std::string describe(const Model& model) const override;
  Eigen::Vector3d force_at(const Model& model, const Positions& x, int node,
                           const Eigen::Vector3d& at) const override;
  double energy(const Model& model, const Positions& x) const override;
  double node_energy_change(const Model& model, const Positions& x, int node,
                            const Eigen::Vector3d& at) const override;
  /// Each spring's 3 × 3 stiffness projected positive semi-definite (spring_energy.hpp).
  void add_stiffness(const Model& model, const Positions& x, StiffnessSink& sink) const override;
  /// k = w·T'/L from the steepest segment of the spring's table, which bounds its stiffness at
  /// every strain, across it as well as along it.
  void bound_stiffness(const Model& model, StiffnessBound& bound) const override;
  bool resists_bending() const override { return role_ == Role::bend; }

 private:
  double node_energy(const Model& model, const Positions& x, int node, const Eigen::Vector3d& at) const;

  Role role_;
};

}  // namespace fabform
