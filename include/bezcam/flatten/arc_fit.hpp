#pragma once
/// Circular-arc fitting with a proven bound after rounding: Bézier pieces
/// become G02/G03 arcs in the XY plane (and G01 lines where no arc fits),
/// such that the path a controller draws *from the printed numbers* stays
/// within the tolerance of the true curve, both ways.
///
/// Method (bezcam's own; the proof is in arc_fit.cpp):
///  * Greedy spans, each as long as possible: from the current point the
///    longest chord the flattener's bound allows is found first, then the
///    longest span a single arc fits; the longer wins (a line on ties). This
///    is "better than biarc": one block per span instead of two, with the
///    centre chosen minimax on the perpendicular bisector of the span's ends.
///  * The printed arc: start S' (the current printed point), end E' (the
///    rounded curve point), centre c' = S' + rounded (I, J). Up to nine
///    neighbouring grid centres are tried so that the radius mismatch
///    |r_start - r_end| stays within the controller's arc tolerance
///    (LinuxCNC and Grbl reject larger ones).
///  * The controller's path is modelled as the spiral around c' from S' to
///    E' whose radius moves linearly from r_start to r_end with the angle
///    (LinuxCNC's circle with a radius mismatch; a plain circle when the
///    radii agree). Its two-sided distance to the true span is bounded by
///    branch and bound over convex hulls of sub-curves (radial distance in
///    the arc's sector, distance to the ends outside it), plus the
///    rounding of the ends; every emitted arc carries that bound.
///  * Only pieces that lie in a plane z = const are fitted with arcs; a
///    piece whose z varies gets G01 lines (flatten_curve.hpp's bound).
///  * With the band (ArcFitOptions::band) those lines' inner ends lie off
///    the curve, as the flattener's band vertices do (band_deviation()).
#include <functional>
#include <span>
#include <vector>

#include "bezcam/kernel/arc.hpp"
#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/units.hpp"

