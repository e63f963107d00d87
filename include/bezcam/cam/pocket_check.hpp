#pragma once
/// The pocket certificate (docs/pocket.md): what a program's moves do to a
/// region, measured from the moves themselves, not from how they were made.
///
/// Method. The region's walls are closed polylines within `wall_bound` of
/// the drawn curves (even-odd: outline, islands, pockets in islands). The
/// set a tool of radius r can reach, R, is the region eroded by
/// r + stock_to_leave and grown back by r (polygon offsets, arcs within
/// 1e-4 of the tolerance). A square grid of pitch `cell` samples the
/// region; a sample of R counts as cut at a depth level when it lies
/// within r + tolerance of a horizontal move at that level (exact distance
/// to the segment). Every sample of R not cut stands for a cell of area
/// cell^2 uncut: the check misses only pieces of material that hold no
/// sample (narrower than `cell` across). The tool centre's nearest
/// approach to a wall is the exact distance from every move below the
/// stock's top to every wall segment. Engagement is read at every `cell`
/// along the moves of each level: the share of the front half of the
/// tool's circle that lies on samples still holding material (the region
/// less what the moves before removed); a full slot reads 180 degrees.
/// The moves that descend into a level (a helix, a ramp) remove material
/// of that level before the moves at it; the material the tool cannot
/// reach, and with `load` the reachable material within that of it, is
/// not counted.
#include <cstddef>
#include <string>
#include <vector>

#include "bezcam/cam/move.hpp"
#include "bezcam/kernel/vec.hpp"

namespace bezcam {

/// Closed loops in XY (even-odd), each vertex once (the last joins the
/// first).
using PocketLoops = std::vector<std::vector<Vec3>>;

/// The loops of `loops` eroded by d (d > 0: away from every wall, into the
/// region; d < 0: grown), within 2 `sag` of the true offset: the loops
/// simplified within `sag`, round corners drawn as chords within `sag` of
/// their arcs. Empty: nothing left.
PocketLoops offset_region(const PocketLoops& loops, double d, double sag);
/// The area the loops enclose (even-odd).
double region_area(const PocketLoops& loops);

struct PocketCheckInput {
  PocketLoops walls;
  double wall_bound = 0;  ///< the walls lie within this of the drawn curves
  double radius = 0;      ///< the tool's
  double stock = 0;       ///< stock_to_leave on the walls
  double tolerance = 0;
  double top_z = 0;            ///< the stock's top: rapids stay at or above it
  std::vector<double> levels;  ///< the depth levels, as printed
  const std::vector<Move>* moves = nullptr;
  size_t from = 0, to = 0;  ///< the region's moves [from, to)
  Vec3 start;               ///< where the tool stands before moves[from]
  double cell = 0;          ///< 0: the tolerance, coarser to stay within `max_cells`
  size_t max_cells = 2'000'000;
  bool engagement = true;  ///< measure the engagement (the slowest part)
  /// Rest machining: what a larger tool cleared before (closed loops,
  /// even-odd). It holds no material, and the coverage is measured on the
  /// reachable set less it.
  PocketLoops cleared_before;
  /// Adaptive: the radial depth of cut. The engagement does not count the
  /// reachable material within `load` of the unreachable places (the last
  /// sliver of a sharp corner), and is held to arccos(1 - load / r) + 2 deg.
  double load = 0;
  /// Field by field, `moves` as a pointer.
  bool operator==(const PocketCheckInput&) const = default;
};

/// Material the tool cannot reach (a neck narrower than the tool, a corner
/// sharper than it): one connected piece.
struct PocketPlace {
  Vec3 at;  ///< a point of it
  double area = 0;
};

/// A place where the engagement passes the bound, and the largest there.
struct PocketEngagementPlace {
  Vec3 at;
  double deg = 0;
};

struct PocketCertificate {
  double cell = 0;                       ///< the grid's pitch
  double region_area = 0;                ///< inside the walls
  double reachable_area = 0;             ///< R (less `cleared_before`): its samples x cell^2
  bool rest = false;                     ///< coverage measured against R less `cleared_before`
  double unreachable_area = 0;           ///< the region less R less the stock left on the walls
  std::vector<PocketPlace> unreachable;  ///< largest first
  double perimeter = 0;                  ///< of the walls
  double uncut_area = 0;                 ///< the largest over the levels
  double uncut_limit = 0;                ///< tolerance x perimeter
  Vec3 uncut_at;                         ///< a sample of it (when uncut_area > 0)
  double uncut_z = 0;                    ///< its level
  /// The tool centre's nearest approach to a wall (polyline), less
  /// `wall_bound`: the smallest distance to the drawn walls; at least
  /// r + stock - tolerance when the walls are kept.
  double wall_distance = 0;
  Vec3 wall_at;
  double engagement_deg = 0;  ///< the largest engagement angle
  Vec3 engagement_at;
  /// The largest engagement where the tool's edge stays farther than
  /// `load` from every unreachable place, and where.
  double engagement_away_deg = 0;
  Vec3 engagement_away_at;
  /// Adaptive: the places where the tool's edge comes within `load` of an
  /// unreachable place (a corner sharper than the tool) and the engagement
  /// passes the bound, largest first.
  std::vector<PocketEngagementPlace> engagement_corners;
  double engagement_bound = 0;    ///< adaptive: arccos(1 - load / r) + 2 degrees (0: none promised)
  size_t rapids_in_material = 0;  ///< G00 moves below the stock's top other than straight up
  Vec3 rapid_at;
  double seconds = 0;  ///< the time the check took

  bool covered() const { return uncut_area <= uncut_limit; }
  bool engagement_kept() const { return engagement_bound == 0 || engagement_deg <= engagement_bound; }
  bool walls_kept(double radius, double stock, double tolerance) const {
    return wall_distance >= radius + stock - tolerance;
  }
};

PocketCertificate check_pocket(const PocketCheckInput& in);

/// The certificate as lines for the program's header and the report:
/// uncut area and its limit, unreachable area and the nearest approach to
/// a wall, largest engagement and rapids through material.
std::vector<std::string> certificate_lines(const std::string& label, const PocketCertificate& c, double radius,
                                           double stock, const std::string& units);

}  // namespace bezcam
