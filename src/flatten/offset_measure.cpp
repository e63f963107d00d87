// Independent measurement of an offset path (offset_measure.hpp). Shares
// nothing with offset.cpp: its own sampling of the curve and of the path,
// its own index, its own nearest points.
#include "bezcam/flatten/offset_measure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "bezcam/kernel/minimize.hpp"

namespace bezcam {

double OffsetReading::deviation(double r) const {
  return std::max({std::abs(min_distance - r), std::abs(max_distance - r), coverage});
}

PathPiece PathPiece::line(const Vec3& a, const Vec3& b) { return of(Bezier::make({a, b})); }

PathPiece PathPiece::of(const Bezier& b) {
  PathPiece p;
  p.curve = b;
  return p;
}

PathPiece PathPiece::of(const Arc& a) {
  PathPiece p;
  p.arc = a;
  return p;
}

namespace {

Vec3 xy(const Vec3& p) { return {p.x, p.y, 0}; }

// One piece of the curve or of the path, evaluated in XY.
struct MeasuredPiece {
  const Bezier* bez = nullptr;
  std::optional<ArcPoints> arc;
  double sweep = 0, radius = 0;  // arcs
  Vec3 at(double t) const { return xy(arc ? arc->at(t) : evaluate(*bez, t)); }
  // Unit left normal (curve pieces), zero where the derivative vanishes.
  Vec3 normal(double t) const {
    const Vec3 d = derivative(*bez, t);
    const double l = std::hypot(d.x, d.y);
    return l > 0 ? Vec3{-d.y / l, d.x / l, 0} : Vec3{};
  }
};

struct Sample {
  Vec3 p;
  double t = 0;
};

// Samples on the piece, consecutive chords within `res` / 4 of it: a line
// is its two ends; an arc is cut into equal angles; a curve is cut in
// halves until the chord's midpoint and quarter points agree with it
// within res / 4 (and the span is short against the piece).
std::vector<Sample> sample_piece(const MeasuredPiece& pc, double res) {
  std::vector<Sample> got;
  if (pc.arc) {
    double step = pc.sweep;
    if (pc.radius > res / 4) step = 2 * std::acos(1 - res / 4 / pc.radius);
    const int n = std::clamp(static_cast<int>(std::ceil(pc.sweep / std::max(step, 1e-9))), 1, 1 << 20);
    for (int i = 0; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      got.push_back({pc.at(t), t});
    }
    return got;
  }
  if (pc.bez->points.size() == 2) return {{pc.at(0), 0}, {pc.at(1), 1}};
  struct PieceSpan {
    double t0, t1;
    int depth;
  };
  std::vector<PieceSpan> stack{{0, 1, 0}};
  got.push_back({pc.at(0), 0});
  while (!stack.empty()) {
    const PieceSpan s = stack.back();
    stack.pop_back();
    const Vec3 a = pc.at(s.t0), c = pc.at(s.t1);
    bool flat = s.depth >= 4;
    for (double f : {0.25, 0.5, 0.75}) {
      if (!flat) break;
      const Vec3 m = pc.at(s.t0 + f * (s.t1 - s.t0));
      const Vec3 q = lerp(a, c, f);
      if (std::hypot(m.x - q.x, m.y - q.y) > res / 4) flat = false;
    }
    if (flat || s.depth >= 40) {
      got.push_back({c, s.t1});
      continue;
    }
    const double tm = 0.5 * (s.t0 + s.t1);
    stack.push_back({tm, s.t1, s.depth + 1});
    stack.push_back({s.t0, tm, s.depth + 1});
  }
  std::sort(got.begin(), got.end(), [](const Sample& x, const Sample& y) { return x.t < y.t; });
  return got;
}

// Chords in order, in chunks with boxes: the nearest distance from a
// point, pruning chunks whose box is farther than the best so far (seeded by
// the chords near the previous answer: consecutive queries are close). Each
// chord knows the stretch of its piece it stands for.
struct Index {
  static constexpr size_t kChunk = 32;
  struct Ref {
    uint32_t piece = 0;
    double t0 = 0, t1 = 0;
  };
  std::vector<std::pair<Vec3, Vec3>> segs;
  std::vector<Ref> refs;
  std::vector<Box3> boxes, groups;  // per chunk, per kChunk chunks
  size_t hint = 0;
  void build() {
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
  /// The smallest distance between the segment pq and any segment; `hint`
  /// is then that segment.
  double nearest(const Vec3& p, const Vec3& q) {
    if (segs.empty()) return HUGE_VAL;
    Box3 pq;
    pq.add(p);
    pq.add(q);
    return std::sqrt(search([&](const auto& s) { return seg_seg_d2(p, q, s.first, s.second); },
                            [&](const Box3& b) { return box_box_d2(pq, b); }));
  }
  /// Calls f(i) for every segment within `radius` of p.
  template <class F>
  void within(const Vec3& p, double radius, F f) const {
    const double r2 = radius * radius;
    for (size_t g = 0; g < groups.size(); ++g) {
      if (box_d2(p, groups[g]) > r2) continue;
      for (size_t c = g * kChunk; c < std::min(boxes.size(), (g + 1) * kChunk); ++c) {
        if (box_d2(p, boxes[c]) > r2) continue;
        for (size_t i = c * kChunk; i < std::min(segs.size(), (c + 1) * kChunk); ++i)
          if (seg_d2(p, segs[i].first, segs[i].second) <= r2) f(i);
      }
    }
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

// The pieces of a curve or a path, their samples and the index of their
// chords.
struct Shape {
  std::vector<MeasuredPiece> pieces;
  std::vector<std::vector<Sample>> samples;  // per piece
  Index index;
  double margin = 0;     // more than the chords' distance from the pieces
  size_t ring_segs = 0;  // the first curve's chords, first in the index (measure_offset())

  void sample(double res) {
    margin = 2 * res;
    samples.resize(pieces.size());
    for (size_t k = 0; k < pieces.size(); ++k) {
      samples[k] = sample_piece(pieces[k], res);
      for (size_t i = 1; i < samples[k].size(); ++i) {
        index.segs.push_back({samples[k][i - 1].p, samples[k][i].p});
        index.refs.push_back({static_cast<uint32_t>(k), samples[k][i - 1].t, samples[k][i].t});
      }
    }
    index.build();
  }

  // The nearest point of the pieces to x and its distance: the squared
  // distance minimised (Brent) over the stretch of each chord within the
  // margin of the nearest one, and a chord's length either side of it.
  std::pair<double, Vec3> nearest_point(const Vec3& x) {
    const double d0 = index.nearest(x);
    if (!std::isfinite(d0)) return {d0, x};
    double best = HUGE_VAL;
    Vec3 at = x;
    index.within(x, d0 + margin, [&](size_t i) {
      const Index::Ref& g = index.refs[i];
      const MeasuredPiece& pc = pieces[g.piece];
      const double w = g.t1 - g.t0;
      const double a = std::max(0.0, g.t0 - w), b = std::min(1.0, g.t1 + w);
      auto f = [&](double t) {
        const Vec3 q = pc.at(t);
        return (q.x - x.x) * (q.x - x.x) + (q.y - x.y) * (q.y - x.y);
      };
      const MinimumFound m = brent_min(a, b, f, 1e-12 * std::max(w, 1e-300) + 1e-15);
      for (const double t : {m.x, a, b}) {
        const double d = t == m.x ? m.f : f(t);
        if (d < best) best = d, at = pc.at(t);
      }
    });
    return {std::sqrt(best), at};
  }
  double exact(const Vec3& x) { return nearest_point(x).first; }
};

MeasuredPiece piece_of(const PathPiece& p) {
  MeasuredPiece pc;
  if (p.arc) {
    pc.arc.emplace(*p.arc);
    pc.sweep = p.arc->sweep();
    pc.radius = std::max(p.arc->r_start(), p.arc->r_end());
  } else {
    pc.bez = &p.curve;
  }
  return pc;
}

// How many of the extreme readings of the polylines are read again
// exactly (the first is enough for the resolution; more make the reading
// nearer the true extreme where the polylines tie).
constexpr size_t kExactReads = 16;

// The smallest distance of the drawn path from the curve: each path chord's
// nearest approach to the curve's polyline finds where to read; the chords
// from the nearest up are read exactly at their ends and at the point of
// their stretch of the path where the chord comes nearest the curve's
// polyline, while a chord could still hide a smaller true distance.
double smallest_distance(Shape& curve, const Shape& drawn) {
  struct Near {
    double d;
    size_t piece;
    Sample a, b;
  };
  std::vector<Near> nears;
  if (curve.index.segs.empty()) return HUGE_VAL;
  for (size_t k = 0; k < drawn.pieces.size(); ++k) {
    const auto& ss = drawn.samples[k];
    for (size_t i = 1; i < ss.size(); ++i)
      nears.push_back({curve.index.nearest(ss[i - 1].p, ss[i].p), k, ss[i - 1], ss[i]});
  }
  std::sort(nears.begin(), nears.end(), [](const Near& x, const Near& y) { return x.d < y.d; });
  double smallest = HUGE_VAL;
  for (size_t i = 0; i < nears.size() && i < kExactReads; ++i) {
    const Near& n = nears[i];
    if (n.d - curve.margin - drawn.margin > smallest) break;
    const Vec3 p = n.a.p, q = n.b.p;
    curve.index.nearest(p, q);
    const auto& s = curve.index.segs[curve.index.hint];
    // Where on pq the nearest approach to the chord s lies (its crossing,
    // or the foot of the nearer end of s, or an end of pq).
    double f = 0;
    const double o1 = Index::cross(s.first, s.second, p), o2 = Index::cross(s.first, s.second, q);
    const double lp = dot(q - p, q - p);
    if ((o1 < 0) != (o2 < 0) && o1 != o2) {
      f = o1 / (o1 - o2);
    } else if (lp > 0) {
      const double dp = Index::seg_d2(p, s.first, s.second), dq = Index::seg_d2(q, s.first, s.second);
      double best = std::min(dp, dq);
      f = dp <= dq ? 0 : 1;
      for (const Vec3& e : {s.first, s.second}) {
        const double g = std::clamp(dot(e - p, q - p) / lp, 0.0, 1.0);
        const Vec3 foot = lerp(p, q, g);
        const double d2 = dot(e - foot, e - foot);
        if (d2 < best) best = d2, f = g;
      }
    }
    const double t = n.a.t + std::clamp(f, 0.0, 1.0) * (n.b.t - n.a.t);
    smallest = std::min({smallest, curve.exact(p), curve.exact(q), curve.exact(drawn.pieces[n.piece].at(t))});
  }
  return smallest;
}

}  // namespace

OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const std::vector<Vec3>> paths,
                             const OffsetMeasure& how) {
  std::vector<PathPiece> pieces;
  for (const auto& path : paths) {
    for (size_t i = 1; i < path.size(); ++i) pieces.push_back(PathPiece::line(xy(path[i - 1]), xy(path[i])));
    if (path.size() == 1) pieces.push_back(PathPiece::line(xy(path[0]), xy(path[0])));
  }
  return measure_offset(curves, pieces, how);
}

OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const Vec3> path,
                             const OffsetMeasure& how) {
  const std::vector<std::vector<Vec3>> one{std::vector<Vec3>(path.begin(), path.end())};
  return measure_offset(curves, one, how);
}

namespace {

// The largest distance of the drawn path from the curve. The path's
// distances from the curve's polyline say where it lies: read at path
// points, the samples, then the middle of a path chord's stretch while it
// could hold a larger distance than read so far. It cannot where one curve
// chord S is within that largest reading of both its ends (the distance to
// S is convex along a line, and the distance to the curve is at most the
// distance to S), nor where the chord is at most 2 resolution long. Then
// the exact pass: the points read, from the largest reading down, while a
// reading could still hide a larger true distance (the polylines are within
// the margin of what they sample), at most kExactReads of them: the first
// alone is within twice the margin of the true largest.
double largest_distance(Shape& curve, const Shape& drawn, double resolution) {
  double hi = 0;
  struct Read {
    Vec3 at;
    size_t seg;  // the curve chord nearest to it
    double t;    // where on its path piece
    double d;    // its distance from the curve's polyline
  };
  std::vector<Read> reads;  // every point read, for the exact pass
  auto read = [&](const Vec3& p, double t) {
    const double d = curve.index.nearest(p);
    hi = std::max(hi, d);
    reads.push_back({p, curve.index.hint, t, d});
    return reads.back();
  };
  auto within = [&](const Read& a, const Read& b, size_t s) {
    return std::max(curve.index.to(s, a.at), curve.index.to(s, b.at)) <= hi;
  };
  std::vector<std::pair<Read, Read>> todo;
  for (size_t k = 0; k < drawn.pieces.size() && !curve.index.segs.empty(); ++k) {
    const auto& ss = drawn.samples[k];
    Read prev = read(ss[0].p, ss[0].t);
    for (size_t i = 1; i < ss.size(); ++i) {
      const Read cur = read(ss[i].p, ss[i].t);
      todo.push_back({prev, cur});
      while (!todo.empty()) {
        const auto [a, b] = todo.back();
        todo.pop_back();
        if (dist(a.at, b.at) <= 2 * resolution || within(a, b, a.seg) || within(a, b, b.seg)) continue;
        const double tm = 0.5 * (a.t + b.t);
        const Read m = read(drawn.pieces[k].at(tm), tm);
        if (within(a, b, m.seg)) continue;
        todo.push_back({m, b});
        todo.push_back({a, m});
      }
      prev = cur;
    }
  }
  std::sort(reads.begin(), reads.end(), [](const Read& x, const Read& y) { return x.d > y.d; });
  double largest = reads.empty() ? 0 : -HUGE_VAL;
  for (size_t i = 0; i < reads.size() && i < kExactReads; ++i) {
    if (reads[i].d + curve.margin < largest) break;
    largest = std::max(largest, curve.exact(reads[i].at));
  }
  return largest;
}

// The material left: a curve point c the tool reaches (its tool position
// at r + middle along c's normal, on the side, no nearer the whole curve
// than r + middle, to rounding: else it is folded away) stands
// dist(c, path) - r from the tool's edge. Read against the part's surface,
// not the offset's points: where the offset turns a sharp inner corner,
// the path's corner may lie a little off the true offset's along the
// corner's bisector while the material it leaves is the same thin sliver.
// Each sample is read by its distance to the path's polyline; from the
// largest reading down, a point the tool reaches is read again exactly,
// and the largest distance sought between its neighbours.
class CoverageReader {
 public:
  // The curve's first `ring` pieces are the first curve, which the
  // coverage is read along; `eps` is the rounding margin of the reach test.
  CoverageReader(Shape& curve, Shape& drawn, const OffsetMeasure& how, size_t ring, double eps)
      : curve_(curve), drawn_(drawn), how_(how), ring_(ring), eps_(eps), reach_(how.r + how.middle) {
    find_region();
  }
  double read();

