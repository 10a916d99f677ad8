#include "io/mesh_file_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "fabform/error.hpp"
#include "io/binary_stl.hpp"
#include "io/file_extension.hpp"
#include "io/text_lines.hpp"

namespace fabform {
namespace {

using Count = unsigned long long;

std::string read_head(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(bytes));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

// The whole file: the walks below need every byte; what they hold is bounded by the file's size.
std::string read_all(const std::string& path) { return read_head(path, std::filesystem::file_size(path)); }

[[noreturn]] void fail(const std::string& path, int line, const std::string& message) {
  throw InputError({path, line, ""}, message);
}

[[noreturn]] void refuse(const std::string& path, const std::string& what, Count count, Count needed,
                         Count available) {
  fail(path, 0, "declares " + std::to_string(count) + " " + what + ", which need at least " +
                    std::to_string(needed) + " bytes, but the file holds " + std::to_string(available));
}

// A word from the file as an error message shows it: quoted, printable ASCII only (anything
// else as '?', so that the message stays one readable line), at most 40 bytes.
std::string shown(const std::string& word) {
  std::string out = "'";
  for (std::size_t i = 0; i < word.size() && i < 40; ++i) {
    const auto c = static_cast<unsigned char>(word[i]);
    out += c >= 0x20 && c < 0x7F ? static_cast<char>(c) : '?';
  }
  return out + (word.size() > 40 ? "...'" : "'");
}

// A number read from a file, as a message shows it: an integer without a fraction.
std::string number_text(double v) {
  char text[40];
  if (v == std::floor(v) && std::abs(v) < 1e18) std::snprintf(text, sizeof text, "%lld", static_cast<long long>(v));
  else std::snprintf(text, sizeof text, "%g", v);
  return text;
}

const std::string kUtf8Bom = "\xEF\xBB\xBF";

// assimp reads bytes as Latin-1 or UTF-8; UTF-16 text looks to it like a binary file or an empty
// mesh, so the user would hear nothing useful.
void check_not_utf16(const std::string& path) {
  const std::string head = read_head(path, 2);
  if (head == "\xFF\xFE" || head == "\xFE\xFF")
    fail(path, 0, "is UTF-16 text (it starts with a byte order mark); save it as ASCII or UTF-8");
}

// A text format holds no NUL byte; UTF-16 text without a byte order mark holds one in every
// ASCII character, and a binary file in nearly every record.
void check_is_text(const std::string& path, const std::string& text) {
  const std::size_t nul = text.find('\0');
  if (nul == std::string::npos) return;
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(nul), '\n'));
  fail(path, line, "holds a NUL byte, so it is not ASCII or UTF-8 text (UTF-16 without a byte order mark?); save "
                   "it as ASCII or UTF-8");
}

// ---------------------------------------------------------------------------------------------
// The same text word by word, for formats whose records span lines (ASCII STL).
class TextWords {
 public:
  explicit TextWords(const std::string& text) : lines_(text, 0, 1, false) {}

  bool next(std::string* word) {
    while (at_ >= line_.words.size()) {
      if (!lines_.next(&line_)) return false;
      at_ = 0;
    }
    *word = line_.words[at_++];
    return true;
  }
  void skip_rest_of_line() { at_ = line_.words.size(); }
  int line() const { return line_.number > 0 ? line_.number : lines_.number(); }

 private:
  TextLines lines_;
  Line line_;
  std::size_t at_ = 0;
};

std::optional<double> number_of(const std::string& word) {
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end == word.c_str() || *end != '\0') return std::nullopt;
  return value;
}

// A coordinate must be a finite number: strtod reads "nan", "inf" and 1e999 (infinity).
void check_coordinate(const std::string& path, int line, const std::string& word) {
  const std::optional<double> value = number_of(word);
  if (!value) fail(path, line, shown(word) + " is not a number");
  if (!std::isfinite(*value)) fail(path, line, "coordinate " + shown(word) + " is not finite");
}

// A face corner must name one of the file's vertices (both formats count from 0).
void check_corner(const std::string& path, int line, double index, Count vertices) {
  if (index != std::floor(index) || index < 0 || index >= static_cast<double>(vertices))
    fail(path, line, "a face names vertex " + number_text(index) + ", but the vertices are 0 to " +
                         std::to_string(static_cast<long long>(vertices) - 1));
}

