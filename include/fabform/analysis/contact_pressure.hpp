#pragma once
// The pressure the formed fabric puts on the bodies: at each fabric node on a body, the body's
// normal reaction λ (equilibrium.hpp's pressing_force, the force with which the node's resultant
// presses it on) over the node's tributary area in the formed fabric (its faces' formed areas
// shared equally among their corners), in Pa. A band of tension T round a cylinder of radius r
// presses p = T / r (Laplace). Each vertex of a body takes the pressure of the nearest fabric
// node on it, within that node's longest warp or weft side (else 0), so the body can be coloured
// by it. A spring wrapped over a body's sharp edge presses on the edge between its nodes; half
// of that force counts at each node. On the edge itself that is a line load (N/m), which no
// finite pressure describes: spread over the cells beside it, it grows as the mesh is refined.
#include <vector>

#include <Eigen/Core>

#include "fabform/model/model.hpp"

namespace fabform {

constexpr double kPascalPerMmHg = 133.322387415;  // 1 mmHg, by definition of the conventional millimetre of mercury

struct ContactPressure {
  std::vector<double> node_Pa;                  // per fabric node; 0 off the bodies
  std::vector<std::vector<double>> body_vertex_Pa;  // per body, per vertex of its posed mesh
  double max_Pa = 0.0;
  int max_node = -1;                            // -1: no node presses on a body
  double mean_Pa = 0.0;                         // the contact force over the area of the nodes that press
};

/// The pressure at `x`; `contact` flags the nodes on a body (EquilibriumReport::contact).
ContactPressure contact_pressure(const Model& model, const std::vector<Eigen::Vector3d>& x,
                                 const std::vector<unsigned char>& contact);

}  // namespace fabform
