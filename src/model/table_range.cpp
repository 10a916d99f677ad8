#include "fabform/model/table_range.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "fabform/model/spring_path.hpp"

namespace fabform {
namespace {

struct RangeCount {
  int beyond = 0;
  double extreme = 0.0;
  int collapsed = 0;  // compressed below kCollapsedStrain with nothing to resist it
  double most_compressed = 0.0;
};

// Half its length gone: a tension-only spring there has folded flat, not merely gone slack.
constexpr double kCollapsedStrain = -0.5;

std::string describe(const TensionTable& table, const char* direction, const RangeCount& c,
                     int total) {
  char text[512];
  std::snprintf(text, sizeof text,
                "%d of %d %s springs end outside the measured range of %s (strain %.4g to %.4g; "
                "reached %.4g): the table's end segment was extended",
                c.beyond, total, direction, table.name().c_str(), table.min_strain(),
                table.max_strain(), c.extreme);
  return text;
}

std::string describe_collapse(const char* direction, const RangeCount& c, int total, bool bending) {
  char text[512];
  std::snprintf(text, sizeof text,
                "%d of %d %s springs are compressed below %.0f %% (down to %.3g %%): their table "
                "resists no compression%s, so nothing keeps the fabric from folding flat there; "
                "this rest is degenerate",
                c.collapsed, total, direction, 100 * kCollapsedStrain, 100 * c.most_compressed,
                bending ? " and the bending did not stop it" : " and no bending is modelled");
  return text;
}

}  // namespace

std::vector<std::string> table_range_warnings(const Model& model,
                                              const std::vector<Eigen::Vector3d>& x) {
  constexpr std::size_t kKinds = 4;  // SpringKind's values
  std::array<RangeCount, kKinds> count{};
  std::array<int, kKinds> total{};
  for (const Spring& spring : model.fabric.springs()) {
    const auto kind = static_cast<std::size_t>(spring.kind);
    const TensionTable& table = model.table(spring.kind);
    const double strain = spring_path_strain(model, spring, x[static_cast<std::size_t>(spring.a)],
                                             x[static_cast<std::size_t>(spring.b)]);
    ++total[kind];
    RangeCount& c = count[kind];
    if (strain < kCollapsedStrain && table.min_strain() >= 0.0) {
      ++c.collapsed;
      c.most_compressed = std::min(c.most_compressed, strain);
    }
    if (!table.beyond_range(strain)) continue;
    ++c.beyond;
    if (std::abs(strain) > std::abs(c.extreme)) c.extreme = strain;
  }
  std::vector<std::string> warnings;
  for (std::size_t k = 0; k < kKinds; ++k)
    if (count[k].beyond > 0)
      warnings.push_back(describe(model.table(SpringKind(k)), to_string(SpringKind(k)), count[k], total[k]));
  for (std::size_t k = 0; k < kKinds; ++k)
    if (count[k].collapsed > 0)
      warnings.push_back(describe_collapse(to_string(SpringKind(k)), count[k], total[k],
                                                   model.resists_bending()));
  return warnings;
}

}  // namespace fabform
