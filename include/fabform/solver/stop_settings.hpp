#pragma once
// What stops a run, whichever solver runs it: every solver's options hold these under the same
// names, so the loop they share (solver_loop.hpp) and the registry (solver_registry.hpp) read
// and set them alike, and they are validated once, here.
#include <string>

namespace fabform {

struct StopSettings {
  double tolerance_N = 0.0;  // e: stop when ‖V‖∞ ≤ e
  double tolerance_m = 0.0;  // > 0: stop too when the distance from the rest is estimated within it
  int max_iterations = 0;    // the iteration cap

  /// Why a run cannot stop by these ("" when it can); the offending field's name in `*field`.
  std::string invalid_reason(std::string* field = nullptr) const;
};

/// A solver's options' stop settings.
template <class Options>
StopSettings stop_settings(const Options& options) {
  return {options.tolerance_N, options.tolerance_m, options.max_iterations};
}

/// Gives a solver's options these stop settings.
template <class Options>
void set_stop_settings(Options& options, const StopSettings& stop) {
  options.tolerance_N = stop.tolerance_N;
  options.tolerance_m = stop.tolerance_m;
  options.max_iterations = stop.max_iterations;
}

}  // namespace fabform
