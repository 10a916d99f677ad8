// A set of solver needs (solver_needs.hpp): a need is a set of one, sets join and take away, and
// a set says its needs in one phrase, in the order the needs are declared.
#include "fabform/model/solver_needs.hpp"

#include <gtest/gtest.h>

namespace fabform::solver_needs_test {
namespace {

TEST(SolverNeeds, JoinTakeAwayAndContain) {
  const SolverNeeds both = SolverNeed::stick | SolverNeed::velocity;
  EXPECT_TRUE(both.contains(SolverNeed::stick));
  EXPECT_TRUE(both.contains(SolverNeed::velocity));
  EXPECT_FALSE(both.contains(SolverNeed::stiff_penalty));
  EXPECT_TRUE(both.contains(SolverNeeds()));
  EXPECT_EQ(both - SolverNeed::stick, SolverNeeds(SolverNeed::velocity));
  EXPECT_TRUE((both - both).empty());
  EXPECT_TRUE(SolverNeeds().empty());
}

TEST(SolverNeeds, SayTheirNeedsInDeclaredOrder) {
  EXPECT_EQ(SolverNeeds().said(), "");
  EXPECT_EQ(SolverNeeds(SolverNeed::stick).said(), to_string(SolverNeed::stick));
  EXPECT_EQ((SolverNeed::loading_branch | SolverNeed::velocity).said(),
            to_string(SolverNeed::velocity) + " and " + to_string(SolverNeed::loading_branch));
  for (const SolverNeed need : kEveryNeed) EXPECT_FALSE(to_string(need).empty());
}

}  // namespace
}  // namespace fabform::solver_needs_test
