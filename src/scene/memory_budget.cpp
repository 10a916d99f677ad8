#include "fabform/scene/memory_budget.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "fabform/angles.hpp"
#include "fabform/error.hpp"

namespace fabform {
namespace {

// Peak resident memory per node of the dome at 101² and 401² nodes, two iterations, one thread
// (`/usr/bin/time -f %M fabform run scenes/dome.toml --max-iter 2 --set fabric.divisions=[N,N]`):
// relax 840 B, dynamic 910 B, newton 6.0 kB (its factor's fill grows with the grid). The bounds
// sit below those, so that only a run that certainly cannot fit is refused.
constexpr double kLeastBytesPerNode = 750.0;
constexpr double kLeastBytesPerNodeNewton = 5000.0;

// A "Key: value kB" line of /proc/meminfo, in bytes; infinity if absent.
double meminfo_bytes(const char* key) {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string name;
    double kb = 0.0;
    if (fields >> name >> kb && name == std::string(key) + ":") return kb * 1024.0;
  }
  return std::numeric_limits<double>::infinity();
}

// The process's own cgroup (v2) folder, from /proc/self/cgroup's "0::/PATH" line.
std::string own_cgroup() {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("0::", 0) == 0) return "/sys/fs/cgroup" + line.substr(3);
  return "/sys/fs/cgroup";
}

// A "key value" line of a cgroup's memory.stat; 0 if absent.
double memory_stat(const std::string& cgroup, const std::string& key) {
  std::ifstream in(cgroup + "/memory.stat");
  std::string name;
  double value = 0.0;
  while (in >> name >> value)
    if (name == key) return value;
  return 0.0;
}

// Bytes the process's cgroup v2 limit still allows, counting the page cache it could drop as
// free; infinity where there is no limit ("max") or no cgroup v2.
double cgroup_room_bytes() {
  const std::string cgroup = own_cgroup();
  std::ifstream max_file(cgroup + "/memory.max"), current_file(cgroup + "/memory.current");
  double max = 0.0, current = 0.0;
  if (!(max_file >> max) || !(current_file >> current)) return std::numeric_limits<double>::infinity();
  return max - std::max(0.0, current - memory_stat(cgroup, "inactive_file"));
}

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  return text;
}

}  // namespace

double expected_nodes(const FabricSpec& spec) {
  if (spec.mesh == FabricSpec::Mesh::arc && spec.shape == FabricSpec::Shape::circle)
    return static_cast<double>(spec.rings) * spec.spokes + 1.0;
  const double across = spec.divisions_warp + 1.0;
  if (spec.shape == FabricSpec::Shape::circle) return 0.25 * kPi * across * across;
  return across * (spec.divisions_weft + 1.0);
}

double least_run_bytes(double nodes, const std::string& solver) {
  return nodes * (solver == "newton" ? kLeastBytesPerNodeNewton : kLeastBytesPerNode);
}

double available_memory_bytes() {
  return std::min(meminfo_bytes("MemAvailable"), cgroup_room_bytes());
}

void check_memory_budget(const Scene& scene, double available) {
  const double nodes = expected_nodes(scene.fabric);
  const double needed = least_run_bytes(nodes, scene.solver.name);
  if (needed <= available) return;
  char text[320];
  std::snprintf(text, sizeof text,
                "a fabric of %.3g nodes needs at least %s with solver %s; this machine has %s available: "
                "use fewer divisions",
                nodes, gigabytes(needed).c_str(), scene.solver.name.c_str(), gigabytes(available).c_str());
  throw InputError(scene.fabric_where, text);
}

}  // namespace fabform
