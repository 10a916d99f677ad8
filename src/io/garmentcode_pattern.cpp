#include "fabform/io/garmentcode_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include <nlohmann/json.hpp>

#include "fabform/error.hpp"
#include "fabform/geometry/placement.hpp"

namespace fabform {
namespace {

// Ordered: a pattern without panel_order keeps its panels in the file's order.
using Json = nlohmann::ordered_json;

// GarmentCode's lengths are centimetres of a body; a value beyond a kilometre of them (or an
// angle beyond a turn) is a broken file, and would overflow the geometry downstream.
constexpr double kMaxPatternLength = 1e5;
constexpr double kMaxAngle_deg = 360.0;
using Vec2 = Eigen::Vector2d;

// A JSON value's path, as the error names it: pattern.panels.left_ftorso.edges.3.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError({file_, 0, key}, message);
  }

  const Json& member(const Json& object, const std::string& key, const std::string& path) const {
    if (!object.is_object() || !object.contains(key)) fail(path.empty() ? key : path + "." + key, "missing");
    return object.at(key);
  }

  double number(const Json& value, const std::string& path) const {
    if (!value.is_number() || !std::isfinite(value.get<double>())) fail(path, "must be a finite number");
    return value.get<double>();
  }

  double bounded(const Json& value, const std::string& path, double limit) const {
    const double v = number(value, path);
    if (std::abs(v) > limit) fail(path, "must lie within ±" + std::to_string(static_cast<long long>(limit)));
    return v;
  }

  Vec2 point(const Json& value, const std::string& path, double limit = kMaxPatternLength) const {
    if (!value.is_array() || value.size() != 2) fail(path, "must be an array of two numbers");
    return {bounded(value[0], path + ".0", limit), bounded(value[1], path + ".1", limit)};
  }

  Eigen::Vector3d vector3(const Json& value, const std::string& path, double limit) const {
    if (!value.is_array() || value.size() != 3) fail(path, "must be an array of three numbers");
    return {bounded(value[0], path + ".0", limit), bounded(value[1], path + ".1", limit), bounded(value[2], path + ".2", limit)};
  }

  // A flag written as a number (0, 1) or as true and false.
  bool flag(const Json& value, const std::string& path) const {
    return value.is_boolean() ? value.get<bool>() : number(value, path) != 0.0;
  }

  int index(const Json& value, const std::string& path, std::size_t count) const {
    if (!value.is_number_integer() || value.get<long long>() < 0 || value.get<long long>() >= static_cast<long long>(count))
      fail(path, "must be an index from 0 to " + std::to_string(count - 1));
    return static_cast<int>(value.get<long long>());
  }

 private:
  std::string file_;
};

Json parsed(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError({path, 0, ""}, "no such sewing pattern file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, ""}, "cannot read the sewing pattern");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    const auto upto = std::min<std::size_t>(e.byte, text.size());
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(upto), '\n'));
    throw InputError({path, line, ""}, "not JSON (a GarmentCode *_specification.json is)");
  } catch (const Json::exception& e) {  // a number it cannot hold (1e400)
    throw InputError({path, 0, ""}, std::string("not a sewing pattern's JSON: ") + e.what());
  }
}

// An edge's curve; Bézier controls given [along, across] its chord and the chord's left normal.
OutlineEdge read_curve(const Reader& r, const Json& edge, const Vec2& a, const Vec2& b, double unit,
                       const std::string& path) {
  OutlineEdge e;
  if (!edge.contains("curvature")) return e;
  const Json& c = edge.at("curvature");
  const std::string at = path + ".curvature";
  const std::string type = r.member(c, "type", at).is_string() ? r.member(c, "type", at).get<std::string>() : "";
  const Json& params = r.member(c, "params", at);
  const Vec2 d = b - a, normal(-d.y(), d.x());
  if (type == "quadratic" || type == "cubic") {
    e.kind = type == "quadratic" ? OutlineEdge::Kind::quadratic : OutlineEdge::Kind::cubic;
    const std::size_t n = type == "quadratic" ? 1 : 2;
    if (!params.is_array() || params.size() != n) r.fail(at + ".params", "a " + type + " curve has " + std::to_string(n) + " control point(s)");
    for (std::size_t k = 0; k < n; ++k) {
      // Relative to the edge: a control a thousand edges away is no curve of a garment.
      const Vec2 rel = r.point(params[k], at + ".params." + std::to_string(k), 1e3);
      e.controls.push_back(a + rel.x() * d + rel.y() * normal);
    }
  } else if (type == "circle") {
    if (!params.is_array() || params.size() != 3) r.fail(at + ".params", "a circle arc has [radius, large_arc, right]");
    e.kind = OutlineEdge::Kind::arc;
    // GarmentCode's radius may fall short of half the chord by rounding; SVG takes it as half.
    e.radius_m = std::max(r.bounded(params[0], at + ".params.0", kMaxPatternLength) / unit, 0.5 * d.norm() / unit);
    e.large_arc = r.flag(params[1], at + ".params.1");
    e.counter_clockwise = r.flag(params[2], at + ".params.2");
  } else {
    r.fail(at + ".type", "must be quadratic, cubic or circle");
  }
  for (Vec2& control : e.controls) control /= unit;
  return e;
}

