#include "bezcam/gcode/number_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/tolerance.hpp"

namespace bezcam {

char* format_number_to(char* buf, double v, int decimals) {
  const int d = decimals < 0 ? 6 : decimals;
  char* end = buf;
  if (double units; printed_units(v, d, units)) {
    // The text to_chars() prints, without it (printed_units()): the units'
    // digits, the point d digits from the right.
    if (units < 0) *end++ = '-';
    char digits[24];
    int len = 0;
    for (auto n = static_cast<std::uint64_t>(std::abs(units)); n > 0 || len <= d; n /= 10)
      digits[len++] = char('0' + n % 10);
    while (len > d) *end++ = digits[--len];
    if (d > 0) *end++ = '.';
    while (len > 0) *end++ = digits[--len];
  } else {
    end = std::to_chars(buf, buf + kNumberChars - 1, v, std::chars_format::fixed, d).ptr;
  }
  if (std::find(buf, end, '.') == end) *end++ = '.';
  while (end[-1] == '0') --end;
  if (end - buf == 3 && buf[0] == '-' && buf[1] == '0' && buf[2] == '.') return std::copy_n("0.", 2, buf);
  return end;
}

std::string format_number(double v, int decimals) {
  char buf[kNumberChars];
  return std::string(buf, format_number_to(buf, v, decimals));
}

std::string format_bound(double v, int digits) {
  std::string s = format_significant(v, digits);
  if (!(v > 0) || !std::isfinite(v)) return s;
  // One unit of the last digit printed, and up by it until the text reads
  // back at or above v.
  const double step = std::pow(10.0, std::floor(std::log10(v)) - digits + 1);
  if (!(step > 0)) return s;
  for (double up = std::ceil(v / step) * step; std::strtod(s.c_str(), nullptr) < v; up += step)
    s = format_significant(up, digits);
  return s;
}

std::string measured_text(double measured, double bound, double tolerance, std::string (*format)(double)) {
  const double resolution = kMeasureResolution * tolerance;
  if (measured > resolution) return format(measured);
  if (bound <= 0) return "0";
  const std::string floor = format(std::min(resolution, bound));
  // The figure as printed must still be above what was measured.
  return std::strtod(floor.c_str(), nullptr) > measured ? "below " + floor : format(measured);
}

std::string format_clock(double s) {
  char b[96];
  const long whole = s > 0 ? std::max(1L, std::lround(s)) : 0L;
  if (whole >= 3600)
    std::snprintf(b, sizeof b, "%ld h %02ld min %02ld s", whole / 3600, whole / 60 % 60, whole % 60);
  else if (whole >= 60)
    std::snprintf(b, sizeof b, "%ld min %02ld s", whole / 60, whole % 60);
  else
    std::snprintf(b, sizeof b, "%ld s", whole);
  return b;
}

std::string format_time(double s, bool round_down) {
  const double c = round_down ? std::floor(s * 100) : std::round(s * 100);  // hundredths
  const auto h = static_cast<long long>(std::max(c, 0.0));
  char b[64];
  if (h < 6000)
    std::snprintf(b, sizeof b, "%lld.%02lld s", h / 100, h % 100);
  else
    std::snprintf(b, sizeof b, "%lld min %02lld.%02lld s", h / 6000, h / 100 % 60, h % 100);
  return b;
}

}  // namespace bezcam
