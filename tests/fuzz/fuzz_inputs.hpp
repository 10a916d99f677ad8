#pragma once
// What each fuzz target does with its bytes, shared by the libFuzzer targets (tools/fuzz.sh) and
// the replay of their corpus and regressions in the test suite (fuzz_replay_test.cpp). Bad input
// must become an InputError, caught here; anything else (a crash, a sanitizer report, another
// exception, a trap) is a bug.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

#include <unistd.h>

#include "fabform/error.hpp"
#include "fabform/material/material_csv.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/study/study_file.hpp"
#include "io/x3d_translation.hpp"

namespace fabform::fuzz {

inline void scene(std::string_view bytes) {
  try {
    parse_scene(bytes, "fuzz.toml");
  } catch (const InputError&) {
  }
}

inline void material(std::string_view bytes) {
  std::istringstream in{std::string(bytes)};
  try {
    const MaterialFile file = parse_material_file(in, "fuzz.csv");
    // Whatever was accepted must evaluate without trouble across and beyond its range.
    for (const double strain : {-1.0, 0.0, 0.5, 1e3}) {
      (void)file.table.tension(strain);
      (void)file.table.energy_density(strain);
    }
  } catch (const InputError&) {
  }
}

inline void x3d(std::string_view bytes) {
  try {
    const X3dTranslation t = translate_x3d_text(std::string(bytes), "fuzz.x3d");
    // What is written is VRML97: it starts with the header and holds no raw control bytes.
    if (t.vrml.rfind("#VRML V2.0 utf8\n", 0) != 0) __builtin_trap();
    for (const char c : t.vrml)
      if (static_cast<unsigned char>(c) < ' ' && c != '\n') __builtin_trap();
  } catch (const InputError&) {
  }
}

// A study names its base scene beside it: the study's bytes are read as a file in a folder that
// holds a small scene (scene.toml) and its table, made once per process.
class StudyFolder {
 public:
  StudyFolder() : dir_(std::filesystem::temp_directory_path() / ("fabform-fuzz-study-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(dir_);
    std::ofstream(dir_ / "table.csv") << "strain,tension_N_per_m\n0,0\n1,500\n";
    std::ofstream(dir_ / "scene.toml") << "[fabric]\nsize_m = [0.1, 0.1]\ndivisions = [4, 4]\n"
                                          "warp = \"table.csv\"\nweft = \"table.csv\"\n"
                                          "[[constraint]]\nnodes = \"perimeter\"\n";
  }
  ~StudyFolder() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  std::string study_path() const { return (dir_ / "fuzz_study.toml").string(); }

 private:
  std::filesystem::path dir_;
};

inline const StudyFolder& study_folder() {
  static const StudyFolder folder;
  return folder;
}

inline void study(std::string_view bytes) {
  try {
    parse_study(bytes, study_folder().study_path());
  } catch (const InputError&) {
  }
}

}  // namespace fabform::fuzz
