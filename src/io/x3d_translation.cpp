#include "io/x3d_translation.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include <tinyxml2.h>

#include "fabform/error.hpp"

namespace fabform {
namespace {

using tinyxml2::XMLElement;

enum class Field { kBool, kInt, kFloat, kVec3, kRotation, kInts, kFloats, kVec2s, kVec3s, kRotations };

// VRML97's fields of the nodes translated (X3D 3 names them alike); others are left out.
const std::map<std::string, std::map<std::string, Field>>& node_fields() {
  static const std::map<std::string, std::map<std::string, Field>> fields = {
      {"Transform", {{"translation", Field::kVec3}, {"rotation", Field::kRotation}, {"scale", Field::kVec3},
                     {"scaleOrientation", Field::kRotation}, {"center", Field::kVec3}}},
      {"Group", {}},
      {"Switch", {{"whichChoice", Field::kInt}}},
      {"Shape", {}},
      {"IndexedFaceSet", {{"coordIndex", Field::kInts}, {"ccw", Field::kBool}, {"solid", Field::kBool},
                          {"convex", Field::kBool}, {"creaseAngle", Field::kFloat}}},
      {"Coordinate", {{"point", Field::kVec3s}}},
      {"Box", {{"size", Field::kVec3}}},
      {"Sphere", {{"radius", Field::kFloat}}},
      {"Cylinder", {{"radius", Field::kFloat}, {"height", Field::kFloat}, {"bottom", Field::kBool},
                    {"side", Field::kBool}, {"top", Field::kBool}}},
      {"Cone", {{"bottomRadius", Field::kFloat}, {"height", Field::kFloat}, {"side", Field::kBool},
                {"bottom", Field::kBool}}},
      {"Extrusion", {{"beginCap", Field::kBool}, {"endCap", Field::kBool}, {"ccw", Field::kBool},
                     {"convex", Field::kBool}, {"solid", Field::kBool}, {"creaseAngle", Field::kFloat},
                     {"crossSection", Field::kVec2s}, {"orientation", Field::kRotations},
                     {"scale", Field::kVec2s}, {"spine", Field::kVec3s}}},
      {"ElevationGrid", {{"height", Field::kFloats}, {"xDimension", Field::kInt}, {"zDimension", Field::kInt},
                         {"xSpacing", Field::kFloat}, {"zSpacing", Field::kFloat}, {"ccw", Field::kBool},
                         {"solid", Field::kBool}, {"creaseAngle", Field::kFloat}}},
      // X3D's triangle sets, written as IndexedFaceSets.
      {"IndexedTriangleSet", {{"ccw", Field::kBool}, {"solid", Field::kBool}}},
      {"TriangleSet", {{"ccw", Field::kBool}, {"solid", Field::kBool}}},
  };
  return fields;
}

bool is_grouping(const std::string& name) { return name == "Transform" || name == "Group" || name == "Switch"; }

bool is_geometry(const std::string& name) {
  return node_fields().count(name) && !is_grouping(name) && name != "Shape" && name != "Coordinate";
}

// How many numbers a value of the field holds: exactly n, or a multiple of n (0 for booleans).
std::pair<int, bool> arity(Field field) {
  switch (field) {
    case Field::kBool: return {0, false};
    case Field::kInt:
    case Field::kFloat: return {1, false};
    case Field::kVec3: return {3, false};
    case Field::kRotation: return {4, false};
    case Field::kInts:
    case Field::kFloats: return {1, true};
    case Field::kVec2s: return {2, true};
    case Field::kVec3s: return {3, true};
    case Field::kRotations: return {4, true};
  }
  return {1, false};
}

std::vector<std::string> tokens(const std::string& text) {
  std::vector<std::string> out;
  std::string word;
  for (const char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
      if (!word.empty()) out.push_back(word), word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) out.push_back(word);
  return out;
}

bool is_number(const std::string& word, bool integer) {
  char* end = nullptr;
  if (integer) std::strtoll(word.c_str(), &end, 10);
  else std::strtod(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size() && word.find_first_of("xXnNiI") == std::string::npos;
}

class Translator {
 public:
  explicit Translator(std::string path) : path_(std::move(path)) {}

  X3dTranslation run(const XMLElement& root) {
    if (std::string(root.Name()) != "X3D") fail(root, "not an X3D file (the root element is not X3D)");
    const XMLElement* scene = root.FirstChildElement("Scene");
    if (!scene) fail(root, "X3D file without a Scene");
    out_ << "#VRML V2.0 utf8\n# translated from X3D by fabform\n";
    for (const XMLElement* e = scene->FirstChildElement(); e; e = e->NextSiblingElement())
      if (is_grouping(e->Name()) || std::string(e->Name()) == "Shape") node(*e);
      else leave_out(*e);
    return {out_.str(), left_out_};
  }

 private:
  [[noreturn]] void fail(const XMLElement& e, const std::string& why) const {
    throw InputError({path_, e.GetLineNum(), ""}, why);
  }

  void leave_out(const XMLElement& e) { ++left_out_[e.Name()]; }

  // DEF and USE names as VRML97 identifiers: X3D's IDs may hold characters VRML forbids.
  static std::string identifier(const std::string& id) {
    std::string out = id;
    for (char& c : out)
      if (static_cast<unsigned char>(c) <= ' ' || std::string("\"'#,.[]\\{}").find(c) != std::string::npos) c = '_';
    if (!out.empty() && (std::isdigit(static_cast<unsigned char>(out[0])) || out[0] == '+' || out[0] == '-'))
      out = "_" + out;
    return out;
  }

  // Writes the element as a VRML97 node: DEF or USE, its fields, its children.
  void node(const XMLElement& e) {
    const std::string name = e.Name();
    if (const char* use = e.Attribute("USE")) {
      if (defined_.count(use)) out_ << "USE " << identifier(use) << '\n';
      else leave_out(e);  // a USE of something left out (or not defined before it)
      return;
    }
    if (const char* def = e.Attribute("DEF")) {
      defined_.insert(def);
      out_ << "DEF " << identifier(def) << ' ';
    }
    const bool triangles = name == "IndexedTriangleSet" || name == "TriangleSet";
    out_ << (triangles ? "IndexedFaceSet" : name) << " {\n";
    fields(e, node_fields().at(name));
    if (triangles) triangle_indices(e, name == "TriangleSet");
    children(e, name);
    out_ << "}\n";
  }

  void fields(const XMLElement& e, const std::map<std::string, Field>& known) {
    for (const tinyxml2::XMLAttribute* a = e.FirstAttribute(); a; a = a->Next()) {
      const auto field = known.find(a->Name());
      if (field != known.end()) value(e, field->first, field->second, a->Value());
    }
  }

  void value(const XMLElement& e, const std::string& name, Field field, const std::string& text) {
    const std::vector<std::string> words = tokens(text);
    if (field == Field::kBool) {
      if (words.size() != 1 || (words[0] != "true" && words[0] != "false"))
        fail(e, e.Name() + std::string(".") + name + ": must be true or false (got '" + text.substr(0, 40) + "')");
      out_ << name << (words[0] == "true" ? " TRUE\n" : " FALSE\n");
      return;
    }
    const auto [n, many] = arity(field);
    const bool integer = field == Field::kInt || field == Field::kInts;
    const bool count_ok = many ? words.size() % static_cast<std::size_t>(n) == 0 : words.size() == static_cast<std::size_t>(n);
    if (!count_ok)
      fail(e, e.Name() + std::string(".") + name + ": needs " + (many ? "a multiple of " : "") + std::to_string(n) +
                  (integer ? " integers" : " numbers") + ", has " + std::to_string(words.size()));
    for (const std::string& w : words)
      if (!is_number(w, integer))
        fail(e, e.Name() + std::string(".") + name + ": '" + w.substr(0, 40) + "' is not " +
                    (integer ? "an integer" : "a number"));
    out_ << name << (many ? " [" : "");
    for (const std::string& w : words) out_ << ' ' << w;
    out_ << (many ? " ]\n" : "\n");
  }

  // IndexedTriangleSet's index, or TriangleSet's implied one, as coordIndex with -1 after each
  // triangle.
  void triangle_indices(const XMLElement& e, bool implied) {
    std::vector<std::string> index;
    if (implied) {
      const XMLElement* coordinate = e.FirstChildElement("Coordinate");
      const char* point = coordinate ? coordinate->Attribute("point") : nullptr;
      const std::size_t count = point ? tokens(point).size() / 3 : 0;
      for (std::size_t i = 0; i < count - count % 3; ++i) index.push_back(std::to_string(i));
    } else if (const char* text = e.Attribute("index")) {
      index = tokens(text);
      for (const std::string& w : index)
        if (!is_number(w, true)) fail(e, std::string(e.Name()) + ".index: '" + w.substr(0, 40) + "' is not an integer");
    }
    if (index.size() % 3 != 0)
      fail(e, std::string(e.Name()) + ": " + std::to_string(index.size()) + " indices are not whole triangles");
    out_ << "coordIndex [";
    for (std::size_t i = 0; i < index.size(); ++i) out_ << ' ' << index[i] << ((i % 3 == 2) ? " -1" : "");
    out_ << " ]\n";
  }

  void children(const XMLElement& e, const std::string& name) {
    if (is_grouping(name)) {
      out_ << (name == "Switch" ? "choice [\n" : "children [\n");
      for (const XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement())
        if (is_grouping(c->Name()) || std::string(c->Name()) == "Shape") node(*c);
        else leave_out(*c);
      out_ << "]\n";
      return;
    }
    bool has_geometry = false;  // a Shape has one geometry; X3D tools sometimes write more
    for (const XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) {
      const std::string child = c->Name();
      if (name == "Shape" && is_geometry(child) && !has_geometry) {
        out_ << "geometry ";
        has_geometry = true;
        node(*c);
      } else if (child == "Coordinate" && is_geometry(name)) {
        out_ << "coord ";
        node(*c);
      } else {
        leave_out(*c);
      }
    }
  }

  std::string path_;
  std::ostringstream out_;
  std::map<std::string, int> left_out_;
  std::set<std::string> defined_;
};

}  // namespace

X3dTranslation translate_x3d_text(const std::string& text, const std::string& path) {
  tinyxml2::XMLDocument document;
  if (document.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    const std::string why = document.ErrorStr() ? document.ErrorStr() : "unreadable";
    throw InputError({path, document.ErrorLineNum(), ""}, "not well-formed XML: " + why.substr(0, 160));
  }
  const XMLElement* root = document.RootElement();
  if (!root) throw InputError({path, 0, ""}, "empty XML document");
  return Translator(path).run(*root);
}

X3dTranslation translate_x3d(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, ""}, "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return translate_x3d_text(text.str(), path);
}

}  // namespace fabform
