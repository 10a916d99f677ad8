// fabform predistort RESULT_DIR IMAGE OUT: the image to print on the flat blank so that the part
// formed in RESULT_DIR shows IMAGE, a design drawn in the part's developed view
// (print_map.hpp). Reads RESULT_DIR/blank.obj, the flat-formed map every run writes. Exit 0
// with OUT written; 2 with one line naming the file when the map or the image cannot be read or
// OUT's folder does not exist; 5 when the system refuses the write (a full disk, a permission),
// with its reason. OUT is then untouched.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/guarded.hpp"
#include "fabform/analysis/print_map.hpp"
#include "fabform/error.hpp"
#include "fabform/io/png_image.hpp"
#include "fabform/output/atomic_file.hpp"
#include "fabform/output/print_map_files.hpp"

namespace fabform::cli {
namespace {

struct PredistortArguments {
  std::vector<std::string> files;  // RESULT_DIR, IMAGE, OUT
};

PredistortArguments read_predistort_arguments(const CLI::App& command) {
  refuse_leftovers(command, "usage: fabform predistort RESULT_DIR IMAGE OUT.png");
  PredistortArguments parsed;
  for (const char* name : {"RESULT_DIR", "IMAGE", "OUT"})
    for (const std::string& v : values_of(command, name)) parsed.files.push_back(v);
  if (parsed.files.size() != 3) throw usage_error("", "usage: fabform predistort RESULT_DIR IMAGE OUT.png");
  return parsed;
}

int predistort_files(const PredistortArguments& parsed) {
  const std::vector<std::string>& args = parsed.files;
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

Command add_predistort_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("predistort", "the image to print on the flat blank so that the formed part shows a design");
  command->add_option("RESULT_DIR", "a run's results folder (its blank.obj)");
  command->add_option("IMAGE", "the design, a PNG in the part's developed view");
  command->add_option("OUT", "the print, a PNG in the blank's frame")->type_name("OUT.png");
  command->allow_extras();
  auto args = std::make_shared<PredistortArguments>();
  return {command, [command, args] { *args = read_predistort_arguments(*command); }, [args] { return predistort_files(*args); }};
}

}  // namespace fabform::cli
