#include "fabform/output/results_folder.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fcntl.h>

#include "fabform/error.hpp"

namespace fabform {
namespace {

namespace fs = std::filesystem;

fs::path normalised(const std::string& dir) {
  fs::path path = fs::path(dir).lexically_normal();
  if (path.filename().empty()) path = path.parent_path();  // "out/" names "out"
  return path;
}

// Beside the folder, so that renaming between them never crosses a file system.
fs::path sibling(const fs::path& dir, const char* role) {
  return dir.parent_path() / ("." + dir.filename().string() + ".fabform-" + role);
}

bool is_results_folder(const fs::path& dir) {
  std::error_code ec;
  return fs::is_empty(dir, ec) || fs::is_regular_file(dir / "result.json", ec);
}

void write_file(const fs::path& path, const std::string& content) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << content;
  out.flush();
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

std::string errno_text() { return std::strerror(errno); }

// Puts `staged` where `dir` is and the old folder where `staged` was.
void swap_in(const fs::path& staged, const fs::path& dir) {
  if (::renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) == 0) return;
  // File systems without the exchange: two renames, with the old folder kept until both are done.
  const fs::path old = sibling(dir, "old");
  std::error_code ec;
  fs::remove_all(old, ec);
  fs::rename(dir, old, ec);
  if (ec) throw std::runtime_error(dir.string() + ": cannot replace the results (" + ec.message() + ")");
  fs::rename(staged, dir, ec);
  if (ec) {
    fs::rename(old, dir);
    throw std::runtime_error(dir.string() + ": cannot replace the results (" + ec.message() + ")");
  }
  fs::rename(old, staged, ec);  // removed by the caller with the staging folder
}

}  // namespace

void check_results_folder(const std::string& dir_text) {
  const fs::path dir = normalised(dir_text);
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError({dir_text, 0, ""}, "is a file, not a folder for results");
  if (fs::is_directory(dir, ec) && !is_results_folder(dir))
    throw InputError({dir_text, 0, ""}, "holds files that are not fabform results (no result.json); "
                                        "choose another output folder");
  if (!dir.parent_path().empty()) fs::create_directories(dir.parent_path(), ec);
  const fs::path probe = sibling(dir, "probe");
  fs::remove_all(probe, ec);
  if (!fs::create_directory(probe, ec))
    throw InputError({dir_text, 0, ""}, "the output folder cannot be written (" +
                                            (ec ? ec.message() : std::string("exists")) + ")");
  fs::remove_all(probe, ec);
}

void publish_results(const std::string& dir_text, const std::vector<ResultFile>& files) {
  const fs::path dir = normalised(dir_text);
  const fs::path staged = sibling(dir, "staging");
  std::error_code ec;
  fs::remove_all(staged, ec);  // left by a run that was killed while writing
  if (!fs::create_directories(staged, ec))
    throw std::runtime_error(staged.string() + ": cannot create (" + ec.message() + ")");
  try {
    for (const auto& [name, content] : files) write_file(staged / name, content);
    if (fs::exists(dir)) swap_in(staged, dir);
    else if (std::rename(staged.c_str(), dir.c_str()) != 0)
      throw std::runtime_error(dir.string() + ": cannot create (" + errno_text() + ")");
  } catch (...) {
    fs::remove_all(staged, ec);
    throw;
  }
  fs::remove_all(staged, ec);  // now the previous results
}

}  // namespace fabform
