#pragma once
// Option groups shared by the subcommands that convert a job (convert,
// check, preview) and by import: one definition of --machine, --tolerance,
// --output, --set and --layer, so that their names, checks and help read
// the same everywhere.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "bezcam/machine/machine_profile.hpp"

namespace bezcam::cli {

struct ConversionOptions {
  std::string machine;               ///< --machine: a profile name or a .json file; empty: the job's, else generic
  double tolerance = 0;              ///< --tolerance: overrides the job's when > 0
  std::string output = "lines";      ///< --output: lines, arcs, nurbs or (where the command takes it) best
  bool strict = false;               ///< --strict: warnings are errors (exit 2, nothing written)
  std::vector<std::string> no_warn;  ///< --no-warn KIND: warnings of these kinds are not given
  std::vector<std::string> sets;     ///< --set KEY=VALUE: job settings of a drawing (.svg, .dxf)
  std::vector<std::string> layers;   ///< --layer NAME: the drawing's layers to cut (default all)
  std::vector<std::string> only;     ///< --only SELECTOR: the drawing's layers or entities to cut (default all)
  std::vector<std::string> skip;     ///< --skip SELECTOR: the drawing's layers or entities left out
  double join_tolerance = 0;         ///< --join-tolerance D: a DXF's ends joined within D (0: the default)
  double scale = 1;                  ///< --scale S: the drawing's coordinates times S
  std::string units;                 ///< --units U: what a unitless drawing's unit is
};

/// Adds --machine, --tolerance, --output, --strict, --set and --layer to
/// `s`; `output_help` is the help of --output (what it means for this
/// command); `takes_best`: --output best is one of its choices.
void add_conversion_options(CLI::App* s, ConversionOptions& o, const std::string& output_help, bool takes_best = false);

/// --output best chooses by the planned cycle time: refused at --output
/// (exit 2, what to choose instead) when `m` has no motion model.
void refuse_best_without_motion(const MachineProfile& m);

/// --set, --layer, --only and --skip: how a drawing (.svg, .dxf) given instead of a job is
/// read (import).
void add_drawing_options(CLI::App* s, ConversionOptions& o);

}  // namespace bezcam::cli
