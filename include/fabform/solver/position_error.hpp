#pragma once
// How far a state is from the exact rest, in metres: what a tolerance in newtons does not say.
// Each estimate is the sum of the moves still to come. newton's starts from the step it would
// take next, δ = K⁻¹R with K the matrix it factorises (x* − x = δ to second order, exactly on a
// linear problem; newton.cpp takes it, as it holds the factorisation); but while nodes still land
// on or leave a body its tail converges linearly, each step ρ times the last, and the steps still
// to come sum to |δ|/(1 − ρ), ρ read from the last steps' sizes (on the dome at 201 × 201 nodes,
// |δ| alone was a quarter of the distance). After inexact steps (multigrid's conjugate
// gradients, loose far from the rest) a loose step's size says little, so ρ is read from ‖V‖∞
// instead, and δ is solved more tightly than they were (newton.cpp's kEstimateForcing). relax and
// dynamic have no matrix, and a node's |V_i| over its own stiffness says little (the slow shapes
// they leave last are held by the fabric's tension alone: on the dome, 530 to 700 times further
// than that); their tail converges linearly, and the moves still to come sum to Δ·ρ/(1 − ρ), Δ the
// last iteration's largest node move, ρ read from ‖V‖∞ over the last iterations. Each holds while
// one slow shape leads; none has a figure while what it reads ρ from does not fall.
#include <vector>

#include <Eigen/Core>

#include "fabform/solver/summary.hpp"

namespace fabform {

/// The largest node move between two states of the same nodes (m); 0 for none.
double largest_move(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to);

/// The largest node move of a displacement field (m); 0 for none.
double largest_move(const std::vector<Eigen::Vector3d>& moves);

/// The iterations ρ is read over: enough to smooth a sweep's or an oscillation's jitter (relax,
/// dynamic) or a contact set's churn (newton, whose iterations are fewer), few enough to follow
/// the tail as it settles.
constexpr int kRateWindow = 20;
constexpr int kNewtonRateWindow = 10;

/// relax's and dynamic's estimate after the history's last iteration, whose largest node move
/// was `last_move_m`: Δ·ρ/(1 − ρ), ρ = (‖V‖∞ now / ‖V‖∞ w iterations back)^(1/w), w the window
/// or half the history. NaN while the history is under two iterations or ‖V‖∞ is not falling.
double rate_position_error(const std::vector<IterationRecord>& history, double last_move_m);

/// newton's estimate when its steps were solved loosely (inexact Newton far from the rest: a
/// loose step leaves out the slow shapes, so its size says little of the distance): |δ|/(1 − ρ),
/// `step_m` the step from the current state solved more tightly, ρ = (‖V‖∞ now / ‖V‖∞ w iterations
/// back)^(1/w), w the window or half the history. NaN while the history is under two iterations
/// or ‖V‖∞ is not falling.
double inexact_newton_position_error(double step_m, const std::vector<IterationRecord>& history);

/// newton's estimate from the sizes of the steps it proposed from each state in turn (m), the
/// last from the current state: |δ|/(1 − ρ), ρ = (|δ| / size w steps back)^(1/w), w the window
/// or what the sizes hold; |δ| alone with one size. NaN without a size or when they do not fall.
double newton_position_error(const std::vector<double>& step_sizes);

}  // namespace fabform
