// The command line, on CLI11: `fabform COMMAND ...`, `fabform COMMAND --help`, `fabform help
// COMMAND`, `fabform --help`, `fabform --version`. A usage error (an unknown option, a missing
// value) is one line naming the option, then that command's usage, exit status 2; each command's
// own errors and statuses are commands.hpp's.
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/guarded.hpp"
#include "fabform/solver/solver_registry.hpp"

namespace fabform::cli {
namespace {

// CLI11's own words for an option without its value ("--out: 1 required TEXT missing") in ours.
InputError usage_error_of(const CLI::ParseError& error) {
  const std::string what = error.what();
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&error)) {
    const std::string option = what.substr(0, what.find(':'));
    return usage_error(option, what.find("required") != std::string::npos ? "needs a value" : "is given more than once");
  }
  return usage_error("", what);
}

const CLI::App* subcommand_named(const CLI::App& app, const std::string& name) {
  for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; }))
    if (command->get_name() == name) return command;
  return nullptr;
}

// A command's help with its full name ("fabform run"), as `fabform run --help` prints it.
std::string help_of(const CLI::App& command) {
  return command.get_parent() ? command.help(command.get_parent()->get_name()) : command.help();
}

int refuse(const InputError& error, const CLI::App& usage) {
  guarded([&]() -> int { throw error; });
  std::fputs(help_of(usage).c_str(), stderr);
  return kExitBadInput;
}

int command_line(int argc, char** argv) {
  CLI::App app{"fabform forms a fabric over rigid bodies and finds where it comes to rest.", "fabform"};
  app.set_version_flag("--version", std::string("fabform ") + FABFORM_VERSION);
  app.require_subcommand(0, 1);
  std::vector<Command> commands = {add_run_command(app), add_study_command(app), add_check_command(app),
                                   add_predistort_command(app)};
  CLI::App* solvers = app.add_subcommand("solvers", "list the solvers");
  CLI::App* help = app.add_subcommand("help", "print a command's options");
  help->add_option("COMMAND", "run, study, check, predistort or solvers");
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && args[0][0] != '-' && !subcommand_named(app, args[0]))
    return refuse(usage_error(args[0], "unknown command"), app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(app.help().c_str(), stdout);  // the selected command's, else fabform's
    return kExitDone;
  } catch (const CLI::CallForVersion& version) {
    std::printf("%s\n", version.what());
    return kExitDone;
  } catch (const CLI::ParseError& error) {
    const std::vector<CLI::App*> chosen = app.get_subcommands();
    return refuse(usage_error_of(error), chosen.empty() ? app : *chosen.front());
  }
  if (help->parsed()) {
    const std::vector<std::string>& topic = values_of(*help, "COMMAND");
    if (topic.empty()) return std::fputs(app.help().c_str(), stdout), kExitDone;
    const CLI::App* command = subcommand_named(app, topic.front());
    if (!command) return refuse(usage_error(topic.front(), "unknown command"), app);
    std::fputs(help_of(*command).c_str(), stdout);
    return kExitDone;
  }
  if (solvers->parsed()) {
    for (const auto& solver : fabform::solvers()) std::printf("%s\n", solver.name.c_str());
    return kExitDone;
  }
  for (const Command& command : commands) {
    if (!command.options->parsed()) continue;
    if (guarded([&] { command.read(); return kExitDone; }) != kExitDone)
      return std::fputs(help_of(*command.options).c_str(), stderr), kExitBadInput;
    return guarded(command.run);
  }
  std::fputs(app.help().c_str(), stderr);  // no command
  return kExitBadInput;
}

}  // namespace
}  // namespace fabform::cli

int main(int argc, char** argv) { return fabform::cli::command_line(argc, argv); }
