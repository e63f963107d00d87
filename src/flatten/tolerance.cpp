#include "bezcam/flatten/tolerance.hpp"

#include <charconv>
#include <cmath>
#include <limits>

namespace bezcam {

double quantize(double v, int decimals) {
  if (decimals < 0 || !std::isfinite(v)) return v;
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

}  // namespace bezcam
