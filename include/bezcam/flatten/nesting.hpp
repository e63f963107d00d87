#pragma once
/// Which closed curves lie inside which (the even-odd rule), decided on the
/// exact curves in XY: the material of a drawn part, its holes, the parts
/// in its holes (docs/import.md, "Sides of a part").
///
/// Method. A point p is inside a closed curve when a ray from p crosses it
/// an odd number of times. The curve is flattened with vertices on it and a
/// proven bound h (flatten_curve.hpp: every piece of curve between two
/// vertices lies within h of its chord); when p is farther than h from every
/// chord, each piece of curve and its chord bound a region inside the
/// h-neighbourhood of the chord, which does not hold p, so the polygon
/// crosses a ray from p as often (mod 2) as the curve does: the answer is
/// exact. Nearer than h, the curve is flattened again, 100 times finer, down
/// to 1e-9 of its size; a point still within the bound there is on the
/// curve. Curve A lies inside curve B when none of A's sample points (the
/// vertices of a flattening of A to 1e-3 of its size, and each piece's
/// middle) is outside B and at least one is inside: A may touch B or run
/// along it. A with points on both sides of B crosses it, and is inside
/// neither way. A curve wholly on another (a duplicate) is inside neither.
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "bezcam/kernel/bezier.hpp"

namespace bezcam {

struct Nesting {
  /// How many of the other curves each curve lies inside (0: outermost).
  /// Even: an outline of material; odd: a hole in it.
  std::vector<int> depth;
  /// The innermost curve around each, if any.
  std::vector<std::optional<std::size_t>> parent;
  /// Pairs (a < b) of curves that cross each other.
  std::vector<std::pair<std::size_t, std::size_t>> crossing;
};

/// The nesting of closed curves, each given as its pieces end to end (z is
/// ignored). Throws what flattening throws (a curve needing more than a
/// million vertices at the finest level).
Nesting nest_closed_curves(std::span<const std::vector<Bezier>> curves);

}  // namespace bezcam
