// The deviation of each cutting block from the true curve (block_deviations,
// preview_svg.hpp): the curve sampled densely, each block measured both
// ways against it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "bezcam/error.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/offset_measure.hpp"
#include "bezcam/report/motion_report.hpp"
#include "preview_draw.hpp"

namespace bezcam {

namespace {

using preview::entity_shape;
using preview::is_plunge;
using preview::Shape;

// An entity's curve as a dense on-curve polyline (2D curves in the XY plane).
struct DenseCurve {
  int entity = -1;
  int dim = 2;
  bool closed = false;
  std::vector<Vec3> pts;
};

DenseCurve dense_curve(const Entity& e, const Shape& sh, double tol) {
  DenseCurve d;
  d.entity = static_cast<int>(e.index);
  d.dim = sh.dim;
  const auto& pc = sh.measure;
  d.closed = sh.closed || (!pc.empty() && pc.front().front() == pc.back().back());
  // The flattener certifies its bound; a thousandth of the tolerance makes
  // the sampling error negligible next to what is measured.
  for (double frac : {1e-3, 1e-2}) {
    try {
      d.pts = flatten(pc, FlattenOptions{.tolerance = tol * frac, .decimals = -1, .on_curve = true}).points;
      return d;
    } catch (const InputError&) {
      // Too fine for double precision at these coordinates: coarser.
    }
  }
  d.pts = flatten(pc, FlattenOptions{.tolerance = tol * 0.1, .decimals = -1, .on_curve = true}).points;
  return d;
}

Vec3 flat_if_2d(const Vec3& p, int dim) { return dim == 2 ? Vec3{p.x, p.y, 0} : p; }

struct Near {
  double d = std::numeric_limits<double>::infinity();
  size_t seg = 0;
};

Near nearest_in(std::span<const Vec3> D, const Vec3& x, size_t a, size_t b) {
  Near n;
  for (size_t i = a; i < b; ++i) {
    const double d = dist_to_segment(x, D[i], D[i + 1]);
    if (d < n.d) n = {d, i};
  }
  return n;
}

// Nearest segment of the dense polyline, looking around `hint` first and
// everywhere when that answer is not small (the blocks advance along the
// curve, so the window almost always holds the answer).
Near nearest(std::span<const Vec3> D, const Vec3& x, size_t hint, double large) {
  if (D.size() < 2) return {D.empty() ? 0.0 : dist(x, D[0]), 0};
  const size_t nseg = D.size() - 1;
  constexpr size_t kWindow = 256;
  const size_t a = hint > kWindow ? hint - kWindow : 0, b = std::min(nseg, hint + kWindow + 1);
  Near n = nearest_in(D, x, a, b);
  if (n.d > large) n = nearest_in(D, x, 0, nseg);
  return n;
}

double dist_to_polyline(const Vec3& x, std::span<const Vec3> P) {
  if (P.size() == 1) return dist(x, P[0]);
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < P.size(); ++i) d = std::min(d, dist_to_segment(x, P[i], P[i + 1]));
  return d;
}

// Points along a block for measuring: its samples, each chord split in 16.
std::vector<Vec3> measuring_points(const MotionBlock& b, double tol, int dim) {
  const auto s = sample_block(b, tol * 1e-3);
  const int split = s.size() == 2 ? 16 : 2;
  std::vector<Vec3> out{flat_if_2d(s[0], dim)};
  for (size_t i = 1; i < s.size(); ++i)
    for (int k = 1; k <= split; ++k) out.push_back(flat_if_2d(lerp(s[i - 1], s[i], double(k) / split), dim));
  return out;
}

// Two-sided deviation of one block from the curve; `hint` follows the cut.
// `prev` and `next` are the blocks cut before and after it on that curve
// (empty: none). A curve point between the projections of the block's ends
// counts against the nearest of the three: at a turn sharper than the band
// is wide, vertices off the curve can project back along it, and the
// stretch of curve there is the neighbours' as much as this block's.
double measure_block(const DenseCurve& c, std::span<const Vec3> P, size_t& hint, double tol,
                     std::span<const Vec3> prev = {}, std::span<const Vec3> next = {}) {
  const std::span<const Vec3> D(c.pts);
  double dev = 0;
  // Block -> curve.
  Near first, last;
  size_t h = hint;
  for (size_t i = 0; i < P.size(); ++i) {
    const Near n = nearest(D, P[i], h, tol);
    dev = std::max(dev, n.d);
    h = n.seg;
    if (i == 0) first = n;
    last = n;
  }
  // Curve -> block: the dense points between the projections of the ends.
  auto span_max = [&](size_t a, size_t b) {
    for (size_t i = a; i <= b && i < D.size(); ++i) {
      double d = dist_to_polyline(D[i], P);
      if (d > dev && !prev.empty()) d = std::min(d, dist_to_polyline(D[i], prev));
      if (d > dev && !next.empty()) d = std::min(d, dist_to_polyline(D[i], next));
      dev = std::max(dev, d);
    }
  };
  if (last.seg >= first.seg) {
    span_max(first.seg + 1, last.seg);
  } else if (c.closed) {  // the cut runs over the closing joint
    span_max(first.seg + 1, D.size() - 1);
    span_max(0, last.seg);
  } else {
    span_max(last.seg + 1, first.seg);
  }
  hint = last.seg;
  return dev;
}

// A part's path against the exact offset of its curve at `r`: each point's
// distance from the nearest point of the exact curve, less r. Never more
// than the point's distance from the offset curve (the distance to the
// curve changes no faster than the point moves), and equal to it wherever
// the tool reaches the curve; the program's own check reads the same
// distances (offset_measure.hpp).
double measure_offset_block(PartDistance& part, std::span<const Vec3> P, double r) {
  double dev = 0;
  for (const Vec3& x : P) dev = std::max(dev, std::abs(dist(x, part.nearest(x)) - r));
  return dev;
}

}  // namespace

