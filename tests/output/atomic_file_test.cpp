// Files change all at once, and a write the system refuses says the system's reason.
#include "fabform/output/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <string>

#include "fabform/error.hpp"
#include "support/cli.hpp"
#include "support/temp_dir.hpp"

namespace fabform::atomic_file_test {
namespace {

std::string refusal(void (*write)(const std::string&, const std::string&), const std::string& path) {
  try {
    write(path, std::string(100000, 'x'));
  } catch (const SystemError& error) {
    return error.what();
  }
  return "written";
}

TEST(AtomicFile, WritesAndReplacesWhole) {
  test::TempDir dir;
  write_file_atomically(dir.path("a.txt"), "first, longer text");
  write_file_atomically(dir.path("a.txt"), "second");
  EXPECT_EQ(test::slurp(dir.path("a.txt")), "second");
  EXPECT_FALSE(std::filesystem::exists(dir.path("a.txt.tmp")));
}

// A file-size limit (RLIMIT_FSIZE) refuses the write as a full disk would, with the system's
// reason; the partial file goes.
TEST(AtomicFile, AWriteTheSystemRefusesSaysWhyAndLeavesNothing) {
  test::TempDir dir;
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // else the process is killed
  rlimit small = saved;
  small.rlim_cur = 1000;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
  const std::string said = refusal(write_file, dir.path("big.vtk"));
  setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(said, dir.path("big.vtk") + ": cannot write (File too large)");
  EXPECT_FALSE(std::filesystem::exists(dir.path("big.vtk")));
}

TEST(AtomicFile, AMissingFolderIsNamedAndNothingIsLeft) {
  test::TempDir dir;
  const std::string path = dir.path("no/such/folder/a.txt");
  EXPECT_EQ(refusal(write_file_atomically, path), path + ".tmp: cannot write (No such file or directory)");
}

// The rename fails (a folder is in the way): the temporary file goes, the folder stays.
TEST(AtomicFile, AFailedRenameLeavesWhatWasThere) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path("taken/inside"));
  EXPECT_NE(refusal(write_file_atomically, dir.path("taken")).find("taken: cannot write ("), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_directory(dir.path("taken/inside")));
  EXPECT_FALSE(std::filesystem::exists(dir.path("taken.tmp")));
}

}  // namespace
}  // namespace fabform::atomic_file_test
