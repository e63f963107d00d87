#include "pocket_grid.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>

namespace bezcam::detail {

Vec3 segment_point(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0;
  return {a.x + t * dx, a.y + t * dy, 0};
}

double point_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 q = segment_point(p, a, b);
  return std::hypot(p.x - q.x, p.y - q.y);
}

PocketGrid::PocketGrid(const PocketLoops& bounds, double c, size_t max_cells) {
  double x1 = -1e300, y1 = -1e300;
  x0 = y0 = 1e300;
  for (const auto& l : bounds)
    for (const Vec3& p : l)
      x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  if (x1 < x0) x0 = y0 = x1 = y1 = 0;
  const double w = x1 - x0, h = y1 - y0;
  cell = std::max(c, std::sqrt(w * h / static_cast<double>(max_cells)));
  while ((w / cell + 3) * (h / cell + 3) > static_cast<double>(max_cells)) cell *= 1.05;
  x0 -= cell, y0 -= cell;
  nx = static_cast<long>(std::ceil((w + 2 * cell) / cell)) + 1;
  ny = static_cast<long>(std::ceil((h + 2 * cell) / cell)) + 1;
}

Vec3 PocketGrid::sample(size_t k) const {
  const long i = static_cast<long>(k) % nx, j = static_cast<long>(k) / nx;
  return {x0 + (static_cast<double>(i) + 0.5) * cell, y0 + (static_cast<double>(j) + 0.5) * cell, 0};
}

std::vector<uint8_t> PocketGrid::fill(const PocketLoops& loops) const {
  std::vector<std::vector<double>> cross(static_cast<size_t>(ny));
  for (const auto& l : loops)
    for (size_t i = 0, n = l.size(); i < n; ++i) {
      const Vec3 &p = l[i], &q = l[(i + 1) % n];
      if (p.y == q.y) continue;
      const double lo = std::min(p.y, q.y), hi = std::max(p.y, q.y);
      // Rows whose sample line y crosses [lo, hi) (half-open: a vertex counts once).
      const long j0 = std::max(0L, static_cast<long>(std::ceil((lo - y0) / cell - 0.5)));
      const long j1 = std::min(ny - 1, static_cast<long>(std::ceil((hi - y0) / cell - 0.5)) - 1);
      for (long j = j0; j <= j1; ++j) {
        const double y = y0 + (static_cast<double>(j) + 0.5) * cell;
        if (y < lo || y >= hi) continue;
        cross[static_cast<size_t>(j)].push_back(p.x + (q.x - p.x) * (y - p.y) / (q.y - p.y));
      }
    }
  std::vector<uint8_t> out(size(), 0);
  for (long j = 0; j < ny; ++j) {
    auto& xs = cross[static_cast<size_t>(j)];
    std::sort(xs.begin(), xs.end());
    for (size_t k = 0; k + 1 < xs.size(); k += 2) {
      const long i0 = std::max(0L, static_cast<long>(std::ceil((xs[k] - x0) / cell - 0.5)));
      const long i1 = std::min(nx - 1, static_cast<long>(std::floor((xs[k + 1] - x0) / cell - 0.5)));
      if (i0 <= i1) std::fill_n(out.begin() + j * nx + i0, i1 - i0 + 1, uint8_t{1});
    }
  }
  return out;
}

std::vector<uint8_t> PocketGrid::fill_within(const PocketLoops& loops, double radius) const {
  std::vector<uint8_t> out = fill(loops);
  for (const auto& l : loops)
    for (size_t i = 0, n = l.size(); i < n; ++i) stamp(l[i], l[(i + 1) % n], radius, out, 1);
  return out;
}

void PocketGrid::stamp(const Vec3& a, const Vec3& b, double radius, std::vector<uint8_t>& bits, uint8_t v) const {
  const Capsule c(a, b, radius);
  const auto [j0, j1] = rows(c);
  for (long j = j0; j <= j1; ++j) {
    const auto [i0, i1] = span(c, j);
    // One run of bytes (a loop storing through the vector's uint8_t may
    // alias its own pointer and writes a byte per iteration).
    if (i0 <= i1) std::fill_n(bits.begin() + j * nx + i0, i1 - i0 + 1, v);
  }
}

std::pair<long, long> PocketGrid::rows(const Capsule& c) const {
  return {std::max(0L, static_cast<long>(std::floor((std::min(c.a.y, c.b.y) - c.radius - y0) / cell - 0.5))),
          std::min(ny - 1, static_cast<long>(std::ceil((std::max(c.a.y, c.b.y) + c.radius - y0) / cell - 0.5)))};
}

