#pragma once
// The examples at the end of each command's --help.
#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

namespace bezcam::cli {

/// Per command (as --help lists them; status and stream keep their own),
/// the example command lines.
const std::vector<std::pair<std::string, std::vector<std::string>>>& help_examples();

/// Appends each command's examples to its footer, and the quick start and
/// where the documentation is to the program's.
void add_help_examples(CLI::App& app);

}  // namespace bezcam::cli