// A panel's edges chained into its outline: edge k leaves the vertex edge k − 1 ends at.
PanelSpec read_panel(const Reader& r, const std::string& name, const Json& panel, double unit, double grain_deg) {
  const std::string path = "pattern.panels." + name;
  PanelSpec p;
  p.name = name;
  p.grain_deg = grain_deg;
  const Json& vertices = r.member(panel, "vertices", path);
  const Json& edges = r.member(panel, "edges", path);
  if (!vertices.is_array() || !edges.is_array() || edges.size() < 3)
    r.fail(path, "a panel has arrays of vertices and of at least 3 edges");
  std::vector<Vec2> v;
  for (std::size_t k = 0; k < vertices.size(); ++k) v.push_back(r.point(vertices[k], path + ".vertices." + std::to_string(k)));
  std::vector<std::array<int, 2>> ends;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const std::string at = path + ".edges." + std::to_string(k) + ".endpoints";
    const Json& e = r.member(edges[k], "endpoints", path + ".edges." + std::to_string(k));
    if (!e.is_array() || e.size() != 2) r.fail(at, "must be two vertex indices");
    ends.push_back({r.index(e[0], at + ".0", v.size()), r.index(e[1], at + ".1", v.size())});
  }
  for (std::size_t k = 0; k < ends.size(); ++k)
    if (ends[k][1] != ends[(k + 1) % ends.size()][0])
      r.fail(path + ".edges." + std::to_string(k), "does not end where the next edge starts: the edges are no loop");
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const Vec2 a = v[static_cast<std::size_t>(ends[k][0])], b = v[static_cast<std::size_t>(ends[k][1])];
    p.outline.vertices.push_back(a / unit);
    p.outline.edges.push_back(read_curve(r, edges[k], a, b, unit, path + ".edges." + std::to_string(k)));
  }
  if (const std::string why = p.outline.invalid_reason(); !why.empty()) r.fail(path, why);
  if (panel.contains("translation"))
    p.translation_m = r.vector3(panel.at("translation"), path + ".translation", kMaxPatternLength) / unit;
  if (panel.contains("rotation"))
    p.rotation = rotation_from_degrees(r.vector3(panel.at("rotation"), path + ".rotation", kMaxAngle_deg));
  return p;
}

SewingPattern::Stitch read_stitch(const Reader& r, const Json& stitch, std::size_t k,
                                  const std::map<std::string, int>& panel_index, const std::vector<PanelSpec>& panels) {
  const std::string path = "pattern.stitches." + std::to_string(k);
  if (!stitch.is_array() || stitch.size() < 2 || stitch.size() > 3) r.fail(path, "a stitch is two {panel, edge} sides");
  SewingPattern::Stitch s;
  for (std::size_t side = 0; side < 2; ++side) {
    const std::string at = path + "." + std::to_string(side);
    const Json& name = r.member(stitch[side], "panel", at);
    if (!name.is_string() || !panel_index.count(name.get<std::string>())) r.fail(at + ".panel", "names no panel of the pattern");
    s.panel[side] = panel_index.at(name.get<std::string>());
    s.edge[side] = r.index(r.member(stitch[side], "edge", at), at + ".edge",
                           panels[static_cast<std::size_t>(s.panel[side])].outline.edges.size());
  }
  if (stitch.size() == 3) {
    if (stitch[2] != "right_wrong") r.fail(path + ".2", "the only stitch flag is \"right_wrong\"");
    s.same_direction = true;
  }
  if (s.panel[0] == s.panel[1] && s.edge[0] == s.edge[1]) r.fail(path, "sews an edge to itself");
  return s;
}

}  // namespace

SewingPattern read_garmentcode_pattern(const std::string& path, double grain_deg) {
  const Reader r(path);
  const Json json = parsed(path);
  const Json& pattern = r.member(json, "pattern", "");
  const Json& properties = r.member(json, "properties", "");
  const double unit = r.number(r.member(properties, "units_in_meter", "properties"), "properties.units_in_meter");
  if (!(unit >= 1e-3 && unit <= 1e6)) r.fail("properties.units_in_meter", "must be between 0.001 and 1e6 (100: centimetres)");
  if (properties.contains("curvature_coords") && properties.at("curvature_coords") != "relative")
    r.fail("properties.curvature_coords", "must be \"relative\" (absolute control points are an older format)");
  const Json& panels = r.member(pattern, "panels", "pattern");
  if (!panels.is_object() || panels.empty()) r.fail("pattern.panels", "must name at least one panel");
  SewingPattern out;
  std::map<std::string, int> index;
  // The pattern's own order when it gives one, else the file's.
  std::vector<std::string> order;
  const auto listed = [&](const std::string& name) { return std::find(order.begin(), order.end(), name) != order.end(); };
  if (pattern.contains("panel_order") && pattern.at("panel_order").is_array())
    for (const Json& name : pattern.at("panel_order"))
      if (name.is_string() && panels.contains(name.get<std::string>()) && !listed(name.get<std::string>()))
        order.push_back(name.get<std::string>());
  for (auto it = panels.begin(); it != panels.end(); ++it)
    if (!listed(it.key())) order.push_back(it.key());
  for (const std::string& name : order) {
    index[name] = static_cast<int>(out.panels.size());
    out.panels.push_back(read_panel(r, name, panels.at(name), unit, grain_deg));
  }
  const Json& stitches = r.member(pattern, "stitches", "pattern");
  if (!stitches.is_array()) r.fail("pattern.stitches", "must be an array");
  for (std::size_t k = 0; k < stitches.size(); ++k) out.stitches.push_back(read_stitch(r, stitches[k], k, index, out.panels));
  return out;
}

}  // namespace fabform
