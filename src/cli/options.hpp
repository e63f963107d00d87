#pragma once
// Option groups shared by the subcommands that convert a job (convert,
// preview): one definition of --machine, --tolerance and --output, so that
// their names, checks and help read the same everywhere.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace bezcam::cli {

/// A number > 0, said plainly ("expected a number > 0, found -1"), not as
/// CLI11's range up to the largest double.
inline CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (end == s.c_str() || *end != '\0' || !(v > 0) || !std::isfinite(v)) return "expected a number > 0, found " + s;
        return {};
      },
      "NUMBER > 0");
}

struct ConversionOptions;
void add_drawing_options(CLI::App* s, ConversionOptions& o);

struct ConversionOptions {
  std::string machine;           ///< --machine: a profile name or a .json file; empty: the job's, else generic
  double tolerance = 0;          ///< --tolerance: overrides the job's when > 0
  std::string output = "lines";  ///< --output: lines, arcs or nurbs
  bool strict = false;           ///< --strict: refuse every unknown key of the job
  std::vector<std::string> sets;    ///< --set KEY=VALUE: job settings of a drawing (.svg, .dxf)
  std::vector<std::string> layers;  ///< --layer NAME: the drawing's layers to cut (default all)
};

/// Adds --machine, --tolerance and --output to `s`; `output_help` is the
/// help of --output (what it means for this command).
inline void add_conversion_options(CLI::App* s, ConversionOptions& o, const std::string& output_help) {
  s->add_option("--machine", o.machine, "machine profile: a name in machines/ or a .json file "
                                        "(default: the job's \"machine\", else generic)");
  s->add_option("--tolerance", o.tolerance, "chord tolerance in the job's units, overriding the job's")
      ->check(positive_number());
  s->add_option("--output", o.output, output_help)
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            if (v == "lines" || v == "arcs" || v == "nurbs") return {};
            // `--output out.nc`: the program's file is -o.
            if (v.find('.') != std::string::npos || v.find('/') != std::string::npos)
              return "expected lines, arcs or nurbs, found \"" + v + "\"; to name the program file, use -o " + v;
            return "expected lines, arcs or nurbs, found \"" + v + "\"";
          },
          "lines|arcs|nurbs"))
      ->capture_default_str();
  s->add_flag("--strict", o.strict, "refuse every unknown key of the job (likely typos such as \"tolerence\" are "
                                    "always refused; other unknown keys are otherwise warnings)");
  add_drawing_options(s, o);
}

/// --set and --layer: how a drawing (.svg, .dxf) given instead of a job is
/// read (import).
inline void add_drawing_options(CLI::App* s, ConversionOptions& o) {
  s->add_option("--set", o.sets, "a job setting for a drawing (.svg, .dxf), KEY=VALUE, repeatable: tolerance, units, "
                                 "feed, plunge_feed, safe_z, cut_z, spindle_rpm, tool, coolant ... (checked as the "
                                 "job file's keys)")
      ->type_name("KEY=VALUE");
  s->add_option("--layer", o.layers, "a layer of the drawing to cut, repeatable (default: every layer)")
      ->type_name("NAME");
}

}  // namespace bezcam::cli
