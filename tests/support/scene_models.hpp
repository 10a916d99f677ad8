#pragma once
// A scene written into a test's folder and built into a model, or the bad-input error building
// it raises (a test that expected one and got none fails).
#include <gtest/gtest.h>

#include <string>

#include "fabform/error.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "support/temp_dir.hpp"

namespace fabform::test {

inline Model build_scene(const TempDir& dir, const std::string& text) {
  return build_model(load_scene(dir.write("scene.toml", text)));
}

inline InputError scene_error(const TempDir& dir, const std::string& text) {
  try {
    build_scene(dir, text);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return InputError({}, "");
}

}  // namespace fabform::test