// ---------------------------------------------------------------------------------------------
// STL. Binary: an 80-byte header, a 32-bit triangle count, 50 bytes per triangle; a binary file
// of exactly that size never comes here (the caller reads it). ASCII: "solid NAME", facets of
// "facet normal x y z / outer loop / vertex x y z (three times) / endloop / endfacet", then
// "endsolid NAME"; several solids may follow one another. assimp 5.2.5 reads a facet of four
// vertices as three, an infinite or NaN coordinate as a number, a file cut short inside a
// facet's last lines or without its endsolid as whole, and a binary STL whose header starts
// with "solid" (as SolidWorks writes it) but whose size is wrong as an empty ASCII solid.

std::uint32_t binary_stl_count(const std::string& head) {
  std::uint32_t count = 0;
  std::memcpy(&count, head.data() + 80, sizeof count);
  return count;
}

[[noreturn]] void refuse_binary_stl(const std::string& path, const std::string& head, Count size, const std::string& why) {
  const Count count = binary_stl_count(head);
  fail(path, 0, why + "; as a binary STL it declares " + std::to_string(count) + " triangles, which take " +
                    std::to_string(84 + 50 * count) + " bytes, but the file holds " + std::to_string(size) +
                    (84 + 50 * count > size ? " (cut short?)" : ""));
}

class AsciiStl {
 public:
  AsciiStl(const std::string& path, const std::string& text) : path_(path), words_(text) {}

  void walk() {
    std::string word;
    words_.next(&word);  // "solid", checked by the caller
    words_.skip_rest_of_line();  // the solid's name
    for (;;) {
      if (!words_.next(&word))
        fail(path_, words_.line(), "the file ends without 'endsolid' (cut short?) after " + std::to_string(facets_) + " facets");
      if (word == "endsolid") {
        words_.skip_rest_of_line();
        if (!words_.next(&word)) return;
        if (word.compare(0, 5, "solid") != 0)
          fail(path_, words_.line(), "expected 'solid' or the end of the file after 'endsolid', found " + shown(word));
        words_.skip_rest_of_line();
      } else if (word == "facet") {
        facet();
      } else {
        fail(path_, words_.line(), "expected 'facet' or 'endsolid', found " + shown(word));
      }
    }
  }

 private:
  std::string next() {
    std::string word;
    if (!words_.next(&word))
      fail(path_, words_.line(), "the file ends inside facet " + std::to_string(facets_ + 1) + " (cut short?)");
    return word;
  }
  void expect(const std::string& keyword, const std::string& word) {
    if (word != keyword)
      fail(path_, words_.line(), "facet " + std::to_string(facets_ + 1) + ": expected '" + keyword + "', found " + shown(word));
  }
  void facet() {
    std::string word = next();
    if (word == "normal") {  // its three numbers are not used (the normals are dropped)
      for (int k = 0; k < 3; ++k) next();
      word = next();
    }
    expect("outer", word);
    expect("loop", next());
    int vertices = 0;
    for (word = next(); word == "vertex"; word = next()) {
      ++vertices;
      for (int k = 0; k < 3; ++k) {
        const std::string coordinate = next();
        check_coordinate(path_, words_.line(), coordinate);
      }
    }
    expect("endloop", word);
    if (vertices != 3)
      fail(path_, words_.line(), "facet " + std::to_string(facets_ + 1) + " has " + std::to_string(vertices) +
                                     " vertices; a facet has 3");
    expect("endfacet", next());
    ++facets_;
  }

  const std::string& path_;
  TextWords words_;
  Count facets_ = 0;
};

void check_stl(const std::string& path, Count size) {
  const std::string head = read_head(path, 84);
  const std::size_t first = head.find_first_not_of(" \t\r\n\f\v");  // assimp skips white space first
  const bool maybe_ascii = first != std::string::npos && head.compare(first, 5, "solid") == 0;
  if (!maybe_ascii) {
    if (head.size() < 84) fail(path, 0, "is neither an ASCII STL (it does not start with 'solid') nor a binary STL (it is shorter than 84 bytes)");
    refuse_binary_stl(path, head, size, "is not an ASCII STL (it does not start with 'solid')");
  }
  const std::string text = read_all(path);
  if (text.find('\0') != std::string::npos && head.size() == 84)
    refuse_binary_stl(path, head, size, "starts with 'solid' but holds binary bytes");
  check_is_text(path, text);
  AsciiStl(path, text).walk();
}