 private:
  struct Cover {
    double d;  // of the curve point from the path's polyline
    size_t piece;
    double t, lo, hi;  // its parameter, and its neighbours'
  };
  void find_region();
  bool on_side(const Vec3& q) const {
    return !(region_ && area_ != 0 && (curve_.index.winding(q, curve_.ring_segs) != 0) != want_inside_);
  }
  bool reaches(size_t k, double t);
  std::vector<Cover> candidates() const;
  // The material left at (piece, t); 0 where the tool does not reach.
  double left(const Cover& c, double t) {
    return reaches(c.piece, t) ? drawn_.exact(curve_.pieces[c.piece].at(t)) - how_.r : 0.0;
  }

  Shape& curve_;
  Shape& drawn_;
  const OffsetMeasure& how_;
  size_t ring_;
  double eps_, reach_;
  bool region_ = false, want_inside_ = false;
  double area_ = 0;
};

// A closed curve bounds a region, and the tool is on one side of it:
// inside (a non-zero winding number of the sampled curve) where the side
// is the left of a counter-clockwise curve or the right of a clockwise
// one. A tool position on the other side (across a wall of the part where
// the curve doubles back on itself, at a cusp or a spur of zero width) is
// not one the tool reaches.
void CoverageReader::find_region() {
  std::vector<Vec3> ring;
  for (size_t k = 0; k < ring_; ++k)
    for (const Sample& x : curve_.samples[k]) ring.push_back(x.p);
  region_ = ring.size() > 2 && dist(ring.front(), ring.back()) <= how_.resolution;
  for (size_t i = 0; region_ && i < ring.size(); ++i) {
    const Vec3& a = ring[i];
    const Vec3& b = ring[(i + 1) % ring.size()];
    area_ += a.x * b.y - b.x * a.y;
  }
  want_inside_ = (how_.side > 0) == (area_ > 0);
}

// Whether the tool reaches the curve at (k, t).
bool CoverageReader::reaches(size_t k, double t) {
  const Vec3 n = curve_.pieces[k].normal(t);
  if (n.x == 0 && n.y == 0) return false;
  const Vec3 q = curve_.pieces[k].at(t) + n * (how_.side * reach_);
  if (curve_.exact(q) < reach_ - eps_) return false;
  return on_side(q);
}

// The curve's samples the tool may reach, read against the path's
// polyline, from the largest reading down.
std::vector<CoverageReader::Cover> CoverageReader::candidates() const {
  std::vector<Cover> cover;
  for (size_t k = 0; k < ring_; ++k) {
    const auto& ss = curve_.samples[k];
    for (size_t i = 0; i < ss.size(); ++i) {
      const Vec3 n = curve_.pieces[k].normal(ss[i].t);
      if (n.x == 0 && n.y == 0) continue;
      const Vec3 q = ss[i].p + n * (how_.side * reach_);
      if (curve_.index.nearest(q) < reach_ - eps_ - curve_.margin) continue;  // folded away for certain
      if (!on_side(q)) continue;
      cover.push_back(
          {drawn_.index.nearest(ss[i].p), k, ss[i].t, ss[i > 0 ? i - 1 : i].t, ss[i + 1 < ss.size() ? i + 1 : i].t});
    }
  }
  std::sort(cover.begin(), cover.end(), [](const Cover& x, const Cover& y) { return x.d > y.d; });
  return cover;
}

double CoverageReader::read() {
  double coverage = 0;
  size_t exact = 0;
  for (const Cover& c : candidates()) {
    if (c.d - how_.r + drawn_.margin < coverage || exact == kExactReads) break;
    if (!reaches(c.piece, c.t)) continue;
    double e = left(c, c.t);
    if (c.lo < c.hi)
      e = std::max(e, -brent_min(
                           c.lo, c.hi, [&](double t) { return -left(c, t); }, 1e-9 * (c.hi - c.lo), 40)
                           .f);
    coverage = std::max(coverage, e);
    ++exact;
  }
  return coverage;
}

}  // namespace

OffsetReading measure_offset(std::span<const std::vector<Bezier>> curves, std::span<const PathPiece> path,
                             const OffsetMeasure& how) {
  OffsetReading out;
  Shape curve;
  size_t first_curve_pieces = 0;
  std::vector<Bezier> all;
  for (size_t c = 0; c < curves.size(); ++c) {
    for (const Bezier& b : curves[c]) {
      MeasuredPiece pc;
      pc.bez = &b;
      curve.pieces.push_back(pc);
      all.push_back(b);
    }
    if (c == 0) first_curve_pieces = curve.pieces.size();
  }
  curve.sample(how.resolution);
  for (size_t k = 0; k < first_curve_pieces; ++k) curve.ring_segs += curve.samples[k].size() - 1;
  Shape drawn;
  for (const PathPiece& p : path) drawn.pieces.push_back(piece_of(p));
  drawn.sample(how.resolution);

  out.max_distance = how.distances ? largest_distance(curve, drawn, how.resolution) : how.r;
  out.min_distance = how.distances ? smallest_distance(curve, drawn) : how.r;
  if (how.side != 0 && first_curve_pieces > 0 && !curve.index.segs.empty() && !drawn.index.segs.empty()) {
    const double eps = 1e-9 * std::max(1.0, control_magnitude(all));
    out.coverage = CoverageReader(curve, drawn, how, first_curve_pieces, eps).read();
  }
  return out;
}

struct PartDistance::Impl {
  Shape curve;
};

PartDistance::PartDistance(std::span<const std::vector<Bezier>> curves, double resolution)
    : impl_(std::make_unique<Impl>()) {
  for (const auto& c : curves)
    for (const Bezier& b : c) {
      MeasuredPiece pc;
      pc.bez = &b;
      impl_->curve.pieces.push_back(pc);
    }
  impl_->curve.sample(resolution);
}

PartDistance::~PartDistance() = default;

Vec3 PartDistance::nearest(const Vec3& p) { return impl_->curve.nearest_point(xy(p)).second; }

double PartDistance::min_distance(std::span<const PathPiece> path) {
  Shape drawn;
  for (const PathPiece& p : path) drawn.pieces.push_back(piece_of(p));
  drawn.sample(impl_->curve.margin / 2);
  return smallest_distance(impl_->curve, drawn);
}

}  // namespace bezcam