namespace bezcam {

struct ArcFitOptions {
  /// Largest allowed distance between the curve and the drawn path (model units).
  double tolerance = kDefaultToleranceMm;
  /// Decimals the end points and I/J words are printed with; -1: no rounding.
  int decimals = -1;
  /// Largest |r_start - r_end| of a printed arc the controller accepts
  /// (model units; the profile's arc_tolerance_mm converted).
  double radius_tolerance = 0.002;
  /// Helical arcs: the pieces are in plane coordinates (a, b, h) of one of
  /// G17/G18/G19 (to_plane()), need not be planar, and every span may be an
  /// arc whose h runs linearly with the angle from the start's to the end's;
  /// the bound covers the in-plane and axial parts together. When false,
  /// only pieces in a plane z = const get arcs, whose z is constant.
  bool helical = false;
  /// The tolerance as a band on both sides of the curve (not with
  /// `helical`): on a piece that gets no arcs (not in a plane z = const)
  /// the G01 lines' inner ends lie off the curve, shifted towards its convex
  /// side as the flattener's band vertices are, so that those lines get
  /// about 1.4 times longer; the piece's ends stay exact (within rounding).
  /// Arcs and their ends stay on the curve (arc_fit.cpp says why). false:
  /// every span end lies on the curve (before rounding).
  bool band = false;
  /// Tangent-continuous chains (not with `helical`): after the first move
  /// of a chain, every arc leaves in the direction the move before ends
  /// in, its centre on the normal there, within the rounding of its centre
  /// words (about 10^-decimals / radius radians); a line is taken only
  /// where it leaves in that direction too (within its ends' rounding, at
  /// most 5e-4 rad), else arcs of any length are tried first. Each arc
  /// ends along the curve (its end direction within 2.5 x the budget over
  /// its chord of the curve's), so that the next can go on from it. A
  /// chain starts again at the curve's own corners, after a piece that
  /// gets no arcs, and where a free arc would reach four times as far
  /// (docs/motion.md). The bound is certified as for any arc. false: each
  /// arc's centre chosen freely (one fewer constraint: longer spans, but
  /// the moves meet at small angles).
  bool tangent = false;
  /// With `tangent`: the direction the move before the first piece ends in
  /// (in the plane; zero: none). The chain then starts already: the first
  /// arc leaves in this direction, as the arcs after it do.
  Vec3 start_direction{};
};

enum class FitKind { line, arc_cw, arc_ccw };

/// One emitted move, with everything as printed.
struct FitMove {
  FitKind kind = FitKind::line;
  Vec3 to;           ///< rounded end point (z rounded too; a 2D curve keeps z = 0)
  Vec3 center;       ///< arcs: S' + rounded (I, J), z = to.z (helical: the start's z)
  Vec3 ij;           ///< arcs: the printed I, J (x, y), relative to the move's start
  size_t piece = 0;  ///< piece and parameter of the curve point the move ends at
  double t = 0;
  double bound = 0;  ///< certified two-sided deviation of this move from its span
};

struct ArcFitResult {
  Vec3 start;  ///< rounded first point (where the tool must be)
  std::vector<FitMove> moves;
  double bound = 0;         ///< largest certified deviation
  Plane plane = Plane::xy;  ///< the arcs' plane (fit_helical_arcs(); G17 otherwise)
};

/// Callback core: emits the moves in order, starting from the rounded start
/// of the first piece. Returns the certified bound. Throws InputError when
/// `decimals` cannot honour the tolerance (as flatten_pieces does).
double fit_arcs(std::span<const Bezier> pieces, const ArcFitOptions& opt,
                const std::function<void(const FitMove&)>& emit);

/// Collecting wrapper around the callback core.
ArcFitResult fit_arcs(std::span<const Bezier> pieces, const ArcFitOptions& opt);

/// Whether the curve goes on from piece a into piece b without a corner
/// (their tangents in the plane within 1e-9 rad; a vanishing derivative
/// counts as one).
bool tangent_joint(const Bezier& a, const Bezier& b);

/// The unit direction in the plane a move printed from `from` ends in, or
/// leaves in (`at_start`): along a line, square to an arc's radius; zero
/// for a move of no length.
Vec3 move_tangent(const Vec3& from, const FitMove& m, bool at_start);

/// The plane for helical arcs along `pieces`: the one whose axis their
/// control points (a hull of the curve) spread least along, so that its
/// arcs climb least. Ties go to G17, then G18.
Plane least_climb_plane(std::span<const Bezier> pieces);

/// Helical arcs in the plane `pl` for pieces in world coordinates:
/// fit_arcs() with `helical` set, on the pieces mapped to the plane's
/// coordinates (to_plane()), its moves mapped back (from_plane()). start,
/// to and center are world points (the centre's coordinate along the
/// plane's axis: the move's start's); ij stays in the plane's (a, b): the
/// printed centre words (I J in G17, K I in G18, J K in G19). Throws as
/// fit_arcs() does.
ArcFitResult fit_helical_arcs(std::span<const Bezier> pieces, const ArcFitOptions& opt, Plane pl);

/// True when the piece lies in a plane z = const (all control points share
/// their z exactly; for rational and polynomial pieces alike that is the
/// condition). 2D pieces always do.
bool planar_xy(const Bezier& piece);

/// A printed G17 arc: what the controller knows (from, to, center = from +
/// I/J, direction). The fitted pieces are planar, so its point(s) keeps
/// z = from.z: the model the bound uses.
using PrintedArc = Arc;

/// Rigorous upper bound of the two-sided distance between the XY part of the
/// curve span (piece on [t0, t1], which must start at S = M(t0) and end at
/// E = M(t1)) and the drawn path of `arc`. Returns +infinity when the proof's
/// preconditions fail (sweep above pi - 0.02, bound not small against the
/// radius). With `budget` >= 0 the search stops once the comparison with it
/// is certain (a result <= budget is proven; a result above it means the
/// bound exceeds it). With `budget` < 0 the bound is refined until it is
/// within `resolution` (model units) or 0.1 % of the supremum it bounds.
double arc_span_deviation(const Bezier& piece, double t0, double t1, const PrintedArc& arc, double budget,
                          double resolution = 0);
/// The same in 3D for a helical arc (arc_fit.cpp's proof, helical part):
/// piece and arc in the coordinates of the arc's plane (a G17 arc whose z
/// may run linearly with the angle), the distance measured in 3D.
double helix_span_deviation(const Bezier& piece, double t0, double t1, const PrintedArc& arc, double budget,
                            double resolution = 0);

/// Dense points of the drawn path of a printed arc, consecutive chords within
/// `sagitta` of it (for independent measurement and drawing); includes both ends.
std::vector<Vec3> sample_arc(const PrintedArc& arc, double sagitta);

}  // namespace bezcam
