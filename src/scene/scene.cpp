#include "fabform/scene/scene.hpp"

namespace fabform {

const std::vector<std::string>& solver_names() {
  static const std::vector<std::string> names = {"relax", "dynamic", "newton"};
  return names;
}

}  // namespace fabform
