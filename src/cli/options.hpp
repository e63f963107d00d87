#pragma once
// Option groups shared by the subcommands that convert a job (convert,
// preview): one definition of --machine, --tolerance and --output, so that
// their names, checks and help read the same everywhere.
#include <CLI/CLI.hpp>
#include <string>

namespace bezcam::cli {

struct ConversionOptions {
  std::string machine;           ///< --machine: a profile name or a .json file; empty: the job's, else generic
  double tolerance = 0;          ///< --tolerance: overrides the job's when > 0
  std::string output = "lines";  ///< --output: lines, arcs or nurbs
  bool strict = false;           ///< --strict: refuse every unknown key of the job
};

/// Adds --machine, --tolerance and --output to `s`; `output_help` is the
/// help of --output (what it means for this command).
inline void add_conversion_options(CLI::App* s, ConversionOptions& o, const std::string& output_help) {
  s->add_option("--machine", o.machine, "machine profile: a name in machines/ or a .json file "
                                        "(default: the job's \"machine\", else generic)");
  s->add_option("--tolerance", o.tolerance, "chord tolerance in the job's units, overriding the job's")
      ->check(CLI::PositiveNumber);
  s->add_option("--output", o.output, output_help)->check(CLI::IsMember({"lines", "arcs", "nurbs"}));
  s->add_flag("--strict", o.strict, "refuse every unknown key of the job (likely typos such as \"tolerence\" are "
                                    "always refused; other unknown keys are otherwise warnings)");
}

}  // namespace bezcam::cli
