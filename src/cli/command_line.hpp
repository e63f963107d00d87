#pragma once
// The bezcam command line as one object: the CLI11 app with every
// subcommand set up (commands.hpp), each bound to its arguments struct,
// and what main() does with argv. Tests parse and run argument vectors
// in-process through it.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "run_command_line.hpp"

namespace bezcam::cli {

/// Every subcommand's arguments, as parsed.
struct Arguments {
  CheckArgs check;
  ConvertArgs convert;
  ImportArgs import_drawing;
  LintArgs lint;
  PreviewArgs preview;
  SheetArgs sheet;
  SimulateArgs simulate;
  StatusArgs status;
  StreamArgs stream;
  VerifyArgs verify;
};

class CommandLine {
 public:
  /// The app with every subcommand, in the order --help lists them.
  CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  /// Parses `argv` (argv[0] is the program's name, shown in --help's
  /// usage line). Throws CLI::ParseError as CLI::App::parse does (--help
  /// and --version too, with exit code 0).
  void parse(const std::vector<std::string>& argv);
  /// The subcommand parsed, or null.
  const CLI::App* chosen() const;
  /// Runs the subcommand parsed with its arguments: its exit status;
  /// refusals are thrown (bezcam::Error).
  int run() const;
  /// The status and the messages on stderr of a command line CLI11
  /// refused: a command that does not exist named with the one meant, the
  /// option meant for a misspelt one, else CLI11's sentence.
  int usage_error(const CLI::ParseError& e);

  const Arguments& args() const { return args_; }
  CLI::App& app() { return app_; }

 private:
  struct Subcommand {
    CLI::App* app;
    std::function<int()> run;
  };
  CLI::App app_;
  Arguments args_;
  std::vector<Subcommand> subcommands_;
  std::vector<std::string> argv_;  ///< as parse() was given it
};

}  // namespace bezcam::cli
