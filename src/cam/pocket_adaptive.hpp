#pragma once
// Internal to cam: the adaptive passes' state (pocket_adaptive.cpp grows
// the cleared area ring by ring, pocket_adaptive_pass.cpp turns rings into
// passes and links).
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "pocket_contour.hpp"
#include "pocket_grid.hpp"
#include "pocket_plan.hpp"

namespace bezcam::detail {

inline constexpr int kAdaptiveCircle = 144;  // samples round the tool's circle (2.5 degrees)
/// Helices of its own at most, per piece, for material the rings could
/// not reach from where they grew (Adaptive::run()).
inline constexpr int kAdaptiveReseeds = 16;

class Adaptive {
  static Vec3 mix(const Vec3& a, const Vec3& b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, 0}; }

 public:
  Adaptive(const Area& region, const Area& centres, const Area& before, const PocketPlanInput& in, double d_wall)
      : in_(in),
        centres_(centres),
        g_(in.walls, std::max(in.tolerance, in.radius / 50), 1'000'000),
        r_(in.radius),
        load_(in.load),
        d_wall_(d_wall),
        delta_(g_.cell),
        walls_(in.walls, d_wall + 4 * g_.cell) {
    alpha_ = std::acos(std::clamp(1 - load_ / r_, -1.0, 1.0)) * 180 / std::numbers::pi;
    target_ = alpha_ - 1.5;
    for (int k = 0; k < kAdaptiveCircle; ++k) {
      const double a = 2 * std::numbers::pi * k / kAdaptiveCircle;
      cs_[k] = std::cos(a), sn_[k] = std::sin(a);
    }
    for (int k = 0; k < 180; ++k) {
      const double th = (-90 + k + 0.5) * std::numbers::pi / 180;
      hc_[k] = std::cos(th), hs_[k] = std::sin(th);
    }
    const double sag = in.tolerance / 20;
    mat_ = g_.fill_within(region.eroded(r_ + in.stock, sag).loops(), r_);
    before_.assign(g_.size(), 0);
    if (!before.empty()) {
      before_ = g_.fill(before.loops());
      for (size_t k = 0; k < g_.size(); ++k) mat_[k] = mat_[k] && !before_[k];
    }
    const std::vector<uint8_t> in_region = g_.fill(in.walls);
    fwall_.assign(g_.size(), 1.0f);
    wdist_.assign(g_.size(), -1.0f);
    std::vector<uint8_t> lost(g_.size(), 0);
    for (size_t k = 0; k < g_.size(); ++k) {
      if (!in_region[k]) continue;
      const double d = walls_.dist(g_.sample(k));
      fwall_[k] = static_cast<float>(d_wall_ + delta_ - d);
      wdist_[k] = static_cast<float>(d);
      lost[k] = !mat_[k] && d > in.stock + in.tolerance / 2;
    }
    strip_.assign(g_.size(), 0);
    for (size_t k = 0; k < g_.size(); ++k)
      strip_[k] = in_region[k] && d_wall_ + delta_ - fwall_[k] < d_wall_ - r_ + delta_ + 1.5 * g_.cell;
    // The corners' last sliver (within load of what no tool position
    // reaches) wraps the tool whatever the path: the rings do not steer by
    // it, the ring along the walls takes it.
    const std::vector<uint8_t> near_lost = g_.dilated(lost, load_);
    for (size_t k = 0; k < g_.size(); ++k) mat_[k] = mat_[k] && !near_lost[k];
    // The circle about a sample meets the grid at fixed offsets from it.
    for (int k = 0; k < kAdaptiveCircle; ++k) {
      const long di = static_cast<long>(std::floor(0.5 + r_ * cs_[k] / g_.cell)),
                 dj = static_cast<long>(std::floor(0.5 + r_ * sn_[k] / g_.cell));
      ring_off_[k] = {di, dj};
      ring_lin_[k] = dj * g_.nx + di;
      ring_reach_ = std::max({ring_reach_, std::abs(di), std::abs(dj)});
    }
    count_.assign(g_.size(), -1);
  }

  std::vector<PocketPass> run();

