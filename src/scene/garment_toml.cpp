#include "scene/garment_toml.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fabform/geometry/placement.hpp"
#include "fabform/io/garmentcode_pattern.hpp"
#include "fabform/model/seam.hpp"
#include "scene/scene_values.hpp"

namespace fabform {
namespace {

using namespace scene_values;

// An outline's vertices: an array of [x, y] in metres.
std::vector<Eigen::Vector2d> read_points(TableReader& r, const std::string& key, std::size_t at_least) {
  const toml::node* n = r.take(key);
  if (!n) r.fail(key, "missing (an array of [x, y] points in metres is required)");
  const toml::array* array = n->as_array();
  if (!array || array->size() < at_least)
    r.fail(key, "must be an array of at least " + std::to_string(at_least) + " [x, y] points");
  std::vector<Eigen::Vector2d> points;
  for (const toml::node& point : *array) {
    points.push_back(r.read_vector<2>(point, key));
    if (points.back().cwiseAbs().maxCoeff() > kMaxLength_m) r.fail(key, "must lie within " + number_text(kMaxLength_m) + " m");
  }
  return points;
}

// One [[fabric.panel.curve]]: which edge, and a quadratic or cubic Bézier's control points or an arc.
void read_curve(TableReader& r, PanelOutline* outline) {
  const int edge = checked_int(r, "edge", r.integer("edge", 0, true), 0, static_cast<long long>(outline->edges.size()) - 1);
  OutlineEdge& e = outline->edges[static_cast<std::size_t>(edge)];
  if (e.kind != OutlineEdge::Kind::straight) r.fail("edge", "edge " + std::to_string(edge) + " has a curve already");
  const int given = static_cast<int>(r.has("quadratic_m")) + static_cast<int>(r.has("cubic_m")) + static_cast<int>(r.has("arc_radius_m"));
  if (given != 1) r.fail("edge", "a curve gives one of quadratic_m, cubic_m (control points) or arc_radius_m");
  if (r.has("quadratic_m") || r.has("cubic_m")) {
    const bool quadratic = r.has("quadratic_m");
    const std::string key = quadratic ? "quadratic_m" : "cubic_m";
    e.kind = quadratic ? OutlineEdge::Kind::quadratic : OutlineEdge::Kind::cubic;
    e.controls = read_points(r, key, quadratic ? 1 : 2);
    if (e.controls.size() != (quadratic ? 1u : 2u)) r.fail(key, quadratic ? "a quadratic curve has 1 control point" : "a cubic curve has 2 control points");
    r.reject_unknown({"edge", key});
    return;
  }
  e.kind = OutlineEdge::Kind::arc;
  e.radius_m = r.number("arc_radius_m", 0.0, true);
  check_size(r, "arc_radius_m", e.radius_m);
  const double chord = (outline->vertices[(static_cast<std::size_t>(edge) + 1) % outline->vertices.size()] -
                        outline->vertices[static_cast<std::size_t>(edge)]).norm();
  if (e.radius_m < 0.5 * chord * (1.0 - 1e-9))  // a semicircle, to rounding
    r.fail("arc_radius_m", "is shorter than half the distance between the edge's ends (" + number_text(chord) + " m)");
  const std::string turn = r.text("turn", "counter_clockwise");
  if (turn != "counter_clockwise" && turn != "clockwise")
    r.fail("turn", "must be counter_clockwise or clockwise (got '" + shown(turn) + "')");
  e.counter_clockwise = turn == "counter_clockwise";
  e.large_arc = r.flag("large_arc", false);
  r.reject_unknown({"edge", "arc_radius_m", "turn", "large_arc"});
}

PanelSpec read_panel(TableReader& r, std::size_t index) {
  PanelSpec p;
  p.name = plain_text(r, "name", "panel" + std::to_string(index));
  p.outline.vertices = read_points(r, "vertices_m", 3);
  p.outline.edges.assign(p.outline.vertices.size(), OutlineEdge{});
  for (TableReader& curve : r.tables("curve")) read_curve(curve, &p.outline);
  if (const std::string why = p.outline.invalid_reason(); !why.empty()) r.fail("vertices_m", why);
  p.grain_deg = angle(r, "grain_deg", 0.0);
  p.translation_m = r.vector<3>("translation_m", Eigen::Vector3d::Zero());
  check_magnitude(r, "translation_m", p.translation_m.cwiseAbs().maxCoeff(), kMaxLength_m, "m");
  p.rotation = rotation_from_degrees(angles<3>(r, "rotation_deg"));
  r.reject_unknown({"name", "vertices_m", "curve", "grain_deg", "translation_m", "rotation_deg"});
  return p;
}

// A lattice of at most kMaxCellsAcross cells across a panel, as a rectangle's divisions: a
// spacing written in the wrong unit is refused before anything is traced or allocated.
constexpr double kMaxCellsAcross = 10000.0;

void check_spacing(TableReader& r, const FabricSpec& f) {
  for (const PanelSpec& panel : f.panels) {
    Eigen::Vector2d low = panel.outline.vertices[0], high = low;
    for (std::size_t k = 0; k < panel.outline.edges.size(); ++k) {
      const OutlineEdge& e = panel.outline.edges[k];
      for (const Eigen::Vector2d& p : e.controls) low = low.cwiseMin(p), high = high.cwiseMax(p);
      // An arc strays from its chord by its sagitta, the long way round by up to its diameter.
      const Eigen::Vector2d& v = panel.outline.vertices[k];
      const double half = 0.5 * (panel.outline.vertices[(k + 1) % panel.outline.vertices.size()] - v).norm();
      const double radius = e.radius_m;
      const Eigen::Vector2d reach = Eigen::Vector2d::Constant(
          e.large_arc ? 2.0 * radius : radius - std::sqrt(std::max(0.0, radius * radius - half * half)));
      low = low.cwiseMin(v - reach), high = high.cwiseMax(v + reach);
    }
    const double across = (high - low).maxCoeff() / std::min(f.panel_spacing_m[0], f.panel_spacing_m[1]);
    if (across > kMaxCellsAcross)
      r.fail("spacing_m", "panel '" + shown(panel.name) + "' spans " + number_text((high - low).maxCoeff()) +
                              " m: at this spacing more than " + number_text(kMaxCellsAcross) + " cells across it");
  }
}

void check_names_differ(TableReader& r, const std::string& key, const std::vector<PanelSpec>& panels) {
  for (std::size_t a = 0; a < panels.size(); ++a)
    for (std::size_t b = a + 1; b < panels.size(); ++b)
      if (panels[a].name == panels[b].name) r.fail(key, "two panels are named '" + shown(panels[a].name) + "'");
}

// To a thousandth of the panel (the ratio it is compared with is 2), in at most 1e5 segments.
double edge_length(const PanelSpec& panel, int edge) {
  double extent = 0.0;
  for (const Eigen::Vector2d& v : panel.outline.vertices) extent = std::max(extent, (v - panel.outline.vertices[0]).norm());
  const double segment = std::max(1e-3 * extent, 1e-5 * panel.outline.length_bound());
  return trace_outline(panel.outline, segment).edge_length[static_cast<std::size_t>(edge)];
}

// Edges sewn together are of about one length: ease and gathers, up to kMaxSeamLengthRatio.
std::string length_mismatch(const Scene& scene, const SeamSpec& s) {
  const auto& panels = scene.fabric.panels;
  const double a = edge_length(panels[static_cast<std::size_t>(s.panel[0])], s.edge[0]);
  const double b = edge_length(panels[static_cast<std::size_t>(s.panel[1])], s.edge[1]);
  if (std::max(a, b) <= kMaxSeamLengthRatio * std::min(a, b)) return "";
  return "its edges are " + number_text(a) + " m and " + number_text(b) + " m long, more than " +
         number_text(kMaxSeamLengthRatio) + " times apart (ease and gathers stay within that)";
}

// A seam side: ["panel name", edge index].
void read_side(TableReader& r, const std::string& key, const Scene& scene, SeamSpec* s, std::size_t side) {
  const toml::node* n = r.take(key);
  if (!n) r.fail(key, "missing (a [\"panel\", edge] pair is required)");
  const toml::array* pair = n->as_array();
  if (!pair || pair->size() != 2 || !(*pair)[0].is_string() || !(*pair)[1].is_integer())
    r.fail(key, "must be a [\"panel\", edge] pair: a panel's name and an edge's index");
  const std::string name = *(*pair)[0].value<std::string>();
  const auto& panels = scene.fabric.panels;
  const auto found = std::find_if(panels.begin(), panels.end(), [&](const PanelSpec& p) { return p.name == name; });
  if (found == panels.end()) r.fail(key, "names no panel ('" + shown(name) + "')");
  const long long edge = *(*pair)[1].value<long long>();
  if (edge < 0 || edge >= static_cast<long long>(found->outline.edges.size()))
    r.fail(key, "panel '" + shown(name) + "' has edges 0 to " + std::to_string(found->outline.edges.size() - 1));
  s->panel[side] = static_cast<int>(found - panels.begin());
  s->edge[side] = static_cast<int>(edge);
}

}  // namespace

void read_panels(TableReader& fabric, Scene* scene) {
  FabricSpec& f = scene->fabric;
  f.shape = FabricSpec::Shape::panels;
  const Eigen::Vector2d h = fabric.number_or_pair("spacing_m");
  if (!(h.minCoeff() > 0.0)) fabric.fail("spacing_m", "must be positive");
  f.panel_spacing_m = {h.x(), h.y()};
  auto panels = fabric.tables("panel");
  for (std::size_t k = 0; k < panels.size(); ++k) f.panels.push_back(read_panel(panels[k], k));
  check_names_differ(fabric, "panel", f.panels);
  scene->fabric_where = fabric.locate_key("spacing_m");
}

void read_garment(TableReader garment, Scene* scene) {
  if (scene->fabric.shape != FabricSpec::Shape::panels)
    garment.fail("pattern", "a sewing pattern's panels need a fabric of them: [fabric] shape = \"panels\"");
  if (!scene->fabric.panels.empty())
    garment.fail("pattern", "the fabric gives its own panels ([[fabric.panel]]): give them or a pattern, not both");
  scene->pattern_path = resolve(scene->path, plain_text(garment, "pattern", "", true));
  const double grain = angle(garment, "grain_deg", 90.0);
  // The pattern's world turned into the scene's: GarmentCode's is y up, fabform's gravity -z.
  const Eigen::Matrix3d turn = rotation_from_degrees(angles<3>(garment, "rotation_deg"));
  garment.reject_unknown({"pattern", "grain_deg", "rotation_deg"});
  SewingPattern pattern = read_garmentcode_pattern(scene->pattern_path, grain);
  for (PanelSpec& panel : pattern.panels) panel.rotation = turn * panel.rotation, panel.translation_m = turn * panel.translation_m;
  scene->fabric.panels = std::move(pattern.panels);
  for (std::size_t k = 0; k < pattern.stitches.size(); ++k) {
    const SewingPattern::Stitch& stitch = pattern.stitches[k];
    scene->seams.push_back({"stitch" + std::to_string(k), stitch.panel, stitch.edge, stitch.same_direction, garment.locate_key("pattern")});
  }
}

void check_panels(TableReader& fabric, Scene* scene) {
  if (scene->fabric.panels.empty())
    fabric.fail("panel", "a fabric of panels needs [[fabric.panel]] tables or a [garment] pattern");
  check_spacing(fabric, scene->fabric);
  // The pattern's stitches, once its panels are known to be of a size the lattice can take.
  for (std::size_t k = 0; k < scene->seams.size(); ++k)
    if (const std::string why = length_mismatch(*scene, scene->seams[k]); !why.empty())
      throw InputError({scene->pattern_path, 0, "pattern.stitches." + std::to_string(k)}, why);
}

void read_seams(std::vector<TableReader> seams, Scene* scene) {
  if (!seams.empty() && scene->fabric.shape != FabricSpec::Shape::panels)
    seams.front().fail("a", "a seam sews panel edges: the fabric must be of panels ([fabric] shape = \"panels\")");
  for (std::size_t k = 0; k < seams.size(); ++k) {
    TableReader& r = seams[k];
    SeamSpec s;
    s.name = plain_text(r, "name", "seam" + std::to_string(k));
    read_side(r, "a", *scene, &s, 0);
    read_side(r, "b", *scene, &s, 1);
    const std::string direction = r.text("direction", "opposite");
    if (direction != "opposite" && direction != "same")
      r.fail("direction", "must be opposite (the second edge from its end, as patterns are sewn) or same (got '" +
                              shown(direction) + "')");
    s.same_direction = direction == "same";
    if (s.panel[0] == s.panel[1] && s.edge[0] == s.edge[1]) r.fail("b", "sews an edge to itself");
    if (const std::string why = length_mismatch(*scene, s); !why.empty()) r.fail("b", why);
    s.where = r.where();
    r.reject_unknown({"name", "a", "b", "direction"});
    scene->seams.push_back(s);
  }
}

void mesh_panels(TableReader& fabric, Scene* scene) {
  FabricSpec& f = scene->fabric;
  std::array<int, 2> extent = {0, 0};
  try {
    if (const std::string why = f.invalid_reason(); !why.empty()) throw std::invalid_argument(why);
    extent = panel_layout(f).lattice_size;
  } catch (const std::invalid_argument& e) {
    fabric.fail("spacing_m", e.what());
  }
  f.divisions_warp = extent[0] - 1, f.divisions_weft = extent[1] - 1;
  f.width_m = f.divisions_warp * f.panel_spacing_m[0], f.height_m = f.divisions_weft * f.panel_spacing_m[1];
}

}  // namespace fabform
