#pragma once
/// Numbers as text, one family for the whole library: messages, reports,
/// pictures and files. G-code coordinates have their own writer
/// (gcode/number_format.hpp: fixed decimals as a controller reads them).
/// None of these depends on the locale.
#include <string>

namespace bezcam {

/// For messages: rounded to `digits` significant digits (10: the last bits
/// of arithmetic are not news), in the shortest text that reads back as
/// that rounded value ("0.05", "1e-07", "120").
std::string fmt_num(double v, int digits = 10);

/// `v` with `digits` significant digits, trailing zeros trimmed, in printf's
/// %g form ("0.00988", "1.432e-14"); "0" for zero.
std::string format_significant(double v, int digits);

/// `v` with exactly `decimals` digits after the point (printf's %.*f),
/// "-0.000" written "0.000".
std::string format_fixed(double v, int decimals);

/// The shortest text that reads back as exactly `v` ("0.1", "1e-300"):
/// for files that must keep every bit (a job written for a drawing).
std::string format_exact(double v);

/// The same without an exponent ("0.000001", never "1e-06"; "-0" written
/// "0"): for readers whose numbers have none (G-code).
std::string format_exact_fixed(double v);

}  // namespace bezcam
