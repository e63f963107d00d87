#include "bezcam/format.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace bezcam {

std::string fmt_num(double v, int digits) {
  // Rounded to what matters, then the shortest text that reads back as
  // that rounded value (0.05000000000000071 is "0.05").
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
  double r = v;
  std::from_chars(buf, res.ptr, r);
  res = std::to_chars(buf, buf + sizeof buf, r);
  return std::string(buf, res.ptr);
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

std::string format_fixed(double v, int decimals) {
  char buf[400];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v == 0 ? 0.0 : v);
  return buf;
}

std::string format_exact(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

std::string format_exact_fixed(double v) {
  char buf[400];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  std::string s(buf, r.ptr);
  if (s == "-0") s = "0";
  return s;
}

}  // namespace bezcam
