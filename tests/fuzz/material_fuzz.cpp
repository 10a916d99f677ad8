// libFuzzer target: any bytes as a material table (what is done with them: fuzz_inputs.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_inputs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fabform::fuzz::material(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
