#include "io/binary_stl.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "fabform/error.hpp"

namespace fabform {
namespace {

constexpr std::size_t kHeaderBytes = 84;  // 80-byte header, then a uint32 triangle count
constexpr std::size_t kFacetBytes = 50;   // normal, three corners (float32 each), attribute
using Corner = std::array<float, 3>;

std::uint32_t declared_count(const char* header) {
  std::uint32_t count = 0;
  std::memcpy(&count, header + 80, sizeof count);
  return count;
}

std::vector<char> read_all(const std::string& path, std::size_t size) {
  std::vector<char> bytes(size);
  std::ifstream in(path, std::ios::binary);
  if (!in.read(bytes.data(), static_cast<std::streamsize>(size)))
    throw InputError({path, 0, ""}, "cannot read the file");
  return bytes;
}

// Merges corners at bit-identical positions: open addressing with linear probing over a
// power-of-two table kept at most half full, so a million triangles take one pass and no
// per-entry allocation. The table starts at a sixth of the corners (a closed mesh has about
// that many vertices) and doubles as needed: small enough to stay in cache. -0 and +0 count as
// one position.
class CornerMerger {
 public:
  explicit CornerMerger(std::size_t corners) {
    std::size_t capacity = 16;
    while (capacity < corners / 3) capacity *= 2;
    slots_.assign(capacity, -1);
    positions_.reserve(corners / 6);
  }

  int index_of(Corner p) {
    for (float& x : p) x += 0.0f;
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t slot = hash(p) & mask;; slot = (slot + 1) & mask) {
      if (slots_[slot] < 0) {
        const int index = slots_[slot] = static_cast<int>(positions_.size());
        positions_.push_back(p);
        if (2 * positions_.size() > slots_.size()) grow();
        return index;
      }
      if (positions_[static_cast<std::size_t>(slots_[slot])] == p) return slots_[slot];
    }
  }

  std::vector<Eigen::Vector3d> vertices() const {
    std::vector<Eigen::Vector3d> out;
    out.reserve(positions_.size());
    for (const Corner& p : positions_) out.emplace_back(p[0], p[1], p[2]);
    return out;
  }

 private:
  void grow() {
    slots_.assign(2 * slots_.size(), -1);
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = 0; i < positions_.size(); ++i) {
      std::size_t slot = hash(positions_[i]) & mask;
      while (slots_[slot] >= 0) slot = (slot + 1) & mask;
      slots_[slot] = static_cast<int>(i);
    }
  }

  static std::size_t hash(const Corner& p) {
    std::uint32_t bits[3];
    std::memcpy(bits, p.data(), sizeof bits);
    std::uint64_t h = 0x9E3779B97F4A7C15ULL;
    for (const std::uint32_t b : bits) h = (h ^ b) * 0xFF51AFD7ED558CCDULL;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }

  std::vector<int> slots_;
  std::vector<Corner> positions_;
};

// An ASCII STL starts with "solid" (after white space) and is text: no NUL byte. A binary
// header may start with "solid" too (SolidWorks writes it), but its count and floats hold NULs.
bool looks_like_ascii(const std::string& head) {
  const std::size_t first = head.find_first_not_of(" \t\r\n\f\v");
  return first != std::string::npos && head.compare(first, 5, "solid") == 0 && head.find('\0') == std::string::npos;
}

Corner corner_at(const char* record, int corner) {
  Corner p{};
  std::memcpy(p.data(), record + 12 * (corner + 1), sizeof p);
  return p;
}

}  // namespace

std::optional<std::uintmax_t> binary_stl_trailing_bytes(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size < kHeaderBytes) return std::nullopt;
  std::string head(kHeaderBytes + kFacetBytes, '\0');
  std::ifstream in(path, std::ios::binary);
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const std::uintmax_t declared = kHeaderBytes + kFacetBytes * static_cast<std::uintmax_t>(declared_count(head.data()));
  if (size < declared) return std::nullopt;
  if (size > declared && looks_like_ascii(head)) return std::nullopt;
  return size - declared;
}

bool is_binary_stl(const std::string& path) { return binary_stl_trailing_bytes(path).has_value(); }

TriangleMesh read_binary_stl(const std::string& path) {
  const std::vector<char> bytes = read_all(path, std::filesystem::file_size(path));
  const std::size_t count = declared_count(bytes.data());
  if (count > static_cast<std::size_t>(std::numeric_limits<int>::max() / 3))
    throw InputError({path, 0, ""}, "declares " + std::to_string(count) + " triangles, more than fabform indexes");
  CornerMerger merger(3 * count);
  TriangleMesh mesh;
  mesh.triangles.resize(count);
  for (std::size_t t = 0; t < count; ++t) {
    const char* record = bytes.data() + kHeaderBytes + kFacetBytes * t;
    for (int c = 0; c < 3; ++c) {
      const Corner p = corner_at(record, c);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        throw InputError({path, 0, ""}, "triangle " + std::to_string(t) + " has a coordinate that is not finite");
      mesh.triangles[t][static_cast<std::size_t>(c)] = merger.index_of(p);
    }
  }
  mesh.vertices = merger.vertices();
  return mesh;
}

}  // namespace fabform
