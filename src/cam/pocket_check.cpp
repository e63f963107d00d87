#include "bezcam/cam/pocket_check.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "bezcam/format.hpp"
#include "pocket_area.hpp"
#include "pocket_grid.hpp"

namespace bezcam {

namespace {

using detail::Piece;
using detail::PocketGrid;

// The moves [from, to) as straight pieces: arcs as chords within `sag`.
std::vector<Piece> replay(const PocketCheckInput& in, double sag) {
  std::vector<Piece> out;
  Vec3 cur = in.start;
  for (size_t i = in.from; i < in.to; ++i) {
    const Move& mv = (*in.moves)[i];
    const Motion* m = motion_of(mv);
    if (!m) continue;
    Vec3 to = cur;
    if (m->axes & kAxisX) to.x = m->to.x;
    if (m->axes & kAxisY) to.y = m->to.y;
    if (m->axes & kAxisZ) to.z = m->to.z;
    const bool rapid = is_rapid(mv);
    if (const auto* a = std::get_if<ArcMove>(&mv.what); a && a->plane == Plane::xy) {
      const double rad = std::hypot(cur.x - a->center.x, cur.y - a->center.y);
      const double a0 = std::atan2(cur.y - a->center.y, cur.x - a->center.x);
      double a1 = std::atan2(to.y - a->center.y, to.x - a->center.x);
      double sweep = a1 - a0;
      if (a->ccw && sweep <= 1e-12) sweep += 2 * std::numbers::pi;
      if (!a->ccw && sweep >= -1e-12) sweep -= 2 * std::numbers::pi;
      const double step = 2 * std::acos(std::clamp(1 - sag / std::max(rad, 1e-12), -1.0, 1.0));
      const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / std::max(step, 1e-3))));
      const double bulge = rad * (1 - std::cos(std::abs(sweep) / (2 * n)));
      Vec3 prev = cur;
      for (int k = 1; k <= n; ++k) {
        const double t = static_cast<double>(k) / n, ang = a0 + sweep * t;
        Vec3 q{a->center.x + rad * std::cos(ang), a->center.y + rad * std::sin(ang), cur.z + (to.z - cur.z) * t};
        if (k == n) q = to;
        out.push_back({prev, q, false, i, true, bulge});
        prev = q;
      }
    } else {
      out.push_back({cur, to, rapid, i});
    }
    cur = to;
  }
  return out;
}

double seg_seg(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  auto cross = [](const Vec3& o, const Vec3& p, const Vec3& q) {
    return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
  };
  const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
  if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0) return 0;
  return std::min({detail::point_segment(c, a, b), detail::point_segment(d, a, b), detail::point_segment(a, c, d),
                   detail::point_segment(b, c, d)});
}

