#pragma once
// Subcommands register themselves: each src/cli/<name>.cpp defines one
// Command and a RegisterCommand, so adding a subcommand touches no other file.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace bezcam::cli {

struct Command {
  std::string name;
  /// Adds the subcommand and its options to the app.
  std::function<CLI::App*(CLI::App&)> add;
  /// Runs it once parsed; returns the exit status (errors are thrown).
  std::function<int()> run;
  CLI::App* app = nullptr;
};

std::vector<Command*>& commands();

struct RegisterCommand {
  explicit RegisterCommand(Command* c) { commands().push_back(c); }
};

/// Writes `data` to `path` atomically: a temporary file beside it, renamed
/// into place only when complete, so a refused or failed run never leaves a
/// partial or truncated file. "-" writes to stdout.
void write_output_atomically(const std::string& path, const std::string& data);

/// Whether stderr is a terminal (progress bars) and whether to be quiet.
bool stderr_is_tty();

}  // namespace bezcam::cli

namespace bezcam {
struct Job;
struct MachineProfile;
}  // namespace bezcam

namespace bezcam::cli {

/// Loads the profile named by `--machine` (a name or a .json file); an
/// unknown name is refused naming the option.
MachineProfile load_profile_option(const std::string& machine);
/// Picks the profile: `--machine` if given, else the job's `machine`, else
/// "generic"; an unknown name from the file is refused naming its key.
MachineProfile resolve_profile(const Job& job, const std::string& cli_machine);

}  // namespace bezcam::cli
