// Garments in a scene: panels, seams and GarmentCode patterns read, their bad input refused by
// file, line and key; two panels sewn rest where one panel of their union rests; GarmentCode's
// shirt placed round its body with every stitch's ends meeting, as the pattern draws them.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fabform/model/seam.hpp"
#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "fabform/solver/solve.hpp"
#include "support/temp_dir.hpp"
#include "test_paths.hpp"

namespace fabform::garment_toml_test {
namespace {

// A 20 × 10 cm knit hung between its two short sides, as one panel or as two sewn in the middle.
std::string hung(bool two_panels) {
  std::string text =
      "[fabric]\n"
      "shape = \"panels\"\n"
      "spacing_m = 0.01\n"
      "warp = \"../materials/white-swim-solid_warp.csv\"\n"
      "weft = \"../materials/white-swim-solid_weft.csv\"\n";
  if (two_panels)
    text +=
        "[[fabric.panel]]\n"
        "name = \"left\"\n"
        "vertices_m = [[0.0, 0.0], [0.1, 0.0], [0.1, 0.1], [0.0, 0.1]]\n"
        "[[fabric.panel]]\n"
        "name = \"right\"\n"
        "vertices_m = [[0.1, 0.0], [0.2, 0.0], [0.2, 0.1], [0.1, 0.1]]\n"
        "[[seam]]\n"
        "name = \"middle\"\n"
        "a = [\"left\", 1]\n"
        "b = [\"right\", 3]\n"
        // The panels lie side by side in the flat layout, a lattice column apart: the right one
        // spans x = 0.12 … 0.22 there.
        "[[constraint]]\n"
        "box_m = [[-0.001, -0.001], [0.001, 0.101]]\n"
        "[[constraint]]\n"
        "box_m = [[0.219, -0.001], [0.221, 0.101]]\n";
  else
    text +=
        "[[fabric.panel]]\n"
        "name = \"whole\"\n"
        "vertices_m = [[0.0, 0.0], [0.2, 0.0], [0.2, 0.1], [0.0, 0.1]]\n"
        "[[constraint]]\n"
        "box_m = [[-0.001, -0.001], [0.001, 0.101]]\n"
        "[[constraint]]\n"
        "box_m = [[0.199, -0.001], [0.201, 0.101]]\n";
  text +=
      "[gravity]\n"
      "[solver]\n"
      "name = \"newton\"\n"
      "tolerance_N = 1e-10\n";
  return text;
}

std::string scene_path() { return test::source_path("scenes/garment.toml"); }

struct Rest {
  Model model;
  SolverState state;
};

Rest rest_of(const std::string& text) {
  const Scene scene = parse_scene(text, scene_path());
  Rest r{build_model(scene), {}};
  r.state = SolverState::at_start(r.model);
  const Summary summary = solve(r.model, r.state, scene.solver);
  EXPECT_TRUE(summary.converged()) << summary.message;
  return r;
}

// Where a panel's node lies in the pattern's plane.
Eigen::Vector2d pattern_point(const Fabric& f, int node) {
  for (const PanelMesh& p : f.panels())
    if (node >= p.first_node && node < p.first_node + p.node_count) return p.plane_point(f.rest_position(node));
  return Eigen::Vector2d::Constant(NAN);
}

TEST(GarmentScene, ReadsPanelsSeamsAndThePatternStart) {
  const Scene scene = parse_scene(hung(true), scene_path());
  ASSERT_EQ(scene.fabric.shape, FabricSpec::Shape::panels);
  ASSERT_EQ(scene.fabric.panels.size(), 2u);
  EXPECT_EQ(scene.fabric.panels[1].name, "right");
  ASSERT_EQ(scene.seams.size(), 1u);
  EXPECT_EQ(scene.seams[0].panel, (std::array<int, 2>{0, 1}));
  EXPECT_EQ(scene.seams[0].edge, (std::array<int, 2>{1, 3}));
  EXPECT_FALSE(scene.seams[0].same_direction);
  EXPECT_EQ(scene.initial.kind, InitialShape::Kind::pattern);
  EXPECT_EQ(scene.fabric.divisions_warp, 22);  // 11 + 1 gap + 11 columns of nodes, less one
}

// Seed 003's F_seams closes the cut: the sewn pair rests where the whole panel rests, node for
// node at the same point of the pattern, to the seam's gap (spacing × strain / 1000).
TEST(GarmentScene, TwoPanelsSewnRestWhereTheirUnionRests) {
  const Rest whole = rest_of(hung(false)), sewn = rest_of(hung(true));
  const Fabric& w = whole.model.fabric;
  const Fabric& s = sewn.model.fabric;
  double largest = 0.0;
  int compared = 0;
  for (int n = 0; n < s.node_count(); ++n) {
    const Eigen::Vector2d at = pattern_point(s, n);
    for (int m = 0; m < w.node_count(); ++m)
      if ((pattern_point(w, m) - at).norm() < 1e-9) {
        largest = std::max(largest, (sewn.state.x[static_cast<std::size_t>(n)] - whole.state.x[static_cast<std::size_t>(m)]).norm());
        ++compared;
      }
  }
  EXPECT_EQ(compared, s.node_count());
  EXPECT_LT(largest, 1e-6);
  // And it sagged: the comparison is of a loaded sheet, not of two flat ones.
  double sag = 0.0;
  for (const Eigen::Vector3d& x : whole.state.x) sag = std::max(sag, -x.z());
  EXPECT_GT(sag, 1e-3);
  const std::vector<SeamFigures> seams = seam_figures(sewn.model, sewn.state.x);
  ASSERT_EQ(seams.size(), 1u);
  EXPECT_EQ(seams[0].name, "middle");
  EXPECT_LT(seams[0].gap_max_m, 1e-6);
  EXPECT_GT(seams[0].tension_mean_N_m, 0.0);
}

// GarmentCode's shirt as its pattern places it round the mean body: every stitch joins the start
// of one edge to the end of the other, and both ends meet in space before anything moves.
TEST(GarmentScene, TheShirtPatternsStitchesMeetWhereItPlacesThem) {
  const std::string text =
      "[fabric]\n"
      "shape = \"panels\"\n"
      "spacing_m = 0.01\n"
      "warp = \"../materials/white-swim-solid_warp.csv\"\n"
      "weft = \"../materials/white-swim-solid_weft.csv\"\n"
      "[garment]\n"
      "pattern = \"../garments/garmentcode_shirt_mean_specification.json\"\n"
      "[solver]\n"
      "name = \"newton\"\n";
  const Scene scene = parse_scene(text, scene_path());
  ASSERT_EQ(scene.fabric.panels.size(), 8u);
  ASSERT_EQ(scene.seams.size(), 18u);
  const Fabric fabric(scene.fabric);
  const std::vector<Eigen::Vector3d> start = initial_positions(fabric, scene.origin_m, scene.initial);
  // GarmentCode lays a garment's front panels in one plane in front of the body and its back
  // panels in one behind it: a stitch between two panels turned alike closes along z, its ends
  // (the start of one edge at the end of the other) agreeing in x and y — all but the shoulders,
  // whose front and back lines the pattern drafts 2.5 cm apart; sewn the same way round, every
  // one of them would cross over.
  int alike = 0, centre = 0, along_z = 0;
  for (const SeamSpec& s : scene.seams) {
    const PanelSpec& pa = scene.fabric.panels[static_cast<std::size_t>(s.panel[0])];
    const PanelSpec& pb = scene.fabric.panels[static_cast<std::size_t>(s.panel[1])];
    if (!pa.rotation.isApprox(pb.rotation, 1e-12)) continue;
    ++alike;
    const auto& a = fabric.panels()[static_cast<std::size_t>(s.panel[0])].edge_nodes[static_cast<std::size_t>(s.edge[0])];
    const auto& b = fabric.panels()[static_cast<std::size_t>(s.panel[1])].edge_nodes[static_cast<std::size_t>(s.edge[1])];
    const Eigen::Vector3d first = start[static_cast<std::size_t>(a.front())] - start[static_cast<std::size_t>(b.back())];
    const Eigen::Vector3d last = start[static_cast<std::size_t>(a.back())] - start[static_cast<std::size_t>(b.front())];
    const Eigen::Vector3d crossed = start[static_cast<std::size_t>(a.front())] - start[static_cast<std::size_t>(b.front())];
    EXPECT_LT(first.head<2>().norm(), 0.03) << s.name << " " << pa.name << " to " << pb.name;
    EXPECT_GT(crossed.head<2>().norm(), first.head<2>().norm() + 0.01) << s.name << " " << pa.name << " to " << pb.name;
    along_z += first.head<2>().norm() < 1e-6 && last.head<2>().norm() < 1e-6;
    centre += first.norm() < 1e-9 && last.norm() < 1e-9;
  }
  EXPECT_EQ(alike, 10);    // sides, shoulders, sleeves' seams and the two centre seams
  EXPECT_EQ(along_z, 8);   // all but the two shoulders
  EXPECT_EQ(centre, 2);    // centre front and centre back: the halves meet already
  // The front lies in front of the body (+z), the back behind it.
  const auto first_of = [&](const std::string& name) {
    for (const PanelMesh& p : fabric.panels())
      if (p.name == name) return start[static_cast<std::size_t>(p.first_node)];
    return Eigen::Vector3d(NAN, NAN, NAN);
  };
  EXPECT_GT(first_of("left_ftorso").z(), 0.2);
  EXPECT_LT(first_of("left_btorso").z(), -0.15);
}

InputError error_of(const std::string& text) {
  try {
    parse_scene(text, scene_path());
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return InputError({}, "");
}

InputError error_of_file(const std::string& path) {
  try {
    load_scene(path);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for " << path;
  return InputError({}, "");
}

std::string replaced(std::string text, const std::string& what, const std::string& with) {
  const auto at = text.find(what);
  EXPECT_NE(at, std::string::npos) << what;
  return text.replace(at, what.size(), with);
}

TEST(GarmentScene, BadPanelsAndSeamsAreNamed) {
  const std::string good = hung(true);
  struct Case {
    std::string what, with, key, message;
  };
  const Case cases[] = {
      {"b = [\"right\", 3]", "b = [\"sleeve\", 3]", "seam.0.b", "names no panel ('sleeve')"},
      {"b = [\"right\", 3]", "b = [\"right\", 4]", "seam.0.b", "panel 'right' has edges 0 to 3"},
      {"b = [\"right\", 3]", "b = [\"right\", 0]\ndirection = \"backwards\"", "seam.0.direction", "must be opposite"},
      {"b = [\"right\", 3]", "b = 3", "seam.0.b", "must be a [\"panel\", edge] pair"},
      {"a = [\"left\", 1]", "a = [\"right\", 3]", "seam.0.b", "sews an edge to itself"},
      {"[0.2, 0.0], [0.2, 0.1], [0.1, 0.1]", "[0.2, 0.0], [0.2, 0.3], [0.1, 0.3]", "seam.0.b", "more than 2 times apart"},
      {"[[0.0, 0.0], [0.1, 0.0], [0.1, 0.1], [0.0, 0.1]]", "[[0.0, 0.0], [0.1, 0.1], [0.1, 0.0], [0.0, 0.1]]",
       "fabric.panel.0.vertices_m", "the outline crosses itself"},
      {"[[0.0, 0.0], [0.1, 0.0], [0.1, 0.1], [0.0, 0.1]]", "[[0.0, 0.0], [0.1, 0.0]]", "fabric.panel.0.vertices_m",
       "at least 3"},
      {"name = \"right\"", "name = \"left\"", "fabric.panel", "two panels are named 'left'"},
      {"spacing_m = 0.01", "spacing_m = -0.01", "fabric.spacing_m", "must be positive"},
      {"spacing_m = 0.01", "spacing_m = 0.3", "fabric.spacing_m", "use a finer lattice spacing"},
      {"name = \"newton\"", "name = \"relax\"", "solver.name", "seams"},
  };
  for (const Case& c : cases) {
    const InputError e = error_of(replaced(good, c.what, c.with));
    EXPECT_EQ(e.where().key, c.key) << e.what();
    EXPECT_GT(e.where().line, 0) << e.what();
    EXPECT_EQ(e.where().file, scene_path());
    EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
  }
}

TEST(GarmentScene, ACurveNeedsItsEdgeAndOneKindOfControl) {
  const std::string good = hung(false);
  const std::string panel = "vertices_m = [[0.0, 0.0], [0.2, 0.0], [0.2, 0.1], [0.0, 0.1]]\n";
  const InputError two = error_of(replaced(good, panel, panel + "[[fabric.panel.curve]]\nedge = 2\nquadratic_m = [[0.1, 0.2]]\narc_radius_m = 0.3\n"));
  EXPECT_EQ(two.where().key, "fabric.panel.0.curve.0.edge");
  const InputError far = error_of(replaced(good, panel, panel + "[[fabric.panel.curve]]\nedge = 4\nquadratic_m = [[0.1, 0.2]]\n"));
  EXPECT_EQ(far.where().key, "fabric.panel.0.curve.0.edge");
  // A curve that bulges into the panel's far side makes the outline cross itself.
  const InputError crossing = error_of(replaced(good, panel, panel + "[[fabric.panel.curve]]\nedge = 0\nquadratic_m = [[0.1, 0.5]]\n"));
  EXPECT_EQ(crossing.where().key, "fabric.panel.0.vertices_m");
  const Scene curved = parse_scene(replaced(good, panel, panel + "[[fabric.panel.curve]]\nedge = 2\nquadratic_m = [[0.1, 0.15]]\n"), scene_path());
  EXPECT_EQ(curved.fabric.panels[0].outline.edges[2].kind, OutlineEdge::Kind::quadratic);
}

// A pattern's faults are named by the JSON path of the value at fault.
TEST(GarmentScene, BadPatternsAreNamedByTheirPath) {
  test::TempDir dir;
  const std::string scene_text =
      "[fabric]\nshape = \"panels\"\nspacing_m = 0.01\nwarp = \"w.csv\"\nweft = \"w.csv\"\n[garment]\npattern = \"p.json\"\n";
  const std::string panel =
      "\"front\": {\"translation\": [0, 0, 0], \"rotation\": [0, 0, 0], \"vertices\": [[0, 0], [10, 0], [10, 10], [0, 10]], "
      "\"edges\": [{\"endpoints\": [0, 1]}, {\"endpoints\": [1, 2]}, {\"endpoints\": [2, 3]}, {\"endpoints\": [3, 0]}]}";
  struct Case {
    std::string json, key, message;
  };
  const Case cases[] = {
      {"{\"pattern\": {\"panels\": {" + panel + "}, \"stitches\": []}, \"properties\": {}}", "properties.units_in_meter", "missing"},
      {"{\"pattern\": {\"panels\": {" + panel + "}, \"stitches\": [[{\"panel\": \"back\", \"edge\": 0}, {\"panel\": \"front\", \"edge\": 2}]]}, "
       "\"properties\": {\"units_in_meter\": 100}}",
       "pattern.stitches.0.0.panel", "names no panel"},
      {"{\"pattern\": {\"panels\": {" + panel + "}, \"stitches\": [[{\"panel\": \"front\", \"edge\": 7}, {\"panel\": \"front\", \"edge\": 2}]]}, "
       "\"properties\": {\"units_in_meter\": 100}}",
       "pattern.stitches.0.0.edge", "must be an index from 0 to 3"},
      {"{\"pattern\": {\"panels\": {" + replaced(panel, "[3, 0]", "[3, 1]") + "}, \"stitches\": []}, \"properties\": {\"units_in_meter\": 100}}",
       "pattern.panels.front.edges.3", "no loop"},
      {"{\"pattern\": {\"panels\": {" + replaced(panel, "[10, 0]", "[1e400, 0]") + "}, \"stitches\": []}, \"properties\": {\"units_in_meter\": 100}}",
       "", "not a sewing pattern's JSON"},
      {"{\"pattern\": {\"panels\": {" + replaced(panel, "[10, 0]", "[1e200, 0]") + "}, \"stitches\": []}, \"properties\": {\"units_in_meter\": 100}}",
       "pattern.panels.front.vertices.1.0", "must lie within"},
      {"{\"pattern\": {\"panels\": {" + panel + "}, \"stitches\": [[{\"panel\": \"front\", \"edge\": 2}, {\"panel\": \"front\", \"edge\": 2}]]}, "
       "\"properties\": {\"units_in_meter\": 100}}",
       "pattern.stitches.0", "sews an edge to itself"},
  };
  for (const Case& c : cases) {
    dir.write("p.json", c.json);
    const InputError e = error_of_file(dir.write("scene.toml", scene_text));
    EXPECT_EQ(e.where().file, dir.path("p.json")) << e.what();
    EXPECT_EQ(e.where().key, c.key) << e.what();
    EXPECT_NE(e.message().find(c.message), std::string::npos) << e.what();
  }
  dir.write("p.json", "{\"pattern\":\n {\"panels\": ]");
  const InputError broken = error_of_file(dir.write("scene.toml", scene_text));
  EXPECT_EQ(broken.where().line, 2) << broken.what();
}

}  // namespace
}  // namespace fabform::garment_toml_test