// The tool centre's nearest approach to a wall, over every piece below the
// stock's top, looking no farther than `reach`. A chord of an arc counts
// its sagitta nearer: the arc may bulge that much towards the wall.
void wall_distance(const PocketCheckInput& in, const std::vector<Piece>& path, double reach, PocketCertificate& c) {
  struct Seg {
    Vec3 a, b;
  };
  std::vector<Seg> walls;
  for (const auto& l : in.walls)
    for (size_t i = 0; i < l.size(); ++i) walls.push_back({l[i], l[(i + 1) % l.size()]});
  // Buckets of wall segments, `reach` wide.
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Seg& s : walls)
    for (const Vec3& p : {s.a, s.b})
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  const double b = std::max(reach, (x1 - x0 + y1 - y0) / 400);
  const long nx = static_cast<long>((x1 - x0) / b) + 1, ny = static_cast<long>((y1 - y0) / b) + 1;
  std::vector<std::vector<uint32_t>> bucket(static_cast<size_t>(nx * ny));
  auto cell_of = [&](double v, double o, long n) { return std::clamp(static_cast<long>((v - o) / b), 0L, n - 1); };
  for (size_t k = 0; k < walls.size(); ++k) {
    const Seg& s = walls[k];
    for (long j = cell_of(std::min(s.a.y, s.b.y), y0, ny); j <= cell_of(std::max(s.a.y, s.b.y), y0, ny); ++j)
      for (long i = cell_of(std::min(s.a.x, s.b.x), x0, nx); i <= cell_of(std::max(s.a.x, s.b.x), x0, nx); ++i)
        bucket[static_cast<size_t>(j * nx + i)].push_back(static_cast<uint32_t>(k));
  }
  c.wall_distance = reach;
  std::vector<uint32_t> seen(walls.size(), 0);
  uint32_t stamp = 0;
  for (const Piece& p : path) {
    if (std::min(p.a.z, p.b.z) >= in.top_z) continue;
    ++stamp;
    const long i0 = cell_of(std::min(p.a.x, p.b.x) - reach, x0, nx),
               i1 = cell_of(std::max(p.a.x, p.b.x) + reach, x0, nx);
    const long j0 = cell_of(std::min(p.a.y, p.b.y) - reach, y0, ny),
               j1 = cell_of(std::max(p.a.y, p.b.y) + reach, y0, ny);
    for (long j = j0; j <= j1; ++j)
      for (long i = i0; i <= i1; ++i)
        for (uint32_t k : bucket[static_cast<size_t>(j * nx + i)]) {
          if (seen[k] == stamp) continue;
          seen[k] = stamp;
          const double d = seg_seg(p.a, p.b, walls[k].a, walls[k].b) - p.bulge;
          if (d < c.wall_distance) {
            c.wall_distance = d;
            c.wall_at = detail::point_segment(p.a, walls[k].a, walls[k].b) <= d + p.bulge + 1e-12 ? p.a : p.b;
          }
        }
  }
  c.wall_distance -= in.wall_bound;
}

void rapids(const PocketCheckInput& in, const std::vector<Piece>& path, PocketCertificate& c) {
  const double eps = 1e-9;
  for (const Piece& p : path) {
    if (!p.rapid || std::min(p.a.z, p.b.z) >= in.top_z - eps) continue;
    const bool straight_up = p.a.x == p.b.x && p.a.y == p.b.y && p.b.z >= p.a.z;
    if (straight_up) continue;
    if (c.rapids_in_material++ == 0) c.rapid_at = p.b;
  }
}

// A place that wraps the tool (a sharp corner, a gap narrower than the
// tool and a load each side) where the engagement passes the bound: kept
// once per 2 r (the largest).
void corner_over(PocketCertificate& c, double deg, const Vec3& at, double r) {
  for (auto& p : c.engagement_corners)
    if (std::hypot(p.at.x - at.x, p.at.y - at.y) <= 2 * r) {
      if (deg > p.deg) p.deg = deg, p.at = at;
      return;
    }
  c.engagement_corners.push_back({at, deg});
}

}  // namespace

