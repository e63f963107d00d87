#include "wall_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bezcam::verify_detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// First and one-past-last column index whose centre lies in [lo, hi].
std::pair<std::size_t, std::size_t> columns(double lo, double hi, double v0, double cell, std::size_t n) {
  const double a = std::ceil((lo - v0) / cell - 0.5), b = std::floor((hi - v0) / cell - 0.5);
  const double first = std::clamp(a, 0.0, static_cast<double>(n)),
               last = std::clamp(b + 1, 0.0, static_cast<double>(n));
  return {static_cast<std::size_t>(first), static_cast<std::size_t>(std::max(first, last))};
}

// Crossing parity of the closed polygon along the row at y: the columns of
// the region inside it get +1 in `inside`.
void fill_row_inside(const Wall& w, double y, const DexelGrid& g, const Region& r, std::size_t row,
                     std::vector<char>& inside) {
  std::vector<double> xs;
  auto ring = [&](const std::vector<Vec3>& pts) {
    const std::size_t n = pts.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& a = pts[k];
      const Vec3& b = pts[(k + 1) % n];
      if ((a.y <= y) == (b.y <= y)) continue;  // half-open: each crossing counted once
      xs.push_back(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
    }
  };
  ring(w.points);
  for (const auto& island : w.islands) ring(island);
  std::sort(xs.begin(), xs.end());
  for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
    const auto [i0, i1] = columns(xs[k], xs[k + 1], g.box().x0, g.cell(), g.nx());
    for (std::size_t i = std::max(i0, r.i0); i < std::min(i1, r.i0 + r.ni); ++i) inside[row * r.ni + (i - r.i0)] = 1;
  }
}

// One pass of the squared distance transform along a line of n values
// (Felzenszwalb and Huttenlocher, "Distance Transforms of Sampled
// Functions", 2012): f in, d out, in cell units squared.
void dt_1d(const double* f, std::size_t n, std::size_t stride, double* d, std::vector<int>& v, std::vector<double>& z) {
  v.assign(n, 0);
  z.assign(n + 1, 0);
  auto at = [&](int q) { return f[static_cast<std::size_t>(q) * stride]; };
  int k = -1;  // the lower envelope: parabolas v[0..k], parabola m left-bounded by z[m]
  for (int q = 0; q < static_cast<int>(n); ++q) {
    if (at(q) == kInf) continue;
    double s = -kInf;
    while (k >= 0) {
      const int p = v[static_cast<std::size_t>(k)];
      s = ((at(q) + q * static_cast<double>(q)) - (at(p) + p * static_cast<double>(p))) / (2.0 * (q - p));
      if (s > z[static_cast<std::size_t>(k)]) break;
      --k;
      s = -kInf;
    }
    ++k;
    v[static_cast<std::size_t>(k)] = q;
    z[static_cast<std::size_t>(k)] = s;
    z[static_cast<std::size_t>(k) + 1] = kInf;
  }
  if (k < 0) {
    for (std::size_t q = 0; q < n; ++q) d[q * stride] = kInf;
    return;
  }
  int m = 0;
  for (int q = 0; q < static_cast<int>(n); ++q) {
    while (z[static_cast<std::size_t>(m) + 1] < q) ++m;
    const int p = v[static_cast<std::size_t>(m)];
    d[static_cast<std::size_t>(q) * stride] = (q - p) * static_cast<double>(q - p) + at(p);
  }
}

}  // namespace

