#pragma once
// The distance of each stock column to a design's wall (a polyline in the
// xy plane), with the side of the wall it lies on, over the columns within
// a band of the wall; and the reach of a round tool into a region (a
// Euclidean distance transform). Used by the design check.
#include <cstddef>
#include <vector>

#include "bezcam/kernel/vec.hpp"
#include "bezcam/stock/dexel_grid.hpp"

namespace bezcam::verify_detail {

struct Wall {
  std::vector<Vec3> points;  ///< xy in mm (z ignored); closed: the first point is not repeated at the end
  bool closed = false;
  /// Closed walls only: more closed rings (a pocket's islands and the
  /// pockets in them); inside and outside count by the even-odd rule over
  /// all the rings.
  std::vector<std::vector<Vec3>> islands;
  /// Closed: the waste is inside. Open: the waste is left of the drawn
  /// direction.
  bool waste_inside_or_left = false;
};

/// Columns i0 <= i < i0 + ni, j0 <= j < j0 + nj of the grid.
struct Region {
  std::size_t i0 = 0, j0 = 0, ni = 0, nj = 0;
  std::size_t size() const { return ni * nj; }
  bool contains(std::size_t i, std::size_t j) const { return i >= i0 && i < i0 + ni && j >= j0 && j < j0 + nj; }
};

struct WallField {
  Region region;
  /// Per column of the region, row by row: the distance to the wall (mm;
  /// infinity beyond the band) and the side: +1 waste, -1 part, 0 neither
  /// (beyond an open wall's ends).
  std::vector<double> distance;
  std::vector<signed char> side;
  /// Closed walls: the side of a column outside the region (+1 when the
  /// waste is outside).
  signed char outside_side = 0;
};

/// The field of `w` over the columns within `band` (mm) of it.
WallField wall_field(const DexelGrid& g, const Wall& w, double band);

/// For each column of region `r` (row by row), the distance (mm) to the
/// nearest marked column of `centres`: how near to it a tool's axis may
/// come when it may stand on the marked columns (infinity when none is
/// marked). Exact between column centres (a squared Euclidean distance
/// transform).
std::vector<double> reach(const Region& r, const std::vector<char>& centres, double cell);

}  // namespace bezcam::verify_detail
