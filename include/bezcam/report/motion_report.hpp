#pragma once
/// The planned motion of a program in numbers (docs/motion.md): what
/// `simulate --program --report` writes and prints, what `convert --report`
/// takes its cycle time from, and the samples of `simulate --motion`.
#include <string>

#include "bezcam/machine/planner.hpp"

namespace bezcam {

/// The report as JSON (`"bezcam_motion": 1`): cycle, cutting, rapid and
/// pause time, programmed-feed time, mean feed ratio, starved and clamped
/// blocks, the largest executed-path deviation (mm, and its line), and per
/// block its figures. Numbers are rounded (times and lengths to 1e-6,
/// feeds to 1e-3) so that the same program gives the same bytes.
/// `program`, `machine`: names for the document.
std::string motion_report_json(const MotionPlan& plan, const std::string& program, const std::string& machine);

/// A short human summary for stderr (lines starting "bezcam: " or two spaces).
std::string motion_summary_text(const MotionPlan& plan, const std::string& what);

/// The samples as text: a header `t x y z feed`, then one row per period
/// (tab-separated, fixed decimals).
std::string motion_samples_tsv(const MotionPlan& plan);

/// A duration for people: "8.65 s", "2 min 05.3 s", "1 h 02 min 05 s".
std::string format_seconds(double s);

}  // namespace bezcam
