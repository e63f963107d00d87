#include "bezcam/flatten/tolerance.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "bezcam/error.hpp"

namespace bezcam {

namespace {
// 10^d, exact doubles for d <= 22.
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
}  // namespace

bool printed_units(double v, int decimals, double& units) {
  // k = v 10^d is within |k| 2^-53 of the exact product (and f within 2^-53
  // of k's fraction), so unless k lies that near a half (a tie, or nearly
  // one) the text's units are round(k), an exact double as |k| < 2^50.
  if (decimals < 0 || decimals > 22 || !std::isfinite(v)) return false;
  const double k = v * kPow10[decimals];
  if (!(std::abs(k) < 0x1p50)) return false;
  const double n = std::floor(k), f = k - n;
  if (!(std::abs(f - 0.5) > std::abs(k) * 0x1p-50 + 0x1p-40)) return false;
  units = f > 0.5 ? n + 1 : n;
  return true;
}

double quantize(double v, int decimals) {
  if (decimals < 0 || !std::isfinite(v)) return v;
  // Without the text when its units N are certain (printed_units()): 10^d
  // is an exact double for d <= 22, and one correctly rounded division
  // gives the double nearest N / 10^d, which is what parsing the text gives.
  if (double units; printed_units(v, decimals, units)) {
    const double out = units / kPow10[decimals];
    return out == 0 ? 0.0 : out;
  }
  char buf[400];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  double out = 0;
  std::from_chars(buf, r.ptr, out);
  return out == 0 ? 0.0 : out;  // no negative zero
}

Vec3 quantize(const Vec3& p, int decimals) {
  return {quantize(p.x, decimals), quantize(p.y, decimals), quantize(p.z, decimals)};
}

double max_rounding_displacement(int decimals, int dim) {
  if (decimals < 0) return 0;
  return 0.5 * std::pow(10.0, -decimals) * std::sqrt(double(dim));
}

double float_margin(double tolerance, double scale) {
  // Evaluation of a Bézier curve by de Casteljau is backward stable: errors
  // are a small multiple of eps times the control points' magnitude.
  return tolerance * kToleranceSafety + 64 * std::numeric_limits<double>::epsilon() * scale;
}

namespace {

// Three significant digits, rounded up, for figures in advice.
std::string advice_num(double v) {
  if (!(v > 0) || !std::isfinite(v)) return fmt_num(v);
  char buf[32];
  const double mag = std::pow(10.0, std::floor(std::log10(v)) - 2);
  std::snprintf(buf, sizeof buf, "%g", std::ceil(v / mag) * mag);
  return buf;
}

}  // namespace

ToleranceBudget check_tolerance(double tol, int decimals, int dim, double scale) {
  if (!(tol > 0) || !std::isfinite(tol))
    throw InputError(errc::flatten_tolerance, Place::at_json("tolerance"),
                     "expected a finite tolerance > 0, found " + fmt_num(tol));
  ToleranceBudget b;
  b.rounding = max_rounding_displacement(decimals, dim);
  if (b.rounding >= 0.9 * tol)
    throw InputError(errc::flatten_tolerance_below_rounding, Place::at_json("tolerance"),
                     "tolerance " + fmt_num(tol) + " cannot be honoured with " + std::to_string(decimals) +
                         " decimals: rounding alone moves a point by up to " + advice_num(b.rounding) +
                         "; use a tolerance above " + advice_num(b.rounding / 0.9) +
                         " or a profile with more decimals");
  b.margin = float_margin(tol, scale);
  if (b.margin >= 0.05 * tol)
    throw InputError(errc::flatten_tolerance_below_precision, Place::at_json("tolerance"),
                     "tolerance " + fmt_num(tol) + " is too small for coordinates of magnitude " + fmt_num(scale) +
                         " in double precision; use a tolerance above " + advice_num(b.margin * 20));
  b.budget = tol - b.margin;
  return b;
}

}  // namespace bezcam