 private:
  // The grid square holding (x, y); false outside the grid.
  bool square_of(double x, double y, size_t& k) const {
    const double u = (x - g_.x0) * inv_cell_, v = (y - g_.y0) * inv_cell_;
    if (!(u >= 0 && v >= 0 && u < static_cast<double>(g_.nx) && v < static_cast<double>(g_.ny))) return false;
    k = static_cast<size_t>(static_cast<long>(v) * g_.nx + static_cast<long>(u));  // floor: u, v >= 0
    return true;
  }
  bool held(double x, double y) const {
    size_t k = 0;
    return square_of(x, y, k) && mat_[k];
  }
  // Material samples on the circle of radius rad about p; stops above `limit`.
  int on_circle(const Vec3& p, double rad, int limit = kAdaptiveCircle) const {
    int n = 0;
    for (int k = 0; k < kAdaptiveCircle && n <= limit; ++k) n += held(p.x + rad * cs_[k], p.y + rad * sn_[k]);
    return n;
  }
  // on_circle(g_.sample(k), r_), kept up to date as material is cut.
  int circle_count(size_t k) const {
    if (count_[k] >= 0) return count_[k];
    const long i = static_cast<long>(k) % g_.nx, j = static_cast<long>(k) / g_.nx;
    int n = 0;
    if (i >= ring_reach_ && j >= ring_reach_ && i + ring_reach_ < g_.nx && j + ring_reach_ < g_.ny) {
      for (const long o : ring_lin_) n += mat_[static_cast<size_t>(static_cast<long>(k) + o)];
      count_[k] = static_cast<int16_t>(n);
      return n;
    }
    for (const auto& [di, dj] : ring_off_)
      if (i + di >= 0 && j + dj >= 0 && i + di < g_.nx && j + dj < g_.ny)
        n += mat_[static_cast<size_t>((j + dj) * g_.nx + i + di)];
    count_[k] = static_cast<int16_t>(n);
    return n;
  }
  // No material under the tool at p, but for what lies within a cell and a
  // half of its edge (the grid's own blur there).
  bool clear(const Vec3& p) const {
    const double rad = r_ - 1.5 * g_.cell;
    return !held(p.x, p.y) && on_circle(p, rad, 0) == 0 && on_circle(p, rad * 2 / 3, 0) == 0 &&
           on_circle(p, rad / 3, 0) == 0;
  }
  // The engagement (degrees) moving along dir at p: the front half's share in material.
  double front(const Vec3& p, const Vec3& dir) const {
    const double l = std::hypot(dir.x, dir.y);
    if (!(l > 0)) return 0;
    const double ux = dir.x / l, uy = dir.y / l;
    int n = 0;
    for (int k = 0; k < 180; ++k) {
      const double c = hc_[k], s = hs_[k];
      n += held(p.x + r_ * (ux * c - uy * s), p.y + r_ * (ux * s + uy * c));
    }
    return n;
  }
  // No material within a cell beyond the tool at p: a link or an entry
  // there touches none.
  // (The strip along the walls that only the last ring reaches is no
  // material for this: no tool position inside that ring comes within r.)
  bool free(const Vec3& p) const {
    if (!clear(p) || on_circle(p, r_, 0) > 0) return false;
    for (int k = 0; k < kAdaptiveCircle; ++k) {
      size_t c = 0;
      if (square_of(p.x + (r_ + g_.cell) * cs_[k], p.y + (r_ + g_.cell) * sn_[k], c) && mat_[c] && !strip_[c])
        return false;
    }
    return true;
  }
  // At least d_wall from the walls: read from the sample's distance where
  // that decides it (the distance changes by at most the way to the sample).
  bool inside(const Vec3& p) const {
    size_t k = 0;
    if (square_of(p.x, p.y, k) && wdist_[k] >= d_wall_ + 0.75 * g_.cell + 1e-4) return true;
    return walls_.dist(p) >= d_wall_;
  }
  bool segment_clear(const Vec3& a, const Vec3& b) const {
    const int n = std::max(1, static_cast<int>(std::ceil(dist_xy(a, b) / g_.cell)));
    for (int k = 0; k <= n; ++k) {
      const Vec3 p = mix(a, b, static_cast<double>(k) / n);
      if (!free(p) || !inside(p)) return false;
    }
    return true;
  }
  void stamp(const std::vector<Vec3>& pts) {
    for (size_t k = 0; k + 1 < pts.size(); ++k) cut(pts[k], pts[k + 1]);
    if (pts.size() == 1) cut(pts[0], pts[0]);
  }
  void cut(const Vec3& a, const Vec3& b);
  double worst(const std::vector<Vec3>& pts, size_t from, size_t to) const {
    double w = 0;
    // Both ways the tool leaves and reaches each point (the check reads
    // along each straight piece), and half way along the piece after it.
    for (size_t i = from; i < to && i < pts.size(); ++i) {
      if (i > 0) w = std::max(w, front(pts[i], pts[i] - pts[i - 1]));
      if (i + 1 < pts.size()) {
        w = std::max(w, front(pts[i], pts[i + 1] - pts[i]));
        w = std::max(w, front(mix(pts[i], pts[i + 1], 0.5), pts[i + 1] - pts[i]));
      }
    }
    return w;
  }

