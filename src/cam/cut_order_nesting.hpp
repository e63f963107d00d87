#pragma once
// Internal to cam: the nesting half of the cut-order planner
// (cut_order_nesting.cpp), and the small geometry both halves use.
#include <algorithm>
#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "bezcam/cam/cut_order.hpp"

namespace bezcam::cut_order_detail {

inline double dxy(const Vec3& a, const Vec3& b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return std::sqrt(dx * dx + dy * dy);
}

struct Box2 {
  double lx = HUGE_VAL, ly = HUGE_VAL, hx = -HUGE_VAL, hy = -HUGE_VAL;
  void add(const Vec3& p) {
    lx = std::min(lx, p.x);
    ly = std::min(ly, p.y);
    hx = std::max(hx, p.x);
    hy = std::max(hy, p.y);
  }
  bool contains(const Box2& in, double eps) const {
    return in.lx >= lx - eps && in.ly >= ly - eps && in.hx <= hx + eps && in.hy <= hy + eps;
  }
  /// Distance from p to the box (0 inside).
  double gap(const Vec3& p) const {
    const double dx = std::max({lx - p.x, 0.0, p.x - hx});
    const double dy = std::max({ly - p.y, 0.0, p.y - hy});
    return std::sqrt(dx * dx + dy * dy);
  }
  double gap(const Box2& o) const {
    const double dx = std::max({lx - o.hx, 0.0, o.lx - hx});
    const double dy = std::max({ly - o.hy, 0.0, o.ly - hy});
    return std::sqrt(dx * dx + dy * dy);
  }
  Vec3 center() const { return {(lx + hx) / 2, (ly + hy) / 2}; }
};

/// Start candidates of a contour: the distinct vertices of a closed one
/// (the repeated last vertex left out), all vertices of an open one.
size_t vertex_count(const OrderContour& c);

/// The touch tolerance: the options', else 1e-9 of the largest coordinate.
double tolerance_of(std::span<const OrderContour> cs, const CutOrderOptions& o);

/// Refuses contours the planner cannot take (std::invalid_argument).
void check_input(std::span<const OrderContour> cs);

/// The pairs (inner, outer) of contours where the inner lies in the outer.
std::vector<std::pair<size_t, size_t>> nesting_of(std::span<const OrderContour> cs, double tol);

}  // namespace bezcam::cut_order_detail
