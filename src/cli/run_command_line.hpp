#pragma once
// main()'s whole work as one call, declared apart from the command line's
// object (command_line.hpp) so that what only runs command lines does not
// compile CLI11.
#include <string>
#include <vector>

namespace bezcam::cli {

/// What main() does: parses `argv`, runs the subcommand and returns the
/// exit status (exit_status.hpp). --help and --version print on stdout;
/// usage errors and refusals on stderr as `bezcam: error: ...` with the
/// error's id.
int run_command_line(const std::vector<std::string>& argv);

}  // namespace bezcam::cli
