// The passes of a pocket (docs/pocket.md, "How the passes are made"):
// rings parallel to the walls from the inside out, or parallel lines and a
// ring along the walls; then, where the grid finds material the passes
// leave (the centre of a square, the middle of a sharp corner), a short
// move out of a pass and back that reaches it.
#include "pocket_plan.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "pocket_grid.hpp"

namespace bezcam::detail {

namespace {

PocketPass pass_of(std::vector<Vec3> pts, bool linked) {
  PocketPass p;
  p.pts = std::move(pts);
  p.linked = linked;
  return p;
}

// A ring as a closed pass in the direction asked: Boost's rings run
// clockwise round the area (outer rings) and counter-clockwise round its
// holes; climb milling keeps the wall on the tool's right, against that.
std::vector<Vec3> closed_pass(std::vector<Vec3> ring, bool climb) {
  if (climb) std::reverse(ring.begin(), ring.end());
  if (!ring.empty()) ring.push_back(ring.front());
  return ring;
}

// The ring turned to start at its vertex nearest `p`.
void start_near(std::vector<Vec3>& pts, const Vec3& p) {
  if (pts.size() < 3 || dist_xy(pts.front(), pts.back()) > 0) return;
  pts.pop_back();
  size_t best = 0;
  for (size_t i = 1; i < pts.size(); ++i)
    if (dist_xy(pts[i], p) < dist_xy(pts[best], p)) best = i;
  std::rotate(pts.begin(), pts.begin() + static_cast<long>(best), pts.end());
  pts.push_back(pts.front());
}

struct Node {
  Area area;
  std::vector<size_t> children;
};

// Offset rings: the area at d0, d0 + s, d0 + 2s, ... as a tree (a piece
// holds the pieces of the next ring inside it); a piece with nothing
// inside gets one more ring where it is about to vanish, near its middle.
std::vector<PocketPass> offset_rings(const Area& region, const PocketPlanInput& in, double d0, double sag) {
  std::vector<Node> nodes;
  std::vector<size_t> roots, level;
  for (const Area& a : region.eroded(d0, sag).pieces()) {
    roots.push_back(nodes.size());
    level.push_back(nodes.size());
    nodes.push_back({a, {}});
  }
  const double s = in.stepover;
  for (int k = 1; !level.empty() && k < 100000; ++k) {
    std::vector<size_t> next;
    for (const Area& a : region.eroded(d0 + k * s, sag).pieces()) {
      const Vec3 v = a.rings().front().front();
      for (size_t p : level)
        if (nodes[p].area.covers(v)) {
          nodes[p].children.push_back(nodes.size());
          next.push_back(nodes.size());
          nodes.push_back({a, {}});
          break;
        }
    }
    for (size_t p : level) {
      if (!nodes[p].children.empty()) continue;
      double lo = 0, hi = s;
      Area last;
      for (int it = 0; it < 7; ++it) {
        const double mid = (lo + hi) / 2;
        Area e = nodes[p].area.eroded(mid, sag);
        if (e.empty())
          hi = mid;
        else
          lo = mid, last = e;
      }
      if (lo > s / 16 && !last.empty()) {
        nodes[p].children.push_back(nodes.size());
        nodes.push_back({last, {}});
      }
    }
    level = std::move(next);
  }
  // Children first, then the ring around them: from the inside out.
  std::vector<PocketPass> out;
  std::function<void(size_t)> walk = [&](size_t n) {
    for (size_t c : nodes[n].children) walk(c);
    for (auto& ring : nodes[n].area.rings()) out.push_back(pass_of(closed_pass(std::move(ring), in.climb), false));
  };
  for (size_t r : roots) walk(r);
  return out;
}

// Zigzag: lines at `angle` across the area eroded by d0 + s/2, spaced s.
std::vector<PocketPass> zigzag_lines(const Area& region, const PocketPlanInput& in, double d0, double sag) {
  const Area inner = region.eroded(d0 + in.stepover / 2, sag);
  const double a = in.angle_deg * std::numbers::pi / 180, ca = std::cos(a), sa = std::sin(a);
  auto to_local = [&](const Vec3& p) { return Vec3{p.x * ca + p.y * sa, -p.x * sa + p.y * ca, 0}; };
  auto to_world = [&](double u, double v) { return Vec3{u * ca - v * sa, u * sa + v * ca, 0}; };
  std::vector<std::vector<Vec3>> loops;
  double lo = std::numeric_limits<double>::max(), hi = -lo;
  for (const auto& ring : inner.rings()) {
    std::vector<Vec3> l;
    for (const Vec3& p : ring) {
      l.push_back(to_local(p));
      lo = std::min(lo, l.back().y), hi = std::max(hi, l.back().y);
    }
    loops.push_back(std::move(l));
  }
  std::vector<std::vector<std::pair<double, double>>> lines;
  std::vector<double> vs;
  if (!loops.empty()) {
    const int n = std::max(1, static_cast<int>(std::ceil((hi - lo) / in.stepover)));
    const double step = (hi - lo) / n;
    for (int i = 0; i <= n; ++i) {
      // Nudged off the ends so that a line never runs along an edge.
      const double v = std::clamp(lo + i * step, lo + 1e-7, hi - 1e-7);
      std::vector<double> xs;
      for (const auto& l : loops)
        for (size_t k = 0; k < l.size(); ++k) {
          const Vec3 &p = l[k], &q = l[(k + 1) % l.size()];
          if ((p.y > v) != (q.y > v)) xs.push_back(p.x + (q.x - p.x) * (v - p.y) / (q.y - p.y));
        }
      std::sort(xs.begin(), xs.end());
      std::vector<std::pair<double, double>> segs;
      for (size_t k = 0; k + 1 < xs.size(); k += 2) segs.push_back({xs[k], xs[k + 1]});
      lines.push_back(std::move(segs));
      vs.push_back(v);
    }
  }
  // Greedy boustrophedon: from each segment's end, the nearest unvisited
  // end on the next line; else the nearest unvisited segment anywhere.
  struct Seg {
    Vec3 a, b;
    size_t line;
    bool done = false;
  };
  std::vector<Seg> segs;
  for (size_t i = 0; i < lines.size(); ++i)
    for (const auto& [u0, u1] : lines[i]) segs.push_back({to_world(u0, vs[i]), to_world(u1, vs[i]), i});
  std::vector<PocketPass> out;
  Vec3 at = segs.empty() ? Vec3{} : segs.front().a;
  size_t cur_line = 0;
  for (size_t left = segs.size(); left > 0; --left) {
    size_t best = segs.size();
    bool flip = false, near = false;
    double bd = std::numeric_limits<double>::max();
    for (size_t k = 0; k < segs.size(); ++k) {
      if (segs[k].done) continue;
      const bool adjacent = !out.empty() && (segs[k].line == cur_line + 1 || segs[k].line + 1 == cur_line);
      for (int e = 0; e < 2; ++e) {
        const Vec3& p = e == 0 ? segs[k].a : segs[k].b;
        const double d = dist_xy(p, at);
        const bool ok = adjacent && d <= 2 * in.stepover && inner.covers(at, p);
        if ((ok && !near) || (ok == near && d < bd)) best = k, flip = e == 1, bd = d, near = ok;
      }
    }
    Seg& s = segs[best];
    s.done = true;
    const Vec3 p = flip ? s.b : s.a, q = flip ? s.a : s.b;
    out.push_back(pass_of({p, q}, near));
    at = q;
    cur_line = s.line;
  }
  // The ring along the walls.
  for (auto& ring : region.eroded(d0, sag).rings())
    out.push_back(pass_of(closed_pass(std::move(ring), in.climb), false));
  return out;
}

// Feeds from one pass to the next where the straight line lies in the
// centres' area and the tool centre stays in what the passes before it
// cleared (within r of them, read every r / 8): links never cut into
// material with the centre; elsewhere the tool goes over the clearance
// plane and enters again.
// A ring entered anew starts where a helix fits: at its start, else at the
// middle of one of its longest edges.
void start_where_helix_fits(std::vector<Vec3>& pts, const Area& centres, double R) {
  if (R <= 0 || pts.size() < 4 || dist_xy(pts.front(), pts.back()) > 0) return;
  double used = 0;
  if (helix_centre(centres, pts.front(), R, 0, used)) return;
  std::vector<size_t> edges(pts.size() - 1);
  for (size_t i = 0; i < edges.size(); ++i) edges[i] = i;
  std::sort(edges.begin(), edges.end(),
            [&](size_t a, size_t b) { return dist_xy(pts[a], pts[a + 1]) > dist_xy(pts[b], pts[b + 1]); });
  for (size_t k = 0; k < edges.size() && k < 6; ++k) {
    const size_t e = edges[k];
    const Vec3 mid{(pts[e].x + pts[e + 1].x) / 2, (pts[e].y + pts[e + 1].y) / 2, 0};
    if (!helix_centre(centres, mid, R, 0, used)) continue;
    pts.pop_back();
    pts.insert(pts.begin() + static_cast<long>(e) + 1, mid);
    std::rotate(pts.begin(), pts.begin() + static_cast<long>(e) + 1, pts.end());
    pts.push_back(pts.front());
    return;
  }
}

void link(std::vector<PocketPass>& passes, const Area& centres, double r, double helix_r, const Area& free) {
  if (!passes.empty()) start_where_helix_fits(passes.front().pts, centres, helix_r);
  for (size_t i = 1; i < passes.size(); ++i) {
    auto& p = passes[i];
    const Vec3 end = passes[i - 1].pts.back();
    start_near(p.pts, end);
    const Vec3 to = p.pts.front();
    const double len = dist_xy(end, to);
    if (!centres.covers(end, to)) continue;
    const int n = std::max(1, static_cast<int>(std::ceil(len / (r / 8))));
    bool cleared = true;
    for (int k = 1; k <= n && cleared; ++k) {
      const double t = static_cast<double>(k) / n;
      const Vec3 q{end.x + (to.x - end.x) * t, end.y + (to.y - end.y) * t, 0};
      bool near = free.covers(q);
      for (size_t j = i; j-- > 0 && !near;)
        for (size_t m = 0; m + 1 < passes[j].pts.size() && !near; ++m)
          near = point_segment(q, passes[j].pts[m], passes[j].pts[m + 1]) <= r;
      cleared = near;
    }
    p.linked = cleared;
    if (!p.linked) start_where_helix_fits(p.pts, centres, helix_r);
  }
}

// Where the passes leave material a tool could reach: a move out of the
// nearest pass to a point within r of it, and back. Repeats until the grid
// finds none (or no such move stays in the centres' area).
size_t clean_up(std::vector<PocketPass>& passes, const Area& region, const Area& centres, const PocketPlanInput& in,
                double sag, const Area& before) {
  const double r = in.radius;
  PocketGrid g(in.walls, in.cell, 2'000'000);
  std::vector<uint8_t> in_reach = g.fill_within(region.eroded(r + in.stock, sag).loops(), r);
  if (!before.empty()) {
    const std::vector<uint8_t> b = g.fill(before.loops());
    for (size_t k = 0; k < g.size(); ++k) in_reach[k] = in_reach[k] && !b[k];
  }
  size_t added = 0;
  for (int round = 0; round < 12; ++round) {
    std::vector<uint8_t> left = in_reach;
    for (const auto& p : passes)
      for (size_t k = 0; k + 1 < p.pts.size(); ++k)
        g.stamp(p.pts[k], p.pts[k + 1], r + in.tolerance / 2 - in.fit, left, 0);
    const auto pieces = g.components(left, 1);
    if (pieces.empty()) break;
    struct Spur {
      size_t pass, seg;
      Vec3 a, t;
    };
    std::vector<Spur> spurs;
    for (const auto& [q, n] : pieces) {
      Spur best{0, 0, {}, {}};
      double bd = std::numeric_limits<double>::max();
      for (size_t i = 0; i < passes.size(); ++i)
        for (size_t k = 0; k + 1 < passes[i].pts.size(); ++k) {
          const double d = point_segment(q, passes[i].pts[k], passes[i].pts[k + 1]);
          if (d >= bd) continue;
          const Vec3 &a = passes[i].pts[k], &b = passes[i].pts[k + 1];
          const double l2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
          const double t =
              l2 > 0 ? std::clamp(((q.x - a.x) * (b.x - a.x) + (q.y - a.y) * (b.y - a.y)) / l2, 0.0, 1.0) : 0;
          bd = d;
          best = {i, k, {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), 0}, {}};
        }
      const double d = dist_xy(q, best.a);
      if (d <= r) continue;  // within reach already: a sample at the grid's edge
      const double f = (d - r + in.tolerance / 4) / d;
      best.t = {best.a.x + (q.x - best.a.x) * f, best.a.y + (q.y - best.a.y) * f, 0};
      if (!centres.covers(best.a, best.t)) continue;
      spurs.push_back(best);
    }
    if (spurs.empty()) break;
    std::sort(spurs.begin(), spurs.end(),
              [](const Spur& x, const Spur& y) { return x.pass != y.pass ? x.pass < y.pass : x.seg > y.seg; });
    for (const Spur& s : spurs) {
      auto& pts = passes[s.pass].pts;
      pts.insert(pts.begin() + static_cast<long>(s.seg) + 1, {s.a, s.t, s.a});
      ++added;
    }
  }
  return added;
}

// Rest machining: the parts of the passes whose tool reaches what the tool
// before left (the reachable set less `before`, grown by a tenth of the
// radius into `before`), each from a point where the tool reaches none of it.
std::vector<PocketPass> rest_parts(const std::vector<PocketPass>& passes, const Area& region, const Area& before,
                                   const PocketPlanInput& in, double sag) {
  const double r = in.radius;
  PocketGrid g(in.walls, std::max(in.cell, r / 40), 1'000'000);
  const std::vector<uint8_t> in_reach = g.fill_within(region.eroded(r + in.stock, sag).loops(), r);
  std::vector<uint8_t> left = in_reach;
  const std::vector<uint8_t> b = g.fill(before.loops());
  for (size_t k = 0; k < g.size(); ++k) left[k] = left[k] && !b[k];
  // Grown by a tenth of the radius into what the tool before cut.
  left = g.dilated(left, r / 10);
  for (size_t k = 0; k < g.size(); ++k) left[k] = left[k] && in_reach[k];
  // Whether the tool at p reaches a sample of `left`: the samples within r.
  const long reach_cells = static_cast<long>(std::ceil(r / g.cell)) + 1;
  auto touches = [&](const Vec3& p) {
    const long ci = static_cast<long>(std::floor((p.x - g.x0) / g.cell)),
               cj = static_cast<long>(std::floor((p.y - g.y0) / g.cell));
    for (long j = std::max(0L, cj - reach_cells); j <= std::min(g.ny - 1, cj + reach_cells); ++j)
      for (long i = std::max(0L, ci - reach_cells); i <= std::min(g.nx - 1, ci + reach_cells); ++i) {
        const size_t k = static_cast<size_t>(j * g.nx + i);
        if (left[k] && dist_xy(g.sample(k), p) <= r + g.cell) return true;
      }
    return false;
  };
  std::vector<PocketPass> out;
  for (const PocketPass& pass : passes) {
    std::vector<Vec3> dense;
    for (size_t i = 0; i + 1 < pass.pts.size(); ++i) {
      const int m = std::max(1, static_cast<int>(std::ceil(dist_xy(pass.pts[i], pass.pts[i + 1]) / (r / 4))));
      for (int k = 0; k < m; ++k) {
        const double t = static_cast<double>(k) / m;
        dense.push_back({pass.pts[i].x + (pass.pts[i + 1].x - pass.pts[i].x) * t,
                         pass.pts[i].y + (pass.pts[i + 1].y - pass.pts[i].y) * t, 0});
      }
    }
    if (!pass.pts.empty()) dense.push_back(pass.pts.back());
    std::vector<uint8_t> t(dense.size());
    for (size_t i = 0; i < dense.size(); ++i) t[i] = touches(dense[i]);
    for (size_t i = 0; i < dense.size();) {
      if (!t[i]) {
        ++i;
        continue;
      }
      size_t j = i;
      while (j < dense.size() && t[j]) ++j;
      const size_t a = i > 0 ? i - 1 : 0, e = std::min(j, dense.size() - 1);
      out.push_back(pass_of(
          std::vector<Vec3>(dense.begin() + static_cast<long>(a), dense.begin() + static_cast<long>(e) + 1), false));
      i = j + 1;
    }
  }
  return out;
}

}  // namespace

