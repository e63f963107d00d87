#pragma once
/// Tolerance and rounding: the two quantities every bound in bezcam adds up.
///
/// A tolerance is the largest distance allowed between the true geometry and
/// the tool path *as printed*, in model units. Printing rounds coordinates to
/// a number of decimals; that displacement counts against the tolerance.
#include <span>

#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/vec.hpp"

namespace bezcam {

/// Relative share of the tolerance kept back for floating-point error in the
/// bound computations (evaluation, root finding, parsing of printed text).
inline constexpr double kToleranceSafety = 1e-9;

/// The value a controller reads back when `v` is printed with `decimals`
/// digits after the point (the printed text is parsed back, so the value is
/// bit-for-bit what the G-code writer prints). decimals < 0: no rounding.
double quantize(double v, int decimals);
/// The whole number of 10^-decimals units that `v` printed with `decimals`
/// digits after the point shows (the text without its point), when that is
/// certain without printing: v 10^decimals is not within its rounding
/// error of a half, under 2^50 in magnitude, and 0 <= decimals <= 22.
/// Otherwise false, and only the text itself tells.
bool printed_units(double v, int decimals, double& units);
/// quantize() on x, y and z.
Vec3 quantize(const Vec3& p, int decimals);
/// Largest displacement rounding can cause to a point of `dim` coordinates.
double max_rounding_displacement(int decimals, int dim);
/// Margin for floating-point error at coordinates of magnitude `scale`.
double float_margin(double tolerance, double scale);

/// What is left of a tolerance for the geometry once rounding and
/// floating-point error are set aside.
struct ToleranceBudget {
  double rounding = 0;  ///< max_rounding_displacement(decimals, dim)
  double margin = 0;    ///< float_margin(tolerance, scale)
  double budget = 0;    ///< tolerance - margin: what the rounded path may deviate by
};
/// The one check every flattener and fitter makes before it starts. Refuses,
/// with an InputError naming "tolerance", a tolerance that is not finite and
/// positive (flatten.tolerance), one that rounding to `decimals` alone would
/// use up (flatten.tolerance-below-rounding), and one too small for double
/// precision at coordinates of magnitude `scale`
/// (flatten.tolerance-below-precision). Each message gives the smallest
/// tolerance that would be accepted.
ToleranceBudget check_tolerance(double tolerance, int decimals, int dim, double scale);

}  // namespace bezcam
