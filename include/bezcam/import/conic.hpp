#pragma once
/// Circular and elliptical arcs as exact rational quadratic Bézier pieces,
/// each spanning at most 90 degrees of the ellipse's parameter (SVG `A`
/// commands, shapes, DXF ARC, CIRCLE, ELLIPSE and bulges).
#include <vector>

#include "bezcam/import/drawing.hpp"
#include "bezcam/kernel/vec.hpp"

namespace bezcam::import {

/// A 2D affine map p -> (a p.x + c p.y + e, b p.x + d p.y + f) (SVG's
/// matrix(a b c d e f)); z is kept.
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  Vec3 apply(const Vec3& p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f, p.z}; }
  /// this after `o` (first o, then this).
  Affine after(const Affine& o) const;
  double det() const { return a * d - b * c; }
};

/// The arc of the ellipse p(t) = center + u cos t + v sin t from t0 over
/// `sweep` radians (signed; |sweep| <= 2 pi), as rational quadratic pieces
/// of at most 90 degrees each (exact: an affine image of circle pieces).
/// The first piece starts at p(t0), the last ends at p(t0 + sweep).
std::vector<Piece> ellipse_arc(const Vec3& center, const Vec3& u, const Vec3& v, double t0, double sweep);

/// An SVG elliptical arc command from `from` to `to` (SVG 1.1, appendix
/// F.6: endpoint to centre parameterisation, radii scaled up when too
/// small; zero radius: a straight line; equal ends: nothing). The first
/// piece starts exactly at `from`, the last ends exactly at `to`.
std::vector<Piece> svg_arc(const Vec3& from, double rx, double ry, double x_axis_rotation_deg, bool large_arc,
                           bool sweep, const Vec3& to);

/// A straight line as a degree-1 Bézier piece.
Piece line_piece(const Vec3& a, const Vec3& b);

}  // namespace bezcam::import
