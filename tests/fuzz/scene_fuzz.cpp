// libFuzzer target: any bytes as a scene file. Bad input must become an InputError; anything
// else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fabform/error.hpp"
#include "fabform/scene/scene_toml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    fabform::parse_scene(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml");
  } catch (const fabform::InputError&) {
  }
  return 0;
}
