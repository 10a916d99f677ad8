// libFuzzer target: any bytes as an X3D file, translated to VRML97 (what is done with them: fuzz_inputs.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fabform::fuzz::x3d(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
