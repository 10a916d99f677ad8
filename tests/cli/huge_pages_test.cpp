// A large fabric's run starts again with malloc asking for transparent huge pages, where the
// kernel gives them on request; it keeps a choice the user made, leaves small fabrics alone, and
// comes to the same answer, bit for bit.
#include "cli/huge_pages.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace fabform::cli::huge_pages_test {
namespace {

TEST(HugePages, TunablesAddTheRequestOrKeepTheUsersChoice) {
  EXPECT_EQ(tunables_with_huge_pages(nullptr), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_pages(""), "glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.arena_max=2"), "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.hugetlb=0"), std::nullopt);
  EXPECT_EQ(tunables_with_huge_pages("glibc.malloc.arena_max=2:glibc.malloc.hugetlb=2"), std::nullopt);
}

TEST(HugePages, PolicyIsTheBracketedWord) {
  EXPECT_EQ(huge_page_policy("always [madvise] never\n"), "madvise");
  EXPECT_EQ(huge_page_policy("[always] madvise never\n"), "always");
  EXPECT_EQ(huge_page_policy("always madvise [never]"), "never");
  EXPECT_EQ(huge_page_policy(""), "");
  EXPECT_EQ(huge_page_policy("always madvise never"), "");
}

// The kernel's policy on this machine, read as the kernel states it.
std::string machine_policy() {
  return huge_page_policy(test::slurp("/sys/kernel/mm/transparent_hugepage/enabled"));
}

struct Ran {
  int status;
  nlohmann::json result;
  std::string fabric;
};

// The dome at `divisions` a side, one Newton iteration, with GLIBC_TUNABLES as given (null: unset).
Ran dome(const test::TempDir& dir, int divisions, const char* tunables) {
  const char* before = std::getenv("GLIBC_TUNABLES");
  const std::optional<std::string> kept = before ? std::optional<std::string>(before) : std::nullopt;
  if (tunables) setenv("GLIBC_TUNABLES", tunables, 1);
  else unsetenv("GLIBC_TUNABLES");
  const std::string side = std::to_string(divisions);
  const test::Outcome outcome = test::run_fabform(
      dir, "run '" + test::source_path("scenes/dome.toml") + "' --out out --quiet --max-iter 1 --set 'fabric.divisions=[" +
               side + "," + side + "]' --set solver.continuation_levels=0");
  if (kept) setenv("GLIBC_TUNABLES", kept->c_str(), 1);
  else unsetenv("GLIBC_TUNABLES");
  return {outcome.status, nlohmann::json::parse(test::slurp(dir.path("out/result.json"))),
          test::slurp(dir.path("out/fabric.obj"))};
}

TEST(HugePages, ALargeFabricRunsWithThemWhereTheKernelGivesThemOnRequest) {
  const std::string policy = machine_policy();
  test::TempDir asked, declined, small;
  // 201 × 201 nodes: from kHugePagesMinNodes.
  const Ran large = dome(asked, 200, nullptr);
  const Ran without = dome(declined, 200, "glibc.malloc.hugetlb=0");
  const Ran few = dome(small, 40, nullptr);
  for (const Ran* r : {&large, &without, &few}) ASSERT_NE(r->status, -1);
  EXPECT_EQ(large.result.at("huge_pages"), policy == "madvise" || policy == "always") << policy;
  EXPECT_EQ(without.result.at("huge_pages"), policy == "always") << policy;
  EXPECT_EQ(few.result.at("huge_pages"), policy == "always") << policy;
  EXPECT_EQ(large.status, without.status);
  EXPECT_TRUE(large.fabric == without.fabric) << "the restarted run came to another answer";
}

}  // namespace
}  // namespace fabform::cli::huge_pages_test
