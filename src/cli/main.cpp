// bezcam: the command-line front end. Thin: the command line
// (command_line.hpp) parses the options, runs the subcommand and maps
// error families to exit codes (docs/cli.md): 0 success, 2 invalid input
// or usage, 3 I/O or connection failure, 4 the controller refused or lost
// the program.
#include <string>
#include <vector>

#include "run_command_line.hpp"

int main(int argc, char** argv) { return bezcam::cli::run_command_line(std::vector<std::string>(argv, argv + argc)); }
