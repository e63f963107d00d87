#pragma once
// Internal to cam: a pocket's plan and certificate, taken from the
// conversion memo (ConvertOptions::memo) where the same inputs were met.
#include "bezcam/cam/pocket_check.hpp"
#include "bezcam/cam/program.hpp"
#include "pocket_plan.hpp"

namespace bezcam::detail {

/// plan_pocket(in), or the plan made before for an equal input.
PocketPlan memo_plan(ConversionMemo* memo, const PocketPlanInput& in);
/// check_pocket(in), or the certificate made before for an equal input
/// (the moves compared, not where they lie in their programs).
PocketCertificate memo_check(ConversionMemo* memo, const PocketCheckInput& in);

}  // namespace bezcam::detail
