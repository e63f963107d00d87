// Independent measurement of an offset path (offset_measure.hpp). Shares
// nothing with offset.cpp: its own sampling of the curve, its own grid.
#include "bezcam/flatten/offset_measure.hpp"

#include <algorithm>
#include <cmath>

namespace bezcam {

double OffsetReading::deviation(double r) const {
  return std::max({std::abs(min_distance - r), std::abs(max_distance - r), coverage});
}

namespace {

struct CurveSample {
  Vec3 p, normal;  // unit left normal
};

// Samples on the curve, consecutive chords within `res` of it: a piece is
// cut in halves until the chord's midpoint and quarter points agree with the
// curve within res / 4 (and the span is short against the piece).
void sample_curve(const Bezier& b, double res, std::vector<CurveSample>& out) {
  auto at = [&](double t) {
    const Vec3 p = evaluate(b, t), d = derivative(b, t);
    const double l = std::hypot(d.x, d.y);
    return CurveSample{{p.x, p.y, 0}, l > 0 ? Vec3{-d.y / l, d.x / l, 0} : Vec3{}};
  };
  struct Span {
    double t0, t1;
    int depth;
  };
  std::vector<Span> stack{{0, 1, 0}};
  std::vector<std::pair<double, CurveSample>> got{{0.0, at(0)}};
  while (!stack.empty()) {
    const Span s = stack.back();
    stack.pop_back();
    const Vec3 a = evaluate(b, s.t0), c = evaluate(b, s.t1);
    bool flat = s.depth >= 4;
    for (double f : {0.25, 0.5, 0.75}) {
      if (!flat) break;
      const Vec3 m = evaluate(b, s.t0 + f * (s.t1 - s.t0));
      const Vec3 q = lerp(a, c, f);
      if (std::hypot(m.x - q.x, m.y - q.y) > res / 4) flat = false;
    }
    if (flat || s.depth >= 40) {
      got.push_back({s.t1, at(s.t1)});
      continue;
    }
    const double tm = 0.5 * (s.t0 + s.t1);
    stack.push_back({tm, s.t1, s.depth + 1});
    stack.push_back({s.t0, tm, s.depth + 1});
  }
  std::sort(got.begin(), got.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& g : got) out.push_back(g.second);
}

// Segments in order, in chunks with boxes: the nearest distance from a
// point, pruning chunks whose box is farther than the best so far (seeded by
// the segments near the previous answer: consecutive queries are close).
struct Index {
  static constexpr size_t kChunk = 32;
  std::vector<std::pair<Vec3, Vec3>> segs;
  std::vector<Box3> boxes, groups;  // per chunk, per kChunk chunks
  size_t hint = 0;
  explicit Index(std::vector<std::pair<Vec3, Vec3>> s) : segs(std::move(s)) {
    for (size_t k = 0; k < segs.size(); k += kChunk) {
      Box3 b;
      for (size_t i = k; i < std::min(segs.size(), k + kChunk); ++i) {
        b.add(segs[i].first);
        b.add(segs[i].second);
      }
      boxes.push_back(b);
    }
    for (size_t k = 0; k < boxes.size(); k += kChunk) {
      Box3 b;
      for (size_t i = k; i < std::min(boxes.size(), k + kChunk); ++i) b.add(boxes[i]);
      groups.push_back(b);
    }
  }
  // Squared distances: no square root in the inner loop.
  static double seg_d2(const Vec3& p, const Vec3& a, const Vec3& b) {
    const double dx = b.x - a.x, dy = b.y - a.y, px = p.x - a.x, py = p.y - a.y;
    const double l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp((px * dx + py * dy) / l2, 0.0, 1.0) : 0.0;
    const double ex = px - t * dx, ey = py - t * dy;
    return ex * ex + ey * ey;
  }
  static double box_d2(const Vec3& p, const Box3& b) {
    const double dx = std::max({b.lo.x - p.x, 0.0, p.x - b.hi.x});
    const double dy = std::max({b.lo.y - p.y, 0.0, p.y - b.hi.y});
    return dx * dx + dy * dy;
  }
  static double box_box_d2(const Box3& a, const Box3& b) {
    const double dx = std::max({b.lo.x - a.hi.x, 0.0, a.lo.x - b.hi.x});
    const double dy = std::max({b.lo.y - a.hi.y, 0.0, a.lo.y - b.hi.y});
    return dx * dx + dy * dy;
  }
  static double cross(const Vec3& o, const Vec3& a, const Vec3& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  }
  // Squared distance between segments pq and ab: zero where they cross,
  // else the nearest of the four ends to the other segment.
  static double seg_seg_d2(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b) {
    const double o1 = cross(p, q, a), o2 = cross(p, q, b), o3 = cross(a, b, p), o4 = cross(a, b, q);
    if (((o1 < 0 && o2 > 0) || (o1 > 0 && o2 < 0)) && ((o3 < 0 && o4 > 0) || (o3 > 0 && o4 < 0))) return 0;
    return std::min({seg_d2(p, a, b), seg_d2(q, a, b), seg_d2(a, p, q), seg_d2(b, p, q)});
  }
  // The smallest squared distance from any segment to what `d2` measures
  // (a point or a segment), chunks pruned by `box` (a lower bound on d2 for
  // a chunk's box); seeded by the segments near the previous answer.
  template <class D2, class BoxD2>
  double search(D2 d2, BoxD2 box) {
    double best = HUGE_VAL;
    size_t at = hint;
    const size_t lo = hint > 4 ? hint - 4 : 0, hi = std::min(segs.size(), hint + 5);
    for (size_t i = lo; i < hi; ++i) {
      const double d = d2(segs[i]);
      if (d < best) best = d, at = i;
    }
    for (size_t g = 0; g < groups.size(); ++g) {
      if (box(groups[g]) >= best) continue;
      for (size_t c = g * kChunk; c < std::min(boxes.size(), (g + 1) * kChunk); ++c) {
        if (box(boxes[c]) >= best) continue;
        for (size_t i = c * kChunk; i < std::min(segs.size(), (c + 1) * kChunk); ++i) {
          const double d = d2(segs[i]);
          if (d < best) best = d, at = i;
        }
      }
    }
    hint = at;
    return best;
  }
  /// Distance from p to the nearest segment; `hint` is then that segment.
  double nearest(const Vec3& p) {
    if (segs.empty()) return HUGE_VAL;
    return std::sqrt(search([&](const auto& s) { return seg_d2(p, s.first, s.second); },
                            [&](const Box3& b) { return box_d2(p, b); }));
  }
  /// The smallest distance between the segment pq and any segment.
  double nearest(const Vec3& p, const Vec3& q) {
    if (segs.empty()) return HUGE_VAL;
    Box3 pq;
    pq.add(p);
    pq.add(q);
    return std::sqrt(search([&](const auto& s) { return seg_seg_d2(p, q, s.first, s.second); },
                            [&](const Box3& b) { return box_box_d2(pq, b); }));
  }
  /// The winding number about p of the closed polyline the first `count`
  /// segments make (crossings of the ray from p towards +x), chunks whose
  /// box the ray misses skipped.
  int winding(const Vec3& p, size_t count) const {
    int w = 0;
    auto missed = [&](const Box3& b) { return b.lo.y > p.y || b.hi.y <= p.y || b.hi.x < p.x; };
    for (size_t g = 0; g < groups.size() && g * kChunk * kChunk < count; ++g) {
      if (missed(groups[g])) continue;
      for (size_t c = g * kChunk; c < std::min(boxes.size(), (g + 1) * kChunk) && c * kChunk < count; ++c) {
        if (missed(boxes[c])) continue;
        for (size_t i = c * kChunk; i < std::min(count, (c + 1) * kChunk); ++i) {
          const Vec3& a = segs[i].first;
          const Vec3& b = segs[i].second;
          if ((a.y > p.y) == (b.y > p.y)) continue;
          if (a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x) > p.x) w += b.y > a.y ? 1 : -1;
        }
      }
    }
    return w;
  }
  /// Distance from p to segment i.
  double to(size_t i, const Vec3& p) const { return std::sqrt(seg_d2(p, segs[i].first, segs[i].second)); }
};

}  // namespace

OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const Vec3> path,
                             const OffsetMeasure& how) {
  const std::vector<std::vector<Vec3>> one{std::vector<Vec3>(path.begin(), path.end())};
  return measure_offset(curves, one, how);
}

OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const std::vector<Vec3>> paths,
                             const OffsetMeasure& how) {
  const double r = how.r, resolution = how.resolution;
  const int side = how.side;
  const bool distances = how.distances;
  OffsetReading out;
  std::vector<std::vector<CurveSample>> samples(curves.size());
  std::vector<std::pair<Vec3, Vec3>> segs;
  size_t ring_segs = 0;  // the first curve's segments, first in the index
  for (size_t c = 0; c < curves.size(); ++c) {
    for (const Bezier& b : curves[c]) {
      const size_t first = samples[c].size();
      sample_curve(b, resolution, samples[c]);
      for (size_t i = first + 1; i < samples[c].size(); ++i) segs.push_back({samples[c][i - 1].p, samples[c][i].p});
    }
    if (c == 0) ring_segs = segs.size();
  }
  Index curve(std::move(segs));
  // The path's distances from the curve's polyline. The smallest is exact:
  // the nearest approach of each path segment to any curve segment. The
  // largest is read at path points: the vertices, then the midpoints of a
  // path segment while it could hold a larger distance than read so far.
  // It cannot where one curve segment S is within that largest reading of
  // both its ends (the distance to S is convex along a line, and the
  // distance to the curve is at most the distance to S), nor where the
  // segment is at most 2 resolution long (no point is farther than
  // `resolution` from a read end, and the distance moves by at most the
  // distance travelled): the largest reading is within `resolution` of the
  // largest distance.
  double lo = HUGE_VAL, hi = 0;
  std::vector<std::pair<Vec3, Vec3>> psegs;
  struct Read {
    Vec3 at;
    size_t seg;  // the curve segment nearest to it
  };
  std::vector<std::pair<Read, Read>> todo;
  auto read = [&](const Vec3& p) {
    const double d = curve.nearest(p);
    hi = std::max(hi, d);
    lo = std::min(lo, d);
    return Read{p, curve.hint};
  };
  auto within = [&](const Read& a, const Read& b, size_t s) {
    return std::max(curve.to(s, a.at), curve.to(s, b.at)) <= hi;
  };
  for (const auto& path : paths) {
    Read prev{};
    for (size_t i = 0; i < path.size(); ++i) {
      const Vec3 p{path[i].x, path[i].y, 0};
      if (i > 0) psegs.push_back({prev.at, p});
      if (!distances) {
        prev.at = p;
        continue;
      }
      const Read cur = read(p);
      if (i > 0 && !curve.segs.empty()) {
        lo = std::min(lo, curve.nearest(prev.at, p));
        todo.push_back({prev, cur});
        while (!todo.empty()) {
          const auto [a, b] = todo.back();
          todo.pop_back();
          if (dist(a.at, b.at) <= 2 * resolution || within(a, b, a.seg) || within(a, b, b.seg)) continue;
          const Read m = read(lerp(a.at, b.at, 0.5));
          if (within(a, b, m.seg)) continue;
          todo.push_back({m, b});
          todo.push_back({a, m});
        }
      }
      prev = cur;
    }
  }
  out.min_distance = distances ? lo : r;
  out.max_distance = distances ? hi : r;
  if (side != 0 && !curves.empty() && !psegs.empty()) {
    // The material left: a curve point the tool reaches (its tool position
    // at r + middle not folded away: no other stretch of the part nearer,
    // less the sampled curve's own error) stands dist(c, path) - r from
    // the tool's edge. Read against the part's surface, not the offset's
    // points: where the offset turns a sharp inner corner, the path's
    // corner may lie a little off the true offset's along the corner's
    // bisector while the material it leaves is the same thin sliver.
    Index pg(std::move(psegs));
    const double reach = r + how.middle;
    // A closed curve bounds a region, and the tool is on one side of it:
    // inside (a non-zero winding number of the sampled curve) where the side
    // is the left of a counter-clockwise curve or the right of a clockwise
    // one. A tool position on the other side (across a wall of the part
    // where the curve doubles back on itself, at a cusp or a spur of zero
    // width) is not one the tool reaches.
    const auto& ring = samples[0];
    const bool region = ring.size() > 2 && dist(ring.front().p, ring.back().p) <= resolution;
    double area = 0;
    for (size_t i = 0; region && i < ring.size(); ++i) {
      const Vec3& a = ring[i].p;
      const Vec3& b = ring[(i + 1) % ring.size()].p;
      area += a.x * b.y - b.x * a.y;
    }
    const bool want_inside = (side > 0) == (area > 0);
    auto inside = [&](const Vec3& q) { return curve.winding(q, ring_segs) != 0; };
    for (const CurveSample& s : samples[0]) {
      if (s.normal.x == 0 && s.normal.y == 0) continue;
      const Vec3 q = s.p + s.normal * (side * reach);
      if (curve.nearest(q) < reach - 2 * resolution) continue;  // folded away
      if (region && area != 0 && inside(q) != want_inside) continue;  // across a wall
      out.coverage = std::max(out.coverage, pg.nearest(s.p) - r);
    }
  }
  return out;
}

}  // namespace bezcam
