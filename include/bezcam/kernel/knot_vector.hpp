#pragma once
/// Knot vectors of B-spline curves: validation, span search and basis
/// functions (The NURBS Book, Piegl & Tiller, 2nd ed., algorithms A2.1 to
/// A2.3).
///
/// A curve of degree p with n + 1 control points has m + 1 = n + p + 2
/// knots u_0 <= ... <= u_m. Its domain is [u_p, u_{m-p}]; the knots outside
/// it only shape the first and last basis functions. A knot vector is
/// clamped when u_0 = ... = u_p and u_{m-p} = ... = u_m: the curve then
/// starts at the first control point and ends at the last.
#include <span>
#include <vector>

namespace bezcam {

/// Checks a knot vector for `n_points` control points of degree `degree`.
/// Throws InputError whose place names the offending item:
///  - `degree` when degree < 1 or degree + 1 > n_points,
///  - `knots` when the count is not n_points + degree + 1 or the domain
///    [u_p, u_{m-p}] is empty,
///  - `knots[i]` for a non-finite knot, a knot smaller than the one before
///    (`knots[7]: expected a knot >= 0.5 (knots must not decrease), found
///    0.25`), or a knot repeated too often: more than degree times strictly
///    inside the domain (the curve would break apart there) or more than
///    degree + 1 times anywhere.
void validate_knots(std::span<const double> knots, int degree, size_t n_points);

/// A2.1: the index i of the knot span [u_i, u_{i+1}) that holds u, with p <=
/// i <= n (u is clamped to the domain; u = u_{m-p} gives the last non-empty
/// span).
int find_span(std::span<const double> knots, int degree, double u);

/// A2.2: the degree + 1 basis functions N_{span-p,p}(u) .. N_{span,p}(u)
/// that can be non-zero at u, written to `out` (size degree + 1).
void basis_functions(std::span<const double> knots, int degree, int span, double u, std::span<double> out);

/// A2.3: the basis functions and their derivatives up to order `n`:
/// result[k][j] = d^k/du^k N_{span-p+j,p}(u), k = 0..n (rows above the
/// degree are zero).
std::vector<std::vector<double>> basis_derivatives(std::span<const double> knots, int degree, int span, double u,
                                                   int n);

/// Number of knots equal to u.
int multiplicity(std::span<const double> knots, double u);

/// True when the first degree + 1 knots are equal and so are the last.
bool is_clamped(std::span<const double> knots, int degree);

/// Clamped knot vector with uniformly spaced interior knots on [a, b] for
/// n_points control points: degree + 1 times a, then the interior knots
/// a + k (b - a) / (n_points - degree), then degree + 1 times b.
std::vector<double> clamped_uniform_knots(size_t n_points, int degree, double a = 0, double b = 1);

}  // namespace bezcam
