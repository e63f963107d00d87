#include "bezcam/machine/motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bezcam/kernel/knot_vector.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/kernel/quadrature.hpp"

namespace bezcam {

namespace {

// A block for evaluation at t in [0, 1]: the reader's evaluate_block()
// (lines, arcs by angle, Bézier blocks, NURBS over their knot domain), so
// that the report and the preview follow exactly the motion the reader and
// the simulated controller define.
class BlockCurve {
 public:
  explicit BlockCurve(const MotionBlock& b) : b_(b) {}
  Vec3 at(double t) const { return evaluate_block(b_, t); }

 private:
  const MotionBlock& b_;
};

// Adaptive sampling of a curved block on [t0, t1]: split while the curve's
// points at the quarter parameters stray more than `chord` from the chord.
// The uniform start (16 intervals) keeps a loop from hiding between samples.
void refine(const BlockCurve& c, double t0, const Vec3& p0, double t1, const Vec3& p1, double chord, int depth,
            std::vector<Vec3>& out) {
  const double tm = 0.5 * (t0 + t1);
  const Vec3 pm = c.at(tm);
  const Vec3 pq = c.at(0.5 * (t0 + tm)), pr = c.at(0.5 * (tm + t1));
  const double err = std::max({dist_to_segment(pm, p0, p1), dist_to_segment(pq, p0, p1), dist_to_segment(pr, p0, p1)});
  if (err <= chord || depth >= 24) {
    out.push_back(p1);
    return;
  }
  refine(c, t0, p0, tm, pm, chord, depth + 1, out);
  refine(c, tm, pm, t1, p1, chord, depth + 1, out);
}

// Arc length on [t0, t1] from chord sums with Richardson extrapolation: a
// chord misses the arc by O(h^3) and two half chords by a quarter of that,
// so (4 halves - whole) / 3 is accurate to O(h^5); intervals are halved
// until the two chord sums agree to `eps`.
double arc_length(const BlockCurve& c, double t0, const Vec3& p0, double t1, const Vec3& p1, double eps, int depth) {
  const double tm = 0.5 * (t0 + t1);
  const Vec3 pm = c.at(tm);
  const double whole = dist(p0, p1), halves = dist(p0, pm) + dist(pm, p1);
  if (halves - whole <= eps || depth >= 30) return halves + (halves - whole) / 3;
  return arc_length(c, t0, p0, tm, pm, eps / 2, depth + 1) + arc_length(c, tm, pm, t1, p1, eps / 2, depth + 1);
}

// Length of a spiral arc (the controllers' arc whose ends lie at different
// radii after rounding: the radius moves linearly with the angle, as the
// axis does): the integral over s in [0, 1] of sqrt(dr^2 + dz^2 + (w r(s))^2),
// a smooth integrand (r >= 0), by the kernel's adaptive Gauss-Legendre
// quadrature to `eps`.
double spiral_length(double r0, double r1, double w, double dz, double eps) {
  const double a = (r1 - r0) * (r1 - r0) + dz * dz;
  return integrate(
      [&](double s) {
        const double r = w * (r0 + (r1 - r0) * s);
        return std::sqrt(a + r * r);
      },
      0, 1, eps);
}

double box_size(const MotionBlock& b) {
  Box3 box;
  box.add(b.from);
  box.add(b.to);
  for (const auto& c : b.ctrl) box.add(c);
  return std::max(norm(box.hi - box.lo), 1e-12);
}

}  // namespace

double block_length(const MotionBlock& b) {
  switch (b.kind) {
    case BlockKind::rapid:
    case BlockKind::linear: return dist(b.from, b.to);
    case BlockKind::arc_cw:
    case BlockKind::arc_ccw: {
      const Arc a = block_arc(b);
      const double r0 = a.r_start(), r1 = a.r_end();
      const int h = world_axis(a.plane, 2);
      if (r0 == r1) return std::hypot(r0 * a.sweep(), b.to[h] - b.from[h]);  // helix: exact
      return spiral_length(r0, r1, a.sweep(), b.to[h] - b.from[h], 1e-9 * box_size(b));
    }
    default: break;
  }
  // 16 uniform spans first, so that a loop cannot hide between samples.
  const BlockCurve c(b);
  const double eps = 1e-9 * box_size(b);
  double len = 0;
  Vec3 prev = b.from;
  for (int i = 1; i <= 16; ++i) {
    const Vec3 p = c.at(i / 16.0);
    len += arc_length(c, (i - 1) / 16.0, prev, i / 16.0, p, eps / 16, 0);
    prev = p;
  }
  return len;
}

std::vector<Vec3> sample_block(const MotionBlock& b, double chord) {
  if (b.kind == BlockKind::rapid || b.kind == BlockKind::linear) return {b.from, b.to};
  chord = std::max(chord, 1e-12 * box_size(b));
  std::vector<Vec3> out{b.from};
  if (is_arc(b)) {
    // Chord error of an arc step dθ at radius r is r (1 - cos(dθ/2)).
    const Arc a = block_arc(b);
    const double r = std::max({a.r_start(), a.r_end(), 1e-300});
    const double dtheta = 2 * std::acos(std::clamp(1 - chord / r, -1.0, 1.0));
    const int n = std::clamp(static_cast<int>(std::ceil(a.sweep() / std::max(dtheta, 1e-9))), 1, 1 << 20);
    for (int i = 1; i <= n; ++i) out.push_back(evaluate_block(b, double(i) / n));
    return out;
  }
  constexpr int kStart = 16;
  const BlockCurve c(b);
  Vec3 prev = b.from;
  for (int i = 1; i <= kStart; ++i) {
    const double t0 = double(i - 1) / kStart, t1 = double(i) / kStart;
    const Vec3 p1 = c.at(t1);
    refine(c, t0, prev, t1, p1, chord, 0, out);
    prev = p1;
  }
  out.back() = b.to;
  return out;
}

Arc block_arc(const MotionBlock& b) { return {b.from, b.to, b.center, b.kind == BlockKind::arc_ccw, b.plane}; }

double arc_sweep(const MotionBlock& b) { return block_arc(b).sweep(); }

namespace {

// The curve of a NURBS block, in 3D, as the reader collected it.
NurbsCurve block_nurbs(const MotionBlock& b) {
  NurbsCurve c;
  c.dim = 3;
  c.degree = b.order - 1;
  c.points = b.ctrl;
  c.weights = b.weights;
  c.knots = b.knots;
  return c;
}

}  // namespace

Vec3 evaluate_block(const MotionBlock& b, double t) {
  if (t <= 0) return b.from;
  if (t >= 1) return b.to;
  switch (b.kind) {
    case BlockKind::rapid:
    case BlockKind::linear: return lerp(b.from, b.to, t);
    case BlockKind::arc_cw:
    case BlockKind::arc_ccw: return block_arc(b).point(t);
    case BlockKind::bezier: {
      Bezier z;
      z.dim = 3;
      z.points = b.ctrl;
      return evaluate(z, t);
    }
    case BlockKind::nurbs: {
      const NurbsCurve c = block_nurbs(b);
      return evaluate(c, c.domain_start() + (c.domain_end() - c.domain_start()) * t);
    }
  }
  return b.to;
}

std::vector<Bezier> block_to_bezier(const MotionBlock& b) {
  auto bez = [](std::vector<Vec3> pts, std::vector<double> w = {}) {
    Bezier z;
    z.dim = 3;
    z.points = std::move(pts);
    z.weights = std::move(w);
    return z;
  };
  switch (b.kind) {
    case BlockKind::rapid:
    case BlockKind::linear: return {bez({b.from, b.to})};
    case BlockKind::bezier: return {bez(b.ctrl)};
    case BlockKind::nurbs: {
      const NurbsCurve c = block_nurbs(b);
      try {
        validate_knots(c.knots, c.degree, c.points.size());
        for (double w : c.weights)
          if (!(w > 0)) throw std::invalid_argument("weight <= 0");
      } catch (const std::exception& e) {
        throw std::invalid_argument(std::string("block_to_bezier: NURBS block of line ") +
                                    std::to_string(b.first_line) + " cannot be decomposed: " + e.what());
      }
      return to_bezier(c);
    }
    case BlockKind::arc_cw:
    case BlockKind::arc_ccw: {
      const int h = world_axis(b.plane, 2);
      if (b.from[h] != b.to[h]) throw std::invalid_argument("block_to_bezier: helical arc");
      return bezier_pieces(block_arc(b));
    }
  }
  return {};
}

MotionTotals motion_totals(std::span<const MotionBlock> motion, double rapid_rate, int entity) {
  MotionTotals t;
  for (const MotionBlock& m : motion) {
    if (entity != kAllEntities && m.entity != entity) continue;
    const double len = block_length(m);
    if (is_feed(m)) {
      t.feed_length += len;
      ++t.feed_blocks;
      if (m.feed > 0) t.feed_time_s += 60 * len / m.feed;
    } else {
      t.rapid_length += len;
      ++t.rapid_blocks;
    }
  }
  if (rapid_rate > 0) t.rapid_time_s = 60 * t.rapid_length / rapid_rate;
  return t;
}

}  // namespace bezcam