// ---------------------------------------------------------------------------------------------
// PLY: a text header, then ASCII or binary data. assimp trusts the data: a list length or an
// index read from the file goes straight into an allocation or a face, so both are checked here.

struct PlyType {
  int bytes = 0;
  bool is_float = false;
  bool is_signed = false;
};

std::optional<PlyType> ply_type(const std::string& name) {
  if (name == "char" || name == "int8") return PlyType{1, false, true};
  if (name == "uchar" || name == "uint8") return PlyType{1, false, false};
  if (name == "short" || name == "int16") return PlyType{2, false, true};
  if (name == "ushort" || name == "uint16") return PlyType{2, false, false};
  if (name == "int" || name == "int32") return PlyType{4, false, true};
  if (name == "uint" || name == "uint32") return PlyType{4, false, false};
  if (name == "float" || name == "float32") return PlyType{4, true, true};
  if (name == "double" || name == "float64") return PlyType{8, true, true};
  return std::nullopt;
}

struct PlyProperty {
  std::string name;
  PlyType type;  // of the value, or of a list's items
  std::optional<PlyType> list_count;
};

struct PlyElement {
  std::string name;
  Count count = 0;
  std::vector<PlyProperty> properties;
  Count min_bytes(bool ascii) const {  // ASCII "0 " is two bytes; a list holds at least its length
    Count bytes = 0;
    for (const PlyProperty& p : properties)
      bytes += ascii ? 2 : static_cast<Count>(p.list_count ? p.list_count->bytes : p.type.bytes);
    return bytes;
  }
};

enum class PlyFormat { ascii, little_endian, big_endian };

struct PlyHeader {
  PlyFormat format = PlyFormat::ascii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;  // the first byte after end_header's line
  int lines = 0;                // the header's line count
};

bool is_face_corners(const PlyElement& e, const PlyProperty& p) {
  return e.name == "face" && p.list_count && (p.name == "vertex_indices" || p.name == "vertex_index");
}

Count vertex_count(const PlyHeader& header) {
  for (const PlyElement& e : header.elements)
    if (e.name == "vertex") return e.count;
  return 0;
}

void read_ply_property(const std::string& path, const Line& line, PlyHeader* header) {
  const auto& w = line.words;
  if (header->elements.empty()) fail(path, line.number, "PLY property before any element");
  PlyProperty p;
  const bool list = w.size() == 5 && w[1] == "list";
  if (list) p.list_count = ply_type(w[2]);
  const std::optional<PlyType> type = ply_type(w.size() > 1 ? w[list ? 3 : 1] : "");
  if ((!list && w.size() != 3) || !type || (list && !p.list_count))
    fail(path, line.number, "unreadable PLY property line");
  p.type = *type;
  p.name = w.back();
  header->elements.back().properties.push_back(p);
}

void read_ply_header_line(const std::string& path, const Line& line, PlyHeader* header) {
  const auto& w = line.words;
  if (w[0] == "comment" || w[0] == "obj_info") return;
  if (w[0] == "format" && w.size() == 3) {
    if (w[1] == "binary_little_endian") header->format = PlyFormat::little_endian;
    else if (w[1] == "binary_big_endian") header->format = PlyFormat::big_endian;
    else if (w[1] != "ascii") fail(path, line.number, "unknown PLY format " + shown(w[1]));
  } else if (w[0] == "element" && w.size() == 3) {
    const char* digits = w[2].c_str();
    if (!std::all_of(w[2].begin(), w[2].end(), [](unsigned char c) { return std::isdigit(c); }) ||
        w[2].size() > 19)
      fail(path, line.number, "PLY element count " + shown(w[2]) + " is not a count");
    header->elements.push_back({w[1], std::strtoull(digits, nullptr, 10), {}});
  } else if (w[0] == "property") {
    read_ply_property(path, line, header);
  } else {
    fail(path, line.number, "unreadable PLY header line");
  }
}

