// A results folder holds one run's complete files at every moment, and a folder that is not
// fabform's is never replaced.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "fabform/error.hpp"
#include "fabform/output/results_folder.hpp"
#include "fabform/thread_count.hpp"
#include "support/cli.hpp"
#include "support/temp_dir.hpp"
#include "support/threads_restored.hpp"

namespace fabform::results_folder_test {
namespace {

namespace fs = std::filesystem;

std::set<std::string> names_in(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

TEST(ResultsFolder, PublishCreatesTheFolderWithExactlyTheFiles) {
  test::TempDir dir;
  const std::string out = dir.path("runs/mold");
  check_results_folder(out);
  publish_results(out, {{"result.json", "{}\n"}, {"fabric.obj", "v 0 0 0\n"}});
  EXPECT_EQ(names_in(out), (std::set<std::string>{"result.json", "fabric.obj"}));
  EXPECT_EQ(test::slurp(out + "/fabric.obj"), "v 0 0 0\n");
  EXPECT_EQ(names_in(dir.path("runs")), std::set<std::string>{"mold"}) << "staging left behind";
}

// The previous run's files all go, including those the new run does not write (a stale
// checkpoint must not sit beside a converged result).
TEST(ResultsFolder, PublishReplacesThePreviousRunWhole) {
  test::TempDir dir;
  const std::string out = dir.path("out/");
  publish_results(out, {{"result.json", "old"}, {"checkpoint.bin", "old state"}});
  publish_results(out, {{"result.json", "new"}});
  EXPECT_EQ(names_in(dir.path("out")), std::set<std::string>{"result.json"});
  EXPECT_EQ(test::slurp(dir.path("out/result.json")), "new");
}

TEST(ResultsFolder, LeftoverStagingOfAKilledRunIsCleared) {
  test::TempDir dir;
  dir.write(".out.fabform-staging", "");  // even a file in its place
  publish_results(dir.path("out"), {{"result.json", "new"}});
  EXPECT_EQ(names_in(dir.root().string()), std::set<std::string>{"out"});
}

TEST(ResultsFolder, AFailedPublishLeavesThePreviousResults) {
  test::TempDir dir;
  publish_results(dir.path("out"), {{"result.json", "old"}});
  EXPECT_THROW(publish_results(dir.path("out"), {{"result.json", "new"}, {"no/such/sub/file", "x"}}),
               std::runtime_error);
  EXPECT_EQ(names_in(dir.path("out")), std::set<std::string>{"result.json"});
  EXPECT_EQ(test::slurp(dir.path("out/result.json")), "old");
  EXPECT_EQ(names_in(dir.root().string()), std::set<std::string>{"out"});
}

// From 16 MB in all the files are written on every thread: each whole, and a file that cannot be
// written still leaves the previous results and no staging folder.
TEST(ResultsFolder, LargeFilesWrittenOnEveryThread) {
  test::TempDir dir;
  const test::ThreadsRestored restored;
  use_threads(2);
  const std::string big(9u << 20, 'a'), other(9u << 20, 'b');
  publish_results(dir.path("out"), {{"fabric.vtk", big}, {"fabric.obj", other}, {"result.json", "{}\n"}});
  EXPECT_TRUE(test::slurp(dir.path("out/fabric.vtk")) == big);
  EXPECT_TRUE(test::slurp(dir.path("out/fabric.obj")) == other);
  EXPECT_THROW(publish_results(dir.path("out"), {{"fabric.vtk", other}, {"no/such/sub/file", big}, {"result.json", "new"}}),
               std::runtime_error);
  EXPECT_EQ(names_in(dir.path("out")), (std::set<std::string>{"fabric.vtk", "fabric.obj", "result.json"}));
  EXPECT_EQ(test::slurp(dir.path("out/result.json")), "{}\n");
  EXPECT_EQ(names_in(dir.root().string()), std::set<std::string>{"out"});
}

TEST(ResultsFolder, NewEmptyOrEarlierResultsAreAccepted) {
  test::TempDir dir;
  EXPECT_NO_THROW(check_results_folder(dir.path("new/deep/folder")));
  fs::create_directories(dir.path("empty"));
  EXPECT_NO_THROW(check_results_folder(dir.path("empty")));
  publish_results(dir.path("earlier"), {{"result.json", "{}"}});
  EXPECT_NO_THROW(check_results_folder(dir.path("earlier")));
}

// The probe never moves an existing folder and leaves nothing beside it.
TEST(ResultsFolder, TheProbeLeavesEarlierResultsAndNoTrace) {
  test::TempDir dir;
  publish_results(dir.path("earlier"), {{"result.json", "{\"converged\": true}"}, {"checkpoint.bin", "state"}});
  check_results_folder(dir.path("earlier"));
  check_results_folder(dir.path("fresh"));
  EXPECT_EQ(names_in(dir.path("earlier")), (std::set<std::string>{"result.json", "checkpoint.bin"}));
  EXPECT_EQ(test::slurp(dir.path("earlier/checkpoint.bin")), "state");
  EXPECT_EQ(names_in(dir.root().string()), std::set<std::string>{"earlier"}) << "a probe or the new folder was left";
}

std::string refusal(const std::string& folder) {
  try {
    check_results_folder(folder);
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find(folder), std::string::npos) << error.what();
    return error.what();
  }
  return "accepted";
}

TEST(ResultsFolder, FoldersThatAreNotFabformsAreRefused) {
  test::TempDir dir;
  dir.write("thesis.tex", "precious");
  EXPECT_NE(refusal(dir.root().string()).find("not fabform results"), std::string::npos);
  EXPECT_EQ(test::slurp(dir.path("thesis.tex")), "precious");
  EXPECT_NE(refusal(dir.path("thesis.tex")).find("is a file"), std::string::npos);
}

// /proc takes no new folders, whoever asks (CI runs as root, who ignores permission bits).
TEST(ResultsFolder, UnwritablePlaceIsRefusedBeforeTheRun) {
  EXPECT_NE(refusal("/proc/fabform-results").find("cannot take results"), std::string::npos);
}

TEST(ResultsFolder, PlaceUnderAFileIsRefusedBeforeTheRun) {
  test::TempDir dir;
  dir.write("plain", "a file");
  EXPECT_NE(refusal(dir.path("plain/out")).find("cannot take results"), std::string::npos);
}

}  // namespace
}  // namespace fabform::results_folder_test
