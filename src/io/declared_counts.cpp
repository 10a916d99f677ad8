#include "io/declared_counts.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "fabform/error.hpp"

namespace fabform {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::string read_head(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(bytes));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

[[noreturn]] void refuse(const std::string& path, const std::string& what, unsigned long long count,
                         unsigned long long needed, unsigned long long available) {
  throw InputError({path, 0, ""}, "declares " + std::to_string(count) + " " + what + ", which need at least " +
                                      std::to_string(needed) + " bytes, but the file holds " +
                                      std::to_string(available));
}

// Binary STL: 80-byte header, a 32-bit triangle count, 50 bytes per triangle. A file starting
// with "solid" may be ASCII; it is binary if its size matches its count exactly.
void check_stl(const std::string& path, unsigned long long size) {
  const std::string head = read_head(path, 84);
  if (head.size() < 84) return;  // too short to be binary; the reader says what is wrong
  std::uint32_t count = 0;
  std::memcpy(&count, head.data() + 80, sizeof count);
  const unsigned long long needed = 84ULL + 50ULL * count;
  const bool maybe_ascii = head.compare(0, 5, "solid") == 0;
  if (needed == size || maybe_ascii) return;
  if (needed > size) refuse(path, "triangles", count, needed, size);
}

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  unsigned long long min_bytes = 0;  // per element
};

unsigned long long scalar_size(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "double" || type == "float64") return 8;
  return 4;  // int, uint, float and their sized names
}

// The least a property can take: ASCII "0 " is two bytes; a binary list holds its count and,
// for faces, at least three indices.
unsigned long long property_min_bytes(std::istringstream& words, bool ascii) {
  std::string type;
  words >> type;
  if (type != "list") return ascii ? 2 : scalar_size(type);
  std::string count_type, item_type;
  words >> count_type >> item_type;
  return ascii ? 2 : scalar_size(count_type) + 3 * scalar_size(item_type);
}

void check_ply(const std::string& path, unsigned long long size) {
  const std::string head = read_head(path, 65536);
  const std::size_t end = head.find("end_header");
  if (head.compare(0, 3, "ply") != 0 || end == std::string::npos) return;  // the reader reports it
  std::istringstream lines(head.substr(0, end));
  std::vector<PlyElement> elements;
  bool ascii = false;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format") {
      std::string format;
      words >> format;
      ascii = format == "ascii";
    } else if (keyword == "element") {
      PlyElement e;
      words >> e.name >> e.count;
      elements.push_back(e);
    } else if (keyword == "property" && !elements.empty()) {
      elements.back().min_bytes += property_min_bytes(words, ascii);
    }
  }
  const unsigned long long body = size - std::min<unsigned long long>(size, end);
  unsigned long long needed = 0;
  for (const PlyElement& e : elements) {
    // Saturate: a declared count near 2^64 must not wrap around to something small.
    const unsigned long long limit = ~0ULL / std::max(1ULL, e.min_bytes);
    if (e.count > limit || needed + e.count * e.min_bytes > body)
      refuse(path, e.name + " elements", e.count, e.count > limit ? ~0ULL : needed + e.count * e.min_bytes, body);
    needed += e.count * e.min_bytes;
  }
}

// OFF: "OFF", then "vertices faces edges"; a vertex line takes at least 6 bytes ("0 0 0\n"),
// a face line at least 8 ("3 0 1 2\n").
void check_off(const std::string& path, unsigned long long size) {
  std::istringstream words(read_head(path, 4096));
  std::string magic;
  unsigned long long vertices = 0, faces = 0;
  words >> magic;
  if (magic != "OFF" || !(words >> vertices >> faces)) return;
  if (vertices > size / 6) refuse(path, "vertices", vertices, vertices * 6, size);
  if (faces > (size - vertices * 6) / 8) refuse(path, "faces", faces, vertices * 6 + faces * 8, size);
}

}  // namespace

void check_declared_counts(const std::string& path) {
  std::error_code ec;
  const unsigned long long size = std::filesystem::file_size(path, ec);
  if (ec) return;  // the reader reports files it cannot open
  const std::string ext = lower_extension(path);
  if (ext == ".stl") check_stl(path, size);
  else if (ext == ".ply") check_ply(path, size);
  else if (ext == ".off") check_off(path, size);
}

}  // namespace fabform
