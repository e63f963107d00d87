// Adaptive clearing's passes (pocket_adaptive.hpp): a ring's parts that
// reach material, the spiral turn or the lead-in into a ring in material
// all round, the ring along the walls, and the links between them.
#include <algorithm>
#include <cmath>

#include "pocket_adaptive.hpp"

namespace bezcam::detail {

// Emits a pass: after the seed's helix when it is pending, else linked by
// a feed through cleared material, else entered where it starts.
void Adaptive::finish(PocketPass p) {
  if (pending_) {
    PocketPass h = std::move(*pending_);
    pending_.reset();
    if (dist_xy(h.pts[0], p.pts[0]) < 1e-9 || segment_clear(h.pts[0], p.pts[0])) {
      if (dist_xy(h.pts[0], p.pts[0]) >= 1e-9) p.pts.insert(p.pts.begin(), h.pts[0]);
      p.helix = h.helix;
      p.helix_r = h.helix_r;
      push(std::move(p));
      return;
    }
    h.pts.push_back(h.pts[0]);
    push(std::move(h));
  }
  if (have_cur_ && segment_clear(cur_, p.pts[0])) {
    p.linked = true;
  } else if (have_cur_) {
    // Through a point aside, in cleared material: the shortest such link.
    const Vec3 a = cur_, b = p.pts[0], mid = mix(a, b, 0.5);
    const double len = dist_xy(a, b);
    const Vec3 n = len > 0 ? Vec3{-(b.y - a.y) / len, (b.x - a.x) / len, 0} : Vec3{1, 0, 0};
    std::optional<Vec3> best;
    for (int k = 1; k <= 8 && !best; ++k)
      for (double sgn : {1.0, -1.0}) {
        const Vec3 m = mid + n * (sgn * k * len / 8);
        if (inside(m) && free(m) && segment_clear(a, m) && segment_clear(m, b)) {
          best = m;
          break;
        }
      }
    if (best) {
      p.pts.insert(p.pts.begin(), *best);
      p.linked = true;
    } else {
      p.in_cleared = clear(p.pts[0]);
    }
  } else {
    p.in_cleared = clear(p.pts[0]);
  }
  push(std::move(p));
}

// A ring in material all round: entered from cleared material beside it
// (where the last pass ended, when near) along a curve tangent to the
// ring some way on, then once round.
void Adaptive::closed_loop(const std::vector<Vec3>& loop) {
  if (spiral(loop)) return;
  const size_t n = loop.size();
  size_t ip = 0;
  if (have_cur_)
    for (size_t i = 1; i < n; ++i)
      if (dist_xy(loop[i], cur_) < dist_xy(loop[ip], cur_)) ip = i;
  auto tangent = [&](size_t i) {
    const Vec3 t = loop[(i + 1) % n] - loop[(i + n - 1) % n];
    const double l = std::hypot(t.x, t.y);
    return l > 0 ? Vec3{t.x / l, t.y / l, 0} : Vec3{1, 0, 0};
  };
  Vec3 q0 = loop[ip], t0 = tangent(ip);
  bool found = false;
  if (have_cur_ && (pending_ || (dist_xy(cur_, loop[ip]) <= 3 * load_ + 2 * g_.cell && clear(cur_)))) {
    q0 = cur_;
    if (std::hypot(dir_.x, dir_.y) > 0) t0 = dir_ * (1 / std::hypot(dir_.x, dir_.y));
    found = true;
  }
  const double side = in_.climb ? 1 : -1;  // the cleared side: left when climbing
  for (double d : {load_, 2 * load_, 3 * load_, r_, 2 * r_}) {
    if (found) break;
    const Vec3 q{loop[ip].x - side * t0.y * d, loop[ip].y + side * t0.x * d, 0};
    if (clear(q) && inside(q)) q0 = q, found = true;
  }
  double perim = 0;
  for (size_t i = 0; i < n; ++i) perim += dist_xy(loop[i], loop[(i + 1) % n]);
  std::vector<Vec3> best;
  size_t best_end = ip;
  double best_w = 1e300;
  for (double ell : {1.5 * r_, 3 * r_, 6 * r_}) {
    if (!found || ell > perim / 2) break;
    size_t ie = ip;
    for (double walked = 0; walked < ell;) {
      walked += dist_xy(loop[ie], loop[(ie + 1) % n]);
      ie = (ie + 1) % n;
    }
    const Vec3 p1 = loop[ie], t1 = tangent(ie);
    const double len = dist_xy(q0, p1);
    const int m = std::max(8, static_cast<int>(std::ceil(len / g_.cell)));
    std::vector<Vec3> h;
    bool ok = true;
    for (int k = 0; k < m && ok; ++k) {
      const double t = static_cast<double>(k) / m, t2 = t * t, t3 = t2 * t;
      const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
      const Vec3 p{h00 * q0.x + h10 * len * t0.x + h01 * p1.x + h11 * len * t1.x,
                   h00 * q0.y + h10 * len * t0.y + h01 * p1.y + h11 * len * t1.y, 0};
      ok = k == 0 || inside(p);
      h.push_back(p);
    }
    if (!ok) continue;
    h.push_back(p1);
    const double w = worst(h, 1, h.size());
    if (w < best_w) best_w = w, best = std::move(h), best_end = ie;
    if (w <= target_) break;
  }
  PocketPass p;
  if (best.empty()) {
    best = {loop[ip]};
    best_end = ip;
  }
  p.pts = std::move(best);
  for (size_t k = 1; k <= n; ++k) p.pts.push_back(loop[(best_end + k) % n]);
  std::vector<Vec3> cut = p.pts;
  finish(std::move(p));
  turn_.assign(cut.end() - static_cast<long>(n) - 1, cut.end());
}

// A ring round the turn just cut (or the entry's helix): one turn that
// leaves the turn before and reaches the ring within four radii (each point
// the mix of the ring's and the nearest point of the turn before, by a
// smooth step), follows the ring round and on over that stretch again,
// which takes the wedge its start left.
std::optional<std::vector<Vec3>> Adaptive::spiral_turn(const std::vector<Vec3>& loop) const {
  if (turn_.size() < 3 || !have_cur_ || dist_xy(turn_.back(), cur_) > 1e-9) return std::nullopt;
  const size_t n = loop.size(), m = turn_.size();
  size_t ip = 0;
  for (size_t i = 1; i < n; ++i)
    if (dist_xy(loop[i], cur_) < dist_xy(loop[ip], cur_)) ip = i;
  if (dist_xy(loop[ip], cur_) > 2 * load_ + 4 * g_.cell) return std::nullopt;
  double perim = 0;
  for (size_t i = 0; i < n; ++i) perim += dist_xy(loop[i], loop[(i + 1) % n]);
  // The turn before, from the tool's place round.
  std::vector<double> at(m, 0);
  for (size_t j = 1; j < m; ++j) at[j] = at[j - 1] + dist_xy(turn_[j - 1], turn_[j]);
  const double tperim = at.back();
  if (!(tperim > 0) || !(perim > 0)) return std::nullopt;
  const double ell = std::min(perim / 2, 4 * r_);
  std::vector<Vec3> pts{cur_};
  double s = 0;
  for (size_t k = 0; k <= n; ++k) {
    const Vec3& v = loop[(ip + k) % n];
    if (k > 0) s += dist_xy(loop[(ip + k - 1) % n], v);
    const double f = std::min(1.0, s / perim), u = std::min(1.0, s / ell), w = u * u * (3 - 2 * u);
    // The nearest point of the turn before, near the same share of it.
    const double want = f * tperim;
    size_t j0 = static_cast<size_t>(std::lower_bound(at.begin(), at.end(), want) - at.begin());
    const long win = static_cast<long>(m / 8 + 8);
    Vec3 q = turn_[std::min(j0, m - 1)];
    double best = 1e300;
    for (long d = -win; d <= win; ++d) {
      const long j = static_cast<long>(j0) + d;
      if (j < 0 || j + 1 >= static_cast<long>(m)) continue;
      const Vec3 &a = turn_[static_cast<size_t>(j)], &b = turn_[static_cast<size_t>(j) + 1];
      const double dist = point_segment(v, a, b);
      if (dist < best) {
        best = dist;
        const double l2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
        const double t =
            l2 > 0 ? std::clamp(((v.x - a.x) * (b.x - a.x) + (v.y - a.y) * (b.y - a.y)) / l2, 0.0, 1.0) : 0;
        q = mix(a, b, t);
      }
    }
    Vec3 x = mix(q, v, w);
    if (!inside(x)) x = v;
    pts.push_back(x);
  }
  // On past the start to where the turn reached the ring: the material its
  // start left goes now, and the next turn starts where the ring is cut.
  s = 0;
  for (size_t k = 1; k <= n && s < ell; ++k) {
    s += dist_xy(loop[(ip + k - 1) % n], loop[(ip + k) % n]);
    pts.push_back(loop[(ip + k) % n]);
  }
  return pts;
}

bool Adaptive::spiral(const std::vector<Vec3>& loop) {
  auto pts = spiral_turn(loop);
  if (!pts) return false;
  PocketPass p;
  p.pts = std::move(*pts);
  std::vector<Vec3> cut = p.pts;
  finish(std::move(p));
  turn_ = std::move(cut);
  return true;
}

// The largest engagement the ring's loops would cut with: a loop in
// material all round as the spiral turn that would cut it, else where it
// reaches material. Once above `stop` the reading ends (the ring is not
// taken whatever the rest reads).
double Adaptive::ring_worst(const std::vector<Chain>& chains, double stop) const {
  double w = 0;
  for (const auto& ch : chains) {
    if (w > stop) break;
    const auto& l = ch.pts;
    if (!ch.closed) {
      for (size_t i = 0; i < l.size() && w <= stop; ++i)
        if (on_front(l[i]) && !clear(l[i])) w = std::max(w, worst(l, i, i + 1));
      continue;
    }
    std::vector<uint8_t> t(l.size());
    size_t touching = 0;
    for (size_t i = 0; i < l.size(); ++i) touching += t[i] = on_front(l[i]) && !clear(l[i]);
    if (touching == l.size())
      if (auto turn = spiral_turn(l)) {
        w = std::max(w, worst(*turn, 1, turn->size()));
        continue;
      }
    const size_t n = l.size();
    std::vector<Vec3> c = l;
    c.push_back(l.front());
    c.insert(c.begin(), l.back());
    for (size_t i = 0; i < n && w <= stop; ++i)
      if (t[i]) w = std::max(w, worst(c, i + 1, i + 2));
  }
  return w;
}

// The parts of a closed loop that reach material, each from and to a point
// clear of it; false when none does.
bool Adaptive::take(std::vector<Vec3> loop, bool closed) {
  size_t n = loop.size();
  if (n < (closed ? 3u : 2u)) return false;
  std::vector<uint8_t> t(n);
  size_t touching = 0;
  for (size_t i = 0; i < n; ++i) touching += t[i] = on_front(loop[i]) && !clear(loop[i]);
  if (touching == 0) return false;
  if (closed && touching == n) {
    closed_loop(loop);
    return true;
  }
  if (closed) {
    // Cut open in the middle of its longest stretch off the material, so
    // that no run's way out to a free point stops at the cut.
    size_t s0 = 0, best = 0;
    for (size_t i = 0; i < n; ++i) {
      if (t[i] || !t[(i + n - 1) % n]) continue;
      size_t len = 0;
      while (!t[(i + len) % n]) ++len;
      if (len > best) best = len, s0 = (i + len / 2) % n;
    }
    std::rotate(loop.begin(), loop.begin() + static_cast<long>(s0), loop.end());
    std::rotate(t.begin(), t.begin() + static_cast<long>(s0), t.end());
    loop.push_back(loop.front());
    t.push_back(0);
  } else {
    // An open chain: its ends stand for clear points before and after.
    loop.insert(loop.begin(), loop.front());
    t.insert(t.begin(), 0);
    loop.push_back(loop.back());
    t.push_back(0);
    n = loop.size() - 1;
  }
  for (size_t i = 0; i <= n;) {
    if (!t[i]) {
      ++i;
      continue;
    }
    // A run from the clear point before it to the clear point after, runs
    // a few points apart joined.
    size_t a = i - 1, b = i;
    while (true) {
      while (b <= n && t[b]) ++b;
      size_t c = b;
      while (c <= n && c < b + 4 && !t[c]) ++c;
      if (c <= n && c < b + 4 && t[c])
        b = c;
      else
        break;
    }
    // Out to points with no material near the tool (the links join there).
    size_t e = std::min(b, n);
    for (int k = 0; k < 12 && a > 0 && !free(loop[a]); ++k) --a;
    for (int k = 0; k < 12 && e < n && !free(loop[e]); ++k) ++e;
    PocketPass p;
    p.pts.assign(loop.begin() + static_cast<long>(a), loop.begin() + static_cast<long>(e) + 1);
    finish(std::move(p));
    i = std::max(b, e) + 1;
  }
  return true;
}

// A ring along the walls, whole (the grid cannot see the last cell there):
// from its point nearest the tool, once round.
void Adaptive::whole(std::vector<Vec3> loop) {
  if (loop.size() < 3) return;
  size_t ip = 0;
  if (have_cur_)
    for (size_t i = 1; i < loop.size(); ++i)
      if (dist_xy(loop[i], cur_) < dist_xy(loop[ip], cur_)) ip = i;
  std::rotate(loop.begin(), loop.begin() + static_cast<long>(ip), loop.end());
  loop.push_back(loop.front());
  PocketPass p;
  p.pts = std::move(loop);
  finish(std::move(p));
}

}  // namespace bezcam::detail
