#include "fabform/solver/stop_settings.hpp"

#include <cmath>

namespace fabform {

std::string StopSettings::invalid_reason(std::string* field) const {
  const auto bad = [&](const char* name, const char* why) {
    if (field) *field = name;
    return std::string(why);
  };
  if (!(std::isfinite(tolerance_N) && tolerance_N > 0.0))
    return bad("tolerance_N", "must be a positive, finite force");
  if (!(std::isfinite(tolerance_m) && tolerance_m >= 0.0))
    return bad("tolerance_m", "must be a positive, finite distance (or 0: none)");
  if (max_iterations < 0) return bad("max_iterations", "must not be negative");
  return "";
}

}  // namespace fabform
