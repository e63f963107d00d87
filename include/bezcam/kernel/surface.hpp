#pragma once
/// A surface entity as the rest of bezcam sees it: the exact grid of Bézier
/// patches (a Bézier patch is one cell, a Coons patch one cell per pair of
/// boundary spans), whatever the source form was, with the normal oriented
/// up out of the material, and the exact curves on it that tool paths
/// follow (iso-parameter passes, borders, curves given in (u, v)).
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "bezcam/kernel/bezier_patch.hpp"
#include "bezcam/kernel/coons_patch.hpp"
#include "bezcam/kernel/curve.hpp"

namespace bezcam {

struct SurfaceGeometry {
  std::string kind;                              ///< "bezier_patch" or "coons_patch"
  std::variant<BezierPatch, CoonsPatch> source;  ///< as given
  PatchGrid grid;                                ///< exact cells
  /// +1 or -1: the factor that makes Su x Sv point up out of the material
  /// (positive z over most of the patch, measured on a 17 x 17 grid).
  double orientation = 1;

  /// Builds the grid and the orientation.
  static std::shared_ptr<const SurfaceGeometry> make(BezierPatch p);
  static std::shared_ptr<const SurfaceGeometry> make(CoonsPatch p);

  /// Highest cell degree in u and in v.
  int degree_u() const;
  int degree_v() const;
  bool rational() const;
};

/// Point and partials at global (u, v) (Coons: from the exact cells).
PatchDerivs evaluate_derivs(const SurfaceGeometry& s, double u, double v);
Vec3 evaluate(const SurfaceGeometry& s, double u, double v);
/// Oriented unit normal N (up out of the material); zero where Su x Sv = 0.
Vec3 unit_normal(const SurfaceGeometry& s, double u, double v);

/// Principal curvatures with the sign convention of the oriented normal:
/// positive where the surface bends toward N (concave seen from the tool,
/// a valley), negative where it bends away (convex, a crest).
struct Curvatures {
  double k_max = 0, k_min = 0;
  bool defined = false;  ///< false where the normal is undefined
};
Curvatures principal_curvatures(const SurfaceGeometry& s, double u, double v);

/// Bounds of the surface (tight: by subdivision of every cell).
Box3 bounds(const SurfaceGeometry& s);

/// An exact curve on the surface: Bézier pieces end to end over a partition
/// of its parameter interval [0,1], and (when asked for) per piece the exact
/// polynomial direction of the oriented normal along it (not unit).
struct SurfaceCurve {
  std::vector<Bezier> points;
  std::vector<Bezier> normals;  ///< empty, or one per piece
  std::vector<double> breaks;   ///< points.size() + 1 values, 0 ... 1
  /// (u, v) of the curve's parameter t, for reports and gouge checks.
  std::vector<Bezier> uv;  ///< one 2D piece per piece: its (u, v) track
};

/// The iso-parameter curve: dir 'u' is u -> S(u, at), dir 'v' is
/// v -> S(at, v); the curve's parameter is the varying surface parameter.
SurfaceCurve iso_curve(const SurfaceGeometry& s, char dir, double at, bool with_normals);

/// The curve w -> S(c(w)) of a 2D curve c in the parameter square, exactly
/// (Bézier composition, split where c crosses cell borders). Precondition:
/// c's Bézier control points lie in [0,1]^2 (checked when the job is read).
/// Piece k of c covers [k, k+1] / pieces of the result's parameter.
SurfaceCurve map_curve(const SurfaceGeometry& s, const CurveGeometry& uv, bool with_normals);

/// The piece and local parameter of global t.
std::pair<size_t, double> locate(const SurfaceCurve& c, double t);
/// (u, v) at global t.
std::pair<double, double> uv_at(const SurfaceCurve& c, double t);
/// The curve restricted to [t0, t1] (t0 < t1), reparametrised on [0,1].
SurfaceCurve restrict(const SurfaceCurve& c, double t0, double t1);
/// The same curve run backwards.
SurfaceCurve reversed(const SurfaceCurve& c);

}  // namespace bezcam
