#include "fabform/output/checkpoint.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <type_traits>

#include "fabform/error.hpp"

namespace fabform {
namespace {

constexpr char kFamily[] = "fabform checkpoint ";
// 2: each node's friction anchor; 3: each record's load step.
constexpr char kMagic[] = "fabform checkpoint 4\n";
constexpr std::uint32_t kByteOrder = 0x01020304;

// FNV-1a: enough to tell a damaged or truncated file from a whole one.
std::uint64_t checksum(const char* data, std::size_t size) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ static_cast<unsigned char>(data[i])) * 0x100000001b3ULL;
  return hash;
}

class Writer {
 public:
  template <typename T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
  }
  void put_vector3(const Eigen::Vector3d& v) { put(v.x()), put(v.y()), put(v.z()); }
  void put_text(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    bytes_ += text;
  }
  std::string finish() {
    put(checksum(bytes_.data(), bytes_.size()));
    return std::move(bytes_);
  }

 private:
  std::string bytes_ = kMagic;
};

class Reader {
 public:
  Reader(std::string bytes, std::string path) : bytes_(std::move(bytes)), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& why) const { throw InputError({path_, 0, ""}, why); }

  void expect_magic() {
    if (bytes_.compare(0, sizeof kMagic - 1, kMagic) == 0) {
      at_ = sizeof kMagic - 1;
      return;
    }
    if (bytes_.compare(0, sizeof kFamily - 1, kFamily) != 0) fail("not a fabform checkpoint");
    fail("written in another checkpoint format (" + bytes_.substr(0, bytes_.find('\n')) + "; this fabform reads " +
         std::string(kMagic, sizeof kMagic - 2) + "): rerun from the scene");
  }

  void expect_checksum() {
    constexpr std::size_t kSize = sizeof(std::uint64_t);
    if (bytes_.size() < at_ + kSize) fail("truncated");
    std::uint64_t stored = 0;
    std::memcpy(&stored, bytes_.data() + bytes_.size() - kSize, kSize);
    if (stored != checksum(bytes_.data(), bytes_.size() - kSize)) fail("damaged (checksum differs)");
    end_ = bytes_.size() - kSize;
  }

  template <typename T>
  T get() {
    if (end_ - at_ < sizeof(T)) fail("truncated");
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  Eigen::Vector3d get_vector3() {
    const double x = get<double>(), y = get<double>(), z = get<double>();
    return {x, y, z};
  }
  /// A count of items of `item_size` bytes, checked against what is left before anyone allocates.
  std::size_t get_count(std::size_t item_size) {
    const auto count = get<std::uint64_t>();
    if (count > (end_ - at_) / item_size) fail("declares more data than it holds");
    return static_cast<std::size_t>(count);
  }
  std::string get_text() {
    const std::size_t size = get_count(1);
    std::string text = bytes_.substr(at_, size);
    at_ += size;
    return text;
  }
  void expect_end() const {
    if (at_ != end_) fail("holds data after its end");
  }

 private:
  std::string bytes_;
  std::string path_;
  std::size_t at_ = 0;
  std::size_t end_ = 0;
};

constexpr std::size_t kNodeBytes = 12 * sizeof(double) + sizeof(std::int32_t);
constexpr std::size_t kVelocityBytes = 3 * sizeof(double);
constexpr std::size_t kRecordBytes = 3 * sizeof(std::int64_t) + 2 * sizeof(double);

void put_state(Writer& out, const SolverState& s) {
  out.put(static_cast<std::uint64_t>(s.x.size()));
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    out.put_vector3(s.x[i]);
    out.put(static_cast<std::int32_t>(s.contact[i].body));
    out.put_vector3(s.contact[i].normal);
    out.put_vector3(s.contact[i].anchor);
    out.put_vector3(s.contact[i].crease);
  }
  out.put(static_cast<std::uint64_t>(s.velocity.size()));
  for (const Eigen::Vector3d& v : s.velocity) out.put_vector3(v);
  out.put(s.regularization);
}