WallField wall_field(const DexelGrid& g, const Wall& w, double band) {
  WallField out;
  Box3 b;
  for (const Vec3& p : w.points) b.add(p);
  for (const auto& island : w.islands)
    for (const Vec3& p : island) b.add(p);
  const auto [i0, i1] = columns(b.lo.x - band, b.hi.x + band, g.box().x0, g.cell(), g.nx());
  const auto [j0, j1] = columns(b.lo.y - band, b.hi.y + band, g.box().y0, g.cell(), g.ny());
  Region& r = out.region;
  r = {i0, j0, i1 - i0, j1 - j0};
  out.distance.assign(r.size(), kInf);
  out.side.assign(r.size(), 0);
  if (r.size() == 0 || w.points.empty()) return out;
  std::vector<int> nearest(r.size(), -1);
  std::vector<double> t_at(r.size(), 0);
  // The segments: the wall's own first (an open wall's side comes from
  // them by index), then the islands'.
  const std::size_t segs = w.closed ? w.points.size() : w.points.size() - 1;
  std::vector<std::pair<Vec3, Vec3>> all;
  for (std::size_t k = 0; k < std::max<std::size_t>(segs, 1); ++k)
    all.push_back({w.points[k], w.points[segs == 0 ? k : (k + 1) % w.points.size()]});
  for (const auto& island : w.islands)
    for (std::size_t k = 0; k < island.size(); ++k) all.push_back({island[k], island[(k + 1) % island.size()]});
  for (std::size_t k = 0; k < all.size(); ++k) {
    const Vec3& a = all[k].first;
    const Vec3& c = all[k].second;
    const auto [si0, si1] = columns(std::min(a.x, c.x) - band, std::max(a.x, c.x) + band, g.box().x0, g.cell(), g.nx());
    const auto [sj0, sj1] = columns(std::min(a.y, c.y) - band, std::max(a.y, c.y) + band, g.box().y0, g.cell(), g.ny());
    const double dx = c.x - a.x, dy = c.y - a.y, len2 = dx * dx + dy * dy;
    for (std::size_t j = std::max(sj0, j0); j < std::min(sj1, j1); ++j) {
      const double y = g.y_center(j);
      for (std::size_t i = std::max(si0, i0); i < std::min(si1, i1); ++i) {
        const double x = g.x_center(i);
        const double t = len2 > 0 ? ((x - a.x) * dx + (y - a.y) * dy) / len2 : 0;
        const double tc = std::clamp(t, 0.0, 1.0);
        const double ex = x - (a.x + tc * dx), ey = y - (a.y + tc * dy);
        const double d = std::sqrt(ex * ex + ey * ey);
        const std::size_t at = (j - j0) * r.ni + (i - i0);
        if (d < out.distance[at]) {
          out.distance[at] = d;
          nearest[at] = static_cast<int>(k);
          t_at[at] = t;
        }
      }
    }
  }
  const signed char waste = 1, part = -1;
  if (w.closed) {
    std::vector<char> inside(r.size(), 0);
    for (std::size_t j = j0; j < j1; ++j) fill_row_inside(w, g.y_center(j), g, r, j - j0, inside);
    for (std::size_t k = 0; k < r.size(); ++k) out.side[k] = (inside[k] != 0) == w.waste_inside_or_left ? waste : part;
    out.outside_side = w.waste_inside_or_left ? part : waste;
    return out;
  }
  for (std::size_t k = 0; k < r.size(); ++k) {
    const int s = nearest[k];
    if (s < 0) continue;
    // Beyond the ends of an open wall neither side is defined.
    if ((s == 0 && t_at[k] < 0) || (static_cast<std::size_t>(s) == segs - 1 && t_at[k] > 1)) continue;
    const Vec3& a = w.points[static_cast<std::size_t>(s)];
    const Vec3& c = w.points[static_cast<std::size_t>(s) + 1];
    const double x = g.x_center(r.i0 + k % r.ni), y = g.y_center(r.j0 + k / r.ni);
    const bool left = (c.x - a.x) * (y - a.y) - (c.y - a.y) * (x - a.x) > 0;
    out.side[k] = left == w.waste_inside_or_left ? waste : part;
  }
  return out;
}

std::vector<double> reach(const Region& r, const std::vector<char>& centres, double cell) {
  std::vector<double> f(r.size()), d(r.size());
  for (std::size_t k = 0; k < r.size(); ++k) f[k] = centres[k] ? 0 : kInf;
  std::vector<int> v;
  std::vector<double> z;
  for (std::size_t j = 0; j < r.nj; ++j) dt_1d(&f[j * r.ni], r.ni, 1, &d[j * r.ni], v, z);
  for (std::size_t i = 0; i < r.ni; ++i) dt_1d(&d[i], r.nj, r.ni, &f[i], v, z);
  for (std::size_t k = 0; k < r.size(); ++k) f[k] = std::sqrt(f[k]) * cell;
  return f;
}

}  // namespace bezcam::verify_detail
