// The command line (CLI11): every command's options on request, in three ways, exit status 0;
// an unknown option or command named on the first line of stderr, the usage after it, exit 2.
#include <gtest/gtest.h>

#include <string>

#include "support/cli.hpp"

namespace fabform::command_line_test {
namespace {

class CommandLine : public ::testing::TestWithParam<const char*> {
 protected:
  test::TempDir dir;
};

TEST_P(CommandLine, EachCommandPrintsItsOptionsThreeWays) {
  const std::string command = GetParam();
  for (const std::string& asked : {command + " --help", command + " -h", "help " + command}) {
    const test::Outcome o = test::run_fabform(dir, asked);
    EXPECT_EQ(o.status, 0) << asked << ": " << o.err;
    EXPECT_NE(o.out.find("Usage: fabform " + command), std::string::npos) << asked << ": " << o.out;
    EXPECT_EQ(o.err, "") << asked;
  }
}

TEST_P(CommandLine, AnUnknownOptionIsNamedWithTheCommandsUsage) {
  const std::string command = GetParam();
  const test::Outcome o = test::run_fabform(dir, command + " --bogus");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err.substr(0, o.err.find('\n')), "fabform: error: command line: --bogus: unknown option") << o.err;
  EXPECT_NE(o.err.find("Usage: fabform " + command), std::string::npos) << o.err;
  EXPECT_EQ(test::error_line_count(o.err), 1) << o.err;
}

INSTANTIATE_TEST_SUITE_P(Every, CommandLine, ::testing::Values("run", "study", "check", "predistort"));

TEST(CommandLineTop, HelpListsTheCommandsAndVersionSaysWhichFabform) {
  test::TempDir dir;
  const test::Outcome help = test::run_fabform(dir, "--help");
  EXPECT_EQ(help.status, 0);
  for (const char* command : {"run", "study", "check", "predistort", "solvers", "help"})
    EXPECT_NE(help.out.find(std::string("  ") + command + " "), std::string::npos) << command << "\n" << help.out;
  const test::Outcome version = test::run_fabform(dir, "--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out.rfind("fabform ", 0), 0u) << version.out;
  const test::Outcome solvers = test::run_fabform(dir, "solvers");
  EXPECT_EQ(solvers.out, "relax\ndynamic\nnewton\n");
}

TEST(CommandLineTop, AnUnknownCommandOrNoneIsAUsageError) {
  test::TempDir dir;
  const test::Outcome bogus = test::run_fabform(dir, "form scene.toml");
  EXPECT_EQ(bogus.status, 2);
  EXPECT_EQ(bogus.err.substr(0, bogus.err.find('\n')), "fabform: error: command line: form: unknown command");
  const test::Outcome topic = test::run_fabform(dir, "help form");
  EXPECT_EQ(topic.status, 2);
  const test::Outcome none = test::run_fabform(dir, "");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("Usage: fabform"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace fabform::command_line_test
