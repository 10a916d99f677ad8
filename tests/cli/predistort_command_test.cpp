// fabform predistort on a real run: the print of a checkerboard, seen back through the run's
// map, is the checkerboard within one pixel; bad input is one line naming the file, with
// nothing written.
#include <gtest/gtest.h>

#include <filesystem>

#include "fabform/analysis/print_map.hpp"
#include "fabform/io/obj_text.hpp"
#include "fabform/io/png_image.hpp"
#include "fabform/output/print_map_files.hpp"
#include "support/cli.hpp"
#include "support/print_round_trip.hpp"
#include "support/shapes.hpp"

namespace fabform::predistort_command_test {
namespace {

using test::run_fabform;

// A clamped square pressed over a sphere 3 cm high: its middle moves in by millimetres, pixels.
class PredistortCommand : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir;
    dir_->write("table.csv", "# linear test table\nstrain,tension_N_per_m\n0,0\n1,500\n");
    dir_->write("sphere.obj", obj_text(test::uv_sphere({0.05, 0.05, 0.0}, 0.03, 20, 40)));
    dir_->write("scene.toml",
                "[fabric]\nsize_m = [0.1, 0.1]\ndivisions = [20, 20]\n"
                "warp = \"table.csv\"\nweft = \"table.csv\"\n"
                "[[body]]\nmesh = \"sphere.obj\"\nunits = \"m\"\n"
                "[[constraint]]\nnodes = \"perimeter\"\n"
                "[initial]\nshape = \"lift\"\nheight_m = 0.04\n"
                "[solver]\ntolerance_N = 1e-5\n");
    ASSERT_EQ(run_fabform(*dir_, "run scene.toml --out out --quiet").status, 0);
    dir_->write("design.png", png_bytes(checkerboard(200, 200, 10)));
  }
  static void TearDownTestSuite() { delete dir_; }
  static test::TempDir* dir_;
};

test::TempDir* PredistortCommand::dir_ = nullptr;

TEST_F(PredistortCommand, CheckerboardReturnsWithinOnePixel) {
  const test::Outcome o = run_fabform(*dir_, "predistort out design.png print.png");
  ASSERT_EQ(o.status, 0) << o.err;
  const Image design = read_png(dir_->path("design.png"));
  const Image print = read_png(dir_->path("print.png"));
  EXPECT_EQ(print.width, 200);
  EXPECT_NE(print.rgba, design.rgba);
  const PrintMap map = read_blank_obj(dir_->path("out/blank.obj"));
  const test::RoundTrip trip = test::round_trip(design, formed_view(map, print));
  EXPECT_GT(trip.covered, 0.8 * 200 * 200);
  EXPECT_LE(trip.worst_px, 1) << trip.wrong << " pixels off";
  std::printf("predistort round trip: %d of %d pixels off, the farthest %d px from its square\n", trip.wrong,
              trip.covered, trip.worst_px);
  for (const char* file : {"formed.obj", "formed.mtl", "blank.mtl", "uv_grid.png", "bodies.vtk"})
    EXPECT_TRUE(std::filesystem::exists(dir_->path(std::string("out/") + file))) << file;
}

TEST_F(PredistortCommand, BadInputIsOneLineNamingTheFileAndWritesNothing) {
  dir_->write("not.png", "not an image\n");
  std::filesystem::create_directories(dir_->path("empty"));
  const std::pair<std::string, std::string> cases[] = {
      {"predistort out not.png bad1.png", "not.png"},
      {"predistort out nowhere.png bad2.png", "nowhere.png"},
      {"predistort empty design.png bad3.png", "empty/blank.obj"},
      {"predistort out design.png no/such/folder/bad4.png", "no/such/folder/bad4.png"},
      {"predistort out design.png", "usage"}};
  for (const auto& [arguments, named] : cases) {
    const test::Outcome o = run_fabform(*dir_, arguments);
    EXPECT_EQ(o.status, 2) << arguments;
    EXPECT_EQ(test::error_line_count(o.err), 1) << o.err;
    EXPECT_NE(o.err.find(named), std::string::npos) << arguments << ": " << o.err;
  }
  for (const char* file : {"bad1.png", "bad2.png", "bad3.png", "no"})
    EXPECT_FALSE(std::filesystem::exists(dir_->path(file))) << file;
  for (const auto& entry : std::filesystem::directory_iterator(dir_->root()))
    EXPECT_NE(entry.path().extension(), ".tmp") << "a temporary file was left: " << entry.path();
}

}  // namespace
}  // namespace fabform::predistort_command_test