// A part cut beside its curve (`side` other than "on"): its path is meant to
// be a tool's radius away, so it is measured against the offset, not the
// curve.
bool beside_its_curve(const Job& job, const Entity& e) {
  const auto side = e.params.side ? e.params.side : job.params.side;
  return side && *side != CutSide::on;
}

std::vector<BlockDeviation> block_deviations(const Job& job, std::span<const MotionBlock> motion, double tolerance,
                                             const EntityProgress& on_entity, const PartPaths& parts) {
  if (!(tolerance > 0))
    throw InputError(errc::preview_tolerance, Place::at_setting("deviation"),
                     "needs a tolerance > 0 to measure against");
  std::vector<BlockDeviation> out;
  const size_t total = job.entities.size();
  bool tagged = false;
  for (const auto& m : motion) tagged = tagged || m.entity >= 0;
  auto cutting = [&](size_t i) { return is_feed(motion[i]) && !is_plunge(motion, i); };
  // One curve against its blocks, in cutting order, each with its
  // neighbours (measure_block()); three blocks' points held at a time.
  auto measure_run = [&](const DenseCurve& c, const std::vector<size_t>& run) {
    size_t hint = 0;
    std::vector<Vec3> prev, cur, next = measuring_points(motion[run[0]], tolerance, c.dim);
    for (size_t k = 0; k < run.size(); ++k) {
      prev.swap(cur), cur.swap(next);  // prev <- cur <- next
      next = k + 1 < run.size() ? measuring_points(motion[run[k + 1]], tolerance, c.dim) : std::vector<Vec3>();
      out.push_back({run[k], c.entity, measure_block(c, cur, hint, tolerance, prev, next)});
    }
  };

  if (tagged) {
    // Each entity against its own blocks, in cutting order.
    std::map<int, std::vector<size_t>> by_entity;
    for (size_t i = 0; i < motion.size(); ++i)
      if (cutting(i) && motion[i].entity >= 0) by_entity[motion[i].entity].push_back(i);
    for (const Entity& e : job.entities) {
      if (on_entity) on_entity(e.index, total, e.label());
      auto it = by_entity.find(static_cast<int>(e.index));
      if (it == by_entity.end()) continue;
      const Shape sh = entity_shape(e);
      if (sh.measure.empty()) continue;
      if (!beside_its_curve(job, e)) {
        measure_run(dense_curve(e, sh, tolerance), it->second);
        continue;
      }
      // A part: its path against the exact offset, its leads left out.
      const double r = e.index < parts.offset.size() ? parts.offset[e.index] : 0;
      if (!(r > 0) || sh.dim != 2 || parts.lead.size() != motion.size()) continue;
      const std::vector<std::vector<Bezier>> curves{sh.measure};
      PartDistance part(curves, 0.01 * tolerance);
      for (size_t i : it->second)
        if (!parts.lead[i])
          out.push_back(
              {i, static_cast<int>(e.index), measure_offset_block(part, measuring_points(motion[i], tolerance, 2), r)});
    }
  } else {
    // A program read from text: each block against the nearest curve.
    std::vector<DenseCurve> curves;
    for (const Entity& e : job.entities) {
      if (on_entity) on_entity(e.index, total, e.label());
      const Shape sh = entity_shape(e);
      if (!sh.measure.empty() && !beside_its_curve(job, e)) curves.push_back(dense_curve(e, sh, tolerance));
    }
    // Each block to the curve nearest its middle, then each curve against
    // its blocks in cutting order.
    std::vector<size_t> hints(curves.size(), 0);
    std::vector<std::vector<size_t>> blocks(curves.size());
    for (size_t i = 0; i < motion.size() && !curves.empty(); ++i) {
      if (!cutting(i)) continue;
      const auto& b = motion[i];
      size_t best = 0;
      Near best_n;
      const Vec3 mid = lerp(b.from, b.to, 0.5);
      for (size_t k = 0; k < curves.size(); ++k) {
        const Near n = nearest(curves[k].pts, flat_if_2d(mid, curves[k].dim), hints[k], tolerance);
        if (n.d < best_n.d) best_n = n, best = k;
      }
      hints[best] = best_n.seg;
      blocks[best].push_back(i);
    }
    for (size_t k = 0; k < curves.size(); ++k)
      if (!blocks[k].empty()) measure_run(curves[k], blocks[k]);
  }
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.block < b.block; });
  if (on_entity) on_entity(total, total, "");
  return out;
}

}  // namespace bezcam