std::vector<std::pair<Vec3, size_t>> PocketGrid::components(const std::vector<uint8_t>& bits, size_t min) const {
  std::vector<std::pair<Vec3, size_t>> out;
  std::vector<int> depth(size(), -1);
  std::vector<size_t> members;
  std::deque<size_t> q;
  auto nbrs = [&](size_t k, auto&& f) {
    const long i = static_cast<long>(k) % nx, j = static_cast<long>(k) / nx;
    if (i > 0) f(k - 1);
    if (i + 1 < nx) f(k + 1);
    if (j > 0) f(k - static_cast<size_t>(nx));
    if (j + 1 < ny) f(k + static_cast<size_t>(nx));
  };
  std::vector<uint8_t> seen(size(), 0);
  for (size_t s = 0; s < size(); ++s) {
    if (!bits[s] || seen[s]) continue;
    members.clear();
    q.push_back(s);
    seen[s] = 1;
    while (!q.empty()) {
      const size_t k = q.front();
      q.pop_front();
      members.push_back(k);
      nbrs(k, [&](size_t n) {
        if (bits[n] && !seen[n]) seen[n] = 1, q.push_back(n);
      });
    }
    if (members.size() < min) continue;
    // Layers from the piece's edge inward: the deepest sample stands for it.
    for (size_t k : members) {
      bool edge = false;
      nbrs(k, [&](size_t n) { edge = edge || !bits[n]; });
      const long i = static_cast<long>(k) % nx, j = static_cast<long>(k) / nx;
      edge = edge || i == 0 || j == 0 || i + 1 == nx || j + 1 == ny;
      if (edge) depth[k] = 0, q.push_back(k);
    }
    size_t deepest = members.front();
    while (!q.empty()) {
      const size_t k = q.front();
      q.pop_front();
      if (depth[k] > depth[deepest]) deepest = k;
      nbrs(k, [&](size_t n) {
        if (bits[n] && depth[n] < 0) depth[n] = depth[k] + 1, q.push_back(n);
      });
    }
    out.push_back({sample(deepest), members.size()});
  }
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return out;
}

std::vector<double> PocketGrid::distance(const std::vector<uint8_t>& bits) const {
  // Two passes of the 8-neighbour chamfer distance (steps 1 and sqrt 2, in cells).
  const double big = 1e30, diag = std::sqrt(2.0);
  std::vector<double> dist(size(), big);
  for (size_t k = 0; k < size(); ++k)
    if (bits[k]) dist[k] = 0;
  auto at = [&](long i, long j) -> double& { return dist[static_cast<size_t>(j * nx + i)]; };
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      double& v = at(i, j);
      if (i > 0) v = std::min(v, at(i - 1, j) + 1);
      if (j > 0) v = std::min(v, at(i, j - 1) + 1);
      if (i > 0 && j > 0) v = std::min(v, at(i - 1, j - 1) + diag);
      if (i + 1 < nx && j > 0) v = std::min(v, at(i + 1, j - 1) + diag);
    }
  for (long j = ny; j-- > 0;)
    for (long i = nx; i-- > 0;) {
      double& v = at(i, j);
      if (i + 1 < nx) v = std::min(v, at(i + 1, j) + 1);
      if (j + 1 < ny) v = std::min(v, at(i, j + 1) + 1);
      if (i + 1 < nx && j + 1 < ny) v = std::min(v, at(i + 1, j + 1) + diag);
      if (i > 0 && j + 1 < ny) v = std::min(v, at(i - 1, j + 1) + diag);
    }
  for (double& v : dist) v *= cell;
  return dist;
}

std::vector<uint8_t> PocketGrid::dilated(const std::vector<uint8_t>& bits, double d) const {
  if (!(d > 0)) return bits;
  const std::vector<double> dist = distance(bits);
  std::vector<uint8_t> out(size());
  for (size_t k = 0; k < size(); ++k) out[k] = dist[k] <= d;
  return out;
}

PocketGrid::Engagement PocketGrid::engagement(const std::vector<Piece>& pieces, double r, std::vector<uint8_t> material,
                                              const std::function<bool(const Vec3&)>& in_zone, double limit) const {
  constexpr int kSamples = 90;  // 2 degrees each over the front half
  double cs[kSamples], sn[kSamples];
  for (int k = 0; k < kSamples; ++k) {
    const double th = -std::numbers::pi / 2 + (k + 0.5) * std::numbers::pi / kSamples;
    cs[k] = std::cos(th), sn[k] = std::sin(th);
  }
  Engagement e;
  auto at = [&](double x, double y) -> long {
    const long i = static_cast<long>(std::floor((x - x0) / cell)), j = static_cast<long>(std::floor((y - y0) / cell));
    return i >= 0 && j >= 0 && i < nx && j < ny ? j * nx + i : -1;
  };
  auto held = [&](double x, double y) {
    const long k = at(x, y);
    return k >= 0 && material[static_cast<size_t>(k)];
  };
  for (const Piece& p : pieces) {
    const double len = std::hypot(p.b.x - p.a.x, p.b.y - p.a.y);
    if (len > 0 && p.measure) {
      const double ux = (p.b.x - p.a.x) / len, uy = (p.b.y - p.a.y) / len;
      const int steps = std::max(1, static_cast<int>(std::ceil(len / cell)));
      for (int s = 0; s <= steps; ++s) {
        const double t = len * s / steps, cx = p.a.x + ux * t, cy = p.a.y + uy * t;
        int n = 0;
        for (int k = 0; k < kSamples; ++k) {
          const double dx = ux * cs[k] - uy * sn[k], dy = ux * sn[k] + uy * cs[k];
          n += held(cx + r * dx, cy + r * dy);
        }
        const double deg = 180.0 * n / kSamples;
        const Vec3 c{cx, cy, p.a.z};
        if (deg > e.deg) e.deg = deg, e.at = c;
        if (deg <= e.away_deg && deg <= limit) continue;
        if (!in_zone(c)) {
          if (deg > e.away_deg) e.away_deg = deg, e.away_at = c;
        } else if (deg > limit) {
          auto near = std::find_if(e.zone_over.begin(), e.zone_over.end(), [&](const auto& z) {
            return std::hypot(z.second.x - cx, z.second.y - cy) <= 2 * r;
          });
          if (near == e.zone_over.end())
            e.zone_over.push_back({deg, c});
          else if (deg > near->first)
            *near = {deg, c};
        }
      }
    }
    stamp(p.a, p.b, r, material, 0);
  }
  return e;
}

}  // namespace bezcam::detail