std::optional<Vec3> helix_centre(const Area& centres, const Vec3& p, double R, double grow, double& used) {
  for (double rad : {R, R * 0.75, R * 0.5, R * 0.25}) {
    // A 24-gon around the circle holds it; the circle keeps that far off p.
    const double out = rad / std::cos(std::numbers::pi / 24) + grow;
    const double gap = out - rad + grow;
    for (int k = 0; k < 16; ++k) {
      const double phi = 2 * std::numbers::pi * k / 16;
      const Vec3 c{p.x + (rad + gap) * std::cos(phi), p.y + (rad + gap) * std::sin(phi), 0};
      std::vector<Vec3> poly;
      for (int j = 0; j < 24; ++j) {
        const double a = 2 * std::numbers::pi * j / 24;
        poly.push_back({c.x + out * std::cos(a), c.y + out * std::sin(a), 0});
      }
      if (!centres.covers_polygon(poly) || !centres.covers(p, c)) continue;
      used = rad;
      return c;
    }
  }
  return std::nullopt;
}

PocketPlan plan_pocket(const PocketPlanInput& in) {
  PocketPlan plan;
  const Area region(in.walls);
  const double sag = in.sag > 0 ? in.sag : in.tolerance / 20;
  const double d_wall = in.radius + in.stock + in.margin + 2 * sag;
  const double d0 = d_wall + in.finish;
  plan.centres = region.eroded(d_wall, sag);
  if (plan.centres.empty()) return plan;
  if (in.rest_from) {
    // What the tool before reached, by the same rule: the region eroded by
    // its radius + stock and grown back by its radius.
    const double rb = *in.rest_from;
    plan.before = region.eroded(rb + in.stock, sag).eroded(-rb, sag);
  }
  if (in.pattern == PocketPattern::adaptive) {
    plan.passes = adaptive_passes(region, plan.centres, plan.before, in, d_wall);
    std::erase_if(plan.passes, [](const PocketPass& p) { return p.pts.size() < 2; });
    return plan;
  }
  plan.passes =
      in.pattern == PocketPattern::offset ? offset_rings(region, in, d0, sag) : zigzag_lines(region, in, d0, sag);
  if (in.finish > 0)
    for (auto& ring : plan.centres.rings())
      plan.passes.push_back(pass_of(closed_pass(std::move(ring), in.climb), false));
  if (in.rest_from) plan.passes = rest_parts(plan.passes, region, plan.before, in, sag);
  std::erase_if(plan.passes, [](const PocketPass& p) { return p.pts.size() < 2; });
  link(plan.passes, plan.centres, in.radius, in.helix_radius, plan.before.eroded(in.radius, sag));
  plan.cleanup = clean_up(plan.passes, region, plan.centres, in, sag, plan.before);
  return plan;
}

}  // namespace bezcam::detail