void put_summary(Writer& out, const Summary& s) {
  out.put_text(s.solver);
  out.put(static_cast<std::int32_t>(s.termination));
  out.put_text(s.message);
  out.put(static_cast<std::int64_t>(s.iterations));
  out.put(s.residual_N);
  out.put(s.tolerance_N);
  out.put(s.seconds);
  out.put(static_cast<std::int64_t>(s.worst_node));
  out.put(static_cast<std::uint64_t>(s.history.size()));
  for (const IterationRecord& r : s.history) {
    out.put(static_cast<std::int64_t>(r.step));
    out.put(static_cast<std::int64_t>(r.iteration));
    out.put(r.residual_N);
    out.put(r.seconds);
    out.put(static_cast<std::int64_t>(r.contact_nodes));
  }
}

SolverState get_state(Reader& in, int node_count, int body_count) {
  const std::size_t nodes = in.get_count(kNodeBytes);
  if (nodes != static_cast<std::size_t>(node_count))
    in.fail("made for " + std::to_string(nodes) + " nodes; the scene has " + std::to_string(node_count));
  SolverState s;
  s.x.resize(nodes);
  s.contact.resize(nodes);
  for (std::size_t i = 0; i < nodes; ++i) {
    s.x[i] = in.get_vector3();
    s.contact[i].body = in.get<std::int32_t>();
    s.contact[i].normal = in.get_vector3();
    s.contact[i].anchor = in.get_vector3();
    s.contact[i].crease = in.get_vector3();
    if (s.contact[i].body < -1 || s.contact[i].body >= body_count)
      in.fail("node " + std::to_string(i) + " rests on body " + std::to_string(s.contact[i].body) +
              "; the scene has " + std::to_string(body_count));
  }
  s.velocity.resize(in.get_count(kVelocityBytes));
  if (!s.velocity.empty() && s.velocity.size() != nodes) in.fail("holds velocities for another node count");
  for (Eigen::Vector3d& v : s.velocity) v = in.get_vector3();
  s.regularization = in.get<double>();
  return s;
}

Summary get_summary(Reader& in) {
  Summary s;
  s.solver = in.get_text();
  const auto termination = in.get<std::int32_t>();
  if (termination < 0 || termination > static_cast<std::int32_t>(Termination::running))
    in.fail("holds an unknown termination");
  s.termination = static_cast<Termination>(termination);
  s.message = in.get_text();
  s.iterations = static_cast<int>(in.get<std::int64_t>());
  s.residual_N = in.get<double>();
  s.tolerance_N = in.get<double>();
  s.seconds = in.get<double>();
  s.worst_node = static_cast<int>(in.get<std::int64_t>());
  s.history.resize(in.get_count(kRecordBytes));
  for (IterationRecord& r : s.history) {
    r.step = static_cast<int>(in.get<std::int64_t>());
    r.iteration = static_cast<int>(in.get<std::int64_t>());
    r.residual_N = in.get<double>();
    r.seconds = in.get<double>();
    r.contact_nodes = static_cast<int>(in.get<std::int64_t>());
  }
  return s;
}

}  // namespace

std::string checkpoint_bytes(const SolverState& state, const Summary& summary) {
  Writer out;
  out.put(kByteOrder);
  put_state(out, state);
  put_summary(out, summary);
  return out.finish();
}

Checkpoint read_checkpoint(const std::string& path, int node_count, int body_count) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError({path, 0, ""}, "cannot be read (no checkpoint to resume from)");
  std::ostringstream bytes;
  bytes << file.rdbuf();
  Reader in(bytes.str(), path);
  in.expect_magic();
  in.expect_checksum();
  if (in.get<std::uint32_t>() != kByteOrder) in.fail("written on a machine of another byte order");
  Checkpoint c{get_state(in, node_count, body_count), get_summary(in)};
  in.expect_end();
  return c;
}

}  // namespace fabform
