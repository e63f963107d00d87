// Adaptive clearing (docs/pocket.md, "Adaptive"): the cleared area grows
// ring by ring. A grid holds the material still there; each ring is the
// edge of the set of tool centres whose circle has at most `load`'s share
// of material on it (arccos(1 - load / r) each side of the normal), inside
// the centres' area: where the cleared edge bulges the ring steps less.
// The ring is kept only where it reaches material, entered along a smooth
// curve from cleared material, and its engagement is read on the grid
// before it is taken (the step shrinks until it keeps to the load).
#include "pocket_adaptive.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <numbers>
#include <optional>

namespace bezcam::detail {

namespace {
constexpr int kCircle = kAdaptiveCircle;

// Sorts sample indices below `n` (a radix sort, 11 bits a pass).
void sort_samples(std::vector<size_t>& v, size_t n) {
  std::vector<size_t> tmp(v.size());
  for (unsigned shift = 0; shift < 64 && (n >> shift) > 0; shift += 11) {
    size_t at[2049] = {};
    for (size_t k : v) ++at[((k >> shift) & 2047) + 1];
    for (size_t d = 1; d < 2049; ++d) at[d] += at[d - 1];
    for (size_t k : v) tmp[at[(k >> shift) & 2047]++] = k;
    v.swap(tmp);
  }
}
}  // namespace

// The samples of piece `cur` not yet settled within 1.5 load of the settled
// ones (Chebyshev steps over the grid), with the material on the circle of
// each, and the settled ones on their edge, of those in `near` (in grid
// order; every settled sample on the edge is there).
Adaptive::Band Adaptive::band(const std::vector<uint8_t>& settled, const std::vector<int>& comp, int cur,
                              const std::vector<size_t>& near) const {
  Band b;
  auto in_piece = [&](size_t k) { return comp[k] == cur; };
  for (size_t k : near) {
    if (!settled[k] || !in_piece(k)) continue;
    const long i = static_cast<long>(k) % g_.nx, j = static_cast<long>(k) / g_.nx;
    bool edge = false;
    for (const auto& [di, dj] : {std::pair{1L, 0L}, {-1L, 0L}, {0L, 1L}, {0L, -1L}}) {
      if (i + di < 0 || j + dj < 0 || i + di >= g_.nx || j + dj >= g_.ny) continue;
      const size_t n = static_cast<size_t>((j + dj) * g_.nx + i + di);
      edge = edge || (!settled[n] && in_piece(n));
    }
    if (edge) b.frontier.push_back(k);
  }
  const long steps = static_cast<long>(std::ceil((1.5 * load_ + 3 * g_.cell) / g_.cell));
  std::vector<int>& seen = seen_;
  seen.resize(g_.size(), -1);
  spread(
      b.frontier, steps, [&](size_t n) { return !settled[n] && !stuck_[n] && in_piece(n); }, b.cells);
  for (size_t k : b.frontier) seen[k] = -1;
  for (size_t k : b.cells) seen[k] = -1;
  // One front at a time: the 8-connected piece of the band nearest the tool.
  std::vector<int>& label = seen;
  for (size_t k : b.cells) label[k] = -2;
  int pieces = 0;
  std::vector<size_t> w;
  for (size_t s0 : b.cells) {
    if (label[s0] != -2) continue;
    w.assign(1, s0);
    label[s0] = pieces;
    while (!w.empty()) {
      const size_t k = w.back();
      w.pop_back();
      around(
          k, [&](size_t n) __attribute__((always_inline)) {
            if (label[n] == -2) label[n] = pieces, w.push_back(n);
          });
    }
    ++pieces;
  }
  if (pieces > 1) {
    // The piece of the sample nearest the tool (the first piece of those
    // as near).
    std::vector<double> near_d(static_cast<size_t>(pieces), 1e300);
    for (size_t k : b.cells) {
      const Vec3 c = g_.sample(k);
      const double d = have_cur_ ? (c.x - cur_.x) * (c.x - cur_.x) + (c.y - cur_.y) * (c.y - cur_.y) : 0;
      double& m = near_d[static_cast<size_t>(label[k])];
      m = std::min(m, d);
    }
    const int best = static_cast<int>(std::min_element(near_d.begin(), near_d.end()) - near_d.begin());
    std::vector<size_t> chosen;
    for (size_t k : b.cells)
      if (label[k] == best) chosen.push_back(k);
    for (size_t k : b.cells) label[k] = -1;
    b.cells = std::move(chosen);
  } else {
    for (size_t k : b.cells) label[k] = -1;
  }
  for (size_t k : b.cells) active_[k] = 1;
  for (size_t k : b.frontier) {
    bool next_to = false;
    around(k, [&](size_t n) { next_to = next_to || active_[n] == 1; });
    if (next_to) active_[k] = 2;
  }
  // The squares the ring is looked for from: within reach of the front of
  // every point smoothing can take onto it (four passes over steps of at
  // most a twelfth of the radius, or two cells), in grid order.
  const long reach = static_cast<long>(std::ceil(4 * std::max(2 * g_.cell, r_ / 12) / g_.cell)) + 2;
  std::vector<size_t> from = b.cells;
  for (size_t k : b.frontier)
    if (active_[k] == 2) from.push_back(k);
  b.seeds = from;
  spread(
      from, reach, [](size_t) { return true; }, b.seeds);
  for (size_t k : b.seeds) seen[k] = -1;
  sort_samples(b.seeds, g_.size());
  // Of those, the squares with settled corners and others: a ring crosses
  // only these and the squares about the samples it grows over.
  auto inside = [&](long i, long j) {
    const size_t k = static_cast<size_t>(j * g_.nx + i);
    return settled[k] && in_piece(k);
  };
  for (size_t sq : b.seeds) {
    const long i = static_cast<long>(sq) % g_.nx, j = static_cast<long>(sq) / g_.nx;
    if (i + 1 >= g_.nx || j + 1 >= g_.ny) continue;
    const int n = inside(i, j) + inside(i + 1, j) + inside(i, j + 1) + inside(i + 1, j + 1);
    if (n > 0 && n < 4) b.edge.push_back(sq);
  }
  const int cap = static_cast<int>(std::ceil(2 * (target_ / 180) * kCircle)) + 1;
  b.count.resize(b.cells.size());
  for (size_t m = 0; m < b.cells.size(); ++m) b.count[m] = std::min(circle_count(b.cells[m]), cap + 1);
  return b;
}

// The samples within `steps` 8-connected steps of `from` through samples
// that satisfy `ok`, each once, appended to `out` (`from` not included).
// seen_ holds each one's steps afterwards: the caller resets it to -1.
template <class Ok>
void Adaptive::spread(const std::vector<size_t>& from, long steps, const Ok& ok, std::vector<size_t>& out) const {
  std::vector<int>& seen = seen_;
  seen.resize(g_.size(), -1);
  std::vector<size_t> q(from);
  for (size_t k : from) seen[k] = 0;
  for (size_t head = 0; head < q.size(); ++head) {
    const size_t k = q[head];
    const int d = seen[k];
    if (d >= steps) continue;
    around(
        k, [&](size_t n) __attribute__((always_inline)) {
          if (seen[n] >= 0 || !ok(n)) return;
          seen[n] = d + 1;
          q.push_back(n);
          out.push_back(n);
        });
  }
}

// Clears the material within r of the segment ab, and the counts of the
// circles through what it clears.
void Adaptive::cut(const Vec3& a, const Vec3& b) {
  const PocketGrid::Capsule c(a, b, r_);
  const auto [j0, j1] = g_.rows(c);
  // The columns of the capsule's box, a cell wider each side: a row with no
  // material there has none in the capsule's span (most rows behind the
  // tool).
  const long b0 = std::max(0L, static_cast<long>(std::floor((std::min(a.x, b.x) - r_ - g_.x0) / g_.cell)) - 2),
             b1 = std::min(g_.nx - 1, static_cast<long>(std::ceil((std::max(a.x, b.x) + r_ - g_.x0) / g_.cell)) + 1);
  for (long j = j0; j <= j1; ++j) {
    uint8_t* const row = mat_.data() + j * g_.nx;
    if (b0 > b1 || !std::memchr(row + b0, 1, static_cast<size_t>(b1 - b0 + 1))) continue;
    const auto [i0, i1] = g_.span(c, j);
    if (i0 > i1) continue;
    for (long i = i0; i <= i1; ++i) {
      // The next sample still in material on the row (most are cleared).
      const void* at = std::memchr(row + i, 1, static_cast<size_t>(i1 - i + 1));
      if (!at) break;
      i = static_cast<const uint8_t*>(at) - row;
      row[i] = 0;
      const long k = j * g_.nx + i;
      if (i >= ring_reach_ && j >= ring_reach_ && i + ring_reach_ < g_.nx && j + ring_reach_ < g_.ny) {
        for (const long o : ring_lin_) {
          int16_t& n = count_[static_cast<size_t>(k - o)];
          if (n > 0) --n;
        }
        continue;
      }
      for (const auto& [di, dj] : ring_off_)
        if (i - di >= 0 && j - dj >= 0 && i - di < g_.nx && j - dj < g_.ny) {
          int16_t& n = count_[static_cast<size_t>((j - dj) * g_.nx + i - di)];
          if (n > 0) --n;
        }
    }
  }
}

// The next ring round the settled samples of piece `cur`: the edge of the
// centres (inside the walls' limit) whose circle holds at most `lambda`
// of material, grown from the settled ones; `grown` gets the new samples.
std::vector<Adaptive::Chain> Adaptive::ring(const Band& b, double lambda, std::vector<size_t>& grown) const {
  grown.clear();
  if (b.frontier.empty()) return {};
  std::vector<float>& f = f_;
  std::vector<uint8_t>& has = has_;  // 1: in the band, 2: and reached
  f.resize(g_.size());
  has.resize(g_.size(), 0);
  for (size_t m = 0; m < b.cells.size(); ++m) {
    const size_t k = b.cells[m];
    const float wall = fwall_[k] / static_cast<float>(r_);
    f[k] = std::max(static_cast<float>(b.count[m]) / kCircle - static_cast<float>(lambda), wall);
    has[k] = 1;
  }
  // Only what grows from the settled samples (4-connected through f < 0).
  std::vector<size_t> q(b.frontier);
  while (!q.empty()) {
    const size_t k = q.back();
    q.pop_back();
    const long i = static_cast<long>(k) % g_.nx, j = static_cast<long>(k) / g_.nx;
    for (const auto& [di, dj] : {std::pair{1L, 0L}, {-1L, 0L}, {0L, 1L}, {0L, -1L}}) {
      if (i + di < 0 || j + dj < 0 || i + di >= g_.nx || j + dj >= g_.ny) continue;
      const size_t n = static_cast<size_t>((j + dj) * g_.nx + i + di);
      if (has[n] != 1 || f[n] >= 0) continue;
      has[n] = 2;
      grown.push_back(n);
      q.push_back(n);
    }
  }
  // The contoured function: f on the band, but 0.01 where not reached;
  // elsewhere level_ holds it.
  for (size_t k : b.cells) level_[k] = f[k] < 0 && has[k] != 2 ? 0.01f : f[k];
  auto val = [&](size_t k) { return level_[k]; };
  // The seed squares the contour may cross (the others' corners are all
  // in or all out): those on the settled edge and those about grown samples.
  std::vector<uint8_t>& mark = mark_;
  mark.resize(g_.size(), 0);
  auto about = [&](size_t k, uint8_t v) {
    const long i = static_cast<long>(k) % g_.nx, j = static_cast<long>(k) / g_.nx;
    for (long dj = -1; dj <= 0; ++dj)
      for (long di = -1; di <= 0; ++di)
        if (i + di >= 0 && j + dj >= 0) mark[static_cast<size_t>((j + dj) * g_.nx + i + di)] = v;
  };
  for (size_t sq : b.edge) mark[sq] = 1;
  for (size_t k : grown) about(k, 1);
  std::vector<size_t> live;
  for (size_t sq : b.seeds)
    if (mark[sq]) live.push_back(sq);
  for (size_t sq : b.edge) mark[sq] = 0;
  for (size_t k : grown) about(k, 0);
  std::vector<std::vector<Vec3>> open;
  auto closed = contours(g_, val, live, contour_, open);
  for (size_t k : b.cells) has[k] = 0, level_[k] = 1.0f;
  std::vector<Chain> out;
  for (auto& l : closed) out.push_back({std::move(l), true});
  for (auto& l : open) out.push_back({std::move(l), false});
  for (auto& c : out) {
    smooth(c.pts, c.closed);
    if (!in_.climb) std::reverse(c.pts.begin(), c.pts.end());
  }
  return out;
}

// Resampled at equal steps of about a twelfth of the radius (the contour's
// points lie on the grid's edges, a cell or less apart), then four passes of
// a [1 2 1] / 4 average; a point the averaging takes nearer the walls than
// the centres' limit keeps its place.
void Adaptive::smooth(std::vector<Vec3>& loop, bool closed) const {
  if (!closed) {
    // A chain the window cut: resampled likewise, its ends kept.
    std::vector<Vec3> even{loop.front()};
    const double step = std::max(2 * g_.cell, r_ / 12);
    for (size_t i = 1; i < loop.size(); ++i)
      if (dist_xy(loop[i], even.back()) >= step || i + 1 == loop.size()) even.push_back(loop[i]);
    for (int pass = 0; pass < 4; ++pass)
      for (size_t i = 1; i + 1 < even.size(); ++i) {
        const Vec3 q{(even[i - 1].x + 2 * even[i].x + even[i + 1].x) / 4,
                     (even[i - 1].y + 2 * even[i].y + even[i + 1].y) / 4, 0};
        if (inside(q)) even[i] = q;
      }
    std::erase_if(even, [&](const Vec3& p) { return !inside(p); });
    loop = std::move(even);
    return;
  }
  double perim = 0;
  for (size_t i = 0; i < loop.size(); ++i) perim += dist_xy(loop[i], loop[(i + 1) % loop.size()]);
  const size_t n = std::max<size_t>(8, static_cast<size_t>(std::ceil(perim / std::max(2 * g_.cell, r_ / 12))));
  if (n < loop.size()) {
    std::vector<Vec3> even;
    const double step = perim / static_cast<double>(n);
    double at = 0, next = 0;
    for (size_t i = 0; i < loop.size() && even.size() < n; ++i) {
      const Vec3 &a = loop[i], &b = loop[(i + 1) % loop.size()];
      const double l = dist_xy(a, b);
      while (next <= at + l && even.size() < n) {
        const Vec3 p = mix(a, b, l > 0 ? (next - at) / l : 0);
        even.push_back(inside(p) ? p : (inside(a) ? a : b));
        next += step;
      }
      at += l;
    }
    loop = std::move(even);
  }
  const size_t m = loop.size();
  for (int pass = 0; pass < 4; ++pass) {
    std::vector<Vec3> s(m);
    for (size_t i = 0; i < m; ++i) {
      const Vec3 &a = loop[(i + m - 1) % m], &b = loop[i], &c = loop[(i + 1) % m];
      s[i] = {(a.x + 2 * b.x + c.x) / 4, (a.y + 2 * b.y + c.y) / 4, 0};
      if (!inside(s[i])) s[i] = b;
    }
    loop = std::move(s);
  }
  std::erase_if(loop, [&](const Vec3& p) { return !inside(p); });
}

// A helix in piece `cur`, about its deepest sample, whose bore the rings
// grow from; false when no helix of an eighth of the tool's radius fits.
bool Adaptive::seed(const std::vector<int>& comp, int cur, const std::vector<double>& depth) {
  size_t best = g_.size();
  for (size_t k = 0; k < g_.size(); ++k)
    if (comp[k] == cur && (best == g_.size() || depth[k] > depth[best])) best = k;
  if (best == g_.size()) return false;
  const Vec3 c = g_.sample(best);
  double rad = std::min(in_.helix_radius > 0 ? in_.helix_radius : r_ / 2, depth[best] / 1.09 - 2 * g_.cell);
  for (int t = 0; t < 6 && rad >= r_ / 8; ++t, rad *= 0.75) {
    std::vector<Vec3> poly;
    const double out = rad / std::cos(std::numbers::pi / 24) + in_.margin;
    for (int j = 0; j < 24; ++j) {
      const double a = 2 * std::numbers::pi * j / 24;
      poly.push_back({c.x + out * std::cos(a), c.y + out * std::sin(a), 0});
    }
    if (!centres_.covers_polygon(poly)) continue;
    // The helix turns the way the rings run; its last point starts them.
    const double a0 = 0;
    const Vec3 start{c.x + rad * std::cos(a0), c.y + rad * std::sin(a0), 0};
    std::vector<Vec3> bore;
    for (int j = 0; j <= 72; ++j) {
      const double a = (in_.climb ? 1 : -1) * 2 * std::numbers::pi * j / 72;
      bore.push_back({c.x + rad * std::cos(a), c.y + rad * std::sin(a), 0});
    }
    stamp(bore);
    PocketPass p;
    p.pts = {start};
    p.helix = c;
    p.helix_r = rad;
    cur_ = start;
    dir_ = {0, in_.climb ? 1.0 : -1.0, 0};
    have_cur_ = true;
    pending_ = std::move(p);
    turn_ = bore;
    return true;
  }
  return false;
}

// A seed's helix no ring has followed yet, as a pass of its own.
void Adaptive::flush_pending() {
  if (!pending_) return;
  pending_->pts.push_back(pending_->pts.front());
  out_.push_back(std::move(*pending_));
  pending_.reset();
}

// The rings of piece `cur` grown from its settled samples, round after
// round, until its band is empty (every sample settled or stuck).
void Adaptive::grow(const std::vector<int>& comp, int cur, std::vector<uint8_t>& settled) {
  for (size_t k = 0; k < g_.size(); ++k) level_[k] = settled[k] && comp[k] == cur ? settled_level(k) : 1.0f;
  // The settled samples that may lie on the edge (the edge only moves
  // out, onto samples just grown).
  std::vector<size_t> near;
  for (size_t k = 0; k < g_.size(); ++k)
    if (comp[k] == cur && settled[k]) near.push_back(k);
  for (int round = 0; round < 20000; ++round) {
    double lambda = 2 * target_ / 360;
    std::vector<size_t> grown;
    std::vector<Chain> loops;
    const Band b = band(settled, comp, cur, near);
    for (int attempt = 0; attempt < 6; ++attempt, lambda *= 0.8) {
      loops = ring(b, lambda, grown);
      if (ring_worst(loops, target_) <= target_) break;
    }
    bool cut = false;
    for (auto& l : loops) cut = take(std::move(l.pts), l.closed) || cut;
    for (size_t k : grown) settled[k] = 1, level_[k] = settled_level(k);
    near = b.frontier;
    near.insert(near.end(), grown.begin(), grown.end());
    sort_samples(near, g_.size());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (size_t k : b.cells) active_[k] = 0;
    for (size_t k : b.frontier) active_[k] = 0;
    if (b.cells.empty()) break;
    if (!cut && grown.empty())
      for (size_t k : b.cells) stuck_[k] = 1;
  }
}

std::vector<PocketPass> Adaptive::run() {
  std::vector<int> comp(g_.size(), -1);
  std::vector<uint8_t> outside(g_.size());
  for (size_t k = 0; k < g_.size(); ++k) outside[k] = !(fwall_[k] < 0);
  int pieces = 0;
  for (size_t s = 0; s < g_.size(); ++s) {
    if (outside[s] || comp[s] >= 0) continue;
    std::deque<size_t> q{s};
    comp[s] = pieces;
    while (!q.empty()) {
      const size_t k = q.front();
      q.pop_front();
      const long i = static_cast<long>(k) % g_.nx, j = static_cast<long>(k) / g_.nx;
      for (const auto& [di, dj] : {std::pair{1L, 0L}, {-1L, 0L}, {0L, 1L}, {0L, -1L}}) {
        if (i + di < 0 || j + dj < 0 || i + di >= g_.nx || j + dj >= g_.ny) continue;
        const size_t m = static_cast<size_t>((j + dj) * g_.nx + i + di);
        if (!outside[m] && comp[m] < 0) comp[m] = pieces, q.push_back(m);
      }
    }
    ++pieces;
  }
  const std::vector<double> depth = g_.distance(outside);
  active_.assign(g_.size(), 0);
  stuck_.assign(g_.size(), 0);
  std::vector<uint8_t> settled(g_.size(), 0);
  // Rest machining: the rings grow from what the tool before cleared.
  for (size_t k = 0; k < g_.size(); ++k) settled[k] = comp[k] >= 0 && before_[k] && clear(g_.sample(k));
  level_.resize(g_.size());
  for (int cur = 0; cur < pieces; ++cur) {
    bool any = false;
    for (size_t k = 0; k < g_.size() && !any; ++k) any = comp[k] == cur && settled[k];
    if (!any) {
      if (!seed(comp, cur, depth)) continue;
      for (size_t k = 0; k < g_.size(); ++k)
        if (comp[k] == cur && dist_xy(g_.sample(k), *pending_->helix) <= pending_->helix_r) settled[k] = 1;
    }
    grow(comp, cur, settled);
    // Material the rings could not reach from where they grew (their
    // front stuck at a gap it cannot pass within the load), deeper than
    // the load: a helix of its own where it is deepest, and rings from
    // there.
    for (int again = 0; again < kAdaptiveReseeds; ++again) {
      std::vector<uint8_t> done(g_.size());
      std::vector<int> rest(g_.size(), -1);
      bool left = false;
      for (size_t k = 0; k < g_.size(); ++k) {
        done[k] = outside[k] || settled[k];
        if (comp[k] == cur && !settled[k]) rest[k] = cur, left = left || stuck_[k];
      }
      if (!left) break;
      // (a sliver no deeper than the load the ring along the walls takes)
      const std::vector<double> deep = g_.distance(done);
      double deepest = 0;
      for (size_t k = 0; k < g_.size(); ++k)
        if (rest[k] == cur) deepest = std::max(deepest, deep[k]);
      if (!(deepest > load_)) break;
      flush_pending();
      if (!seed(rest, cur, deep)) break;
      for (size_t k = 0; k < g_.size(); ++k) {
        if (rest[k] == cur) stuck_[k] = 0;
        if (rest[k] == cur && dist_xy(g_.sample(k), *pending_->helix) <= pending_->helix_r) settled[k] = 1;
      }
      grow(comp, cur, settled);
    }
  }
  // The walls: the edge of the centres' area, where anything is left.
  for (auto ring : centres_.rings()) {
    if (in_.climb) std::reverse(ring.begin(), ring.end());
    std::vector<Vec3> dense;
    for (size_t i = 0; i < ring.size(); ++i) {
      const Vec3 &a = ring[i], &b = ring[(i + 1) % ring.size()];
      const int m = std::max(1, static_cast<int>(std::ceil(dist_xy(a, b) / g_.cell)));
      for (int k = 0; k < m; ++k) dense.push_back(mix(a, b, static_cast<double>(k) / m));
    }
    whole(std::move(dense));
  }
  flush_pending();
  return out_;
}

std::vector<PocketPass> adaptive_passes(const Area& region, const Area& centres, const Area& before,
                                        const PocketPlanInput& in, double d_wall) {
  return Adaptive(region, centres, before, in, d_wall).run();
}

}  // namespace bezcam::detail
