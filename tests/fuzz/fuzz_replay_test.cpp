// Every fuzz target's corpus and every input that ever crashed one (tests/fuzz/regressions/TARGET/,
// where tools/fuzz.sh leaves them) replayed through the same code as the libFuzzer targets: bad
// input becomes an InputError, nothing else escapes. The fuzzing itself, for minutes per parser,
// is tools/fuzz.sh's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "fuzz/fuzz_inputs.hpp"
#include "test_paths.hpp"

namespace fabform::fuzz_replay_test {
namespace {

namespace fs = std::filesystem;

using Target = void (*)(std::string_view);

int replay(const std::string& target, Target run) {
  int inputs = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = test::source_path(std::string("tests/fuzz/") + kind + "/" + target);
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().filename() == ".keep") continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::ostringstream bytes;
      bytes << in.rdbuf();
      SCOPED_TRACE(entry.path().string());
      EXPECT_NO_THROW(run(bytes.str()));
      ++inputs;
    }
  }
  return inputs;
}

TEST(FuzzReplay, Scene) { EXPECT_GT(replay("scene", fuzz::scene), 0); }
TEST(FuzzReplay, Material) { EXPECT_GT(replay("material", fuzz::material), 0); }
TEST(FuzzReplay, X3d) { EXPECT_GT(replay("x3d", fuzz::x3d), 0); }
TEST(FuzzReplay, Study) { EXPECT_GT(replay("study", fuzz::study), 0); }

// The study target reads a valid study as one: the fixture folder holds what it names.
TEST(FuzzReplay, StudyFixtureAcceptsAValidStudy) {
  const std::string text = "[study]\nscene = \"scene.toml\"\nfigures = [\"iterations\"]\n[grid]\n\"fabric.divisions\" = [[4, 4], [6, 6]]\n";
  EXPECT_EQ(parse_study(text, fuzz::study_folder().study_path()).cases.size(), 2u);
}

}  // namespace
}  // namespace fabform::fuzz_replay_test