PlyHeader read_ply_header(const std::string& path, const std::string& bytes) {
  std::size_t end = bytes.find("\nend_header");
  if (end == std::string::npos) fail(path, 0, "PLY header has no end_header line (cut short?)");
  PlyHeader header;
  const std::string text = bytes.substr(0, end + 1);
  TextLines lines(text, 0, 1, false);
  Line line;
  lines.next(&line);  // "ply"
  while (lines.next(&line)) read_ply_header_line(path, line, &header);
  header.lines = static_cast<int>(std::count(bytes.begin(), bytes.begin() + static_cast<long>(end), '\n')) + 2;
  end = bytes.find('\n', end + 1);
  header.data_offset = end == std::string::npos ? bytes.size() : end + 1;
  return header;
}

// The least bytes the declared elements take: a 100-byte file declaring a billion faces is
// refused before anything is walked.
void check_ply_sizes(const std::string& path, const PlyHeader& header, Count size) {
  const bool ascii = header.format == PlyFormat::ascii;
  const Count body = size - std::min<Count>(size, header.data_offset);
  Count needed = 0;
  for (const PlyElement& e : header.elements) {
    // Saturate: a declared count near 2^64 must not wrap around to something small.
    const Count per = std::max<Count>(1, e.min_bytes(ascii));
    if (e.count > (body - needed) / per) refuse(path, e.name + " elements", e.count, needed + e.count * per, body);
    needed += e.count * per;
  }
}

// Binary data, value by value. A list's length is checked against the bytes left before it is
// used; assimp 5.2.5 would allocate for it.
class PlyBinary {
 public:
  PlyBinary(const std::string& path, const std::string& bytes, const PlyHeader& header)
      : path_(path), bytes_(bytes), at_(header.data_offset), big_endian_(header.format == PlyFormat::big_endian) {}

  double value(const PlyType& type) {
    if (bytes_.size() - at_ < static_cast<std::size_t>(type.bytes)) fail(path_, 0, "the data ends before its declared elements do");
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + at_, static_cast<std::size_t>(type.bytes));
    if (big_endian_) std::reverse(raw, raw + type.bytes);
    at_ += static_cast<std::size_t>(type.bytes);
    return decode(raw, type);
  }

  std::size_t left() const { return bytes_.size() - at_; }

 private:
  static double decode(const unsigned char* raw, const PlyType& t) {
    if (t.is_float) return t.bytes == 4 ? double(load<float>(raw)) : load<double>(raw);
    if (t.bytes == 1) return t.is_signed ? double(load<std::int8_t>(raw)) : double(load<std::uint8_t>(raw));
    if (t.bytes == 2) return t.is_signed ? double(load<std::int16_t>(raw)) : double(load<std::uint16_t>(raw));
    return t.is_signed ? double(load<std::int32_t>(raw)) : double(load<std::uint32_t>(raw));
  }
  template <typename T>
  static T load(const unsigned char* raw) {
    T v;
    std::memcpy(&v, raw, sizeof v);
    return v;
  }

  const std::string& path_;
  const std::string& bytes_;
  std::size_t at_;
  bool big_endian_;
};

// ASCII data, word by word (a line per element is usual but not required); errors give the line.
class PlyWords {
 public:
  PlyWords(const std::string& path, const std::string& bytes, const PlyHeader& header)
      : path_(path), lines_(bytes, header.data_offset, header.lines + 1, false) {}

  double number() {
    while (word_ >= line_.words.size()) {
      if (!lines_.next(&line_)) fail(path_, 0, "the data ends before its declared elements do");
      word_ = 0;
    }
    const std::string& word = line_.words[word_++];
    const std::optional<double> value = number_of(word);
    if (!value) fail(path_, line_.number, shown(word) + " is not a number");
    return *value;
  }
  int line() const { return line_.number; }

 private:
  const std::string& path_;
  TextLines lines_;
  Line line_;
  std::size_t word_ = 0;
};

// A value as ASCII PLY writes it, exactly: 9 significant digits give a float back bit for bit,
// 17 a double; an integer type holds an integer.
void append_ascii(double v, const PlyType& type, std::string* out) {
  char text[40];
  if (!type.is_float) std::snprintf(text, sizeof text, "%lld", static_cast<long long>(v));
  else std::snprintf(text, sizeof text, type.bytes == 4 ? "%.9g" : "%.17g", v);
  if (!out->empty() && out->back() != '\n') *out += ' ';
  *out += text;
}

// The body as ASCII PLY with nothing but the vertices' x, y, z and the faces' corner lists.
struct PlyBody {
  std::string vertices, faces;  // an instance a line
  Count vertex_count = 0, face_count = 0;
  std::string text() const {
    return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertex_count) +
           "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(face_count) +
           "\nproperty list uint int vertex_indices\nend_header\n" + vertices + faces;
  }
};