  struct Band {
    std::vector<size_t> frontier, cells;
    std::vector<int> count;
    std::vector<size_t> seeds;  // the squares the ring is looked for from
    std::vector<size_t> edge;   // those the settled samples' edge crosses
  };
  Band band(const std::vector<uint8_t>& settled, const std::vector<int>& comp, int cur,
            const std::vector<size_t>& near) const;
  // Calls f with each of the (up to) 8 neighbours of sample k.
  template <class F>
  void around(size_t k, const F& f) const {
    const long i = static_cast<long>(k) % g_.nx, j = static_cast<long>(k) / g_.nx;
    const size_t nx = static_cast<size_t>(g_.nx);
    if (i > 0 && j > 0 && i + 1 < g_.nx && j + 1 < g_.ny) {
      f(k - nx - 1), f(k - nx), f(k - nx + 1), f(k - 1), f(k + 1), f(k + nx - 1), f(k + nx), f(k + nx + 1);
      return;
    }
    for (long dj = -1; dj <= 1; ++dj)
      for (long di = -1; di <= 1; ++di)
        if ((di || dj) && i + di >= 0 && j + dj >= 0 && i + di < g_.nx && j + dj < g_.ny)
          f(static_cast<size_t>((j + dj) * g_.nx + i + di));
  }
  template <class Ok>
  void spread(const std::vector<size_t>& from, long steps, const Ok& ok, std::vector<size_t>& out) const;
  struct Chain {
    std::vector<Vec3> pts;
    bool closed = true;
  };
  std::vector<Chain> ring(const Band& b, double lambda, std::vector<size_t>& grown) const;
  void smooth(std::vector<Vec3>& loop, bool closed) const;
  bool seed(const std::vector<int>& comp, int cur, const std::vector<double>& depth);
  void grow(const std::vector<int>& comp, int cur, std::vector<uint8_t>& settled);
  void flush_pending();
  bool take(std::vector<Vec3> loop, bool closed = true);
  void whole(std::vector<Vec3> loop);
  void closed_loop(const std::vector<Vec3>& loop);
  bool spiral(const std::vector<Vec3>& loop);
  std::optional<std::vector<Vec3>> spiral_turn(const std::vector<Vec3>& loop) const;
  double ring_worst(const std::vector<Chain>& chains, double stop) const;
  void finish(PocketPass p);
  void push(PocketPass p) {
    turn_.clear();
    stamp(p.pts);
    cur_ = p.pts.back();
    dir_ = p.pts.size() > 1 ? p.pts.back() - p.pts[p.pts.size() - 2] : Vec3{};
    have_cur_ = true;
    out_.push_back(std::move(p));
  }

  const PocketPlanInput& in_;
  const Area& centres_;
  PocketGrid g_;
  double r_, load_, d_wall_, delta_, alpha_ = 0, target_ = 0;
  double inv_cell_ = 1 / g_.cell;  // square_of multiplies by it
  WallField walls_;
  double cs_[kAdaptiveCircle], sn_[kAdaptiveCircle];
  double hc_[180], hs_[180];  // the front half, a degree apart
  std::vector<uint8_t> mat_;
  std::vector<float> fwall_;
  std::vector<float> wdist_;                         // distance to the walls (capped) of samples inside them, else -1
  std::pair<long, long> ring_off_[kAdaptiveCircle];  // the circle's samples about a sample, in cells
  long ring_lin_[kAdaptiveCircle];                   // the same as index offsets
  long ring_reach_ = 0;                              // their largest coordinate
  mutable std::vector<int16_t> count_;               // circle_count per sample, -1 until read
  std::vector<PocketPass> out_;
  Vec3 cur_, dir_;
  bool have_cur_ = false;
  std::optional<PocketPass> pending_;  // the helix, before the first ring
  std::vector<Vec3> turn_;             // the last closed turn cut, ending where the tool is
  mutable std::vector<int> seen_;      // scratch, all -1 between uses
  mutable std::vector<float> f_;
  mutable ContourScratch contour_;
  // The function the rings are contours of, off the band: negative on the
  // settled samples of the piece worked on (the walls' limit there), else 1.
  mutable std::vector<float> level_;
  float settled_level(size_t k) const { return std::max(-1.0f, fwall_[k] / static_cast<float>(r_)); }
  mutable std::vector<uint8_t> mark_;    // scratch, all 0 between uses
  mutable std::vector<uint8_t> has_;     // scratch, all 0 between uses
  mutable std::vector<uint8_t> active_;  // the front this round works on
  std::vector<uint8_t> stuck_;           // band samples of fronts that no ring reached
  std::vector<uint8_t> before_;          // cleared by the tool before (rest machining)
  std::vector<uint8_t> strip_;           // along the walls, beyond every ring but the last
  // Whether a point of a ring lies on the front this round works on.
  bool on_front(const Vec3& p) const {
    const long i = static_cast<long>(std::floor((p.x - g_.x0) / g_.cell - 0.5)),
               j = static_cast<long>(std::floor((p.y - g_.y0) / g_.cell - 0.5));
    for (long dj = 0; dj <= 1; ++dj)
      for (long di = 0; di <= 1; ++di)
        if (i + di >= 0 && j + dj >= 0 && i + di < g_.nx && j + dj < g_.ny &&
            active_[static_cast<size_t>((j + dj) * g_.nx + i + di)])
          return true;
    return false;
  }
};

}  // namespace bezcam::detail
