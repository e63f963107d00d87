#pragma once
/// Numbers as G-code prints them: fixed decimals, trailing zeros trimmed,
/// the decimal point always kept ("10.", "0.5", "-1.25"), never "-0.".
/// The value a controller reads back is exactly quantize(v, decimals).
#include <string>

namespace bezcam {

std::string format_number(double v, int decimals);

}  // namespace bezcam
