#include "fabform/output/results_folder.hpp"

#include <cerrno>
#include <cstddef>
#include <cstdio>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>

#include "fabform/error.hpp"
#include "fabform/output/atomic_file.hpp"
#include "fabform/thread_count.hpp"
#include "linalg/parallel_failure.hpp"

namespace fabform {
namespace {

namespace fs = std::filesystem;

// From this many bytes in all, the files are written on every thread.
constexpr std::size_t kParallelWriteBytes = std::size_t{16} << 20;

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

[[noreturn]] void cannot_replace(const fs::path& dir, const std::error_code& ec) {
  throw SystemError(dir.string(), "replace the results", ec.message());
}

// Puts `staged` where `dir` is and the old folder where `staged` was.
void swap_in(const fs::path& staged, const fs::path& dir) {
  if (::renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) == 0) return;
  // File systems without the exchange: two renames, with the old folder kept until both are done.
  const fs::path old = sibling(dir, "old");
  std::error_code ec;
  fs::remove_all(old, ec);
  fs::rename(dir, old, ec);
  if (ec) cannot_replace(dir, ec);
  fs::rename(staged, dir, ec);
  if (ec) {
    fs::rename(old, dir);
    cannot_replace(dir, ec);
  }
  fs::rename(old, staged, ec);  // removed by the caller with the staging folder
  if (ec) fs::remove_all(old, ec);  // the new results are in place; the old ones go either way
}

// Fills a fresh staging folder beside `dir` with `files`.
fs::path stage(const fs::path& dir, const char* role, const std::vector<ResultFile>& files) {
  const fs::path staged = sibling(dir, role);
  std::error_code ec;
  fs::remove_all(staged, ec);  // left by a run that was killed while writing
  if (!fs::create_directories(staged, ec))
    throw SystemError(staged.string(), "create a folder", ec ? ec.message() : "it exists");
  // Each file on its own thread when they are large (the page cache's copy of a million nodes'
  // half gigabyte of text took 3.5 s on one).
  std::size_t bytes = 0;
  for (const auto& file : files) bytes += file.second.size();
  ParallelFailure failure;
  const auto count = static_cast<std::ptrdiff_t>(files.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_in_use()) if (bytes >= kParallelWriteBytes)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    if (failure.caught()) continue;
    const auto& [name, content] = files[static_cast<std::size_t>(k)];
    try {
      write_file((staged / name).string(), content);
    } catch (...) {
      failure.capture();
    }
  }
  try {
    failure.rethrow();
  } catch (...) {
    fs::remove_all(staged, ec);
    throw;
  }
  return staged;
}

// Puts the staged folder in place of `dir`, whether `dir` exists or not.
void put_in_place(const fs::path& staged, const fs::path& dir) {
  if (fs::exists(dir)) return swap_in(staged, dir);
  if (std::rename(staged.c_str(), dir.c_str()) != 0) throw SystemError(dir.string(), "create", system_reason(errno));
}

// A folder on another file system than its parent (a mount point) cannot be renamed, so the
// results could never be swapped into it.
void require_renamable(const fs::path& dir) {
  struct stat own{}, parent{};
  const fs::path above = dir.parent_path().empty() ? fs::path(".") : dir.parent_path();
  if (::stat(dir.c_str(), &own) != 0 || ::stat(above.c_str(), &parent) != 0)
    throw SystemError(dir.string(), "examine the folder", system_reason(errno));
  if (own.st_dev != parent.st_dev)
    throw SystemError(dir.string(), "replace the results", "it is a mount point; choose a folder inside it");
}

// What a publish will do, done once with a small file before the solve, so that a folder fabform
// cannot create, fill or rename into place (a full or read-only disk, a mount point) fails now,
// not after it. An existing folder is never moved by the probe: a killed probe loses nothing.
void probe(const fs::path& dir) {
  const fs::path staged = stage(dir, "probe", {{"probe", "fabform checks it can write here\n"}});
  std::error_code ec;
  try {
    if (fs::exists(dir)) {
      require_renamable(dir);
    } else {
      put_in_place(staged, dir);
      fs::rename(dir, staged, ec);
      if (ec) throw SystemError(dir.string(), "undo the probe", ec.message());
    }
  } catch (...) {
    fs::remove_all(staged, ec);
    throw;
  }
  fs::remove_all(staged, ec);
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
  try {
    probe(dir);
  } catch (const SystemError& error) {
    throw InputError({dir_text, 0, ""}, std::string("the output folder cannot take results: ") + error.what());
  }
}

void publish_results(const std::string& dir_text, const std::vector<ResultFile>& files) {
  const fs::path dir = normalised(dir_text);
  const fs::path staged = stage(dir, "staging", files);
  std::error_code ec;
  try {
    put_in_place(staged, dir);
  } catch (...) {
    fs::remove_all(staged, ec);
    throw;
  }
  fs::remove_all(staged, ec);  // now the previous results
}

}  // namespace fabform
