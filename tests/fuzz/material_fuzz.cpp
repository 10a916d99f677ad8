// libFuzzer target: any bytes as a material table. Bad input must become an InputError;
// anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fabform/error.hpp"
#include "fabform/material/material_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const fabform::TensionTable table = fabform::parse_material_table(in, "fuzz.csv");
    // Whatever was accepted must evaluate without trouble across and beyond its range.
    for (const double strain : {-1.0, 0.0, 0.5, 1e3}) {
      (void)table.tension(strain);
      (void)table.energy_density(strain);
    }
  } catch (const fabform::InputError&) {
  }
  return 0;
}
