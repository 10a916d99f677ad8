#pragma once
// How far a state is from the exact rest, in metres: what a tolerance in newtons does not say.
// newton's estimate is the step it would take next, δ = K⁻¹R with K the matrix it factorises
// (x* − x = δ to second order near the rest, exactly on a linear problem); newton.cpp takes it,
// as it holds the factorisation. relax and dynamic have no matrix, and a node's |V_i| over its
// own stiffness says little (the slow modes they leave last are shapes over many nodes, held by
// the fabric's tension alone: on the dome, 600 to 5000 times further than that), so their
// estimate is the rest of a geometric series: their tail converges linearly, each iteration
// ρ times the last, and the moves still to come sum to Δ·ρ/(1 − ρ), Δ the last iteration's
// largest node move, ρ read from ‖V‖∞ over the last iterations. It holds while one slow mode
// leads; it has no figure while ‖V‖∞ does not fall.
#include <vector>

#include <Eigen/Core>

#include "fabform/solver/summary.hpp"

namespace fabform {

/// The largest node move between two states of the same nodes (m); 0 for none.
double largest_move(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to);

/// The largest node move of a displacement field (m); 0 for none.
double largest_move(const std::vector<Eigen::Vector3d>& moves);

/// The iterations ρ is read over: enough to smooth a sweep's or an oscillation's jitter, few
/// enough to follow the tail as it settles.
constexpr int kRateWindow = 20;

/// relax's and dynamic's estimate after the history's last iteration, whose largest node move
/// was `last_move_m`: Δ·ρ/(1 − ρ), ρ = (‖V‖∞ now / ‖V‖∞ w iterations back)^(1/w), w the window
/// or half the history. NaN while the history is under two iterations or ‖V‖∞ is not falling.
double rate_position_error(const std::vector<IterationRecord>& history, double last_move_m);

}  // namespace fabform