PocketCertificate check_pocket(const PocketCheckInput& in) {
  const auto t0 = std::chrono::steady_clock::now();
  PocketCertificate c;
  const double r = in.radius, s = in.stock, tol = in.tolerance;
  const double sag = tol / 100;
  const detail::Area region(in.walls);
  PocketGrid g(in.walls, in.cell > 0 ? in.cell : tol, in.max_cells);
  c.cell = g.cell;
  const std::vector<uint8_t> in_region = g.fill(in.walls);
  // R: the centres that keep r + stock off every wall, grown back by r.
  std::vector<uint8_t> in_reach = g.fill_within(region.eroded(r + s, sag).loops(), r);
  std::vector<uint8_t> before(g.size(), 0);
  if (!in.cleared_before.empty()) {
    before = g.fill(in.cleared_before);
    for (size_t k = 0; k < g.size(); ++k) in_reach[k] = in_reach[k] && !before[k];
    c.rest = true;
  }
  for (const auto& l : in.walls)
    for (size_t i = 0; i < l.size(); ++i) c.perimeter += norm(l[(i + 1) % l.size()] - l[i]);
  c.uncut_limit = tol * c.perimeter;
  const double a = g.cell * g.cell;
  c.region_area = region.area();
  // Unreachable: in the region, not in R, farther than the stock left (and
  // half the tolerance) from every wall.
  std::vector<uint8_t> strip(g.size(), 0);
  for (const auto& l : in.walls)
    for (size_t i = 0; i < l.size(); ++i) g.stamp(l[i], l[(i + 1) % l.size()], s + tol / 2, strip, 1);
  std::vector<uint8_t> lost(g.size(), 0);
  for (size_t k = 0; k < g.size(); ++k) lost[k] = in_region[k] && !in_reach[k] && !strip[k];
  for (const auto& [at, n] : g.components(lost, 3)) c.unreachable.push_back({at, static_cast<double>(n) * a});
  for (const auto& p : c.unreachable) c.unreachable_area += p.area;
  for (size_t k = 0; k < g.size(); ++k) c.reachable_area += in_reach[k] ? a : 0;
  // The material the engagement reads: the region less what was cleared
  // before, less the places the tool cannot reach (and the sliver near them).
  std::vector<uint8_t> material = in_region;
  const std::vector<uint8_t> never = g.dilated(lost, in.load);
  // The tool positions whose edge comes within `load` of what no tool
  // position reaches (a sample of it): working in a corner sharper than
  // the tool. The grid's distance (at most 1.09 times the true one) rules
  // most out; the rest are measured.
  const std::vector<double> to_lost = g.distance(lost);
  const double wrap = r + in.load;
  // Or in a gap narrower than the tool and a load each side: walls on
  // two sides (their nearest points more than 90 degrees apart round the
  // position) nearer together than 2 (r + load).
  auto wedged = [&](const Vec3& p) {
    Vec3 n1;
    double d1 = 1e300;
    for (const auto& l : in.walls)
      for (size_t i = 0; i < l.size(); ++i) {
        const Vec3 q = detail::segment_point(p, l[i], l[(i + 1) % l.size()]);
        const double d = std::hypot(q.x - p.x, q.y - p.y);
        if (d < d1) d1 = d, n1 = q;
      }
    for (const auto& l : in.walls)
      for (size_t i = 0; i < l.size(); ++i) {
        const Vec3 q = detail::segment_point(p, l[i], l[(i + 1) % l.size()]);
        const double d = std::hypot(q.x - p.x, q.y - p.y);
        if (d1 + d < 2 * wrap && (q.x - p.x) * (n1.x - p.x) + (q.y - p.y) * (n1.y - p.y) < 0) return true;
      }
    return false;
  };
  auto corner = [&](const Vec3& p) {
    if (wedged(p)) return true;
    const long i = static_cast<long>(std::floor((p.x - g.x0) / g.cell)),
               j = static_cast<long>(std::floor((p.y - g.y0) / g.cell));
    if (i < 0 || j < 0 || i >= g.nx || j >= g.ny ||
        to_lost[static_cast<size_t>(j * g.nx + i)] > 1.09 * wrap + 2 * g.cell)
      return false;
    const long m = static_cast<long>(std::ceil(wrap / g.cell)) + 1;
    for (long v = std::max(0L, j - m); v <= std::min(g.ny - 1, j + m); ++v)
      for (long u = std::max(0L, i - m); u <= std::min(g.nx - 1, i + m); ++u) {
        const size_t k = static_cast<size_t>(v * g.nx + u);
        if (!lost[k]) continue;
        const Vec3 q = g.sample(k);
        if (std::hypot(q.x - p.x, q.y - p.y) <= wrap) return true;
      }
    return false;
  };
  const double bound =
      in.load > 0 ? std::acos(std::clamp(1 - in.load / r, -1.0, 1.0)) * 180 / std::numbers::pi + 2 : 1e300;
  for (size_t k = 0; k < g.size(); ++k) material[k] = material[k] && !before[k] && !never[k];

  const std::vector<Piece> path = replay(in, sag);
  for (size_t li = 0; li < in.levels.size(); ++li) {
    const double z = in.levels[li], above = li == 0 ? in.top_z : in.levels[li - 1];
    std::vector<Piece> level, into;  // at z; and at z or descending into the level
    for (const Piece& p : path) {
      if (p.rapid) continue;
      const double lo = std::min(p.a.z, p.b.z), hi = std::max(p.a.z, p.b.z);
      if (std::abs(lo - z) < 1e-9 && std::abs(hi - z) < 1e-9) {
        level.push_back(p);
        into.push_back(p);
      } else if (lo >= z - 1e-9 && hi <= above + 1e-9 && lo < above - 1e-9) {
        into.push_back(p);
        into.back().measure = false;
      }
    }
    std::vector<uint8_t> cut(g.size(), 0);
    for (const Piece& p : level) g.stamp(p.a, p.b, r + tol - sag, cut, 1);
    size_t uncut = 0;
    Vec3 at;
    for (size_t k = 0; k < g.size(); ++k)
      if (in_reach[k] && !cut[k] && uncut++ == 0) at = g.sample(k);
    if (static_cast<double>(uncut) * a > c.uncut_area || (uncut > 0 && c.uncut_area == 0)) {
      c.uncut_area = static_cast<double>(uncut) * a;
      c.uncut_at = at;
      c.uncut_z = z;
    }
    if (in.engagement) {
      const auto e = g.engagement(into, r, material, corner, bound);
      if (e.deg > c.engagement_deg) c.engagement_deg = e.deg, c.engagement_at = e.at;
      if (e.away_deg > c.engagement_away_deg) c.engagement_away_deg = e.away_deg, c.engagement_away_at = e.away_at;
      for (const auto& [deg, where] : e.zone_over) corner_over(c, deg, where, r);
    }
  }
  std::sort(c.engagement_corners.begin(), c.engagement_corners.end(),
            [](const PocketEngagementPlace& p, const PocketEngagementPlace& q) { return p.deg > q.deg; });
  if (in.load > 0) c.engagement_bound = bound;
  wall_distance(in, path, r + s + 10 * tol + g.cell, c);
  rapids(in, path, c);
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return c;
}

