#pragma once
// Internal to cam: the exact distance to a pocket's walls, and the
// contours of a function sampled on the pocket grid (marching squares),
// for the adaptive passes (pocket_adaptive.hpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "pocket_grid.hpp"

namespace bezcam::detail {

// The exact distance from a point to the walls' segments, up to a cap,
// through buckets of segments.
class WallField {
 public:
  WallField(const PocketLoops& walls, double cap) : cap_(cap) {
    for (const auto& l : walls)
      for (size_t i = 0; i < l.size(); ++i) segs_.push_back({l[i], l[(i + 1) % l.size()]});
    x0_ = y0_ = 1e300;
    double x1 = -1e300, y1 = -1e300;
    for (const auto& [a, b] : segs_)
      for (const Vec3& p : {a, b})
        x0_ = std::min(x0_, p.x), y0_ = std::min(y0_, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
    b_ = std::max(cap, (x1 - x0_ + y1 - y0_) / 512);
    nx_ = static_cast<long>((x1 - x0_) / b_) + 1, ny_ = static_cast<long>((y1 - y0_) / b_) + 1;
    bucket_.resize(static_cast<size_t>(nx_ * ny_));
    for (size_t k = 0; k < segs_.size(); ++k) {
      const auto& [a, b] = segs_[k];
      for (long j = cy(std::min(a.y, b.y)); j <= cy(std::max(a.y, b.y)); ++j)
        for (long i = cx(std::min(a.x, b.x)); i <= cx(std::max(a.x, b.x)); ++i)
          bucket_[static_cast<size_t>(j * nx_ + i)].push_back(k);
    }
  }
  double dist(const Vec3& p) const {
    double d = cap_;
    for (long j = cy(p.y - cap_); j <= cy(p.y + cap_); ++j)
      for (long i = cx(p.x - cap_); i <= cx(p.x + cap_); ++i)
        for (size_t k : bucket_[static_cast<size_t>(j * nx_ + i)])
          d = std::min(d, point_segment(p, segs_[k].first, segs_[k].second));
    return d;
  }

 private:
  long cx(double x) const { return std::clamp(static_cast<long>((x - x0_) / b_), 0L, nx_ - 1); }
  long cy(double y) const { return std::clamp(static_cast<long>((y - y0_) / b_), 0L, ny_ - 1); }
  double cap_, x0_, y0_, b_;
  long nx_, ny_;
  std::vector<std::pair<Vec3, Vec3>> segs_;
  std::vector<std::vector<size_t>> bucket_;
};

// Scratch for contours(): whether each square was looked at, and each
// grid edge's slot in `links` (-1: none); all clear between uses.
struct ContourScratch {
  // The crossing on an edge: the edge its segment leads to (-1 once taken
  // or none) and the point on it, and the edge whose segment leads to it.
  struct Link {
    long next = -1, prev = -1;
    Vec3 at;
  };
  std::vector<uint8_t> done;
  std::vector<int32_t> slot;
  std::vector<Link> links;
  std::vector<long> edges;      // the edges given a slot
  std::vector<size_t> squares;  // the squares looked at
};

// The loops round the samples where f < 0 (marching squares), each with
// that set on its left, that pass through one of the squares `seeds` (by
// their lower left sample, in order): each is followed square by square
// from the first seed it crosses, whatever its length, and none other is
// looked at. A chain the grid's edge cuts goes to `open`.
template <class F>
inline std::vector<std::vector<Vec3>> contours(const PocketGrid& g, const F& f, const std::vector<size_t>& seeds,
                                               ContourScratch& sc, std::vector<std::vector<Vec3>>& open) {
  auto val = [&](long i, long j) { return static_cast<double>(f(static_cast<size_t>(j * g.nx + i))); };
  auto pos = [&](long i, long j) {
    return Vec3{g.x0 + (static_cast<double>(i) + 0.5) * g.cell, g.y0 + (static_cast<double>(j) + 0.5) * g.cell, 0};
  };
  sc.done.resize(g.size(), 0);
  sc.slot.resize(2 * g.size(), -1);
  // Edge ids: 2 (j nx + i) for the edge from (i, j) to (i + 1, j), + 1 for (i, j) to (i, j + 1).
  auto link = [&](long e) -> ContourScratch::Link& {
    int32_t& s = sc.slot[static_cast<size_t>(e)];
    if (s < 0) {
      s = static_cast<int32_t>(sc.links.size());
      sc.links.emplace_back();
      sc.edges.push_back(e);
    }
    return sc.links[static_cast<size_t>(s)];
  };
  // The link of edge e, or null when it has none.
  auto find = [&](long e) -> ContourScratch::Link* {
    const int32_t s = sc.slot[static_cast<size_t>(e)];
    return s < 0 ? nullptr : &sc.links[static_cast<size_t>(s)];
  };
  // The segments of square (i, j), once; their "from" edges go to `from`.
  auto square = [&](long i, long j, std::vector<long>* from) {
    if (i < 0 || j < 0 || i + 1 >= g.nx || j + 1 >= g.ny) return;
    const size_t sq = static_cast<size_t>(j * g.nx + i);
    if (sc.done[sq]) return;
    sc.done[sq] = 1;
    sc.squares.push_back(sq);
    const long ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
    double v[4];
    bool in[4];
    for (int k = 0; k < 4; ++k) v[k] = val(ci[k], cj[k]), in[k] = v[k] < 0;
    const int n_in = in[0] + in[1] + in[2] + in[3];
    if (n_in == 0 || n_in == 4) return;
    // Edge k joins corner k and k + 1.
    const long eid[4] = {2 * (j * g.nx + i), 2 * (j * g.nx + i + 1) + 1, 2 * ((j + 1) * g.nx + i),
                         2 * (j * g.nx + i) + 1};
    auto cross_pt = [&](int k) {
      const int a = k, b = (k + 1) % 4;
      const double t = v[a] / (v[a] - v[b]);
      const Vec3 u = pos(ci[a], cj[a]), w = pos(ci[b], cj[b]);
      const double s = std::clamp(t, 0.0, 1.0);
      return Vec3{u.x + (w.x - u.x) * s, u.y + (w.y - u.y) * s, 0};
    };
    auto add = [&](int ea, int eb, int corner) {
      // A segment between edges ea and eb, corner k on its left when inside.
      Vec3 p = cross_pt(ea);
      Vec3 q = cross_pt(eb);
      const Vec3 c = pos(ci[corner], cj[corner]);
      const double side = (q.x - p.x) * (c.y - p.y) - (q.y - p.y) * (c.x - p.x);
      long e0 = eid[ea], e1 = eid[eb];
      if ((side > 0) != in[corner]) std::swap(e0, e1), std::swap(p, q);
      ContourScratch::Link& l0 = link(e0);
      l0.next = e1, l0.at = p;
      link(e1).prev = e0;
      if (from) from->push_back(e0);
    };
    if (n_in == 2 && in[0] == in[2]) {  // a saddle
      const bool centre_in = (v[0] + v[1] + v[2] + v[3]) < 0;
      for (int k = 0; k < 4; ++k)
        if (in[k] != centre_in) add((k + 3) % 4, k, k);
      return;
    }
    int e[2], m = 0;
    for (int k = 0; k < 4 && m < 2; ++k)
      if (in[k] != in[(k + 1) % 4]) e[m++] = k;
    add(e[0], e[1], in[e[0]] ? e[0] : (e[0] + 1) % 4);
  };
  // The two squares an edge lies between.
  auto sides = [&](long e) {
    const long k = e / 2, i = k % g.nx, j = k / g.nx;
    square(i, j, nullptr);
    if (e % 2)
      square(i - 1, j, nullptr);
    else
      square(i, j - 1, nullptr);
  };
  // The edge the segment from e leads to, its squares looked at first; -1
  // when none.
  auto find_next = [&](long e) {
    const ContourScratch::Link* l = find(e);
    if (!l || l->next < 0) sides(e), l = find(e);
    return l ? l->next : -1;
  };
  auto find_prev = [&](long e) {
    const ContourScratch::Link* l = find(e);
    if (!l || l->prev < 0) sides(e), l = find(e);
    return l ? l->prev : -1;
  };
  std::vector<std::vector<Vec3>> loops;
  std::vector<long> from;
  for (size_t sq : seeds) {
    from.clear();
    square(static_cast<long>(sq) % g.nx, static_cast<long>(sq) / g.nx, &from);
    for (long start : from) {
      if (find(start)->next < 0) continue;  // taken by a loop already followed
      std::vector<Vec3> loop;
      long at = start;
      bool closed = false;
      while (!closed) {
        const long to = find_next(at);
        if (to < 0) break;
        ContourScratch::Link& l = *find(at);
        loop.push_back(l.at);
        l.next = -1;
        find(to)->prev = -1;
        at = to;
        closed = at == start;
      }
      if (!closed) {
        // The grid's edge cuts the chain: its part before `start`, back to that edge.
        std::vector<Vec3> before;
        for (long e = find_prev(start); e >= 0; e = find_prev(start)) {
          find(start)->prev = -1;
          ContourScratch::Link& l = *find(e);
          before.push_back(l.at);
          l.next = -1;
          start = e;
        }
        loop.insert(loop.begin(), before.rbegin(), before.rend());
      }
      if (closed && loop.size() >= 3)
        loops.push_back(std::move(loop));
      else if (!closed && loop.size() >= 2)
        open.push_back(std::move(loop));
    }
  }
  for (size_t sq : sc.squares) sc.done[sq] = 0;
  for (long e : sc.edges) sc.slot[static_cast<size_t>(e)] = -1;
  sc.squares.clear(), sc.edges.clear(), sc.links.clear();
  return loops;
}

}  // namespace bezcam::detail
