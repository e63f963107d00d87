#pragma once
// The figures of a plan as both reports write them: `convert --report`'s
// "planned" object and `simulate --program`'s motion report share these
// keys, their order and their rounding.
#include <nlohmann/json.hpp>

#include "bezcam/report/report.hpp"

namespace bezcam::detail {

/// `v` rounded to a multiple of `q`, never -0.
double round_to(double v, double q);

/// The plan's times (s, to 1e-6), mean feed ratio and starved and clamped
/// block counts, appended to `j` in that order.
void put_plan_figures(nlohmann::ordered_json& j, const ProgramReport::Planned& q);

}  // namespace bezcam::detail