bool is_coordinate(const PlyElement& e, const PlyProperty& p) {
  return e.name == "vertex" && !p.list_count && (p.name == "x" || p.name == "y" || p.name == "z");
}

// Walks every value of the data, ASCII or binary, checking list lengths, corner indices and
// vertex values. When body is not null, writes the vertices and faces to it.
template <typename Data>
void walk_ply(const std::string& path, Data* data, const PlyHeader& header, PlyBody* body) {
  const Count vertices = vertex_count(header);
  for (const PlyElement& e : header.elements)
    for (Count k = 0; k < e.count; ++k) {
      std::string xyz[3];
      for (const PlyProperty& p : e.properties) {
        const double n = p.list_count ? data->value(*p.list_count) : 1.0;
        if (p.list_count && !data->list_fits(n, p.type))
          fail(path, data->line(), e.name + " " + std::to_string(k) + " declares a list of " + number_text(n) +
                                       " values, more than the data holds (cut short?)");
        const bool corners = is_face_corners(e, p);
        if (body && corners) append_ascii(n, *p.list_count, &body->faces), ++body->face_count;
        for (long long i = 0; i < static_cast<long long>(n); ++i) {
          const double v = data->value(p.type);
          if (corners) check_corner(path, data->line(), v, vertices);
          if (e.name == "vertex" && !std::isfinite(v))
            fail(path, data->line(), "vertex " + std::to_string(k) + " has a value that is not finite");
          if (body && corners) append_ascii(v, p.type, &body->faces);
          if (body && is_coordinate(e, p)) append_ascii(v, p.type, &xyz[p.name[0] - 'x']);
        }
        if (body && corners) body->faces += '\n';
      }
      if (body && e.name == "vertex") body->vertices += xyz[0] + ' ' + xyz[1] + ' ' + xyz[2] + '\n', ++body->vertex_count;
    }
}

// The two kinds of data as walk_ply reads them.
class PlyBinaryData {
 public:
  PlyBinaryData(const std::string& path, const std::string& bytes, const PlyHeader& header)
      : data_(path, bytes, header) {}
  double value(const PlyType& type) { return data_.value(type); }
  bool list_fits(double n, const PlyType& item_type) const {
    return n >= 0 && n * item_type.bytes <= static_cast<double>(data_.left());
  }
  int line() const { return 0; }

 private:
  PlyBinary data_;
};

class PlyAsciiData {
 public:
  PlyAsciiData(const std::string& path, const std::string& bytes, const PlyHeader& header)
      : words_(path, bytes, header) {}
  double value(const PlyType&) { return words_.number(); }
  // A list is an integer count of values, each at least two bytes of text: a bound, not exact.
  bool list_fits(double n, const PlyType&) const { return n >= 0 && n == std::floor(n) && n <= 1e6; }
  int line() const { return words_.line(); }

 private:
  PlyWords words_;
};

// assimp 5.2.5 misreads two layouts that PLY allows, without a word: binary data whose first
// byte is 0x0A (it skips every line feed after end_header, so it reads one byte late: garbage,
// or an assertion that aborts the process; a first CR, space or tab is read right), and an
// element it does not know, before or between the vertices and faces (its values are read as
// vertices or as a face). So unless the file holds just vertices then faces, in binary not
// starting with 0x0A or in ASCII, its vertices and faces alone, as ASCII PLY, are returned to
// be read in the file's place.
std::optional<std::string> check_ply(const std::string& path, Count size) {
  if (read_head(path, 3) != "ply") return std::nullopt;  // not PLY at all: assimp says so
  const std::string bytes = read_all(path);
  const PlyHeader header = read_ply_header(path, bytes);
  check_ply_sizes(path, header, size);
  const bool binary = header.format != PlyFormat::ascii;
  const bool line_feed_first = binary && header.data_offset < bytes.size() && bytes[header.data_offset] == '\n';
  const bool plain = header.elements.size() == 2 && header.elements[0].name == "vertex" && header.elements[1].name == "face";
  std::string coordinates;  // which of x, y, z the vertices have
  for (const PlyElement& e : header.elements)
    for (const PlyProperty& p : e.properties)
      if (is_coordinate(e, p) && coordinates.find(p.name) == std::string::npos) coordinates += p.name;
  const bool has_xyz = coordinates.size() == 3;
  PlyBody body;
  PlyBody* mend = (line_feed_first || !plain) && has_xyz ? &body : nullptr;
  if (binary) {
    PlyBinaryData data(path, bytes, header);
    walk_ply(path, &data, header, mend);
  } else {
    PlyAsciiData data(path, bytes, header);
    walk_ply(path, &data, header, mend);
  }
  if (!mend) return std::nullopt;
  return body.text();
}

