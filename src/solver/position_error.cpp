#include "fabform/solver/position_error.hpp"

#include <algorithm>
#include <cmath>

namespace fabform {

double largest_move(const std::vector<Eigen::Vector3d>& from, const std::vector<Eigen::Vector3d>& to) {
  double largest = 0.0;
  for (std::size_t i = 0; i < from.size(); ++i) largest = std::max(largest, (to[i] - from[i]).norm());
  return largest;
}

double largest_move(const std::vector<Eigen::Vector3d>& moves) {
  double largest = 0.0;
  for (const Eigen::Vector3d& m : moves) largest = std::max(largest, m.norm());
  return largest;
}

namespace {

// ρ, the factor a sequence falls by per entry from `before` to `now` over `entries`; NaN unless it falls.
double falling_rate(double before, double now, int entries) {
  if (!(now >= 0.0 && now < before)) return std::nan("");
  return std::pow(now / before, 1.0 / entries);
}

// ρ read from ‖V‖∞ over the last `window` iterations or half the history; NaN under three
// records or while ‖V‖∞ does not fall.
double residual_rate(const std::vector<IterationRecord>& history, int window) {
  if (history.size() < 3) return std::nan("");
  window = std::min(window, static_cast<int>(history.size() - 1) / 2);
  const double now = history.back().residual_N;
  const double before = history[history.size() - 1 - static_cast<std::size_t>(window)].residual_N;
  return falling_rate(before, now, window);
}

}  // namespace

double rate_position_error(const std::vector<IterationRecord>& history, double last_move_m) {
  const double rate = residual_rate(history, kRateWindow);
  return last_move_m * rate / (1.0 - rate);
}

double inexact_newton_position_error(double step_m, const std::vector<IterationRecord>& history) {
  return step_m / (1.0 - residual_rate(history, kNewtonRateWindow));
}

double newton_position_error(const std::vector<double>& step_sizes) {
  if (step_sizes.empty()) return std::nan("");
  const double now = step_sizes.back();
  if (step_sizes.size() == 1) return now;
  const int window = std::min(kNewtonRateWindow, static_cast<int>(step_sizes.size()) - 1);
  const double rate = falling_rate(step_sizes[step_sizes.size() - 1 - static_cast<std::size_t>(window)], now, window);
  return now / (1.0 - rate);
}

}  // namespace fabform
