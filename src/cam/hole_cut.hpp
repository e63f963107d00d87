#pragma once
// Internal to the post layer: holes (docs/holes.md). A `point` entity or a
// closed curve that is a circle within the tolerance, drilled in a canned
// cycle (hole_cut.cpp) or bored with an end mill by a helix and a full
// circle at the bottom (hole_bore.cpp).
#include <optional>
#include <span>

#include "cut_emitters.hpp"

namespace bezcam::detail {

/// Where a hole is and how large.
struct HoleShape {
  Vec3 centre;                     ///< z 0
  std::optional<double> diameter;  ///< a circle's; none for a point
  /// A circle: proven bound of the distance between the curve and the
  /// circle of `diameter` about `centre` (0 for a point).
  double bound = 0;
};

/// The circle a closed 2D curve is within `tolerance`, proven: its pieces
/// lie within `bound` (<= tolerance) of the circle about the centre found.
/// Nothing when the curve is open, 3D, or strays further.
std::optional<HoleShape> fit_circle(std::span<const Bezier> pieces, bool closed, double tolerance);

/// The centre of the hole an entity makes, for ordering: its point, or
/// the centre of the circle its closed curve is nearest to (least
/// squares, unproven). Nothing for an entity that is not drilled or bored.
std::optional<Vec3> hole_centre(const Entity& e, const CutParams& cp);

/// Whether `next` is drilled right after `e` with the same tool, spindle,
/// coolant and R plane and nothing printed between them: the drill then
/// stays at the R plane (G99) between the two holes.
bool holes_join(const Job& job, const MachineProfile& m, const Entity& e, const Entity* next, int decimals);

/// Cuts an entity with `operation: "drill"` or `"bore"` (false for any
/// other): after the tool change, a drilling cycle (canned on profiles
/// that have them, the same motion as G00/G01 moves on others) or a bore;
/// `prev_joins` / `next_joins` from holes_join(). Ends at safe Z, or at
/// the R plane when the next hole joins. `arcs`: a bore's helix as G02/G03
/// arcs, else as lines within the tolerance.
bool cut_hole(CutContext& c, MotionState& ms, double safe, bool prev_joins, bool next_joins, bool arcs);

/// The bore (hole_bore.cpp): the tool centre down a helix inside the
/// circle `h`, a full circle at the bottom, back to the centre and up to
/// safe Z; in G02/G03 arcs (`arcs`) or lines within the tolerance. Fills
/// `r`.
void emit_bore(CutContext& c, MotionState& ms, EntityReport& r, const HoleShape& h, double safe, double clear,
               bool arcs);

}  // namespace bezcam::detail