// ---------------------------------------------------------------------------------------------
// OFF: "OFF", then "vertices faces [edges]" (on the keyword's line or the next), a line per
// vertex, a line per face "n i1 ... in [colour]". assimp 5.2.5 takes out-of-range indices and
// short face records without a word, so each line is checked here.

struct OffCounts {
  Count vertices = 0, faces = 0;
};

Count off_count(const std::string& path, const Line& line, std::size_t i) {
  if (i >= line.words.size() || line.words[i].size() > 19 ||
      !std::all_of(line.words[i].begin(), line.words[i].end(), [](unsigned char c) { return std::isdigit(c); }))
    fail(path, line.number, "OFF needs the vertex and face counts here");
  return std::strtoull(line.words[i].c_str(), nullptr, 10);
}

// Reads the keyword and the counts, leaving lines at the first vertex. The counts may follow
// the keyword, even glued to it ("OFF8 6 12", trimesh's whitespace.off).
OffCounts read_off_counts(const std::string& path, TextLines* lines) {
  Line head;
  const bool any = lines->next(&head);
  const std::size_t keyword = any ? head.words[0].find("OFF") : std::string::npos;
  if (keyword == std::string::npos) fail(path, head.number, "no OFF keyword");
  const std::string glued = head.words[0].substr(keyword + 3);
  head.words.erase(head.words.begin());
  if (!glued.empty()) head.words.insert(head.words.begin(), glued);
  if (head.words.empty() && !lines->next(&head)) fail(path, head.number, "OFF needs the vertex and face counts");
  return {off_count(path, head, 0), off_count(path, head, 1)};
}

void check_off_vertex(const std::string& path, const Line& line) {
  if (line.words.size() < 3) fail(path, line.number, "a vertex needs three coordinates");
  for (std::size_t i = 0; i < 3; ++i) check_coordinate(path, line.number, line.words[i]);
}

void check_off_face(const std::string& path, const Line& line, Count vertices) {
  const std::optional<double> n = number_of(line.words[0]);
  if (!n || *n < 0 || *n != std::floor(*n)) fail(path, line.number, shown(line.words[0]) + " is not a corner count");
  if (*n > static_cast<double>(line.words.size() - 1))
    fail(path, line.number, "a face of " + line.words[0] + " corners lists " + std::to_string(line.words.size() - 1));
  for (std::size_t i = 1; i <= static_cast<std::size_t>(*n); ++i) {
    const std::optional<double> index = number_of(line.words[i]);
    if (!index) fail(path, line.number, shown(line.words[i]) + " is not a vertex index");
    check_corner(path, line.number, *index, vertices);
  }
}

// The quick bound first: a vertex line takes at least 6 bytes ("0 0 0\n"), a face line at
// least 8 ("3 0 1 2\n"), so no line is walked for a count the file cannot hold. Then the
// lines are counted, so that a file cut short says so rather than what its last line lacks.
void check_off(const std::string& path, Count size) {
  const std::string head = read_head(path, 4096);
  Line first;
  if (!TextLines(head, 0, 1, true).next(&first) || first.words[0].find("OFF") == std::string::npos)
    return;  // assimp says what the file is
  TextLines head_lines(head, 0, 1, true);
  const OffCounts declared = read_off_counts(path, &head_lines);
  if (declared.vertices > size / 6) refuse(path, "vertices", declared.vertices, declared.vertices * 6, size);
  if (declared.faces > (size - declared.vertices * 6) / 8)
    refuse(path, "faces", declared.faces, declared.vertices * 6 + declared.faces * 8, size);
  const std::string text = read_all(path);
  check_is_text(path, text);
  Line line;
  TextLines counting(text, 0, 1, true);
  read_off_counts(path, &counting);
  Count records = 0;
  while (records < declared.vertices + declared.faces && counting.next(&line)) ++records;
  if (records < declared.vertices + declared.faces)
    fail(path, 0, "declares " + std::to_string(declared.vertices) + " vertices and " + std::to_string(declared.faces) +
                      " faces, a line each, but only " + std::to_string(records) + " lines follow (cut short?)");
  TextLines lines(text, 0, 1, true);
  read_off_counts(path, &lines);
  for (Count i = 0; i < declared.vertices + declared.faces; ++i) {
    lines.next(&line);
    if (i < declared.vertices) check_off_vertex(path, line);
    else check_off_face(path, line, declared.vertices);
  }
}

