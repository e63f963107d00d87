#pragma once
/// What `bezcam verify` reports: the machined stock's figures, and against
/// a design, per entity the largest gouge and excess. As JSON (the
/// report's keys are in docs/verify.md) and as the lines it prints.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bezcam/kernel/units.hpp"
#include "bezcam/verify/design_check.hpp"

namespace bezcam {

struct VerifyFigures {
  std::string program, machine;
  Units units = Units::mm;  ///< the program's
  StockBox box;
  double cell = 0;
  std::size_t nx = 0, ny = 0;
  double memory_bytes = 0;
  StockTools tools;  ///< the tools the program used
  double removed_volume = 0;
  DexelGrid::Deepest deepest;
  std::string hash;
  double added_error = 0;  ///< mm: the flattening bound of NURBS and curve blocks swept
  std::size_t blocks = 0, rapid_cuts = 0;
  SweepStats sweep;  ///< the columns the sweeps evaluated
  int first_rapid_cut_line = 0;
  std::optional<double> cycle_time_s;  ///< planned on the machine's motion model
  double verify_seconds = 0;           ///< the verifier's own run time
  std::optional<DesignCheck> design;
  std::string design_file;
};

/// The report as a JSON document (lengths in mm, volumes in mm^3).
std::string verify_report_json(const VerifyFigures& f);
/// The lines `bezcam verify` prints.
std::string verify_summary(const VerifyFigures& f);

}  // namespace bezcam
