#include "io/vrml_reader.hpp"

#include <Inventor/SbLinear.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoPrimitiveVertex.h>
#include <Inventor/VRMLnodes/SoVRMLBox.h>
#include <Inventor/VRMLnodes/SoVRMLCone.h>
#include <Inventor/VRMLnodes/SoVRMLCoordinate.h>
#include <Inventor/VRMLnodes/SoVRMLCylinder.h>
#include <Inventor/VRMLnodes/SoVRMLElevationGrid.h>
#include <Inventor/VRMLnodes/SoVRMLExtrusion.h>
#include <Inventor/VRMLnodes/SoVRMLIndexedFaceSet.h>
#include <Inventor/VRMLnodes/SoVRMLIndexedLineSet.h>
#include <Inventor/VRMLnodes/SoVRMLInline.h>
#include <Inventor/VRMLnodes/SoVRMLPointSet.h>
#include <Inventor/VRMLnodes/SoVRMLShape.h>
#include <Inventor/VRMLnodes/SoVRMLSphere.h>
#include <Inventor/VRMLnodes/SoVRMLText.h>
#include <Inventor/VRMLnodes/SoVRMLTexture.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoError.h>
#include <Inventor/errors/SoMemoryError.h>
#include <Inventor/errors/SoReadError.h>
#include <Inventor/nodes/SoSeparator.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <regex>
#include <set>

#include "fabform/error.hpp"
#include "io/vertex_welder.hpp"

namespace fabform {
namespace {

// ---- Coin, wrapped once ---------------------------------------------------------------------

// Coin's scene database is process-global and not thread-safe: SoDB::init runs once (a
// function-local static is initialised exactly once, even when threads race), and every read
// holds the lock for its whole length, so the error handlers below see one read at a time.
struct CoinRuntime {
  CoinRuntime() {
    SoDB::init();
    // Coin would read an Inline's file while parsing, searching only its own directory list,
    // and recurse without end on a file that Inlines itself (a stack overflow); fabform
    // resolves Inlines itself (resolve_inlines).
    SoVRMLInline::setReadAsSoFile(FALSE);
  }
  // No SoDB::finish at exit: other static destructors may still hold Coin objects, and the
  // operating system reclaims the memory anyway.
  std::mutex lock;
};

std::mutex& coin_lock() {
  static CoinRuntime runtime;
  return runtime.lock;
}

// What Coin posted while one file was read and traversed.
struct CoinMessages {
  std::vector<std::string> read_errors;  // SoReadError: the file is not what Coin can read
  std::vector<std::string> errors;       // SoError, SoMemoryError, SoDebugError (error)
  std::vector<std::string> warnings;     // SoDebugError (warning, info)
};

void capture_read_error(const SoError* error, void* data) {
  static_cast<CoinMessages*>(data)->read_errors.emplace_back(error->getDebugString().getString());
}

void capture_error(const SoError* error, void* data) {
  static_cast<CoinMessages*>(data)->errors.emplace_back(error->getDebugString().getString());
}

void capture_debug(const SoError* error, void* data) {
  auto* messages = static_cast<CoinMessages*>(data);
  const std::string text = error->getDebugString().getString();
  if (static_cast<const SoDebugError*>(error)->getSeverity() == SoDebugError::ERROR)
    messages->errors.push_back(text);
  else
    messages->warnings.push_back(text);
}

// Routes every kind of Coin message into *messages (instead of Coin's default handlers, which
// print to stderr) for as long as it lives, then puts the previous handlers back.
class ScopedCoinHandlers {
 public:
  explicit ScopedCoinHandlers(CoinMessages* messages)
      : error_(SoError::getHandlerCallback(), SoError::getHandlerData()),
        read_(SoReadError::getHandlerCallback(), SoReadError::getHandlerData()),
        debug_(SoDebugError::getHandlerCallback(), SoDebugError::getHandlerData()),
        memory_(SoMemoryError::getHandlerCallback(), SoMemoryError::getHandlerData()) {
    SoError::setHandlerCallback(capture_error, messages);
    SoReadError::setHandlerCallback(capture_read_error, messages);
    SoDebugError::setHandlerCallback(capture_debug, messages);
    SoMemoryError::setHandlerCallback(capture_error, messages);
  }
  ~ScopedCoinHandlers() {
    SoError::setHandlerCallback(error_.first, error_.second);
    SoReadError::setHandlerCallback(read_.first, read_.second);
    SoDebugError::setHandlerCallback(debug_.first, debug_.second);
    SoMemoryError::setHandlerCallback(memory_.first, memory_.second);
  }
  ScopedCoinHandlers(const ScopedCoinHandlers&) = delete;
  ScopedCoinHandlers& operator=(const ScopedCoinHandlers&) = delete;