// ---------------------------------------------------------------------------------------------
// OBJ: "v x y z" records and "f"/"l"/"p" records of corners "v", "v/t", "v//n" or "v/t/n",
// counted from 1, or back from the last vertex read when negative. assimp 5.2.5 reads "nan",
// "inf" and misspelt numbers ("3.1+e2" as 3.1) without a word and names no line for a bad index.

void check_obj_vertex(const std::string& path, const Line& line) {
  if (line.words.size() < 4) fail(path, line.number, "a vertex needs three coordinates");
  for (std::size_t i = 1; i < 4; ++i) check_coordinate(path, line.number, line.words[i]);
}

void check_obj_corner(const std::string& path, const Line& line, const std::string& corner, Count read,
                      Count total) {
  const std::string index = corner.substr(0, corner.find('/'));
  char* end = nullptr;
  const long long i = std::strtoll(index.c_str(), &end, 10);
  if (end == index.c_str() || *end != '\0') fail(path, line.number, shown(corner) + " is not a vertex index");
  if (i == 0) fail(path, line.number, "vertex index 0 (OBJ counts vertices from 1)");
  if (i < 0 && static_cast<Count>(-i) > read)
    fail(path, line.number, "relative vertex index " + index + " reaches before the first vertex (" +
                                std::to_string(read) + " read so far)");
  if (i > 0 && static_cast<Count>(i) > total)
    fail(path, line.number, "vertex index " + index + ", but the file has " + std::to_string(total) + " vertices");
}

bool is_obj_element(const std::string& keyword) { return keyword == "f" || keyword == "l" || keyword == "p"; }

// assimp 5.2.5 does not skip a UTF-8 byte order mark in OBJ: it takes "\xEF\xBB\xBFv" for an
// unknown keyword, loses the first vertex, and then finds an index out of range. Without the
// mark, the file reads; the mended bytes are returned.
std::optional<std::string> check_obj(const std::string& path) {
  std::string text = read_all(path);
  const bool bom = text.compare(0, kUtf8Bom.size(), kUtf8Bom) == 0;
  if (bom) text.erase(0, kUtf8Bom.size());
  check_is_text(path, text);
  Count total = 0;
  Line line;
  for (TextLines lines(text, 0, 1, true); lines.next(&line);) total += line.words[0] == "v";
  Count read = 0;
  for (TextLines lines(text, 0, 1, true); lines.next(&line);) {
    if (line.words[0] == "v") check_obj_vertex(path, line), ++read;
    if (!is_obj_element(line.words[0])) continue;
    for (std::size_t c = 1; c < line.words.size(); ++c) check_obj_corner(path, line, line.words[c], read, total);
  }
  if (bom) return text;
  return std::nullopt;
}

}  // namespace

std::optional<std::string> check_mesh_file(const std::string& path) {
  std::error_code ec;
  const Count size = std::filesystem::file_size(path, ec);
  if (ec) return std::nullopt;  // the reader reports files it cannot open
  if (size == 0) fail(path, 0, "the file is empty");
  const std::string head = read_head(path, 4096);
  if (size == head.size() && head.find_first_not_of(" \t\r\n\f\v") == std::string::npos)
    fail(path, 0, "the file is empty (nothing but white space)");
  const std::string ext = lower_extension(path);
  if (ext == ".stl" && is_binary_stl(path)) return std::nullopt;  // a binary header may start with any bytes
  check_not_utf16(path);
  if (ext == ".stl") check_stl(path, size);
  else if (ext == ".ply") return check_ply(path, size);
  else if (ext == ".off") check_off(path, size);
  else if (ext == ".obj") return check_obj(path);
  return std::nullopt;
}

}  // namespace fabform
