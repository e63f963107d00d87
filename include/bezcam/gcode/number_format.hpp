#pragma once
/// Numbers as G-code prints them: fixed decimals, trailing zeros trimmed,
/// the decimal point always kept ("10.", "0.5", "-1.25"), never "-0.".
/// The value a controller reads back is exactly quantize(v, decimals).
#include <string>

#include "bezcam/format.hpp"

namespace bezcam {

std::string format_number(double v, int decimals);

/// Room format_number_to() needs: every double in fixed notation with up to
/// 17 decimals (309 digits before the point at most).
inline constexpr int kNumberChars = 400;
/// format_number() into `buf` (kNumberChars long), no allocation; returns
/// the end of the text written.
char* format_number_to(char* buf, double v, int decimals);

/// A proven bound as bezcam states it: `v` with `digits` significant
/// digits, rounded up, so that the figure printed is never below the bound
/// proven (0.0098645 is "0.009865" at 4 digits, "0.00987" at 3).
std::string format_bound(double v, int digits);

/// A measured deviation as bezcam states it (program header, report,
/// preview) beside its proven bound: `format(measured)`, or, when it is
/// within the measurement's resolution (kMeasureResolution of the
/// tolerance, where a figure would only show the measurement's own error),
/// "below " the smaller of the resolution and a positive bound, so that the
/// figure read beside the bound is never the larger; "0" when the bound is
/// 0 (nothing to measure but the measurement's own error).
std::string measured_text(double measured, double bound, double tolerance, std::string (*format)(double));

/// A cycle time as a program's header prints it: whole seconds, at least
/// 1 s for any time ("1 h 02 min 05 s", "2 min 05 s", "45 s").
std::string format_clock(double seconds);

/// A time to the hundredth of a second ("8.23 s", "2 min 05.31 s"); with
/// `round_down` rounded down, so that a lower bound printed stays one.
std::string format_time(double seconds, bool round_down = false);

}  // namespace bezcam
