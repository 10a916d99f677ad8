// fabform predistort RESULT_DIR IMAGE OUT: the image to print on the flat blank so that the part
// formed in RESULT_DIR shows IMAGE, a design drawn in the part's developed view
// (print_map.hpp). Reads RESULT_DIR/blank.obj, the flat-formed map every run writes. Exit 0
// with OUT written; 2 with one line naming the file when the map or the image cannot be read or
// OUT's folder does not exist; 5 when the system refuses the write (a full disk, a permission),
// with its reason. OUT is then untouched.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/guarded.hpp"
#include "fabform/analysis/print_map.hpp"
#include "fabform/error.hpp"
#include "fabform/io/png_image.hpp"
#include "fabform/output/atomic_file.hpp"
#include "fabform/output/print_map_files.hpp"

namespace fabform::cli {
namespace {

int predistort_files(const std::vector<std::string>& args) {
  if (args.size() != 3 || args[0].rfind('-', 0) == 0)
    throw InputError({"command line", 0, ""}, "usage: fabform predistort RESULT_DIR IMAGE OUT.png");
  const std::filesystem::path folder = std::filesystem::path(args[2]).parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder))
    throw InputError({args[2], 0, ""}, "no such folder to write into");
  const PrintMap map = read_blank_obj((std::filesystem::path(args[0]) / "blank.obj").string());
  const Image print = predistort(map, read_png(args[1]));
  write_file_atomically(args[2], png_bytes(print));
  std::printf("wrote %s (%d x %d pixels, the blank's frame)\n", args[2].c_str(), print.width, print.height);
  return kExitDone;
}

}  // namespace

int predistort_command(const std::vector<std::string>& args) {
  return guarded([&] { return predistort_files(args); });
}

}  // namespace fabform::cli
