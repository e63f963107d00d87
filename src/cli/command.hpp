#pragma once
// Subcommands register themselves: each src/cli/<name>.cpp defines one
// Command and a RegisterCommand, so adding a subcommand touches no other file.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <string_view>
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

/// Writes `data` to `path` without ever destroying what is there:
///  - a regular file (or a new one) atomically: a temporary file beside it,
///    renamed into place only when complete, with the replaced file's mode
///    and owner, so a refused or failed run never leaves a partial or
///    truncated file;
///  - a symbolic link is followed: its target is written, the link stays;
///  - anything else (a serial port for DNC, a FIFO, /dev/null) is written
///    through, every write checked, never replaced by a file;
///  - "-" writes to stdout.
/// A failed write is an IoError naming the path and the cause.
void write_output(const std::string& path, const std::string& data);

/// Receives the output's text in order, piece by piece.
using OutputSink = std::function<void(std::string_view)>;
/// Makes the output: hands its text to the sink as it goes; may throw.
using OutputProducer = std::function<void(const OutputSink&)>;
/// The same, streamed: `produce` writes the text in pieces, never held
/// whole. A regular file is still renamed into place only when `produce`
/// has returned: an exception (a refusal found while writing) leaves no
/// file, or the old one. Standard output and devices receive the pieces
/// as they come.
void write_output(const std::string& path, const OutputProducer& produce);

/// Whether stderr is a terminal (progress bars) and whether to be quiet.
bool stderr_is_tty();

}  // namespace bezcam::cli

namespace bezcam {
struct Job;
struct MachineProfile;
namespace link {
struct ControllerReport;
struct Endpoint;
}  // namespace link
}  // namespace bezcam

namespace bezcam::cli {

/// Loads the profile named by `--machine` (a name or a .json file); an
/// unknown name is refused naming the option.
MachineProfile load_profile_option(const std::string& machine);
/// `--tool-diameter D=MM` (repeatable): the controller's D registers for
/// cutter compensation (G41/G42 D-), added to the profile's tool table.
void add_tool_diameter_option(CLI::App* s, std::vector<std::string>& values);
void apply_tool_diameters(MachineProfile& m, const std::vector<std::string>& values);
/// Picks the profile: `--machine` if given, else the job's `machine`, else
/// "generic"; an unknown name from the file is refused naming its key.
MachineProfile resolve_profile(const Job& job, const std::string& cli_machine);

/// Reads a job file. When the job is refused, the warnings found before
/// are printed first: a refusal never hides a warning.
Job read_job(const std::string& path);
struct ConversionOptions;
}  // namespace bezcam::cli
namespace bezcam::import {
struct Drawing;
struct ImportOptions;
}  // namespace bezcam::import
namespace bezcam::cli {
/// Reads a job file, or a drawing (.svg, .dxf) as the job it stands for,
/// with the options' --set settings and --layer layers (which apply to
/// drawings only: a job file states its own settings).
/// `drawing`, when given, receives the drawing read (check lists it).
Job read_job(const std::string& path, const ConversionOptions& o, import::Drawing* drawing = nullptr);
/// The --set and --layer options as import options (KEY=VALUE checked).
import::ImportOptions import_options(const ConversionOptions& o);
/// Prints a controller's state on stdout (status, stream --abort).
void print_controller(const link::ControllerReport& r, const link::Endpoint& to);
/// Prints warnings on stderr as `bezcam: warning: ...`.
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace bezcam::cli
