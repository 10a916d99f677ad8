// Every key of the scene format swept with bad values (issue "Reliability", item 1). One table,
// key_table(), lists each key, its type and the verdict on each kind of bad value; the cases
// are generated from it. Each case starts from a valid scene holding every key, replaces or
// removes one, and expects either an InputError whose key is the dotted key and whose message
// gives the file, the line and the key ("sweep.toml:12: solver.C: ..."), or, where the table
// says the value is legitimate, a scene that parses. A few values pass the parser and are
// refused when the model is built, which knows the grid, the files and the placed geometry;
// the table says so (verdict B) and the case builds the model to check it. A sewing pattern the
// scene reads is another file: an error in it names that file (and the JSON path at fault), not
// a key of the scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fabform/scene/model_builder.hpp"
#include "fabform/scene/scene_toml.hpp"
#include "test_paths.hpp"

namespace fabform::scene_bad_values_test {
namespace {

// ---------------------------------------------------------------------------------------------
// The valid scene every case starts from: every key of the format, written once, with the
// repository's material tables and dome mold. Eight variants, as some keys depend on others:
// the initial shape's on the shape, lift (height_m) or wrap (axis_m, radius_m, facing_deg,
// span_deg); the fabric's on its outline, a rectangle or a circle meshed as a lattice (circle),
// as rings on spokes (arc) or as a jittered lattice (jittered, the circle's scene with its mesh
// and jitter); a body's path on load steps, which the rectangles' friction in bending and shear
// refuses (travel, lift's scene with the path and without that friction). The circles also hold
// the drape test's force terms and [drape]. A garment's keys need a fabric of panels: lift's
// scene as two panels sewn together, started where they are placed (panels), and the same with
// GarmentCode's shirt for its panels and seams (pattern, [garment]).

enum class Base { lift, wrap, circle, arc, jittered, travel, panels, pattern };

const char* prefix_of(Base base) {
  switch (base) {
    case Base::lift: return "";
    case Base::wrap: return "wrap_";
    case Base::circle: return "circle_";
    case Base::arc: return "arc_";
    case Base::jittered: return "jittered_";
    case Base::travel: return "travel_";
    case Base::panels: return "panels_";
    case Base::pattern: return "pattern_";
  }
  return "";
}

struct Entry {
  std::string key;
  std::string value;  // TOML text; may span lines
};

struct Section {
  std::string name;    // the dotted prefix of its keys: "fabric", "body.0"
  std::string header;  // "[fabric]", "[[body]]"
  std::vector<Entry> entries;
};

struct SceneText {
  std::vector<Entry> root;  // keys before the first header (a section replaced by a value)
  std::vector<Section> sections;
};

Section initial_section(Base base) {
  if (base != Base::wrap)
    return {"initial", "[initial]", {{"shape", "\"lift\""}, {"height_m", "0.01"}, {"perturbation_m", "1e-4"}, {"seed", "7"}}};
  return {"initial", "[initial]",
          {{"shape", "\"wrap\""}, {"axis_m", "[0.05, 0.05]"}, {"radius_m", "0.05"},
           {"facing_deg", "0.0"}, {"span_deg", "90.0"}, {"perturbation_m", "1e-4"}, {"seed", "7"}}};
}

Section fabric_section(Base base) {
  std::vector<Entry> outline;
  if (base == Base::circle)
    outline = {{"shape", "\"circle\""}, {"diameter_m", "0.1"}, {"mesh", "\"quadrangular\""}, {"divisions", "8"}};
  else if (base == Base::arc)
    outline = {{"shape", "\"circle\""}, {"diameter_m", "0.1"}, {"mesh", "\"arc\""}, {"rings", "4"}, {"spokes", "8"}};
  else
    outline = {{"shape", "\"rectangle\""}, {"size_m", "[0.1, 0.1]"}, {"divisions", "[4, 4]"}};
  outline.insert(outline.end(), {{"origin_m", "[0.0, 0.0, 0.05]"},
                                 {"warp", "\"../materials/white-swim-solid_warp.csv\""},
                                 {"weft", "\"../materials/white-swim-solid_weft.csv\""},
                                 {"softening", "false"}, {"locking_angle_deg", "45.0"},
                                 {"areal_mass_g_m2", "204.0"}});  // the tables' own 0.204 kg/m²
  outline.push_back({"compression", "\"linear\""});
  return {"fabric", "[fabric]", outline};
}

// The drape test's sections, in the circles' scenes: the dome is the support; the circle bends
// with seed 004's bend springs under a pressure, a quarter of it in a blank holder (its solver
// is newton, the only one that models the holder), the arc mesh with hinges and is blown by seed 004's wind (its
// solver is dynamic, the only one that models wind).
std::vector<Section> drape_sections(Base base) {
  if (base != Base::circle && base != Base::arc) return {};
  std::vector<Section> sections = {{"shear", "[shear]", {{"material", "\"../materials/synthetic/linear-500.csv\""}}}};
  if (base == Base::circle)
    sections.insert(sections.end(), {{"bending", "[bending]", {{"stiffness_N_m", "0.5"}}},
                                     {"pressure", "[pressure]", {{"pressure_Pa", "100.0"}}},
                                     {"clamp", "[clamp]",
                                      {{"box_m", "[[0.0, 0.0], [0.05, 0.05]]"}, {"force_N", "10.0"}, {"friction", "0.3"}}}});
  else
    sections.insert(sections.end(), {{"bending", "[bending]", {{"rigidity_Nm", "5e-5"}}},
                                     {"wind", "[wind]", {{"velocity_m_s", "[1.0, 0.0, -0.5]"}, {"coefficient_N_s_m3", "0.5"}}}});
  if (base == Base::circle)
    sections.insert(sections.end(), {{"drape", "[drape]", {{"support", "\"dome\""}, {"clamp_radius_m", "0.02"}}},
                                     {"self_contact", "[self_contact]", {{"thickness_m", "5e-4"}}}});
  else
    sections.push_back({"drape", "[drape]", {{"support", "\"dome\""}}});
  return sections;
}

// The circle's scene meshed as a jittered lattice.
SceneText jittered(SceneText circle) {
  std::vector<Entry>& fabric = circle.sections[1].entries;
  const auto mesh = std::find_if(fabric.begin(), fabric.end(), [](const Entry& e) { return e.key == "mesh"; });
  mesh->value = "\"jittered\"";
  fabric.insert(mesh + 2, {"jitter", "0.15"});  // after divisions
  return circle;
}

// The square's scene with its dome travelling 4 mm and turning 10° in four load steps, and
// without friction in bending and shear, which load steps refuse.
SceneText travelling(SceneText lift) {
  for (auto s = lift.sections.begin(); s != lift.sections.end(); ++s) {
    if (s->name == "body.0")
      s = lift.sections.insert(s + 1, {"body.0.path", "[body.path]",
                                       {{"steps", "4"}, {"translation_m", "[0.0, 0.0, 0.004]"},
                                        {"rotation_deg", "[0.0, 0.0, 10.0]"}, {"pivot_m", "[0.05, 0.05, 0.0]"}}});
    if (s->name == "shear" || s->name == "bending")
      s->entries.erase(std::remove_if(s->entries.begin(), s->entries.end(),
                                      [](const Entry& e) { return e.key.rfind("hysteresis", 0) == 0; }),
                       s->entries.end());
  }
  return lift;
}

// The square's scene as a garment on a lattice of 1 cm: two 5 cm panels side by side, sewn where
// they meet and bulging outwards on three edges, one of each kind of curve (a quadratic, an arc
// and a cubic Bézier) (panels); or GarmentCode's shirt, whose pattern gives the panels and the
// seams, turned y up to z up as the torso's scenes turn their body (pattern). Seams need newton;
// a garment starts where its panels are placed (initial shape "pattern"). The constraints stay,
// as far as the shirt's lattice allows: they select on the panels' flat layout, side by side a
// lattice column apart.
SceneText garment(SceneText lift, Base base) {
  auto& sections = lift.sections;
  const auto named = [&](const std::string& name) {
    return std::find_if(sections.begin(), sections.end(), [&](const Section& s) { return s.name == name; });
  };
  std::vector<Entry>& fabric = named("fabric")->entries;
  fabric.erase(std::remove_if(fabric.begin(), fabric.end(),
                              [](const Entry& e) { return e.key == "shape" || e.key == "size_m" || e.key == "divisions"; }),
               fabric.end());
  // The shirt at 2 cm: its 8 panels meshed in every case of the sweep, twice under the sanitizers.
  fabric.insert(fabric.begin(), {{"shape", "\"panels\""}, {"spacing_m", base == Base::pattern ? "0.02" : "0.01"}});
  const std::vector<Section> panels = {
      {"fabric.panel.0", "[[fabric.panel]]",
       {{"name", "\"left\""}, {"vertices_m", "[[0.0, 0.0], [0.05, 0.0], [0.05, 0.05], [0.0, 0.05]]"},
        {"grain_deg", "0.0"}, {"translation_m", "[0.0, 0.0, 0.0]"}, {"rotation_deg", "[0.0, 0.0, 0.0]"}}},
      // Its bottom edge bows 2.5 mm down, its left one (from [0, 0.05] to the origin) 6.7 mm left.
      {"fabric.panel.0.curve.0", "[[fabric.panel.curve]]", {{"edge", "0"}, {"quadratic_m", "[[0.025, -0.005]]"}}},
      {"fabric.panel.0.curve.1", "[[fabric.panel.curve]]",
       {{"edge", "3"}, {"arc_radius_m", "0.05"}, {"turn", "\"counter_clockwise\""}, {"large_arc", "false"}}},
      {"fabric.panel.1", "[[fabric.panel]]",
       {{"name", "\"right\""}, {"vertices_m", "[[0.05, 0.0], [0.1, 0.0], [0.1, 0.05], [0.05, 0.05]]"},
        {"grain_deg", "0.0"}, {"translation_m", "[0.0, 0.0, 0.0]"}, {"rotation_deg", "[0.0, 0.0, 0.0]"}}},
      // Its top edge (from [0.1, 0.05] to [0.05, 0.05]) bows 3.75 mm up.
      {"fabric.panel.1.curve.0", "[[fabric.panel.curve]]", {{"edge", "2"}, {"cubic_m", "[[0.085, 0.055], [0.065, 0.055]]"}}},
      {"seam.0", "[[seam]]", {{"name", "\"middle\""}, {"a", "[\"left\", 1]"}, {"b", "[\"right\", 3]"}, {"direction", "\"opposite\""}}}};
  const std::vector<Section> pattern = {
      {"garment", "[garment]",
       {{"pattern", "\"../garments/garmentcode_shirt_mean_specification.json\""}, {"grain_deg", "90.0"},
        {"rotation_deg", "[90.0, 0.0, 0.0]"}}}};
  const std::vector<Section>& added = base == Base::pattern ? pattern : panels;
  sections.insert(named("fabric") + 1, added.begin(), added.end());
  // The shirt's lattice (its panels' own, side by side, each from its lower-left corner) has no
  // node [2, 2], nor any in the square's box of 3 cm: its box is of 30 cm.
  if (base == Base::pattern) {
    sections.erase(named("constraint.1"));
    named("constraint.3")->entries.front().value = "[[0.0, 0.0], [0.3, 0.3]]";
  }
  named("initial")->entries = {{"shape", "\"pattern\""}, {"perturbation_m", "1e-4"}, {"seed", "7"}};
  named("solver")->entries.front().value = "\"newton\"";
  return lift;
}

// A 10 cm knit (a square of 4 x 4 divisions or a circle), 5 cm above a 3 cm dome, held by one
// constraint of each selector kind. The scene's own path is scenes/sweep.toml, so paths are
// relative to scenes/.
SceneText base_scene(Base base) {
  if (base == Base::jittered) return jittered(base_scene(Base::circle));
  if (base == Base::travel) return travelling(base_scene(Base::lift));
  if (base == Base::panels || base == Base::pattern) return garment(base_scene(Base::lift), base);
  SceneText scene{{},
          {{"scene", "[scene]", {{"name", "\"sweep\""}, {"description", "\"every key of the scene format\""}}},
           fabric_section(base),
           {"body.0", "[[body]]",
            {{"name", "\"dome\""},
             {"mesh", "\"../molds/dome_hemisphere_r30mm.obj\""},
             {"units", "\"mm\""},
             {"scale", "1.0"},
             {"rotation_deg", "[0.0, 0.0, 90.0]"},
             {"translation_m", "[0.05, 0.05, 0.0]"},
             {"friction", "0.0"},
             {"edge_contact_deg", "0.0"},
             {"spring_contact", "false"}}},
           {"constraint.0", "[[constraint]]", {{"nodes", "\"perimeter\""}, {"axes", "\"xyz\""}}},
           {"constraint.1", "[[constraint]]", {{"node", "[2, 2]"}, {"axes", "\"z\""}}},
           {"constraint.2", "[[constraint]]", {{"nearest_m", "[0.025, 0.025]"}, {"axes", "\"xy\""}}},
           {"constraint.3", "[[constraint]]", {{"box_m", "[[0.0, 0.0], [0.03, 0.03]]"}, {"axes", "\"xyz\""}}},
           {"gravity", "[gravity]", {{"acceleration_m_s2", "9.81"}}},
           initial_section(base),
           {"solver", "[solver]",
            {{"name", base == Base::arc ? "\"dynamic\"" : base == Base::circle ? "\"newton\"" : "\"relax\""},
             {"tolerance_N", "1e-3"},
             {"tolerance_m", "1e-4"},
             {"max_iterations", "1000"},
             {"max_step_cuts", "4"},
             {"C", "2.0"},
             {"regularization", "1e-8"},
             {"slack_stiffness", "0.0"},
             {"armijo", "1e-4"},
             {"max_backtracks", "60"},
             {"friction_creep", "1e-3"},
             {"linear_solver", "\"auto\""},
             {"damping", "0.05"},
             {"time_step_fraction", "0.9"},
             {"stretch_limit", "0.0"},
             {"threads", "1"},
             {"continuation_levels", "0"}}},
           {"output", "[output]",
            {{"dir", "\"out\""}, {"checkpoint_every_iterations", "100"}, {"checkpoint_every_minutes", "10.0"}}}}};
  const auto gravity = std::find_if(scene.sections.begin(), scene.sections.end(),
                                    [](const Section& s) { return s.name == "gravity"; });
  std::vector<Section> drape = drape_sections(base);
  // The rectangles' shear rigidity and bending in a lab's units: G as FAST and as KES give it,
  // rigidity as a bending length and in µN·m.
  if (base == Base::lift)
    drape = {{"shear", "[shear]",
              {{"rigidity_N_m", "40.0"}, {"hysteresis_N_m", "1.5"}, {"hysteresis_rounding_deg", "0.1"}}}, {"bending", "[bending]",
              {{"bending_length_cm", "2.0"}, {"hysteresis_Nm_m", "5e-4"}, {"hysteresis_rounding_per_m", "10.0"}}}};
  if (base == Base::wrap)
    drape = {{"shear", "[shear]", {{"rigidity_gf_cm_deg", "0.8"}, {"hysteresis_gf_cm", "1.5"}}}, {"bending", "[bending]", {{"rigidity_uNm", "7.0"}, {"hysteresis_gf_cm_cm", "0.05"}}}};
  scene.sections.insert(gravity + 1, drape.begin(), drape.end());
  // Springs wrap the dome's facets' edges, but not in dynamic (the arc's solver), which refuses them.
  if (base != Base::arc) scene.sections[2].entries.push_back({"wrap_edges_deg", "30.0"});
  return scene;
}

std::string scene_path() { return test::source_path("scenes/sweep.toml"); }

// The text, and the line each dotted key and each section header is written on.
struct Rendered {
  std::string text;
  std::map<std::string, int> line_of;
};

// A section's name without its index in an array: "fabric.panel.0" -> "fabric.panel".
std::string array_of(const std::string& section) {
  const auto dot = section.rfind('.');
  if (dot == std::string::npos || section.find_first_not_of("0123456789", dot + 1) != std::string::npos) return section;
  return section.substr(0, dot);
}

Rendered render(const SceneText& scene) {
  Rendered r;
  int line = 1;
  const auto put = [&](const std::string& name, const std::string& text) {
    r.line_of.emplace(name, line);
    r.text += text + "\n";
    for (const char c : text) line += c == '\n' ? 1 : 0;
    ++line;
  };
  for (const auto& e : scene.root) put(e.key, e.key + " = " + e.value);
  for (const auto& s : scene.sections) {
    put(s.name.substr(0, s.name.find('.')), s.header);  // "body": its first element's header
    r.line_of.emplace(array_of(s.name), line - 1);       // "fabric.panel", "fabric.panel.0.curve" too
    r.line_of.emplace(s.name, line - 1);
    for (const auto& e : s.entries) put(s.name + "." + e.key, e.key + " = " + e.value);
  }
  return r;
}

// ---------------------------------------------------------------------------------------------
// The table

enum class Type {
  number,       // a float (an integer is also a number)
  integer,      // an integer within the key's range
  text,         // a free string, a name or a path
  choice,       // one of a fixed list of words
  vec2,         // [x, y]
  vec3,         // [x, y, z]
  int_pair,     // [i, j], integers
  box,          // [[x0, y0], [x1, y1]]
  points,       // [[x, y], ...]: an outline's vertices, a curve's control points
  side,         // ["panel", edge]: a seam's side
  table,        // a [section]
  table_array,  // an [[array]] of sections
  only_extras,  // a key seen from another base scene: only its listed values
};

// R: refused by parse_scene; A: accepted (legitimate); B: accepted by the parser, refused by
// build_model (a file, the grid or the placed geometry is needed to see it); _: not applicable.
enum class Verdict { _, R, A, B };
using V = Verdict;
constexpr V _ = V::_, R = V::R, A = V::A, B = V::B;

// A key-specific value: `value` nullptr removes the key; `names` is the key the message must
// name when that is not the row's (e.g. a constraint's selector missing names the constraint),
// or "file:PATH" when the error is another file's (PATH from the repository's root), such as a
// sewing pattern the scene reads.
struct Extra {
  const char* label;
  const char* value;
  Verdict verdict;
  const char* names;
};

struct KeyRow {
  const char* key;  // dotted, as messages spell it
  Type type;
  Base base;
  // Verdicts on: the key left out; a negative, zero and huge value (1e300, or 99999999999 for
  // an integer); an empty string (for a seam's side, an empty panel name). Wrong types, NaN,
  // infinities and numbers TOML cannot hold are always refused and need no column.
  Verdict missing, negative, zero, huge, empty;
  const char* builder_names;  // for B: the key build_model names, "" = the row's key
  std::vector<Extra> extras;
};

constexpr const char* kRemove = nullptr;
constexpr const char* kSame = "";

const std::vector<KeyRow>& key_table() {
  using T = Type;
  const Base lift = Base::lift, wrap = Base::wrap, circle = Base::circle, arc = Base::arc, jittered = Base::jittered,
             travel = Base::travel, panels = Base::panels, pattern = Base::pattern;
  static const std::vector<KeyRow> rows = {
      // key                             type          base  miss neg zero huge empty builder
      {"scene",                          T::table,     lift, A,   _,  _,   _,   _,    "", {}},
      {"scene.name",                     T::text,      lift, A,   _,  _,   _,   R,    "",
       {{"dot_dot", "\"..\"", R, kSame}, {"dot", "\".\"", R, kSame}, {"slash", "\"runs/a\"", R, kSame},
        {"backslash", "\"a\\\\b\"", R, kSame}, {"newline", "\"a\\nb\"", R, kSame},
        {"spaces", "\"mold fit 2\"", A, kSame}, {"digits", "\"007\"", A, kSame}}},
      {"scene.description",              T::text,      lift, A,   _,  _,   _,   A,    "",
       {{"newline", "\"two\\nlines\"", A, kSame}}},
      {"fabric",                         T::table,     lift, R,   _,  _,   _,   _,    "", {}},
      {"fabric.shape",                   T::choice,    lift, A,   _,  _,   _,   R,    "",
       {{"upper_case", "\"Circle\"", R, kSame}, {"circle_without_its_keys", "\"circle\"", R, "fabric.diameter_m"},
        {"panels_without_their_keys", "\"panels\"", R, "fabric.spacing_m"}}},
      {"fabric.shape",                   T::only_extras, circle, _, _, _,  _,   _,    "",
       {{"rectangle_without_its_keys", "\"rectangle\"", R, "fabric.size_m"}}},
      {"fabric.diameter_m",              T::number,    circle, R, R,  R,   R,   _,    "",
       {{"beyond_1e6_m", "2e6", R, kSame}}},
      {"fabric.mesh",                    T::choice,    circle, R, _,  _,   _,   R,    "",
       {{"upper_case", "\"Arc\"", R, kSame}, {"triangular", "\"triangular\"", A, kSame},
        {"arc_without_its_keys", "\"arc\"", R, "fabric.rings"}, {"jittered", "\"jittered\"", A, kSame}}},
      // A fraction of the lattice spacing, at most 0.2 (kMaxJitter); the default 0.2.
      {"fabric.jitter",                  T::number,    jittered, A, R, R,  R,   _,    "",
       {{"cap", "0.2", A, kSame}, {"beyond_cap", "0.21", R, kSame}}},
      {"fabric.divisions",               T::integer,   circle, R, R,  R,   R,   _,    "",
       {{"two", "2", R, kSame}, {"three", "3", A, kSame}, {"beyond_10000", "10001", R, kSame},
        {"a_pair", "[8, 8]", R, kSame}}},
      {"fabric.rings",                   T::integer,   arc,  R,   R,  R,   R,   _,    "",
       {{"one", "1", A, kSame}, {"cap", "5000", A, kSame}, {"beyond_5000", "5001", R, kSame}}},
      {"fabric.spokes",                  T::integer,   arc,  R,   R,  R,   R,   _,    "",
       {{"two", "2", R, kSame}, {"three", "3", A, kSame}, {"beyond_10000", "10001", R, kSame}}},
      {"fabric.size_m",                  T::vec2,      lift, R,   R,  R,   R,   _,    "",
       {{"one_side_zero", "[0.1, 0.0]", R, kSame}, {"one_side_negative", "[0.1, -0.1]", R, kSame},
        {"beyond_1e6_m", "[2e6, 0.1]", R, kSame}, {"1e6_m", "[1e6, 1e6]", A, kSame}}},
      {"fabric.divisions",               T::int_pair,  lift, R,   R,  R,   R,   _,    "",
       {{"one_zero", "[4, 0]", R, kSame}, {"beyond_10000", "[10001, 4]", R, kSame},
        {"10000_by_1", "[10000, 1]", A, kSame}}},
      {"fabric.origin_m",                T::vec3,      lift, A,   A,  A,   B,   _,    "initial", {}},
      {"fabric.warp",                    T::text,      lift, R,   _,  _,   _,   R,    "",
       {{"newline", "\"a\\nb.csv\"", R, kSame}, {"no_such_file", "\"nowhere.csv\"", B, kSame}}},
      {"fabric.weft",                    T::text,      lift, R,   _,  _,   _,   R,    "",
       {{"newline", "\"a\\nb.csv\"", R, kSame}, {"no_such_file", "\"nowhere.csv\"", B, kSame}}},
      // The tables' 0.204 kg/m² in g/m²: another mass conflicts with them.
      {"fabric.areal_mass_g_m2",         T::number,    lift, A,   R,  R,   R,   _,    "",
       {{"cap", "1e5", B, kSame}, {"beyond_cap", "1.1e5", R, kSame}, {"another_mass", "192.0", B, kSame}}},
      {"fabric.locking_angle_deg",       T::number,    lift, A,   R,  R,   R,   _,    "",
       {{"ninety", "90.0", R, kSame}, {"thirty", "30.0", A, kSame}}},
      {"fabric.softening",               T::only_extras, lift, _, _,  _,   _,   _,    "",
       {{"true", "true", A, kSame}, {"false", "false", A, kSame}, {"a_number", "1", R, kSame},
        {"a_string", "\"yes\"", R, kSame}}},
      // Buckling needs the hinges' rigidity, which the circle's bend springs do not give.
      {"fabric.compression",             T::choice,    lift, A,   _,  _,   _,   R,    "",
       {{"upper_case", "\"Linear\"", R, kSame}, {"none", "\"none\"", A, kSame},
        {"buckling_from_a_bending_length", "\"buckling\"", A, kSame}}},
      {"fabric.compression",             T::only_extras, circle, _, _, _,   _,   _,    "",
       {{"buckling_without_hinges", "\"buckling\"", B, kSame}}},
      {"fabric.compression",             T::only_extras, arc, _,  _,  _,   _,   _,    "",
       {{"buckling_with_hinges", "\"buckling\"", A, kSame}}},
      // A garment: panels on a lattice of spacing_m, given as [[fabric.panel]] or by a [garment]
      // pattern, sewn by [[seam]]. Without its shape the fabric is a rectangle, without a size.
      {"fabric.shape",                   T::only_extras, panels, _, _, _,  _,   _,    "",
       {{"missing", kRemove, R, "fabric.size_m"}, {"upper_case", "\"Panels\"", R, kSame},
        {"rectangle_without_its_keys", "\"rectangle\"", R, "fabric.size_m"}}},
      // A panel is meshed while its lattice cells form one piece: one cell of 5 cm each does, a
      // lattice of 10 cm (or 1e300 m) does not. More than 10000 cells across a panel is refused
      // before anything is traced: at 5 µm (1e4 across these 5 cm panels and their bows), 1 nm
      // and 1 pm.
      {"fabric.spacing_m",               T::number,    panels, R, R,  R,   R,   _,    "",
       {{"warp_and_weft", "[0.01, 0.0125]", A, kSame}, {"one_direction_zero", "[0.01, 0.0]", R, kSame},
        {"one_direction_negative", "[-0.01, 0.01]", R, kSame}, {"three_values", "[0.01, 0.01, 0.01]", R, kSame},
        {"a_millimetre", "0.001", A, kSame}, {"a_cell_a_panel", "0.05", A, kSame},
        {"coarser_than_the_panels", "0.1", R, kSame}, {"five_micrometres", "5e-6", R, kSame},
        {"a_nanometre", "1e-9", R, kSame}, {"a_picometre", "1e-12", R, kSame}}},
      {"fabric.spacing_m",               T::only_extras, pattern, _, _, _, _,   _,    "",
       {{"coarser_than_the_cuffs", "0.1", R, kSame}}},
      // A fabric of panels without any is refused before its seams are read.
      {"fabric.panel",                   T::table_array, panels, _, _, _,  _,   _,    "",
       {{"missing", kRemove, R, "fabric.panel"}}},
      // A seam names its panels: without its name (panel0) or with the other's, "left" is no panel.
      {"fabric.panel.0.name",            T::text,      panels, _, _,  _,   _,   R,    "",
       {{"missing", kRemove, R, "seam.0.a"}, {"newline", "\"le\\nft\"", R, kSame},
        {"the_others", "\"right\"", R, "fabric.panel"}}},
      // An outline of three vertices or more that does not cross itself; its curves name its edges.
      {"fabric.panel.0.vertices_m",      T::points,    panels, R, _,  R,   R,   _,    "",
       {{"two_points", "[[0.0, 0.0], [0.05, 0.0]]", R, kSame},
        {"crossing", "[[0.0, 0.0], [0.05, 0.05], [0.05, 0.0], [0.0, 0.05]]", R, kSame},
        {"triangle_without_the_arcs_edge", "[[0.0, 0.0], [0.05, 0.0], [0.05, 0.05]]", R, "fabric.panel.0.curve.1.edge"},
        {"pentagon", "[[0.0, 0.0], [0.05, 0.0], [0.05, 0.05], [0.025, 0.06], [0.0, 0.05]]", A, kSame},
        {"beyond_1e6_m", "[[0.0, 0.0], [2e6, 0.0], [0.05, 0.05]]", R, kSame}}},
      {"fabric.panel.0.grain_deg",       T::number,    panels, A, A,  A,   R,   _,    "",
       {{"full_turn", "360.0", A, kSame}, {"beyond_a_turn", "361.0", R, kSame}, {"bias", "45.0", A, kSame}}},
      {"fabric.panel.0.translation_m",   T::vec3,      panels, A, A,  A,   R,   _,    "",
       {{"beyond_1e6_m", "[2e6, 0.0, 0.0]", R, kSame}}},
      {"fabric.panel.0.rotation_deg",    T::vec3,      panels, A, A,  A,   R,   _,    "",
       {{"full_turns", "[360.0, -360.0, 0.0]", A, kSame}, {"beyond_a_turn", "[0.0, 361.0, 0.0]", R, kSame}}},
      // Straight edges without.
      {"fabric.panel.0.curve",           T::table_array, panels, A, _, _,  _,   _,    "", {}},
      // One curve an edge: a second one on the arc's edge (3) or the quadratic's (0) is named by
      // the curve that comes second. A value TOML cannot hold in a [[fabric.panel.curve]] (1e999,
      // beyond 64 bits) is named like any other, with its panel's and its curve's index.
      {"fabric.panel.0.curve.0.edge",    T::integer,   panels, R, R,  A,   R,   _,    "",
       {{"beyond_the_last", "4", R, kSame}, {"the_arcs", "3", R, "fabric.panel.0.curve.1.edge"}}},
      // Its control point given, the curve is a quadratic Bézier: one of quadratic_m, cubic_m or
      // arc_radius_m, or the curve is no curve (named by its edge). A control point 50 m out (a
      // length written in mm) makes a panel 25 m across, refused as 2500 times the spacing's
      // 10000 cells; the check that the outline does not cross itself is bounded in segments.
      {"fabric.panel.0.curve.0.quadratic_m", T::points, panels, _, _,  _,   R,   _,    "",
       {{"missing", kRemove, R, "fabric.panel.0.curve.0.edge"}, {"two_points", "[[0.02, -0.005], [0.03, -0.005]]", R, kSame},
        {"on_the_chord", "[[0.025, 0.0]]", A, kSame}, {"at_a_vertex", "[[0.0, 0.0]]", A, kSame},
        {"a_fifth_of_a_metre_out", "[[0.025, -0.2]]", A, kSame}, {"beyond_1e6_m", "[[0.025, -2e6]]", R, kSame},
        {"in_millimetres", "[[25.0, -50.0]]", R, "fabric.spacing_m"},
        {"across_the_panel", "[[0.025, 0.2]]", R, "fabric.panel.0.vertices_m"},
        {"and_an_arc", "[[0.025, -0.005]]\narc_radius_m = 0.05", R, "fabric.panel.0.curve.0.edge"}}},
      {"fabric.panel.0.curve.1.edge",    T::integer,   panels, R, R,  _,   R,   _,    "",
       {{"beyond_the_last", "4", R, kSame}, {"the_quadratics", "0", R, kSame}, {"the_seams", "1", A, kSame}}},
      // An arc's radius is at least half its chord (5 cm here): a semicircle at that.
      {"fabric.panel.0.curve.1.arc_radius_m", T::number, panels, _, R, R,  R,   _,    "",
       {{"missing", kRemove, R, "fabric.panel.0.curve.1.edge"}, {"half_the_chord", "0.025", A, kSame},
        {"shorter_than_half_the_chord", "0.02", R, kSame},
        {"a_kilometre", "1000.0", A, kSame}, {"beyond_1e6_m", "2e6", R, kSame}}},
      {"fabric.panel.0.curve.1.turn",    T::choice,    panels, A, _,  _,   _,   R,    "",
       {{"clockwise", "\"clockwise\"", A, kSame}, {"upper_case", "\"Clockwise\"", R, kSame}}},
      {"fabric.panel.0.curve.1.large_arc", T::only_extras, panels, _, _, _,  _,   _,    "",
       {{"true", "true", A, kSame}, {"false", "false", A, kSame}, {"missing", kRemove, A, kSame},
        {"a_number", "1", R, kSame}, {"a_string", "\"yes\"", R, kSame}}},
      // Two control points: a cubic Bézier.
      {"fabric.panel.1.curve.0.cubic_m", T::points,    panels, _, _,  _,   R,   _,    "",
       {{"missing", kRemove, R, "fabric.panel.1.curve.0.edge"}, {"one_point", "[[0.075, 0.055]]", R, kSame},
        {"three_points", "[[0.09, 0.055], [0.075, 0.055], [0.06, 0.055]]", R, kSame},
        {"on_the_chord", "[[0.085, 0.05], [0.065, 0.05]]", A, kSame},
        {"and_a_quadratic", "[[0.085, 0.055], [0.065, 0.055]]\nquadratic_m = [[0.075, 0.055]]", R,
         "fabric.panel.1.curve.0.edge"}}},
      // Seams need panels, and newton.
      {"seam",                           T::table_array, panels, A, _,  _,   _,   _,    "", {}},
      {"seam.0.name",                    T::text,      panels, A, _,  _,   _,   R,    "",
       {{"newline", "\"a\\nb\"", R, kSame}}},
      // Any two edges of about one length: the bow of the quadratic's edge (0) is ease.
      {"seam.0.a",                       T::side,      panels, R, R,  A,   R,   R,    "",
       {{"no_such_panel", "[\"sleeve\", 1]", R, kSame}, {"beyond_the_last", "[\"left\", 4]", R, kSame},
        {"the_arcs_edge", "[\"left\", 3]", A, kSame}, {"the_others", "[\"right\", 3]", R, "seam.0.b"}}},
      {"seam.0.b",                       T::side,      panels, R, R,  A,   R,   R,    "",
       {{"no_such_panel", "[\"sleeve\", 3]", R, kSame}, {"beyond_the_last", "[\"right\", 4]", R, kSame},
        {"the_others", "[\"left\", 1]", R, kSame}, {"on_its_own_panel", "[\"left\", 3]", A, kSame}}},
      {"seam.0.direction",               T::choice,    panels, A, _,  _,   _,   R,    "",
       {{"same", "\"same\"", A, kSame}, {"upper_case", "\"Same\"", R, kSame}}},
      {"solver.name",                    T::only_extras, panels, _, _, _,  _,   _,    "",
       {{"relax_with_seams", "\"relax\"", R, kSame}, {"missing_with_seams", kRemove, R, kSame}}},
      // A fabric of panels starts where they are placed (its default), or as any sheet does.
      {"initial.shape",                  T::only_extras, panels, _, _, _,  _,   _,    "",
       {{"missing", kRemove, A, kSame}, {"flat", "\"flat\"", A, kSame},
        {"lift_without_height", "\"lift\"", R, "initial.height_m"}, {"tube", "\"tube\"", R, kSame}}},
      // Without the pattern the fabric has no panels. A pattern that cannot be read (or a folder)
      // names its file (and, within it, the JSON path at fault).
      {"garment",                        T::table,     pattern, _, _, _,   _,   _,    "",
       {{"missing", kRemove, R, "fabric.panel"}}},
      {"garment.pattern",                T::text,      pattern, R, _, _,   _,   R,    "",
       {{"newline", "\"a\\nb.json\"", R, kSame}, {"no_such_file", "\"nowhere.json\"", R, "file:scenes/nowhere.json"},
        {"not_json", "\"../materials/white-swim-solid_warp.csv\"", R, "file:materials/white-swim-solid_warp.csv"},
        {"a_folder", "\"../garments\"", R, "file:garments"},
        {"the_hoody", "\"../garments/garmentcode_hoody_mean_specification.json\"", A, kSame}}},
      // The panels' grain, from the pattern's x axis (90: along its y, a garment's length).
      {"garment.grain_deg",              T::number,    pattern, A, A, A,   R,   _,    "",
       {{"full_turn", "360.0", A, kSame}, {"beyond_a_turn", "361.0", R, kSame}}},
      {"garment.rotation_deg",           T::vec3,      pattern, A, A, A,   R,   _,    "",
       {{"beyond_a_turn", "[0.0, 361.0, 0.0]", R, kSame}}},
      {"body",                           T::table_array, lift, A, _,  _,   _,   _,    "", {}},
      {"body.0.name",                    T::text,      lift, A,   _,  _,   _,   R,    "",
       {{"newline", "\"a\\nb\"", R, kSame}}},
      {"body.0.mesh",                    T::text,      lift, R,   _,  _,   _,   R,    "",
       {{"newline", "\"a\\nb.obj\"", R, kSame}, {"no_such_file", "\"nowhere.obj\"", B, kSame}}},
      {"body.0.units",                   T::choice,    lift, R,   _,  _,   _,   R,    "",
       {{"upper_case", "\"MM\"", R, kSame}, {"word", "\"millimetres\"", R, kSame}, {"newline", "\"m\\nm\"", R, kSame},
        {"m", "\"m\"", A, kSame}, {"cm", "\"cm\"", A, kSame}, {"in", "\"in\"", A, kSame}}},
      {"body.0.scale",                   T::number,    lift, A,   R,  R,   B,   _,    "body.0",
       {{"a_thousandth", "0.001", A, kSame}}},
      {"body.0.rotation_deg",            T::vec3,      lift, A,   A,  A,   R,   _,    "",
       {{"full_turns", "[360.0, -360.0, 0.0]", A, kSame}, {"beyond_a_turn", "[0.0, 361.0, 0.0]", R, kSame}}},
      {"body.0.translation_m",           T::vec3,      lift, A,   A,  A,   B,   _,    "body.0", {}},
      {"body.0.friction",                T::number,    arc,  A,   R,  A,   R,   _,    "",
       {{"cap", "10.0", A, kSame}, {"beyond_cap", "10.1", R, kSame}}},
      {"body.0.wrap_edges_deg",          T::number,    lift, A,   R,  A,   R,   _,    "",
       {{"right_angle", "90.0", A, kSame}, {"half_turn", "180.0", R, kSame}}},
      // Every base but the arc wraps the body's edges, which edge contact excludes.
      {"body.0.edge_contact_deg",        T::number,    lift, A,   R,  A,   R,   _,    "",
       {{"with_wrapped_edges", "2.0", R, kSame}, {"half_turn", "180.0", R, kSame}}},
      // Every base but the arc wraps the body's edges, which spring contact excludes.
      {"body.0.spring_contact",          T::only_extras, lift, _, _,  _,   _,   _,    "",
       {{"false", "false", A, kSame}, {"missing", kRemove, A, kSame}, {"with_wrapped_edges", "true", R, kSame},
        {"a_number", "1", R, kSame}, {"a_string", "\"yes\"", R, kSame}}},
      // The body travels 4 mm and turns 10° in four load steps; without a path it stays put.
      {"body.0.path",                    T::only_extras, travel, _, _,  _,   _,   _,    "",
       {{"missing", kRemove, A, kSame}}},
      {"body.0.path.steps",              T::integer,   travel, R,   R,  R,   R,   _,    "",
       {{"one", "1", A, kSame}, {"cap", "100000", A, kSame}, {"beyond_cap", "100001", R, kSame}}},
      {"body.0.path.translation_m",      T::vec3,      travel, A,   A,  A,   R,   _,    "",
       {{"beyond_1e6_m", "[0.0, 0.0, 2e6]", R, kSame}}},
      {"body.0.path.rotation_deg",       T::vec3,      travel, A,   A,  A,   R,   _,    "",
       {{"beyond_a_turn", "[0.0, 361.0, 0.0]", R, kSame}}},
      {"body.0.path.pivot_m",            T::vec3,      travel, A,   A,  A,   R,   _,    "", {}},
      // Seed 003's relaxation has no stick or slip.
      {"body.0.friction",                T::only_extras, lift, _, _,  _,   _,   _,    "",
       {{"with_relax", "0.3", R, "solver.name"}, {"none_with_relax", "0.0", A, kSame}}},
      {"constraint",                     T::table_array, lift, A, _,  _,   _,   _,    "", {}},
      {"constraint.0.nodes",             T::choice,    lift, _,   _,  _,   _,   R,    "",
       {{"missing", kRemove, R, "constraint.0"}, {"upper_case", "\"Perimeter\"", R, kSame},
        {"edge_without_side", "\"edge\"", R, kSame}, {"corners", "\"corners\"", A, kSame},
        {"edge_left", "\"edge:left\"", A, kSame}, {"edge_right", "\"edge:right\"", A, kSame},
        {"edge_bottom", "\"edge:bottom\"", A, kSame}, {"edge_top", "\"edge:top\"", A, kSame}}},
      {"constraint.0.axes",              T::choice,    lift, A,   _,  _,   _,   R,    "",
       {{"repeated", "\"xx\"", R, kSame}, {"upper_case", "\"XYZ\"", R, kSame}, {"spaced", "\"x y\"", R, kSame},
        {"reordered", "\"zyx\"", A, kSame}, {"one_axis", "\"x\"", A, kSame}}},
      {"constraint.1.node",              T::int_pair,  lift, _,   R,  A,   R,   _,    "",
       {{"missing", kRemove, R, "constraint.1"}, {"second_selector", "[2, 2]\nnodes = \"corners\"", R, "constraint.1"},
        {"last_node", "[4, 4]", A, kSame}, {"off_the_grid", "[5, 0]", B, "constraint.1"}}},
      {"constraint.2.nearest_m",         T::vec2,      lift, _,   R,  A,   R,   _,    "",
       {{"missing", kRemove, R, "constraint.2"}, {"off_the_fabric", "[0.2, 0.05]", R, kSame},
        {"far_corner", "[0.1, 0.1]", A, kSame}}},
      {"constraint.3.box_m",             T::box,       lift, _,   A,  A,   A,   _,    "",
       {{"missing", kRemove, R, "constraint.3"}, {"reversed", "[[0.03, 0.03], [0.0, 0.0]]", R, kSame},
        {"off_the_fabric", "[[0.2, 0.2], [0.3, 0.3]]", B, "constraint.3"}}},
      {"gravity",                        T::table,     lift, A,   _,  _,   _,   _,    "", {}},
      {"gravity.acceleration_m_s2",      T::number,    lift, A,   R,  R,   R,   _,    "",
       {{"earth", "9.80665", A, kSame}, {"cap", "1000.0", A, kSame}, {"beyond_cap", "1000.1", R, kSame}}},
      // Each term is built only when its section is there.
      {"shear",                          T::table,     circle, A, _,  _,   _,   _,    "", {}},
      {"shear.rigidity_N_m",             T::number,    lift, _,   R,  R,   R,   _,    "",
       {{"missing", kRemove, R, "shear"}, {"cap", "1e9", A, kSame}, {"and_a_table", "40.0\nmaterial = \"../materials/synthetic/linear-500.csv\"", R, "shear"}}},
      {"shear.rigidity_gf_cm_deg",       T::number,    wrap, _,   R,  R,   R,   _,    "",
       {{"missing", kRemove, R, "shear"}, {"and_N_m", "0.8\nrigidity_N_m = 40.0", R, "shear"}}},
      // Shear friction, KES's 2HG: in gf/cm beside the wrap's G, in N/m beside the lift's.
      {"shear.hysteresis_gf_cm",         T::number,    wrap, A,   R,  R,   R,   _,    "",
       {{"cap", "1000.0", A, kSame}, {"beyond_cap", "1001.0", R, kSame},
        {"and_N_m", "1.5\nhysteresis_N_m = 1.5", R, kSame}}},
      {"shear.hysteresis_N_m",           T::number,    lift, _,   R,  R,   R,   _,    "",
       {{"cap", "980.665", A, kSame}, {"beyond_cap", "981.0", R, kSame},
        {"missing", kRemove, R, "shear.hysteresis_rounding_deg"}}},
      {"shear.hysteresis_rounding_deg",  T::number,    lift, A,   R,  R,   R,   _,    "",
       {{"cap", "10.0", A, kSame}, {"beyond_cap", "10.1", R, kSame}, {"floor", "0.0001", A, kSame},
        {"below_floor", "0.00009", R, kSame}}},
      {"shear.material",                 T::text,      circle, _, _,  _,   _,   R,    "",
       {{"missing", kRemove, R, "shear"}, {"newline", "\"a\\nb.csv\"", R, kSame}, {"no_such_file", "\"nowhere.csv\"", B, kSame}}},
      {"bending",                        T::table,     circle, A, _,  _,   _,   _,    "", {}},
      {"bending.stiffness_N_m",          T::number,    circle, _, R,  R,   R,   _,    "",
       {{"cap", "1e9", A, kSame}, {"beyond_cap", "1.1e9", R, kSame}, {"missing", kRemove, R, "bending"},
        {"and_rigidity", "0.5\nrigidity_Nm = 5e-5", R, "bending"}}},
      {"bending.rigidity_Nm",           T::number,    arc,  _,   R,  R,   R,   _,    "",
       {{"cap", "1e3", A, kSame}, {"beyond_cap", "1001.0", R, kSame}, {"missing", kRemove, R, "bending"},
        {"measured_denim", "6.42e-5", A, kSame}, {"warp_and_weft", "[6e-6, 5e-6]", A, kSame},
        {"one_direction_zero", "[6e-6, 0.0]", R, kSame}, {"three_values", "[6e-6, 5e-6, 4e-6]", R, kSame},
        {"and_micro", "5e-5\nrigidity_uNm = 50.0", R, "bending"}}},
      {"bending.rigidity_uNm",          T::number,    wrap, _,   R,  R,   R,   _,    "",
       {{"cap", "1e9", A, kSame}, {"beyond_cap", "1.1e9", R, kSame}, {"missing", kRemove, R, "bending"},
        {"warp_and_weft", "[7.5, 6.4]", A, kSame}, {"one_direction_negative", "[7.5, -6.4]", R, kSame}}},
      // B = m·g·c³ needs the mass, which the base's tables and fabric.areal_mass_g_m2 give.
      {"bending.bending_length_cm",     T::number,    lift, _,   R,  R,   R,   _,    "",
       {{"cap", "1000.0", A, kSame}, {"beyond_cap", "1001.0", R, kSame}, {"missing", kRemove, R, "bending"},
        {"warp_and_weft", "[2.5, 1.8]", A, kSame}, {"and_rigidity", "2.0\nrigidity_uNm = 7.0", R, "bending"}}},
      // Bending friction, KES's 2HB: in gf·cm/cm on the wrap's hinges, in N·m/m on the lift's.
      {"bending.hysteresis_gf_cm_cm",   T::number,    wrap, A,   R,  R,   R,   _,    "",
       {{"cap", "1000.0", A, kSame}, {"beyond_cap", "1001.0", R, kSame}, {"warp_and_weft", "[0.05, 0.0]", A, kSame},
        {"both_zero", "[0.0, 0.0]", R, kSame}, {"one_direction_negative", "[0.05, -0.01]", R, kSame},
        {"and_N", "0.05\nhysteresis_Nm_m = 5e-4", R, kSame}}},
      {"bending.hysteresis_Nm_m",       T::number,    lift, _,   R,  R,   R,   _,    "",
       {{"cap", "9.80665", A, kSame}, {"beyond_cap", "9.81", R, kSame},
        {"missing", kRemove, R, "bending.hysteresis_rounding_per_m"}}},
      {"bending.hysteresis_rounding_per_m", T::number, lift, A,  R,  R,   R,   _,    "",
       {{"cap", "1e4", A, kSame}, {"beyond_cap", "1.1e4", R, kSame}, {"floor", "0.001", A, kSame},
        {"below_floor", "0.0009", R, kSame}}},
      {"wind",                           T::table,     arc,  A,   _,  _,   _,   _,    "", {}},
      {"wind.velocity_m_s",              T::vec3,      arc,  R,   A,  R,   R,   _,    "",
       {{"along_x", "[5.0, 0.0, 0.0]", A, kSame}, {"speed_of_sound", "[0.0, 0.0, 1000.0]", A, kSame},
        {"beyond_1000_m_s", "[0.0, 800.0, 800.0]", R, kSame}}},
      {"wind.coefficient_N_s_m3",        T::number,    arc,  R,   R,  R,   R,   _,    "",
       {{"cap", "1e6", A, kSame}, {"beyond_cap", "1.1e6", R, kSame}}},
      // Only dynamic models wind.
      {"solver.name",                    T::only_extras, arc, _,  _,  _,   _,   _,    "",
       {{"newton_in_a_wind", "\"newton\"", R, kSame}, {"relax_in_a_wind", "\"relax\"", R, kSame},
        {"missing_in_a_wind", kRemove, R, kSame}}},
      {"pressure",                       T::table,     circle, A, _,  _,   _,   _,    "", {}},
      {"pressure.pressure_Pa",           T::number,    circle, R, A,  R,   R,   _,    "",
       {{"cap", "1e7", A, kSame}, {"beyond_cap", "1.1e7", R, kSame}, {"suction", "-1e7", A, kSame}}},
      // A pressure needs a clamped blank: its edge held in x, y and z.
      {"constraint.0.axes",              T::only_extras, circle, _, _, _,  _,   _,    "",
       {{"edge_free_under_pressure", "\"xy\"", B, "pressure"}}},
      {"clamp",                          T::table,     circle, A, _,  _,   _,   _,    "", {}},
      // A region with no node is no holder (a box beyond the fabric, or of no size).
      {"clamp.box_m",                    T::box,       circle, _, A,  B,   A,   _,    "clamp",
       {{"missing", kRemove, R, "clamp"}, {"off_the_fabric", "[[0.2, 0.2], [0.3, 0.3]]", B, "clamp"},
        {"and_a_frame", "[[0.0, 0.0], [0.05, 0.05]]\nwidth_m = 0.01", R, "clamp"}}},
      // The holder's other selectors are a constraint's, swept there; its frame (width_m) is
      // checked in scene_toml_test.cpp, as the base holds one selector.
      {"clamp.nodes",                    T::only_extras, circle, _, _, _,  _,   _,    "", {}},
      {"clamp.node",                     T::only_extras, circle, _, _, _,  _,   _,    "", {}},
      {"clamp.nearest_m",                T::only_extras, circle, _, _, _,  _,   _,    "", {}},
      {"clamp.width_m",                  T::only_extras, circle, _, _, _,  _,   _,    "", {}},
      {"clamp.force_N",                  T::number,    circle, R, R,  A,   R,   _,    "",
       {{"cap", "1e6", A, kSame}, {"beyond_cap", "1.1e6", R, kSame}}},
      {"clamp.friction",                 T::number,    circle, R, R,  A,   R,   _,    "",
       {{"cap", "10.0", A, kSame}, {"beyond_cap", "10.1", R, kSame}}},
      // Only newton models the holder.
      {"solver.name",                    T::only_extras, circle, _, _, _,  _,   _,    "",
       {{"relax_with_a_clamp", "\"relax\"", R, kSame}, {"dynamic_with_a_clamp", "\"dynamic\"", R, kSame}}},
      {"drape",                          T::table,     circle, A, _,  _,   _,   _,    "", {}},
      {"self_contact",                   T::table,     circle, A, _,  _,   _,   _,    "", {}},
      {"self_contact.thickness_m",       T::number,    circle, A, R,  R,   R,   _,    "", {}},
      // No support: a pin test, A_disc = 0.
      {"drape.support",                  T::text,      circle, A, _,  _,   _,   R,    "",
       {{"newline", "\"a\\nb\"", R, kSame}, {"no_such_body", "\"mold\"", B, kSame}}},
      // The tester's clamp: a disc of nodes round the specimen's centre, narrower than the specimen.
      {"drape.clamp_radius_m",           T::number,    circle, A, R,  R,   R,   _,    "",
       {{"the_specimens_radius", "0.05", R, kSame}, {"nearly_the_specimen", "0.049", A, kSame}}},
      {"initial",                        T::table,     lift, A,   _,  _,   _,   _,    "", {}},
      {"initial.shape",                  T::choice,    lift, A,   _,  _,   _,   R,    "",
       {{"upper_case", "\"Lift\"", R, kSame}, {"flat", "\"flat\"", A, kSame}, {"bump", "\"bump\"", A, kSame},
        {"wrap_without_its_keys", "\"wrap\"", R, "initial.axis_m"}, {"pattern_of_a_rectangle", "\"pattern\"", R, kSame}}},
      {"initial.height_m",               T::number,    lift, R,   A,  R,   B,   _,    "initial", {}},
      {"initial.perturbation_m",         T::number,    lift, A,   R,  A,   R,   _,    "",
       {{"beyond_a_tenth", "0.2", R, kSame}}},
      {"initial.seed",                   T::integer,   lift, A,   R,  A,   R,   _,    "",
       {{"cap", "2147483647", A, kSame}, {"beyond_cap", "2147483648", R, kSame}}},
      {"initial.shape",                  T::only_extras, wrap, _, _,  _,   _,   _,    "",
       {{"lift_without_height", "\"lift\"", R, "initial.height_m"}}},
      {"initial.axis_m",                 T::vec2,      wrap, R,   A,  A,   B,   _,    "initial", {}},
      {"initial.radius_m",               T::number,    wrap, R,   R,  R,   B,   _,    "initial", {}},
      {"initial.facing_deg",             T::number,    wrap, R,   A,  A,   R,   _,    "",
       {{"full_turn", "-360.0", A, kSame}, {"beyond_a_turn", "361.0", R, kSame}}},
      {"initial.span_deg",               T::number,    wrap, R,   R,  R,   R,   _,    "",
       {{"full_circle", "360.0", R, kSame}, {"almost_a_circle", "359.0", A, kSame}}},
      {"solver",                         T::table,     lift, A,   _,  _,   _,   _,    "", {}},
      {"solver.name",                    T::choice,    lift, A,   _,  _,   _,   R,    "",
       {{"simplex", "\"simplex\"", R, kSame}, {"upper_case", "\"Newton\"", R, kSame},
        {"dynamic_with_wrapped_edges", "\"dynamic\"", R, kSame}, {"newton", "\"newton\"", A, kSame}}},
      // A loose e is the user's to choose: the run stops at iteration 0 and says so.
      {"solver.tolerance_N",             T::number,    lift, A,   R,  R,   A,   _,    "", {}},
      // Exclusive with tolerance_N, which the base gives: checked in scene_toml_test.cpp.
      {"solver.tolerance_relative",      T::only_extras, lift, _, _,  _,   _,   _,    "", {}},
      // A distance from the rest in metres: a loose one, like a loose e, is the user's to choose.
      {"solver.tolerance_m",             T::number,    lift, A,   R,  R,   A,   _,    "",
       {{"a_micrometre", "1e-6", A, kSame}}},
      {"solver.max_iterations",          T::integer,   lift, A,   R,  A,   R,   _,    "",
       {{"cap", "1_000_000_000", A, kSame}, {"beyond_cap", "1_000_000_001", R, kSame}}},
      {"solver.max_step_cuts",           T::integer,   lift, A,   R,  A,   R,   _,    "",
       {{"cap", "20", A, kSame}, {"beyond_cap", "21", R, kSame}}},
      {"solver.C",                       T::number,    lift, A,   R,  R,   R,   _,    "",
       {{"one", "1.0", R, kSame}, {"too_close_to_one", "1.0000001", R, kSame}, {"cap", "1e6", A, kSame}}},
      {"solver.regularization",          T::number,    lift, A,   R,  R,   R,   _,    "", {{"one", "1.0", A, kSame}}},
      {"solver.slack_stiffness",         T::number,    lift, A,   R,  A,   R,   _,    "",
       {{"one", "1.0", A, kSame}, {"beyond_one", "1.01", R, kSame}}},
      {"solver.armijo",                  T::number,    lift, A,   R,  R,   R,   _,    "", {{"half", "0.5", R, kSame}}},
      {"solver.max_backtracks",          T::integer,   lift, A,   R,  R,   R,   _,    "",
       {{"cap", "200", A, kSame}, {"beyond_cap", "201", R, kSame}}},
      {"solver.friction_creep",          T::number,    lift, A,   R,  R,   R,   _,    "",
       {{"cap", "0.1", A, kSame}, {"beyond_cap", "0.11", R, kSame}}},
      {"solver.linear_solver",           T::choice,    lift, A,   _,  _,   _,   R,    "",
       {{"upper_case", "\"Multigrid\"", R, kSame}, {"lu", "\"lu\"", R, kSame},
        {"multigrid", "\"multigrid\"", A, kSame}}},
      // Dynamic's mass for a fabric without one: every base weighs its fabric, beside which the
      // key is refused (lab_units_test.cpp); its range is checked in scene_toml_test.cpp.
      {"solver.areal_density_kg_m2",     T::only_extras, lift, _, _,  _,   _,   _,    "", {}},
      {"solver.damping",                 T::number,    lift, A,   R,  A,   R,   _,    "", {{"one", "1.0", R, kSame}}},
      {"solver.time_step_fraction",      T::number,    lift, A,   R,  R,   R,   _,    "", {{"one", "1.0", A, kSame}}},
      {"solver.stretch_limit",           T::number,    lift, A,   R,  A,   R,   _,    "", {{"cap", "100.0", A, kSame}}},
      {"solver.threads",                 T::integer,   lift, A,   R,  R,   R,   _,    "",
       {{"cap", "1024", A, kSame}, {"beyond_cap", "1025", R, kSame}}},
      // Newton's alone, and not in load steps: the lift's relax and the circle's newton both have a
      // body path, so only 0 is accepted here; what it accepts is in continuation_grids_test.cpp.
      {"solver.continuation_levels",     T::integer,   lift, A,   R,  A,   R,   _,    "",
       {{"one_with_relax", "1", R, "solver.name"}, {"cap", "10", R, "solver.name"}, {"beyond_cap", "11", R, kSame}}},
      {"solver.continuation_levels",     T::only_extras, circle, _, _, _,  _,   _,    "",
       {{"one_with_load_steps", "1", R, kSame}}},
      {"output",                         T::table,     lift, A,   _,  _,   _,   _,    "", {}},
      {"output.dir",                     T::text,      lift, A,   _,  _,   _,   R,    "",
       {{"newline", "\"a\\nb\"", R, kSame}}},
      {"output.checkpoint_every_iterations", T::integer, lift, A, R,  A,   R,   _,    "", {}},
      {"output.checkpoint_every_minutes",    T::number,  lift, A, R,  A,   R,   _,    "", {}},
  };
  return rows;
}

// ---------------------------------------------------------------------------------------------
// Cases generated from the table

enum class Edit {
  replace,     // the key's value becomes `value`
  remove,      // the key (or the whole section) is left out
  header,      // the section's header becomes `value` ("[[fabric]]")
  root_value,  // the section is replaced by `KEY = value` before the first header (in its parent's)
  insert,      // `value` is added as a line of the section (an unknown key)
};

struct Case {
  std::string name;
  Base base;
  std::string key;
  Edit edit;
  std::string value;
  Verdict verdict;
  std::string names;  // the key the message must name (R, B)
};

std::ostream& operator<<(std::ostream& out, const Case& c) { return out << c.name; }

// A value with one element replaced, for the vector types: [v, 0.01] or [v, 0.01, 0.01].
std::string vec_with(Type type, const std::string& first) {
  return "[" + first + (type == Type::vec3 ? ", 0.01, 0.01]" : ", 0.01]");
}

std::string vec_of(Type type, const std::string& each) {
  return "[" + each + ", " + each + (type == Type::vec3 ? ", " + each + "]" : "]");
}

// Wrong types, NaN, infinities and numbers TOML cannot hold: refused for every key of the type.
std::vector<std::pair<std::string, std::string>> always_refused(Type type) {
  switch (type) {
    case Type::number:
      return {{"string", "\"fast\""}, {"bool", "true"}, {"array", "[1.0]"}, {"table", "{ value = 1.0 }"},
              {"date", "1980-01-01"}, {"nan", "nan"}, {"inf", "inf"}, {"minus_inf", "-inf"},
              {"beyond_double", "1e999"}};
    case Type::integer:
      return {{"string", "\"many\""}, {"float", "1.5"}, {"integral_float", "2.0"}, {"bool", "true"},
              {"array", "[1]"}, {"table", "{ value = 1 }"}, {"nan", "nan"}, {"inf", "inf"},
              {"huge_float", "1e300"}, {"beyond_int64", "99999999999999999999"}};
    case Type::text:
    case Type::choice:
      return {{"number", "3"}, {"bool", "true"}, {"array", "[\"a\"]"}, {"table", "{ value = \"a\" }"}};
    case Type::vec2:
    case Type::vec3:
      return {{"string", "\"0.1\""}, {"number", "0.1"}, {"too_short", type == Type::vec3 ? "[0.01, 0.01]" : "[0.01]"},
              {"too_long", type == Type::vec3 ? "[0.01, 0.01, 0.01, 0.01]" : "[0.01, 0.01, 0.01]"},
              {"string_element", vec_with(type, "\"a\"")}, {"bool_element", vec_with(type, "true")},
              {"nested", vec_with(type, "[0.01]")}, {"table", "{ x = 0.01 }"}, {"nan", vec_with(type, "nan")},
              {"inf", vec_with(type, "inf")}, {"beyond_double", vec_with(type, "1e999")}};
    case Type::int_pair:
      return {{"string", "\"4, 4\""}, {"number", "4"}, {"too_short", "[4]"}, {"too_long", "[4, 4, 4]"},
              {"float_element", "[2.0, 2]"}, {"string_element", "[\"2\", 2]"}, {"table", "{ i = 2, j = 2 }"},
              {"nan", "[nan, 2]"}, {"beyond_int64", "[99999999999999999999, 2]"}};
    case Type::box:
      return {{"number", "0.1"}, {"string", "\"box\""}, {"flat", "[0.0, 0.0]"}, {"one_corner", "[[0.0, 0.0]]"},
              {"three_corners", "[[0.0, 0.0], [0.01, 0.01], [0.03, 0.03]]"},
              {"corner_too_long", "[[0.0, 0.0, 0.0], [0.03, 0.03]]"}, {"table", "{ min = [0.0, 0.0] }"},
              {"nan", "[[nan, 0.0], [0.03, 0.03]]"}, {"inf", "[[0.0, 0.0], [inf, 0.03]]"},
              {"beyond_double", "[[0.0, 0.0], [1e999, 0.03]]"}};
    // Three points, the first one bad: an outline needs three, and a curve's control points are
    // each read before they are counted.
    case Type::points:
      return {{"string", "\"0.1\""}, {"number", "0.1"}, {"empty", "[]"}, {"flat", "[0.01, 0.01, 0.01]"},
              {"table", "{ x = 0.01 }"}, {"point_too_long", "[[0.01, 0.01, 0.01], [0.02, 0.0], [0.0, 0.02]]"},
              {"point_too_short", "[[0.01], [0.02, 0.0], [0.0, 0.02]]"},
              {"string_element", "[[\"a\", 0.01], [0.02, 0.0], [0.0, 0.02]]"},
              {"bool_element", "[[true, 0.01], [0.02, 0.0], [0.0, 0.02]]"},
              {"point_a_table", "[{ x = 0.01, y = 0.01 }, [0.02, 0.0], [0.0, 0.02]]"},
              {"nan", "[[nan, 0.01], [0.02, 0.0], [0.0, 0.02]]"}, {"inf", "[[inf, 0.01], [0.02, 0.0], [0.0, 0.02]]"},
              {"beyond_double", "[[1e999, 0.01], [0.02, 0.0], [0.0, 0.02]]"}};
    case Type::side:
      return {{"string", "\"left\""}, {"number", "1"}, {"too_short", "[\"left\"]"}, {"too_long", "[\"left\", 1, 2]"},
              {"swapped", "[1, \"left\"]"}, {"float_edge", "[\"left\", 1.0]"}, {"bool_edge", "[\"left\", true]"},
              {"nested", "[[\"left\"], 1]"}, {"table", "{ panel = \"left\", edge = 1 }"}, {"nan", "[\"left\", nan]"},
              {"beyond_int64", "[\"left\", 99999999999999999999]"}};
    default:
      return {};
  }
}

// The values of the verdict columns, per type ("" when the column does not apply to it).
std::string column_value(Type type, const std::string& column) {
  const bool vector = type == Type::vec2 || type == Type::vec3;
  if (column == "negative") {
    if (type == Type::number) return "-1.0";
    if (type == Type::integer) return "-1";
    if (vector) return vec_of(type, "-0.01");
    if (type == Type::int_pair) return "[-1, 2]";
    if (type == Type::box) return "[[-0.01, -0.01], [0.03, 0.03]]";
    if (type == Type::side) return "[\"left\", -1]";
  } else if (column == "zero") {
    if (type == Type::number) return "0.0";
    if (type == Type::integer) return "0";
    if (vector) return vec_of(type, "0.0");
    if (type == Type::int_pair) return "[0, 0]";
    if (type == Type::box) return "[[0.0, 0.0], [0.0, 0.0]]";
    if (type == Type::points) return "[[0.0, 0.0], [0.0, 0.0], [0.0, 0.0], [0.0, 0.0]]";
    if (type == Type::side) return "[\"left\", 0]";
  } else if (column == "huge") {
    if (type == Type::number) return "1e300";
    if (type == Type::integer) return "99999999999";
    if (vector) return vec_of(type, "1e300");
    if (type == Type::int_pair) return "[99999999999, 2]";
    if (type == Type::box) return "[[0.0, 0.0], [1e300, 1e300]]";
    if (type == Type::points) return "[[1e300, 0.0], [0.02, 0.0], [0.0, 0.02]]";
    if (type == Type::side) return "[\"left\", 99999999999]";
  } else if (column == "empty") {
    if (type == Type::text || type == Type::choice) return "\"\"";
    if (type == Type::side) return "[\"\", 1]";
  }
  return "";
}

std::string test_name(const KeyRow& row, const std::string& label) {
  std::string name = prefix_of(row.base) + std::string(row.key) + "__" + label;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

void add_section_cases(const KeyRow& row, std::vector<Case>* cases) {
  const std::string key = row.key;
  const auto add = [&](const std::string& label, Edit edit, const std::string& value, const std::string& names) {
    cases->push_back({test_name(row, label), row.base, key, edit, value, R, names});
  };
  const std::string first = row.type == Type::table_array ? key + ".0" : key;
  add("number", Edit::root_value, "3", key);
  add("string", Edit::root_value, "\"" + key + "\"", key);
  add("unknown_key", Edit::insert, "colour = \"red\"", first + ".colour");
  if (row.type == Type::table) add("array_of_tables", Edit::header, "[[" + key + "]]", key);
  if (row.type == Type::table_array) add("array_of_numbers", Edit::root_value, "[3]", key);
  if (key == "body") add("single_table", Edit::header, "[body]", key);  // one element: a plain table
}

void add_value_cases(const KeyRow& row, std::vector<Case>* cases) {
  const auto add = [&](const std::string& label, const std::string& value, Verdict verdict, const std::string& names) {
    const std::string named = !names.empty() ? names
                              : verdict == B && *row.builder_names ? row.builder_names
                                                                   : row.key;
    cases->push_back({test_name(row, label), row.base, row.key, Edit::replace, value, verdict, named});
  };
  for (const auto& [label, value] : always_refused(row.type)) add(label, value, R, "");
  if (row.type == Type::choice) add("unknown", "\"bogus\"", R, "");
  const std::pair<const char*, Verdict> columns[] = {
      {"negative", row.negative}, {"zero", row.zero}, {"huge", row.huge}, {"empty", row.empty}};
  for (const auto& [column, verdict] : columns) {
    if (verdict == _) continue;
    const std::string value = column_value(row.type, column);
    if (value.empty()) throw std::logic_error(std::string(row.key) + ": no " + column + " value for its type");
    add(column, value, verdict, "");
  }
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const KeyRow& row : key_table()) {
    const bool section = row.type == Type::table || row.type == Type::table_array;
    if (section) add_section_cases(row, &cases);
    else add_value_cases(row, &cases);
    if (row.missing != _)
      cases.push_back({test_name(row, "missing"), row.base, row.key, Edit::remove, "", row.missing, row.key});
    for (const Extra& e : row.extras) {
      const std::string names = *e.names ? e.names : e.verdict == B && *row.builder_names ? row.builder_names : row.key;
      cases.push_back({test_name(row, e.label), row.base, row.key, e.value ? Edit::replace : Edit::remove,
                       e.value ? e.value : "", e.verdict, names});
    }
  }
  return cases;
}

// ---------------------------------------------------------------------------------------------
// Applying a case to the base scene

// A section's name is KEY or, in an array, KEY.N; with `nested`, also a table inside one of
// the array's elements (KEY.N.path), which goes where its element goes.
bool is_section_of(const std::string& section, const std::string& key, bool nested = true) {
  if (section == key) return true;
  if (section.rfind(key + ".", 0) != 0) return false;
  const std::string rest = section.substr(key.size() + 1);
  const std::string index = nested ? rest.substr(0, rest.find('.')) : rest;
  return !index.empty() && index.find_first_not_of("0123456789") == std::string::npos;
}

bool names_a_section(const SceneText& scene, const std::string& key) {
  for (const auto& s : scene.sections)
    if (is_section_of(s.name, key)) return true;
  return false;
}

void edit_section(SceneText* scene, const Case& c) {
  auto& sections = scene->sections;
  if (c.edit == Edit::insert) {
    for (auto& s : sections)
      if (s.name == c.key || s.name == c.key + ".0") {
        const auto equals = c.value.find(" = ");
        s.entries.push_back({c.value.substr(0, equals), c.value.substr(equals + 3)});
        return;
      }
  }
  if (c.edit == Edit::header) {
    for (auto& s : sections)
      if (is_section_of(s.name, c.key, false)) s.header = c.value;
    return;
  }
  sections.erase(std::remove_if(sections.begin(), sections.end(),
                                [&](const Section& s) { return is_section_of(s.name, c.key); }),
                 sections.end());
  if (c.edit != Edit::root_value) return;
  // A table inside another ([[fabric.panel]]) becomes a key of its parent's: panel = 3 in [fabric].
  const auto dot = c.key.rfind('.');
  if (dot == std::string::npos) {
    scene->root.push_back({c.key, c.value});
    return;
  }
  for (auto& s : sections)
    if (s.name == c.key.substr(0, dot)) s.entries.push_back({c.key.substr(dot + 1), c.value});
}

void edit_entry(SceneText* scene, const Case& c) {
  const std::string section = c.key.substr(0, c.key.rfind('.'));
  const std::string name = c.key.substr(c.key.rfind('.') + 1);
  for (auto& s : scene->sections) {
    if (s.name != section) continue;
    for (auto e = s.entries.begin(); e != s.entries.end(); ++e) {
      if (e->key != name) continue;
      if (c.edit == Edit::remove) s.entries.erase(e);
      else e->value = c.value;
      return;
    }
  }
  throw std::logic_error(c.key + " is not in the base scene");
}

Rendered scene_of(const Case& c) {
  SceneText scene = base_scene(c.base);
  if (names_a_section(scene, c.key)) edit_section(&scene, c);
  else edit_entry(&scene, c);
  return render(scene);
}

// The line an error about `key` must give: the key's own, else its section's header; 0 when
// neither is in the file (a missing section).
int expected_line(const Rendered& scene, const std::string& key) {
  for (std::string k = key; !k.empty(); k = k.rfind('.') == std::string::npos ? "" : k.substr(0, k.rfind('.'))) {
    const auto found = scene.line_of.find(k);
    if (found != scene.line_of.end()) return found->second;
  }
  return 0;
}

std::optional<InputError> parse_error(const std::string& text, Scene* scene) {
  try {
    *scene = parse_scene(text, scene_path());
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

std::optional<InputError> build_error(const Scene& scene) {
  try {
    build_model(scene);
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

// The message is one line, names the key, and gives the file and line when the key (or its
// section) is in the file.
void expect_names(const InputError& e, const std::string& key, int line) {
  const std::string what = e.what();
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  if (key.rfind("file:", 0) == 0) {  // another file's error: that file, and no key of the scene's
    const std::string file = test::source_path(key.substr(5));
    EXPECT_EQ(e.where().file, file) << what;
    EXPECT_EQ(what.rfind(file + ":", 0), 0u) << what << "\ndoes not start with " << file << ":";
    return;
  }
  EXPECT_EQ(e.where().key, key) << what;
  if (line > 0) {
    EXPECT_EQ(e.where().line, line) << what;
    const std::string prefix = scene_path() + ":" + std::to_string(line) + ": " + key + ": ";
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what << "\ndoes not start with " << prefix;
  } else {
    EXPECT_NE(what.find(key + ": "), std::string::npos) << what;
  }
}

class SceneBadValue : public ::testing::TestWithParam<Case> {};

TEST_P(SceneBadValue, IsRefusedNamingItsKeyOrAcceptedWhereLegitimate) {
  const Case& c = GetParam();
  const Rendered text = scene_of(c);
  SCOPED_TRACE("scene:\n" + text.text);
  Scene scene;
  const std::optional<InputError> error = parse_error(text.text, &scene);
  if (c.verdict == R) {
    ASSERT_TRUE(error.has_value()) << c.key << " = " << c.value << " was accepted";
    expect_names(*error, c.names, expected_line(text, c.names));
    return;
  }
  ASSERT_FALSE(error.has_value()) << error->what();
  if (c.verdict == B) {
    const std::optional<InputError> built = build_error(scene);
    ASSERT_TRUE(built.has_value()) << c.key << " = " << c.value << " was accepted by build_model";
    expect_names(*built, c.names, expected_line(text, c.names));
  }
}

INSTANTIATE_TEST_SUITE_P(EveryKey, SceneBadValue, ::testing::ValuesIn(all_cases()),
                         [](const auto& case_info) { return case_info.param.name; });

// ---------------------------------------------------------------------------------------------
// The table itself

// The base scenes are valid through to a model: every failure above is the edited key's.
TEST(SceneBadValueTable, BaseScenesBuildAModel) {
  for (const Base base : {Base::lift, Base::wrap, Base::circle, Base::arc, Base::jittered, Base::travel, Base::panels,
                          Base::pattern}) {
    const std::string text = render(base_scene(base)).text;
    const Scene scene = parse_scene(text, scene_path());
    EXPECT_NO_THROW(build_model(scene)) << text;
  }
}

// The keys a section knows, as the parser lists them when it meets an unknown one.
std::set<std::string> known_keys(SceneText scene, const std::string& section) {
  if (section.empty()) scene.root.push_back({"colour", "\"red\""});
  for (auto& s : scene.sections)
    if (s.name == section) s.entries.push_back({"colour", "\"red\""});
  Scene unused;
  const auto error = parse_error(render(scene).text, &unused);
  std::set<std::string> keys;
  if (!error) return keys;
  const std::string what = error->what();
  const auto from = what.find("known here: ");
  if (from == std::string::npos) return keys;
  std::stringstream list(what.substr(from + 12, what.rfind(')') - from - 12));
  for (std::string k; std::getline(list, k, ',');) keys.insert(k.substr(k.find_first_not_of(' ')));
  return keys;
}

// A row key with its array indices dropped: "constraint.1.node" -> "constraint.node".
std::string family_of(const std::string& key) {
  std::string out;
  std::stringstream parts(key);
  for (std::string p; std::getline(parts, p, '.');)
    if (p.find_first_not_of("0123456789") != std::string::npos) out += (out.empty() ? "" : ".") + p;
  return out;
}

// Every key the parser knows has a row: a key added to scene_toml.cpp without one fails here.
TEST(SceneBadValueTable, ListsEveryKeyTheParserKnows) {
  std::set<std::string> rows;
  for (const KeyRow& row : key_table()) rows.insert(family_of(row.key));
  const std::pair<Base, const char*> sections[] = {
      {Base::lift, ""},          {Base::lift, "scene"},  {Base::lift, "fabric"}, {Base::lift, "body.0"},
      {Base::lift, "constraint.0"}, {Base::lift, "initial"}, {Base::lift, "solver"}, {Base::lift, "output"},
      {Base::wrap, "initial"},   {Base::circle, "fabric"}, {Base::arc, "fabric"},  {Base::circle, "shear"},
      {Base::circle, "bending"}, {Base::arc, "bending"},  {Base::circle, "drape"}, {Base::lift, "shear"},
      {Base::travel, "body.0.path"}, {Base::circle, "clamp"}, {Base::jittered, "fabric"}, {Base::panels, ""},
      {Base::panels, "fabric"},  {Base::panels, "fabric.panel.0"}, {Base::panels, "fabric.panel.0.curve.0"},
      {Base::panels, "fabric.panel.0.curve.1"}, {Base::panels, "fabric.panel.1.curve.0"}, {Base::panels, "seam.0"},
      {Base::panels, "initial"}, {Base::pattern, ""}, {Base::pattern, "fabric"}, {Base::pattern, "garment"}};
  for (const auto& [base, section] : sections) {
    const std::set<std::string> known = known_keys(base_scene(base), section);
    EXPECT_FALSE(known.empty()) << "no list of known keys for section '" << section << "'";
    const std::string family = family_of(section);
    for (const auto& k : known)
      EXPECT_TRUE(rows.count(family.empty() ? k : family + "." + k)) << "no row for " << family << "." << k;
  }
}

}  // namespace
}  // namespace fabform::scene_bad_values_test
