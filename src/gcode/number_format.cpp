#include "bezcam/gcode/number_format.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"

namespace bezcam {

std::string format_number(double v, int decimals) {
  char buf[400];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals < 0 ? 6 : decimals);
  std::string s(buf, r.ptr);
  if (s.find('.') == std::string::npos) s += '.';
  while (s.back() == '0') s.pop_back();
  if (s == "-0.") s = "0.";
  return s;
}

std::string format_significant(double v, int digits) {
  if (!std::isfinite(v)) return fmt_num(v);
  if (v == 0) return "0";
  char buf[64];
  // %g trims trailing zeros and switches to exponents only for very small
  // or large values, which deviations of 1e-5 and lengths of 1e4 are not.
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string measured_text(double measured, double tolerance, std::string (*format)(double)) {
  const double resolution = kMeasureResolution * tolerance;
  return measured <= resolution ? "below " + format(resolution) : format(measured);
}

}  // namespace bezcam
