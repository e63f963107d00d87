// The planner's speeds and times (planner_builder.hpp): a windowed
// backward pass for the look-ahead, a backward and a forward pass give
// every junction's speed; each segment is then a trapezoid (an S-curve's
// durations with a jerk limit); the totals sum the times per block and
// say what held each block below its feed.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <numeric>

#include "planner_builder.hpp"

namespace bezcam::planner_detail {

namespace {

// A speed change from v0 to v1 (either way) at acceleration a, jerk j
// (0: none): its duration (a symmetric S-curve with jerk; its distance is
// then the mean speed times the duration, as for a linear ramp).
double ramp_time(double v0, double v1, double a, double j) {
  const double dv = std::abs(v1 - v0);
  if (dv <= 0) return 0;
  if (j <= 0) return dv / a;
  if (dv >= a * a / j) return dv / a + a / j;
  return 2 * std::sqrt(dv / j);
}
double ramp_distance(double v0, double v1, double a, double j) { return 0.5 * (v0 + v1) * ramp_time(v0, v1, a, j); }

// The same with the jerk's build-up at the ramp's start (`in`) and its
// wind-down at the end (`out`) each counted only where the acceleration
// really starts or ends: a ramp that continues over several segments
// builds up its acceleration once.
double ramp_time(double v0, double v1, double a, double j, bool in, bool out) {
  if (j <= 0 || (in && out)) return ramp_time(v0, v1, a, j);
  const double dv = std::abs(v1 - v0);
  if (dv <= 0) return 0;
  if (!in && !out) return dv / a;
  // One end only: half of the jerk phases, limited as for a short ramp.
  return std::max(dv / a + 0.5 * a / j * std::min(1.0, dv * j / (a * a)), 0.5 * ramp_time(v0, v1, a, j));
}

// The highest speed reachable from v0 within distance L (the inverse of
// ramp_distance in v1, by bisection with jerk, closed form without).
double reachable(double v0, double L, double a, double j, double cap) {
  if (j <= 0) return std::min(cap, std::sqrt(v0 * v0 + 2 * a * L));
  if (ramp_distance(v0, cap, a, j) <= L) return cap;
  double lo = v0, hi = cap;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ramp_distance(v0, mid, a, j) <= L ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

void Builder::speeds() {
  const size_t n = lean.size();
  lookahead_limited_.clear();
  // junction has n + 1 entries: entering each segment, then the end (read
  // here only: taken, not copied).
  std::vector<double> v(std::move(junction));
  for (size_t i = 0; i < n; ++i) {
    v[i] = std::min(v[i], lean[i].vmax);
    if (i > 0) v[i] = std::min(v[i], lean[i - 1].vmax);
  }
  // Look-ahead: at each segment the controller must be able to stop
  // within the segments it sees (counted in blocks). One pass, every
  // index it reads moving forward only: the sums of lengths and the counts
  // of blocks before a segment are kept as they go, in the order a table
  // of them would add them, not stored for every segment.
  const int window = std::max(1, model.lookahead_blocks);
  {
    // Only where the window is short compared with a stop.
    // Distinct blocks and path length before a segment, at a cursor
    // moving forward.
    struct Before {
      size_t at = 0;
      int blocks = 0;
      double length = 0;
    };
    const auto advance = [&](Before& c, size_t to) {
      for (; c.at < to; ++c.at) {
        if (c.at == 0 || lean[c.at].block != lean[c.at - 1].block) ++c.blocks;
        c.length += lean[c.at].length;
      }
    };
    // Window end of segment k: the segment after `window` distinct blocks
    // (segments [k, e) are seen); asked for k = 0, 0, 1, 2 ... in order.
    size_t e = 0;
    Before at_k, after_e, at_i, at_stop;
    const auto end_of = [&](size_t k) {
      if (e < k) e = k;
      advance(at_k, k);
      while (e < n) {
        advance(after_e, e + 1);
        if (after_e.blocks - at_k.blocks > window) break;
        ++e;
      }
      return e;
    };
    // The least acceleration over each window, by a sliding minimum (both
    // ends only move forward).
    std::deque<size_t> mins;
    size_t pushed = 0;
    for (size_t i = 0; i < n; ++i) {
      // Entering segment i, the controller is still executing segment
      // i - 1: it sees the window that began there.
      const size_t stop = end_of(i > 0 ? i - 1 : 0);
      if (stop >= n) continue;  // sees the program's end: the normal passes cover it
      for (; pushed < stop; ++pushed) {
        while (!mins.empty() && lean[mins.back()].accel >= lean[pushed].accel) mins.pop_back();
        mins.push_back(pushed);
      }
      while (!mins.empty() && mins.front() < i) mins.pop_front();
      const double a_min = mins.empty() ? lean[i].accel : lean[mins.front()].accel;
      // A window long enough to stop from the top speed does not limit.
      const double dist_needed = ramp_distance(0, lean[i].vmax, a_min, 0);
      advance(at_i, i);
      advance(at_stop, stop);
      if (at_stop.length - at_i.length >= dist_needed * 1.0001) continue;
      double w = 0;
      for (size_t k = stop; k-- > i;) w = std::min(reachable(w, lean[k].length, lean[k].accel, 0, lean[k].vmax), v[k]);
      // The window read v from i on only: taken at once.
      if (w < v[i]) {
        v[i] = w;
        lookahead_limited_.resize(n, false);
        lookahead_limited_[i] = true;
      }
    }
  }
  // Backward then forward (speeds by the acceleration; the jerk's share
  // of a ramp is counted below, once per ramp).
  for (size_t i = n; i-- > 0;)
    v[i] = std::min(v[i], reachable(v[i + 1], lean[i].length, lean[i].accel, 0, lean[i].vmax));
  for (size_t i = 0; i < n; ++i)
    v[i + 1] = std::min(v[i + 1], reachable(v[i], lean[i].length, lean[i].accel, 0, lean[i].vmax));
  speed_ = std::move(v);
}

// The segments' profiles, one after the other (each made once, when
// read): trapezoids, then (with a jerk limit) S-curves, a ramp's build-up
// and wind-down where the acceleration starts and ends, not at every
// joint, as the trapezoids of the segment and its neighbours say.
class Builder::Profiles {
 public:
  // The profiles of lean's segments [0, n).
  Profiles(const Builder& b, size_t n) : b_(b), j_(b.jerk()), n_(n) {
    if (j_ > 0 && n_ > 0) {
      here_ = trapezoid(0);
      if (n_ > 1) next_ = trapezoid(1);
    }
  }
  // Segment i's profile: asked for i = 0, 1, 2 ... in order.
  Profile next(size_t i) {
    if (j_ <= 0) return trapezoid(i);
    const size_t n = n_;
    if (i > 0) {
      before_ = here_;
      here_ = next_;
      next_ = i + 1 < n ? trapezoid(i + 1) : Profile{};
    }
    const Lean& q = b_.lean[i];
    const bool in = i > 0, out = i + 1 < n;
    const Lean& p = b_.lean[in ? i - 1 : i];
    const Lean& r = b_.lean[out ? i + 1 : i];
    std::array<char, 4> f{1, 1, 1, 1};
    if (in && ends_acc(p, before_) && starts_acc(q, here_)) f[0] = 0;
    if (out && ends_acc(q, here_) && starts_acc(r, next_)) f[1] = 0;
    if (in && ends_dec(p, before_) && starts_dec(q, here_)) f[2] = 0;
    if (out && ends_dec(q, here_) && starts_dec(r, next_)) f[3] = 0;
    return profile_one(q, b_.speed_[i], b_.speed_[i + 1], j_, f);
  }

 private:
  Profile trapezoid(size_t k) const { return profile_one(b_.lean[k], b_.speed_[k], b_.speed_[k + 1], 0, {1, 1, 1, 1}); }
  // A phase counts when it covers more than rounding would leave of the
  // segment (1e-9 of its length, at most its peak speed times its
  // duration): a cruise or a ramp of a few ulps, left where the speeds
  // meet exactly on paper, must not decide whether a ramp continues into
  // the next segment (that would move the time by a jerk's share of a
  // ramp for a change of 1e-12 in a length).
  static bool has(const Lean& q, const Profile& s, double t) { return t * s.vpeak > 1e-9 * q.length; }
  static bool ends_acc(const Lean& q, const Profile& s) {
    return has(q, s, s.t_acc) && !has(q, s, s.t_cruise) && !has(q, s, s.t_dec);
  }
  static bool starts_acc(const Lean& q, const Profile& s) { return has(q, s, s.t_acc); }
  static bool ends_dec(const Lean& q, const Profile& s) { return has(q, s, s.t_dec); }
  static bool starts_dec(const Lean& q, const Profile& s) {
    return has(q, s, s.t_dec) && !has(q, s, s.t_acc) && !has(q, s, s.t_cruise);
  }
  const Builder& b_;
  double j_;
  size_t n_;
  Profile before_, here_, next_;  // the trapezoids of segments i - 1, i, i + 1
};

// One segment from v0 to v1: the highest peak that fits its length.
Profile Builder::profile_one(const Lean& s, double v0, double v1, double j, std::array<char, 4> f) {
  const double a = s.accel;
  auto up = [&](double vp) { return ramp_time(v0, vp, a, j, f[0], f[1]); };
  auto down = [&](double vp) { return ramp_time(vp, v1, a, j, f[2], f[3]); };
  auto used = [&](double vp) { return 0.5 * (v0 + vp) * up(vp) + 0.5 * (vp + v1) * down(vp); };
  double lo = std::max(v0, v1), hi = s.vmax;
  double vp = hi;
  if (used(hi) > s.length * (1 + 1e-12)) {
    if (j <= 0) {
      vp = std::clamp(std::sqrt(std::max(0.0, (2 * a * s.length + v0 * v0 + v1 * v1) / 2)), lo, hi);
    } else {
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (used(mid) <= s.length ? lo : hi) = mid;
      }
      vp = lo;
    }
  }
  Profile r;
  r.vpeak = vp;
  r.t_acc = up(vp);
  r.t_dec = down(vp);
  const double rest = s.length - used(vp);
  r.t_cruise = vp > 0 ? std::max(0.0, rest) / vp : 0;
  return r;
}

void Builder::totals() {
  totals_part(lean.size());
  totals_end();
}

void Builder::totals_part(size_t n) {
  double t = t_done_;
  size_t pause = pause_done_;
  if (!timed_any_) {
    timed_any_ = true;
    plan.pause_start_s.assign(tl.pauses.size(), 0);
  }
  // (Blocks still come while a summary times its first parts.)
  why_.resize(plan.blocks.size(), static_cast<std::uint8_t>(SpeedLimit::programmed));
  top_.resize(plan.blocks.size(), 0);
  // Pauses sit before the first segment of their block (or of the next
  // block that has one): per pause, found in one pass over the segments
  // with the pauses taken by block (a pause whose block comes later waits
  // for the part that holds it, or the end).
  constexpr size_t kLater = std::numeric_limits<size_t>::max();
  std::vector<size_t> pause_seg(tl.pauses.size(), kLater);
  {
    const auto block_of = [&](size_t k) { return std::min(tl.pauses[k].before_block, block_count); };
    std::vector<size_t> by_block(tl.pauses.size() - pause);
    std::iota(by_block.begin(), by_block.end(), pause);
    std::stable_sort(by_block.begin(), by_block.end(), [&](size_t a, size_t b) { return block_of(a) < block_of(b); });
    size_t k = 0;
    for (size_t i = 0; i < n && k < by_block.size(); ++i)
      for (; k < by_block.size() && block_of(by_block[k]) <= static_cast<size_t>(lean[i].block); ++k)
        pause_seg[by_block[k]] = i;
  }
  // One pass over the segments, in order: the times, per block what held
  // it below its programmed feed (the limit of its fastest segment), and
  // the mean feed ratio over the cutting moves: the length cut over the
  // length the programmed feeds would have cut in the same time (so each
  // stretch of path counts by its length, blends with their block). A
  // cutting segment's block is a cutting block, whose programmed feed
  // add_block() took from the block as it is.
  Profiles profiles(*this, n);
  for (size_t i = 0; i < n; ++i) {
    while (pause < tl.pauses.size() && pause_seg[pause] <= i) {
      plan.pause_start_s[pause] = t;
      t += tl.pauses[pause].seconds;
      plan.pause_time_s += tl.pauses[pause].seconds;
      ++pause;
    }
    const Lean& s = lean[i];
    const Profile pr = profiles.next(i);
    if (!summary) {
      PlanSegment& sg = segs[i];
      sg.v0 = speed_[i];
      sg.v1 = speed_[i + 1];
      sg.vpeak = pr.vpeak;
      sg.t_acc = pr.t_acc;
      sg.t_cruise = pr.t_cruise;
      sg.t_dec = pr.t_dec;
      sg.t_start = t;
    }
    // A parabolic blend at its end: the next move starts once this one has
    // slowed to the blend's speed, and the rest of its ramp down runs
    // together with the next move's start.
    const double ov = i + 1 < overlap_.size() && overlap_[i + 1] > 0 && s.accel > 0
                          ? std::min(overlap_[i + 1], pr.vpeak) / s.accel
                          : 0;
    const double own = std::max(0.0, pr.time() - ov);
    t += own;
    (s.rapid ? plan.rapid_time_s : plan.cutting_time_s) += own;
    const size_t b = static_cast<size_t>(s.block);
    // The cut along a curve, with the blends at both its ends (where the
    // machine turns from the plunge and into the retract).
    auto marked = [&](size_t k) { return k < tl.on_path.size() && tl.on_path[k]; };
    if (marked(b) || (s.blend && i + 1 < lean.size() && marked(static_cast<size_t>(lean[i + 1].block))))
      plan.path_time_s += own;
    PlannedBlock& pb = plan.blocks[b];
    pb.time_s += own;
    pb.peak_feed = std::max(pb.peak_feed, pr.vpeak * 60);
    SpeedLimit l = static_cast<SpeedLimit>(s.limit);
    if (i < lookahead_limited_.size() && lookahead_limited_[i]) l = SpeedLimit::lookahead;
    if (s.vmax >= top_[b]) {
      top_[b] = s.vmax;
      why_[b] = static_cast<std::uint8_t>(l);
    }
    if (s.rapid) continue;
    const double want = pb.programmed_feed / 60;
    if (!(want > 0)) continue;
    cut_done_ += s.length;
    at_feed_done_ += own * want;
  }
  // The pauses before the first segment after the part.
  while (pause < tl.pauses.size() && pause_seg[pause] <= n) {
    plan.pause_start_s[pause] = t;
    t += tl.pauses[pause].seconds;
    plan.pause_time_s += tl.pauses[pause].seconds;
    ++pause;
  }
  t_done_ = t;
  pause_done_ = pause;
}

void Builder::totals_end() {
  if (!timed_any_) totals_part(0);
  double t = t_done_;
  for (size_t pause = pause_done_; pause < tl.pauses.size(); ++pause) {
    plan.pause_start_s[pause] = t;
    t += tl.pauses[pause].seconds;
    plan.pause_time_s += tl.pauses[pause].seconds;
  }
  plan.cycle_time_s = t;
  plan.mean_feed_ratio = at_feed_done_ > 0 ? cut_done_ / at_feed_done_ : 1;
  // Per block (add_block() gave a cutting block its programmed feed, a
  // rapid the axes' rate along it).
  for (size_t b = 0; b < plan.blocks.size(); ++b) {
    PlannedBlock& pb = plan.blocks[b];
    const bool rapid = pb.kind == BlockKind::rapid;
    if (pb.length <= 1e-9) {
      if (rapid) pb.programmed_feed = 0;
      continue;  // no move: no time, no limit
    }
    const double want = pb.programmed_feed;
    if (want > 0) plan.programmed_feed_time_s += pb.length / want * 60;
    if (pb.clamped) ++plan.clamped_blocks;
    if (pb.peak_feed < want * (1 - 1e-6)) {
      pb.limit = static_cast<SpeedLimit>(why_[b]);
      if (pb.limit == SpeedLimit::programmed) pb.limit = SpeedLimit::acceleration;
    }
    pb.starved = pb.peak_feed < want * 0.99 && is_starvation(pb.limit);
    if (pb.starved) ++plan.starved_blocks;
  }
}

void Builder::time_done_part() {
  // The last stop (a junction at rest, not a parabolic blend's) with more
  // than the look-ahead's blocks after it, and two to spare: every window
  // of a segment before it ends inside `lean`, so the passes give those
  // segments the speeds a plan of the whole program would.
  const size_t window = static_cast<size_t>(std::max(1, model.lookahead_blocks));
  const size_t n = lean.size();
  size_t blocks_after = 0, J = 0;
  for (size_t i = n; i-- > 1;) {
    if (lean[i].block != lean[i - 1].block) ++blocks_after;
    if (blocks_after < window + 3) continue;
    if (junction[i] == 0 && (i >= overlap_.size() || overlap_[i] == 0)) {
      J = i;
      break;
    }
  }
  next_part_at_ = n + (size_t{1} << 14);
  if (J < 2) return;
  std::vector<double> keep(junction.begin() + static_cast<std::ptrdiff_t>(J), junction.end());
  std::vector<double> keep_overlap;
  if (overlap_.size() > J) keep_overlap.assign(overlap_.begin() + static_cast<std::ptrdiff_t>(J), overlap_.end());
  speeds();  // takes `junction`
  totals_part(J);
  lean.erase(lean.begin(), lean.begin() + static_cast<std::ptrdiff_t>(J));
  junction = std::move(keep);
  overlap_ = std::move(keep_overlap);
  lookahead_limited_.clear();
  speed_.clear();
  next_part_at_ = lean.size() + (size_t{1} << 16);
}

}  // namespace bezcam::planner_detail