 private:
  using Handler = std::pair<SoErrorCB*, void*>;
  Handler error_, read_, debug_, memory_;
};

// Holds one reference to a Coin node (a scene root) and drops it when it goes out of scope,
// which deletes the scene unless something else holds it too.
class NodeRef {
 public:
  explicit NodeRef(SoNode* node) : node_(node) {
    if (node_) node_->ref();
  }
  ~NodeRef() {
    if (node_) node_->unref();
  }
  NodeRef(NodeRef&& other) noexcept : node_(other.node_) { other.node_ = nullptr; }
  NodeRef(const NodeRef&) = delete;
  NodeRef& operator=(const NodeRef&) = delete;
  NodeRef& operator=(NodeRef&&) = delete;
  SoNode* get() const { return node_; }

 private:
  SoNode* node_;
};

// A Coin read error reads "Coin read error: WHAT\n\tOccurred at line N in FILE". Returns WHAT
// and N (0 when absent).
// Coin's names of VRML97 nodes carry a "VRML" prefix ("VRMLCoordinate"); users wrote "Coordinate".
std::pair<std::string, int> parse_read_error(const std::string& text) {
  std::string what = text.substr(0, text.find('\n'));
  const std::string prefix = "Coin read error: ";
  if (what.rfind(prefix, 0) == 0) what = what.substr(prefix.size());
  static const std::regex kCoinName("\\bVRML(?=[A-Z])");
  what = std::regex_replace(what, kCoinName, "");
  int line = 0;
  std::smatch match;
  static const std::regex kLine("Occurred at line\\s+([0-9]+)");
  if (std::regex_search(text, match, kLine)) line = std::stoi(match[1].str());
  return {what, line};
}

// Coin reports a texture image it cannot find as a read error, yet reads on; the body does not
// depend on it.
bool is_missing_image(const std::string& read_error) {
  const std::string what = parse_read_error(read_error).first;
  return what.rfind("Could not read texture file", 0) == 0 || what.rfind("Could not read image file", 0) == 0;
}

// One line of a Coin message, for a warning or an error, cut after its first sentence.
std::string first_line(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  const std::size_t stop = line.find(". ");
  return stop == std::string::npos ? line : line.substr(0, stop + 1);
}

std::string counted(int n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// Coin's VRML97 node type names carry a "VRML" prefix ("VRMLIndexedFaceSet").
std::string vrml_type_name(const SoNode* node) {
  std::string name = node->getTypeId().getName().getString();
  if (name.rfind("VRML", 0) == 0) name = name.substr(4);
  return name;
}

// ---- The scene, prepared --------------------------------------------------------------------

// Every node of type `type` that the triangulation will reach: nodes held in fields
// (Shape.geometry) included, a Switch's chosen child only (Coin's VRMLSwitch traverses no
// other). A callback action reaches the nodes themselves; SoSearchAction's paths would end at
// the Shape, and their hidden tails are reachable only by casting SoPath to SoFullPath, an
// object it is not.
std::vector<SoNode*> find_all(SoNode* root, const SoType& type) {
  std::vector<SoNode*> nodes;
  SoCallbackAction visit;
  visit.addPreCallback(
      type,
      [](void* found, SoCallbackAction*, const SoNode* node) {
        static_cast<std::vector<SoNode*>*>(found)->push_back(const_cast<SoNode*>(node));
        return SoCallbackAction::CONTINUE;
      },
      &nodes);
  visit.apply(root);
  return nodes;
}

// Makes Coin triangulate every polygon as possibly concave, and drops the per-vertex attributes
// fabform does not use.
//
// VRML97's `convex` defaults to TRUE, and with it Coin fans each polygon from its first corner:
// an L-shaped hexagon listed from a corner next to the reflex one comes out as four triangles
// covering area 4 instead of 3, one of them facing backwards (checked on Coin 4.0.0; see
// tests/io/vrml_reader_test.cpp, ConcavePolygonsAreTriangulated). Exporters leave `convex` at
// its default on concave faces, so every face set is read with convex FALSE, which sends each
// polygon through Coin's tessellator (SbTesselator); triangles pass through it unchanged and
// it keeps each polygon's winding.
//
// VRML97 lets the last polygon end without -1. Coin 4.0.0 then fans that polygon even with
// convex FALSE (a U listed from an inner corner came out folded), so a -1 is appended.
//
// Normals, colours and texture coordinates (and their index lists) are removed because Coin
// does not check their indices; positions are checked in check_face_set.
void prepare(SoNode* root) {
  for (SoNode* node : find_all(root, SoVRMLIndexedFaceSet::getClassTypeId())) {
    auto* faces = static_cast<SoVRMLIndexedFaceSet*>(node);
    faces->convex.setValue(FALSE);
    const int n = faces->coordIndex.getNum();
    if (n > 0 && faces->coordIndex[n - 1] != -1) faces->coordIndex.set1Value(n, -1);
    faces->normal.setValue(nullptr);
    faces->normalIndex.setNum(0);
    faces->color.setValue(nullptr);
    faces->colorIndex.setNum(0);
    faces->texCoord.setValue(nullptr);
    faces->texCoordIndex.setNum(0);
  }
  for (SoNode* node : find_all(root, SoVRMLExtrusion::getClassTypeId()))
    static_cast<SoVRMLExtrusion*>(node)->convex.setValue(FALSE);
  for (SoNode* node : find_all(root, SoVRMLElevationGrid::getClassTypeId())) {
    auto* grid = static_cast<SoVRMLElevationGrid*>(node);
    grid->normal.setValue(nullptr);
    grid->color.setValue(nullptr);
    grid->texCoord.setValue(nullptr);
  }
}

// "" when Coin can generate the face set's triangles safely, else what is wrong.
std::string check_face_set(const SoVRMLIndexedFaceSet& faces) {
  const SoNode* coord = faces.coord.getValue();
  int points = 0;
  if (coord && coord->isOfType(SoVRMLCoordinate::getClassTypeId()))
    points = static_cast<const SoVRMLCoordinate*>(coord)->point.getNum();
  else if (coord)
    return "IndexedFaceSet coord is a " + vrml_type_name(coord) + ", not a Coordinate";
  const int n = faces.coordIndex.getNum();
  const int32_t* index = faces.coordIndex.getValues(0);
  for (int i = 0; i < n; ++i)
    if (index[i] < -1 || index[i] >= points)
      return "IndexedFaceSet coordIndex " + std::to_string(index[i]) + " (entry " + std::to_string(i) +
             ") is out of range: its Coordinate has " + counted(points, "point", "points");
  return "";
}

std::string check_elevation_grid(const SoVRMLElevationGrid& grid) {
  const long long need = static_cast<long long>(grid.xDimension.getValue()) * grid.zDimension.getValue();
  if (grid.xDimension.getValue() < 0 || grid.zDimension.getValue() < 0 || grid.height.getNum() < need)
    return "ElevationGrid has " + std::to_string(grid.height.getNum()) + " heights for " +
           std::to_string(grid.xDimension.getValue()) + " x " + std::to_string(grid.zDimension.getValue()) +
           " points";
  return "";
}

// ---- A check Coin does not make ---------------------------------------------------------------

// The text after the header line, decompressed when the file is gzip (Coin does that).
std::string text_after_header(const std::string& path) {
  SoInput input;
  std::string text;
  if (!input.openFile(path.c_str())) return text;
  char c = 0;
  while (input.get(c)) text.push_back(c);
  return text;
}

// A node used inside its own definition (DEF A Group { children USE A }) makes the scene a
// cycle, which VRML97 forbids; Coin 4.0.0 crashes on it (segmentation fault while reading).
// Returns the name and line of the first such USE ("" when none). `text` starts on line 2.
std::pair<std::string, int> find_use_inside_own_def(const std::string& text) {
  struct Open {
    std::string name;
    int depth;  // brace depth outside the node
  };
  std::vector<Open> open;                     // DEF'd nodes whose braces are not closed yet
  std::map<std::string, std::size_t> latest;  // name -> its latest DEF, as an index into `defs`
  std::vector<bool> defs_open;
  std::string pending_def;                    // DEF NAME seen, its '{' not yet
  int depth = 0, line = 2;
  enum class Expect { kNothing, kDefName, kUseName } expect = Expect::kNothing;
  std::size_t i = 0;
  const std::size_t n = text.size();
  auto is_separator = [](char ch) {
    return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\n' || ch == ',' || ch == '{' || ch == '}' || ch == '[' ||
           ch == ']' || ch == '#' || ch == '"';
  };
  while (i < n) {
    const char ch = text[i];
    if (ch == '\n') {
      ++line;
      ++i;
    } else if (ch == ' ' || ch == '\t' || ch == '\r' || ch == ',') {
      ++i;
    } else if (ch == '#') {
      while (i < n && text[i] != '\n') ++i;
    } else if (ch == '"') {
      for (++i; i < n && text[i] != '"'; ++i) {
        if (text[i] == '\\' && i + 1 < n) ++i;
        if (text[i] == '\n') ++line;
      }
      ++i;
      expect = Expect::kNothing;
    } else if (ch == '{') {
      if (!pending_def.empty()) {
        latest[pending_def] = defs_open.size();
        defs_open.push_back(true);
        open.push_back({pending_def, depth});
        pending_def.clear();
      }
      ++depth;
      ++i;
      expect = Expect::kNothing;
    } else if (ch == '}') {
      --depth;
      while (!open.empty() && open.back().depth >= depth) {
        defs_open[latest[open.back().name]] = false;
        open.pop_back();
      }
      ++i;
      expect = Expect::kNothing;
    } else if (ch == '[' || ch == ']') {
      ++i;
      expect = Expect::kNothing;
    } else {
      const std::size_t start = i;
      while (i < n && !is_separator(text[i])) ++i;
      const std::string word = text.substr(start, i - start);
      if (expect == Expect::kDefName) {
        pending_def = word;
        expect = Expect::kNothing;
      } else if (expect == Expect::kUseName) {
        const auto it = latest.find(word);
        if (it != latest.end() && defs_open[it->second]) return {word, line};
        expect = Expect::kNothing;
      } else if (word == "DEF") {
        expect = Expect::kDefName;
      } else if (word == "USE") {
        expect = Expect::kUseName;
      }
    }
  }
  return {"", 0};
}

// ---- Reading, Inlines included ---------------------------------------------------------------

// A local file an Inline names: its first url that exists, relative to the including file.
// "" when none does.
std::string inline_target(const SoVRMLInline& node, const std::filesystem::path& directory) {
  for (int i = 0; i < node.url.getNum(); ++i) {
    std::string url = node.url[i].getString();
    if (url.rfind("file://", 0) == 0) url = url.substr(7);
    if (url.find("://") != std::string::npos) continue;  // http and the like: not fetched
    std::filesystem::path file(url);
    if (file.is_relative()) file = directory / file;
    std::error_code ec;
    if (std::filesystem::is_regular_file(file, ec)) return std::filesystem::canonical(file, ec).string();
  }
  return "";
}

std::string url_list(const SoVRMLInline& node) {
  std::string text;
  for (int i = 0; i < node.url.getNum(); ++i) text += std::string(i ? ", " : "") + "'" + node.url[i].getString() + "'";
  return text.empty() ? "no url" : text;
}

struct SceneReader {
  CoinMessages* messages;
  std::vector<std::string> chain;           // the files being read, outermost first
  std::vector<std::string> image_warnings;  // texture images Coin did not find

  // Reads one VRML97 file and, recursively, the files it Inlines.
  NodeRef read(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError({path, 0, ""}, "no such mesh file");
    if (std::filesystem::file_size(path, ec) == 0) throw InputError({path, 0, ""}, "empty file");

    SoInput input;  // closes the file when it goes out of scope
    if (!input.openFile(path.c_str())) throw failure(path, "cannot open the file");
    return parse(input, path, text_after_header(path));
  }

  // Reads VRML97 text that stands for the file `path` (a translation of it).
  NodeRef read_text(const std::string& text, const std::string& path) {
    SoInput input;
    input.setBuffer(text.data(), text.size());
    return parse(input, path, text.substr(std::min(text.size(), text.find('\n') + 1)));
  }

  NodeRef parse(SoInput& input, const std::string& path, const std::string& body) {
    std::error_code ec;
    // Coin reads the header itself (through gzip when the file is compressed).
    const std::string header = input.getHeader().getString();
    if (!input.isValidFile() || !input.isFileVRML2()) {
      const std::string seen = header.empty() ? "no header" : "the header '" + header + "'";
      throw InputError({path, 1, ""},
                       "not a VRML97 file: the first line must be '#VRML V2.0 utf8' (found " + seen + ")");
    }
    const auto [cycle, cycle_line] = find_use_inside_own_def(body);
    if (!cycle.empty())
      throw InputError({path, cycle_line, ""}, "USE " + cycle + " inside the definition of " + cycle +
                                                   " (a node cannot contain itself)");
    NodeRef root(SoDB::readAll(&input));
    for (auto it = messages->read_errors.begin(); it != messages->read_errors.end();) {
      if (!is_missing_image(*it)) {
        ++it;
        continue;
      }
      const auto [what, line] = parse_read_error(*it);
      image_warnings.push_back(std::filesystem::path(path).filename().string() + ":" + std::to_string(line) + ": " +
                               what + " (textures do not matter to the body)");
      it = messages->read_errors.erase(it);
    }
    // Coin goes on after some errors (a float out of range becomes 0), so any error fails the read.
    if (!root.get() || !messages->read_errors.empty() || !messages->errors.empty())
      throw failure(path, "cannot read VRML");

    chain.push_back(std::filesystem::canonical(path, ec).string());
    resolve_inlines(root.get(), path);
    chain.pop_back();
    return root;
  }

  void resolve_inlines(SoNode* root, const std::string& path) {
    const std::filesystem::path directory = std::filesystem::absolute(path).parent_path();
    std::set<SoNode*> done;  // a USE'd Inline is found once per use
    for (SoNode* node : find_all(root, SoVRMLInline::getClassTypeId())) {
      if (!done.insert(node).second) continue;
      auto* inlined = static_cast<SoVRMLInline*>(node);
      const std::string target = inline_target(*inlined, directory);
      if (target.empty())
        throw InputError({path, 0, ""}, "Inline " + url_list(*inlined) + ": no such local file");
      if (std::find(chain.begin(), chain.end(), target) != chain.end()) {
        std::string cycle;
        for (const std::string& file : chain) cycle += file + " -> ";
        throw InputError({path, 0, ""}, "Inline cycle: " + cycle + target);
      }
      const NodeRef child(read(target));
      inlined->setChildData(child.get());
    }
  }

  // The first read error Coin posted (with its line), else the first other error.
  InputError failure(const std::string& path, const std::string& fallback) const {
    if (!messages->read_errors.empty()) {
      const auto [what, line] = parse_read_error(messages->read_errors.front());
      return InputError({path, line, ""}, "cannot read VRML: " + what);
    }
    if (!messages->errors.empty()) return InputError({path, 0, ""}, "cannot read VRML: " + first_line(messages->errors.front()));
    return InputError({path, 0, ""}, fallback);
  }
};

// ---- Traversal ------------------------------------------------------------------------------

enum class Kind { kSurface, kText, kLinesOrPoints, kOther };

Kind kind_of(const SoNode* node) {
  for (const SoType& t : {SoVRMLIndexedFaceSet::getClassTypeId(), SoVRMLBox::getClassTypeId(),
                          SoVRMLSphere::getClassTypeId(), SoVRMLCylinder::getClassTypeId(),
                          SoVRMLCone::getClassTypeId(), SoVRMLExtrusion::getClassTypeId(),
                          SoVRMLElevationGrid::getClassTypeId()})
    if (node->isOfType(t)) return Kind::kSurface;
  if (node->isOfType(SoVRMLText::getClassTypeId())) return Kind::kText;
  if (node->isOfType(SoVRMLIndexedLineSet::getClassTypeId()) || node->isOfType(SoVRMLPointSet::getClassTypeId()))
    return Kind::kLinesOrPoints;
  return Kind::kOther;
}

// The geometry node's own `ccw` (IndexedFaceSet, Extrusion, ElevationGrid); TRUE when it has none
// (Box, Sphere, Cylinder and Cone are generated with outward, counter-clockwise faces).
bool counter_clockwise(const SoNode* node) {
  if (node->isOfType(SoVRMLIndexedFaceSet::getClassTypeId()))
    return static_cast<const SoVRMLIndexedFaceSet*>(node)->ccw.getValue() != FALSE;
  if (node->isOfType(SoVRMLExtrusion::getClassTypeId()))
    return static_cast<const SoVRMLExtrusion*>(node)->ccw.getValue() != FALSE;
  if (node->isOfType(SoVRMLElevationGrid::getClassTypeId()))
    return static_cast<const SoVRMLElevationGrid*>(node)->ccw.getValue() != FALSE;
  return true;
}

bool two_sided(const SoNode* node) {
  if (node->isOfType(SoVRMLIndexedFaceSet::getClassTypeId()))
    return static_cast<const SoVRMLIndexedFaceSet*>(node)->solid.getValue() == FALSE;
  if (node->isOfType(SoVRMLExtrusion::getClassTypeId()))
    return static_cast<const SoVRMLExtrusion*>(node)->solid.getValue() == FALSE;
  if (node->isOfType(SoVRMLElevationGrid::getClassTypeId()))
    return static_cast<const SoVRMLElevationGrid*>(node)->solid.getValue() == FALSE;
  return false;
}

struct Traversal {
  Traversal() = default;
  Traversal(const Traversal&) = delete;  // welder points into this object's own mesh
  Traversal& operator=(const Traversal&) = delete;

  TriangleMesh mesh;
  VertexWelder welder{&mesh.vertices};

  // The geometry node whose triangles are coming, with its model matrix and orientation.
  const SoNode* current = nullptr;
  Eigen::Matrix3d linear = Eigen::Matrix3d::Identity();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  bool reverse = false;
  std::size_t triangles_before = 0;

  int shapes_without_geometry = 0;
  std::map<std::string, int> text, lines_or_points, other, no_triangles;
  int two_sided = 0;
  std::string error;  // set by a callback, which then aborts the traversal

  int vertex(const SbVec3f& local) {
    const Eigen::Vector3d p = linear * Eigen::Vector3d(local[0], local[1], local[2]) + offset;
    if (!p.allFinite()) {
      if (error.empty()) error = "a transformed point is not finite";
      return 0;
    }
    return welder.index_of(p);
  }
};

SoCallbackAction::Response prune(void*, SoCallbackAction*, const SoNode*) { return SoCallbackAction::PRUNE; }

SoCallbackAction::Response on_shape(void* data, SoCallbackAction*, const SoNode* node) {
  auto* t = static_cast<Traversal*>(data);
  if (!static_cast<const SoVRMLShape*>(node)->geometry.getValue()) ++t->shapes_without_geometry;
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response before_geometry(void* data, SoCallbackAction* action, const SoNode* node) {
  auto* t = static_cast<Traversal*>(data);
  t->current = nullptr;
  const std::string type = vrml_type_name(node);
  switch (kind_of(node)) {
    case Kind::kText:
      ++t->text[type];
      return SoCallbackAction::PRUNE;
    case Kind::kLinesOrPoints:
      ++t->lines_or_points[type];
      return SoCallbackAction::PRUNE;
    case Kind::kOther:
      ++t->other[type];
      return SoCallbackAction::PRUNE;
    case Kind::kSurface:
      break;
  }
  if (node->isOfType(SoVRMLIndexedFaceSet::getClassTypeId()))
    t->error = check_face_set(*static_cast<const SoVRMLIndexedFaceSet*>(node));
  else if (node->isOfType(SoVRMLElevationGrid::getClassTypeId()))
    t->error = check_elevation_grid(*static_cast<const SoVRMLElevationGrid*>(node));
  if (!t->error.empty()) return SoCallbackAction::ABORT;

  // Coin's SbMatrix acts on row vectors (p' = p M); here p' = linear p + offset.
  const SbMatrix& m = action->getModelMatrix();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) t->linear(r, c) = m[c][r];
    t->offset(r) = m[3][r];
  }
  // Coin hands triangles over in the file's vertex order whatever `ccw` says (it only turns
  // its normals), and a mirroring transform turns counter-clockwise into clockwise.
  t->reverse = !counter_clockwise(node) != (t->linear.determinant() < 0.0);
  if (two_sided(node)) ++t->two_sided;
  t->current = node;
  t->triangles_before = t->mesh.triangles.size();
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response after_geometry(void* data, SoCallbackAction*, const SoNode* node) {
  auto* t = static_cast<Traversal*>(data);
  if (node == t->current && t->mesh.triangles.size() == t->triangles_before) ++t->no_triangles[vrml_type_name(node)];
  t->current = nullptr;
  return SoCallbackAction::CONTINUE;
}

void on_triangle(void* data, SoCallbackAction*, const SoPrimitiveVertex* a, const SoPrimitiveVertex* b,
                 const SoPrimitiveVertex* c) {
  auto* t = static_cast<Traversal*>(data);
  if (!t->current || !t->error.empty()) return;
  std::array<int, 3> triangle{t->vertex(a->getPoint()), t->vertex(b->getPoint()), t->vertex(c->getPoint())};
  if (t->reverse) std::swap(triangle[1], triangle[2]);
  t->mesh.triangles.push_back(triangle);
}

std::string by_type(const std::map<std::string, int>& counts) {
  std::string text;
  for (const auto& [type, n] : counts) text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + type;
  return text;
}

void add_warnings(const Traversal& t, const CoinMessages& messages, std::vector<std::string>* warnings) {
  if (t.shapes_without_geometry > 0)
    warnings->push_back(counted(t.shapes_without_geometry, "Shape has", "Shapes have") +
                        " no geometry and were skipped");
  if (!t.text.empty()) warnings->push_back("skipped text (" + by_type(t.text) + "): text is not a surface of the body");
  if (!t.lines_or_points.empty())
    warnings->push_back("skipped " + by_type(t.lines_or_points) + ": lines and points have no faces");
  if (!t.other.empty()) warnings->push_back("skipped " + by_type(t.other) + ": not VRML97 surface geometry");
  if (!t.no_triangles.empty()) warnings->push_back("no triangles from " + by_type(t.no_triangles));
  if (t.two_sided > 0)
    warnings->push_back(counted(t.two_sided, "geometry node is", "geometry nodes are") +
                        " marked solid FALSE (two-sided): their faces are not promised to point outward");
  for (const std::string& text : messages.warnings) warnings->push_back("Coin: " + first_line(text));
}

}  // namespace

// The triangles of a scene read from `path`, with the warnings of reading and traversing it.
TriangleMesh triangles_of(const NodeRef& root, const std::string& path, const SceneReader& reader,
                          const CoinMessages& messages, std::vector<std::string>* warnings) {
  const std::vector<std::string>& image_warnings = reader.image_warnings;

  prepare(root.get());
  Traversal traversal;
  SoCallbackAction action;
  action.addPreCallback(SoVRMLTexture::getClassTypeId(), prune, nullptr);  // no image decoding
  action.addPreCallback(SoVRMLShape::getClassTypeId(), on_shape, &traversal);
  action.addPreCallback(SoShape::getClassTypeId(), before_geometry, &traversal);
  action.addPostCallback(SoShape::getClassTypeId(), after_geometry, &traversal);
  action.addTriangleCallback(SoShape::getClassTypeId(), on_triangle, &traversal);
  action.apply(root.get());
  if (!traversal.error.empty()) throw InputError({path, 0, ""}, traversal.error);
  if (!messages.errors.empty()) throw InputError({path, 0, ""}, "Coin: " + first_line(messages.errors.front()));

  std::vector<std::string> found;
  add_warnings(traversal, messages, &found);
  if (traversal.mesh.triangles.empty()) {
    std::string why;
    for (const std::string& w : found) why += "; " + w;
    throw InputError({path, 0, ""}, "no triangles" + why);
  }
  if (warnings) {
    warnings->insert(warnings->end(), found.begin(), found.end());
    warnings->insert(warnings->end(), image_warnings.begin(), image_warnings.end());
  }
  return std::move(traversal.mesh);
}

TriangleMesh read_vrml(const std::string& path, std::vector<std::string>* warnings) {
  const std::lock_guard<std::mutex> guard(coin_lock());
  CoinMessages messages;
  const ScopedCoinHandlers handlers(&messages);
  SceneReader reader{&messages, {}, {}};
  const NodeRef root(reader.read(path));
  return triangles_of(root, path, reader, messages, warnings);
}

TriangleMesh read_vrml_text(const std::string& text, const std::string& path, std::vector<std::string>* warnings) {
  const std::lock_guard<std::mutex> guard(coin_lock());
  CoinMessages messages;
  const ScopedCoinHandlers handlers(&messages);
  SceneReader reader{&messages, {}, {}};
  const NodeRef root(reader.read_text(text, path));
  return triangles_of(root, path, reader, messages, warnings);
}

}  // namespace fabform
