#pragma once
// The subcommands of bezcam, each as CLI11 shows it: a struct of the
// arguments it takes, setup_NAME() adding the subcommand to the app with
// its options bound to that struct (returning the subcommand), and
// run_NAME() running it once parsed: the exit status (exit_status.hpp),
// refusals thrown as bezcam::Error. command_line.cpp sets them all up;
// src/cli/NAME.cpp defines each.
#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "conversion_options.hpp"
#include "post_options.hpp"
#include "resume_option.hpp"

namespace bezcam::link {
struct ControllerReport;
struct Endpoint;
}  // namespace bezcam::link

namespace bezcam::cli {

/// bezcam check JOB: validates and describes a job, writes no G-code.
struct CheckArgs {
  std::string job;
  ConversionOptions conv;
  PostOptions post;
};
CLI::App* setup_check(CLI::App& app, CheckArgs& o);
int run_check(const CheckArgs& o);

/// bezcam convert JOB [-o FILE]: writes the job's program.
struct ConvertArgs {
  std::string job, out = "-", report;
  ConversionOptions conv;
  PostOptions post;
  bool quiet = false, compare = false;
};
CLI::App* setup_convert(CLI::App& app, ConvertArgs& o);
int run_convert(const ConvertArgs& o);

/// bezcam import DRAWING [-o FILE]: writes the job a drawing is read as.
struct ImportArgs {
  std::string drawing, out = "-";
  ConversionOptions conv;  ///< --set and --layer only
  bool quiet = false;
};
CLI::App* setup_import(CLI::App& app, ImportArgs& o);
int run_import(const ImportArgs& o);

/// bezcam lint FILE: checks a G-code program against a machine profile.
struct LintArgs {
  std::string file;
  std::string machine;  ///< empty: the machine the program's header names, else generic
  bool quiet = false;
  std::vector<std::string> tool_diameters;  ///< --tool-diameter D=MM
};
CLI::App* setup_lint(CLI::App& app, LintArgs& o);
int run_lint(const LintArgs& o);

/// bezcam preview [JOB] [--program FILE] -o SVG: draws a job or a program.
struct PreviewArgs {
  std::string job, out, program;
  ConversionOptions conv;
  bool output_given = false;  ///< --output was on the command line (it does not apply to --program)
  double width = 1200;
  bool no_control = false, deviation = false, feed = false, quiet = false;
  std::vector<std::string> tool_diameters;  ///< --tool-diameter D=MM
};
CLI::App* setup_preview(CLI::App& app, PreviewArgs& o);
int run_preview(const PreviewArgs& o);

/// bezcam sheet JOB -o SHEET.html: the setup sheet of the job's program.
struct SheetArgs {
  std::string job, out;
  ConversionOptions conv;
  PostOptions post;
  bool quiet = false;
};
CLI::App* setup_sheet(CLI::App& app, SheetArgs& o);
int run_sheet(const SheetArgs& o);

/// bezcam simulate --listen HOST:PORT | --program FILE: the simulated controller.
struct SimulateArgs {
  std::string listen, program, machine = "generic", trace, report, motion;
  std::size_t buffer = 4096;
  int max_connections = 8;
  double idle_timeout = 30, session_timeout = 30, exec_delay_ms = 0;
  std::string time_scale = "1";
  std::vector<std::string> faults;
  std::uint32_t session_base = 0;
  bool quiet = false;
  std::vector<std::string> tool_diameters;  ///< --tool-diameter D=MM
  ResumeArgs resume;                        ///< --from-line (with --program)
  std::string stock, memory_limit, tools;   ///< --stock BOX, --memory-limit SIZE, --tools FILE
  double cell = 0;                          ///< --cell (0: the default)
};
CLI::App* setup_simulate(CLI::App& app, SimulateArgs& o);
int run_simulate(const SimulateArgs& o);

/// bezcam status --to HOST:PORT: what a controller is doing.
struct StatusArgs {
  std::string to;
  double timeout = 2;
};
CLI::App* setup_status(CLI::App& app, StatusArgs& o);
int run_status(const StatusArgs& o);
/// Prints a controller's state on stdout (status, stream --abort).
void print_controller(const link::ControllerReport& r, const link::Endpoint& to);

/// bezcam stream FILE --to HOST:PORT: sends a program to a controller.
struct StreamArgs {
  std::string file, to, progress = "auto";
  double timeout = 2, retry_time = 60, stall_timeout = 60;
  int retries = 30;
  int chunk = 0;
  bool quiet = false, abort = false, no_preflight = false;
  ResumeArgs resume;  ///< --from-line
};
CLI::App* setup_stream(CLI::App& app, StreamArgs& o);
int run_stream(const StreamArgs& o);

/// bezcam verify PROGRAM: cuts a program into a stock and reports the machined result.
struct VerifyArgs {
  std::string program, machine = "generic", tools, stock, design, report, image, heightmap, memory_limit;
  double cell = 0;
  unsigned threads = 0;
  bool hash = false, quiet = false;
};
CLI::App* setup_verify(CLI::App& app, VerifyArgs& o);
int run_verify(const VerifyArgs& o);

}  // namespace bezcam::cli