std::vector<std::string> certificate_lines(const std::string& label, const PocketCertificate& c, double radius,
                                           double stock, const std::string& units) {
  const auto sig = [](double v) { return format_significant(v, 4); };
  const std::string head = "pocket " + label + ": ";
  std::string uncut = head + "uncut " + sig(c.uncut_area) + " " + units + "^2 at the worst level" +
                      (c.rest ? " of the " + sig(c.reachable_area) + " " + units + "^2 the tool before left" : "") +
                      ", limit " + sig(c.uncut_limit) + " = tolerance x perimeter";
  if (c.uncut_area > 0) uncut += ", at " + sig(c.uncut_at.x) + ", " + sig(c.uncut_at.y) + " z " + sig(c.uncut_z);
  uncut += "; checked on a " + sig(c.cell) + " " + units + " grid";
  std::string reach = head + "unreachable " + sig(c.unreachable_area) + " " + units + "^2 in " +
                      std::to_string(c.unreachable.size()) + (c.unreachable.size() == 1 ? " place" : " places") +
                      "; nearest approach to a wall " + sig(c.wall_distance) + " " + units + " at " + sig(c.wall_at.x) +
                      ", " + sig(c.wall_at.y) + ", asked r + stock " + sig(radius + stock);
  std::string eng = head + "largest engagement " + sig(c.engagement_deg) + " deg at " + sig(c.engagement_at.x) + ", " +
                    sig(c.engagement_at.y) +
                    (c.engagement_bound > 0 ? ", bound arccos(1 - load/r) + 2 = " + sig(c.engagement_bound) : "") +
                    " [a full slot: 180]; ";
  if (!c.engagement_corners.empty())
    eng += "elsewhere than " + std::to_string(c.engagement_corners.size()) +
           (c.engagement_corners.size() == 1 ? " place that wraps" : " places that wrap") + " the tool at most " +
           sig(c.engagement_away_deg) + " deg at " + sig(c.engagement_away_at.x) + ", " + sig(c.engagement_away_at.y) +
           "; ";
  eng += c.rapids_in_material == 0 ? "no rapid through material"
                                   : std::to_string(c.rapids_in_material) + " rapids through material";
  return {uncut, reach, eng};
}

}  // namespace bezcam
