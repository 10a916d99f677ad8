// libFuzzer target: any bytes as an X3D file, translated to VRML97. Bad input must become an
// InputError; anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fabform/error.hpp"
#include "io/x3d_translation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const fabform::X3dTranslation t =
        fabform::translate_x3d_text(std::string(reinterpret_cast<const char*>(data), size), "fuzz.x3d");
    // What is written is VRML97: it starts with the header and holds no raw control bytes.
    if (t.vrml.rfind("#VRML V2.0 utf8\n", 0) != 0) __builtin_trap();
    for (const char c : t.vrml)
      if (static_cast<unsigned char>(c) < ' ' && c != '\n') __builtin_trap();
  } catch (const fabform::InputError&) {
  }
  return 0;
}
