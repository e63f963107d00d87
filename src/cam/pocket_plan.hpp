#pragma once
// Internal to cam: the tool centre's passes that clear a pocket, in XY
// (pocket_plan.cpp), before any depth or entry (pocket_emit.cpp).
#include <optional>
#include <string>
#include <vector>

#include "bezcam/cam/pocket_check.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/job/job.hpp"
#include "pocket_area.hpp"

namespace bezcam::detail {

struct PocketPlanInput {
  PocketLoops walls;      ///< closed polylines (even-odd)
  double wall_bound = 0;  ///< the walls lie within this of the drawn curves
  double radius = 0, stock = 0, finish = 0;
  double stepover = 0;
  PocketPattern pattern = PocketPattern::offset;
  double angle_deg = 0;  ///< zigzag
  bool climb = true;
  double tolerance = 0;
  /// Added to every offset from the walls: the flattening, the offset's
  /// chords and rounding, so that no pass comes nearer than r + stock.
  double margin = 0;
  std::optional<double> rest_from;  ///< the radius of the tool before
  double load = 0;                  ///< adaptive: the radial depth of cut
  double cell = 0;                  ///< the grid the search for material left reads
  double helix_radius = 0;          ///< the entry's helix (0: no helix): rings start where one fits
  /// The passes will be drawn within this of their polylines (arcs output):
  /// the search for material left reads them that much shorter.
  double fit = 0;
  /// The offsets' chord and simplification error (0: tolerance / 20).
  double sag = 0;
  bool operator==(const PocketPlanInput&) const = default;
};

/// One pass: a polyline in XY in the order of travel (a ring repeats its
/// first point at the end).
struct PocketPass {
  std::vector<Vec3> pts;
  /// Reached from the previous pass's end by a straight feed at depth
  /// (inside the centres' area, through cleared material).
  bool linked = false;
  /// Not linked, but its start is in material this level already cleared:
  /// the tool feeds straight down there.
  bool in_cleared = false;
  /// Adaptive: the entry's helix about this centre, of radius `helix_r`
  /// (its first point on the circle), which the passes count as cleared.
  std::optional<Vec3> helix;
  double helix_r = 0;
};

struct PocketPlan {
  std::vector<PocketPass> passes;
  Area centres;        ///< where the tool centre may go: the region eroded by r + stock (+ margin)
  size_t cleanup = 0;  ///< the extra moves added where rings left material
  Area before;         ///< rest_from: what the tool before cleared (its reachable set)
};

/// The adaptive passes (pocket_adaptive.cpp): rings along the edge of the
/// cleared area where the tool's arc in material keeps to the load,
/// entered from a helix in each piece of `centres`, then the walls.
std::vector<PocketPass> adaptive_passes(const Area& region, const Area& centres, const Area& before,
                                        const PocketPlanInput& in, double d_wall);

/// The centre of a helix of radius R or less (R, 3/4, 1/2, 1/4 of it; the
/// one used in `used`) whose circle, enlarged by `grow`, lies in `centres`
/// and passes near p (a short straight line in `centres` joins them).
std::optional<Vec3> helix_centre(const Area& centres, const Vec3& p, double R, double grow, double& used);

/// The polyline (XY, its vertices printed as they are) as arcs and lines,
/// greedily the longest, each within `tol` of the polyline both ways after
/// the rounding of its centre words to `decimals` (its `bound`, proven in
/// closed form: pocket_arcs.cpp), with |r_start - r_end| <= radius_tol.
/// The blocks end at vertices of the polyline.
std::vector<FitMove> polyline_arcs(const std::vector<Vec3>& polyline, double tol, int decimals, double radius_tol);

/// The passes; InputError-free: the caller refuses an empty `centres`.
PocketPlan plan_pocket(const PocketPlanInput& in);

}  // namespace bezcam::detail
