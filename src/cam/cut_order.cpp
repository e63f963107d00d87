// The cut-order planner (cam/cut_order.hpp, docs/cut-order.md); nesting is
// found in cut_order_nesting.cpp.
//
// Order: the contours between two fixed (not movable) ones form a segment,
// planned from the end of the previous fixed contour (or home) to the start
// of the next (or nowhere). In a segment, the precedence "inner before
// outer" is a DAG (find_nesting never makes a cycle). A small segment is
// solved exactly (branch and bound over the valid orders, a dynamic
// programme over the starts). Otherwise two tours are built, nearest
// neighbour under the precedence and the written order made valid (stable
// topological sort), both improved by local search (exact start choice,
// Or-opt, 2-opt over K nearest neighbours, each move checked against the
// precedence), and the shorter one is kept. The written order made valid
// wins unless the plan is shorter by more than rounding.
#include "bezcam/cam/cut_order.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <queue>
#include <stdexcept>
#include <string>
#include <utility>

#include "cut_order_nesting.hpp"
#include "cut_order_tree.hpp"

namespace bezcam {
namespace {

using cut_order_detail::Box2;
using cut_order_detail::BoxTree;
using cut_order_detail::check_input;
using cut_order_detail::dxy;
using cut_order_detail::nesting_of;
using cut_order_detail::tolerance_of;
using cut_order_detail::vertex_count;

// ---- planning a segment -------------------------------------------------

Box2 point_box(const Vec3& p) {
  Box2 b;
  b.add(p);
  return b;
}

struct Tour {
  std::vector<uint32_t> seq;  // local nodes, with the home sentinel first and the tail sentinel last
  std::vector<size_t> start;  // per local node
  std::vector<char> rev;      // per local node
  // Where each node is entered and left with its start and direction
  // (home's exit is the start point, the tail's entry the end point): the
  // local search reads these for every candidate.
  std::vector<Vec3> in, out;
};

class Segment {
 public:
  Segment(std::span<const OrderContour> cs, std::vector<size_t> ids, Vec3 from, std::optional<Vec3> to,
          const std::vector<std::pair<size_t, size_t>>& local_nesting, double eps)
      : cs_(cs),
        ids_(std::move(ids)),
        m_(ids_.size()),
        home_(static_cast<uint32_t>(m_)),
        tail_(static_cast<uint32_t>(m_ + 1)),
        from_(from),
        to_(to),
        eps_(eps) {
    preds_.resize(m_);
    succs_.resize(m_);
    for (const auto& [in, out] : local_nesting) {
      preds_[out].push_back(static_cast<uint32_t>(in));
      succs_[in].push_back(static_cast<uint32_t>(out));
    }
    box_.resize(m_);
    nv_.resize(m_);
    ends_.resize(m_);
    closed_.resize(m_);
    flips_.resize(m_);
    for (size_t u = 0; u < m_; ++u) {
      for (const auto& p : c(u).outline) box_[u].add(p);
      nv_[u] = vertex_count(c(u));
      if (!c(u).outline.empty()) ends_[u] = {c(u).outline.front(), c(u).outline.back()};
      closed_[u] = c(u).closed;
      flips_[u] = !c(u).closed && c(u).reversible;
    }
    build_neighbours();
  }

  size_t size() const { return m_; }

  /// Nearest neighbour under the precedence: from the last exit, the
  /// available contour with the nearest start (ties: the lowest index).
  /// The starts are searched in a tree (cut_order_tree.hpp) of their boxes:
  /// each end of an open contour a point, a closed contour's allowed start
  /// vertices one box.
  Tour nearest() const {
    Tour t = fresh();
    std::vector<Box2> ports;
    std::vector<uint32_t> owner, first(m_ + 1, 0);
    for (uint32_t u = 0; u < m_; ++u) {
      const auto& o = c(u).outline;
      first[u] = static_cast<uint32_t>(ports.size());
      if (c(u).closed) {
        Box2 b;
        for (size_t q = 0; q < count(u); ++q) b.add(o[vertex(u, q)]);
        ports.push_back(b);
      } else {
        ports.push_back(point_box(o.front()));
        if (c(u).reversible) ports.push_back(point_box(o.back()));
      }
      owner.resize(ports.size(), u);
    }
    first[m_] = static_cast<uint32_t>(ports.size());
    BoxTree tree(ports);
    auto set = [&](uint32_t u, bool active) {
      for (uint32_t k = first[u]; k < first[u + 1]; ++k) tree.set_active(k, active);
    };
    std::vector<size_t> waiting(m_);
    for (uint32_t u = 0; u < m_; ++u) {
      waiting[u] = preds_[u].size();
      if (waiting[u] != 0) set(u, false);
    }
    Vec3 p = from_;
    for (size_t left = m_; left > 0; --left) {
      double best = HUGE_VAL;
      uint32_t bu = UINT32_MAX;
      size_t bs = 0;
      bool br = false;
      tree.search<double>([&](const Box2& boxes, const Box2&) { return boxes.gap(p); },
                          [&](uint32_t k) {
                            const uint32_t u = owner[k];
                            if (ports[k].gap(p) > best) return;
                            size_t s = 0;
                            bool r = false;
                            const double d = start_nearest(u, p, s, r);
                            if (d < best || (d == best && u < bu)) best = d, bu = u, bs = s, br = r;
                          },
                          [&](double lower) { return lower > best; });
      t.seq.insert(t.seq.end() - 1, bu);
      choose(t, bu, bs, br);
      p = exit(t, bu);
      set(bu, false);
      for (uint32_t o : succs_[bu])
        if (--waiting[o] == 0) set(o, true);
    }
    return t;
  }

  /// The written order made valid: stable topological sort (the lowest
  /// index whose inner contours are all cut comes next), written starts.
  Tour written() const {
    Tour t = fresh();
    std::vector<size_t> waiting(m_);
    std::priority_queue<uint32_t, std::vector<uint32_t>, std::greater<>> ready;
    for (size_t u = 0; u < m_; ++u) {
      waiting[u] = preds_[u].size();
      if (waiting[u] == 0) ready.push(static_cast<uint32_t>(u));
    }
    while (!ready.empty()) {
      const uint32_t u = ready.top();
      ready.pop();
      t.seq.insert(t.seq.end() - 1, u);
      for (uint32_t o : succs_[u])
        if (--waiting[o] == 0) ready.push(o);
    }
    return t;
  }

  double cost(const Tour& t) const {
    double s = 0;
    for (size_t i = 0; i + 1 < t.seq.size(); ++i) s += link(t, t.seq[i], t.seq[i + 1]);
    return s;
  }

  /// Local search until no move shortens the tour.
  void improve(Tour& t) const {
    std::vector<size_t> pos(m_ + 2);
    for (int round = 0; round < 200; ++round) {
      bool any = starts(t);
      any = or_opt(t, pos) || any;
      any = two_opt(t, pos) || any;
      if (!any) break;
    }
    starts(t);
  }

  /// The shortest tour, by depth-first search over the orders that keep
  /// the precedence (branch and bound), each extended by a dynamic programme
  /// over the choices of start and direction. Empty when over the budget.
  std::optional<Tour> exact(size_t limit) const {
    if (m_ == 0 || m_ > limit) return std::nullopt;
    std::vector<std::vector<Choice>> ch(m_);
    size_t widest = 1;
    for (uint32_t u = 0; u < m_; ++u) {
      choices(u, ch[u]);
      widest = std::max(widest, ch[u].size());
    }
    double work = static_cast<double>(widest * widest) * 2.72;
    for (size_t k = 2; k <= m_; ++k) work *= static_cast<double>(k);
    if (work > 2e7) return std::nullopt;

    std::vector<std::vector<double>> acc(m_ + 1);
    std::vector<std::vector<uint32_t>> back(m_ + 1);
    std::vector<uint32_t> order(m_ + 1, home_), best_order;
    std::vector<std::vector<uint32_t>> best_back;
    std::vector<size_t> waiting(m_);
    std::vector<char> used(m_, 0);
    for (size_t u = 0; u < m_; ++u) waiting[u] = preds_[u].size();
    const std::vector<Choice> home_choice = {{from_, from_, 0, 0}};
    acc[0] = {0.0};
    double best = HUGE_VAL;
    size_t best_last = 0;
    const Tour probe = fresh();
    std::function<void(size_t)> dfs = [&](size_t depth) {
      const auto& pc = depth == 0 ? home_choice : ch[order[depth]];
      if (depth == m_) {
        for (size_t q = 0; q < pc.size(); ++q) {
          const double d = acc[depth][q] + to(probe, pc[q].out, tail_);
          if (d < best) best = d, best_last = q, best_order = order, best_back = back;
        }
        return;
      }
      for (uint32_t u = 0; u < m_; ++u) {
        if (used[u] || waiting[u] != 0) continue;
        const auto& cc = ch[u];
        auto& a = acc[depth + 1];
        auto& b = back[depth + 1];
        a.assign(cc.size(), HUGE_VAL);
        b.assign(cc.size(), 0);
        double lo = HUGE_VAL;
        for (size_t k = 0; k < cc.size(); ++k) {
          for (size_t q = 0; q < pc.size(); ++q) {
            const double d = acc[depth][q] + dxy(pc[q].out, cc[k].in);
            if (d < a[k]) a[k] = d, b[k] = static_cast<uint32_t>(q);
          }
          lo = std::min(lo, a[k]);
        }
        if (lo >= best) continue;
        used[u] = 1;
        order[depth + 1] = u;
        for (uint32_t o : succs_[u]) --waiting[o];
        dfs(depth + 1);
        for (uint32_t o : succs_[u]) ++waiting[o];
        used[u] = 0;
      }
    };
    dfs(0);
    Tour t = fresh();
    size_t k = best_last;
    for (size_t d = m_; d >= 1; --d) {
      const uint32_t u = best_order[d];
      t.seq.insert(t.seq.begin() + 1, u);
      choose(t, u, ch[u][k].start, ch[u][k].rev);
      k = best_back[d][k];
    }
    return t;
  }

  std::vector<OrderStep> steps(const Tour& t) const {
    std::vector<OrderStep> out;
    for (size_t i = 1; i + 1 < t.seq.size(); ++i) {
      const uint32_t u = t.seq[i];
      out.push_back({ids_[u], t.start[u], t.rev[u] != 0});
    }
    return out;
  }

 private:
  const OrderContour& c(size_t u) const { return cs_[ids_[u]]; }

  Tour fresh() const {
    Tour t;
    t.seq = {home_, tail_};
    t.start.assign(m_, 0);
    t.rev.assign(m_, 0);
    t.in.resize(m_ + 2);
    t.out.resize(m_ + 2);
    for (uint32_t u = 0; u < m_; ++u) choose(t, u, 0, 0);
    t.out[home_] = from_;
    t.in[tail_] = to_.value_or(Vec3{});
    return t;
  }

  /// Gives u the start vertex `start` and direction `rev`.
  void choose(Tour& t, uint32_t u, size_t start, char rev) const {
    t.start[u] = start;
    t.rev[u] = rev;
    if (closed_[u]) {
      t.in[u] = t.out[u] = c(u).outline[start];
    } else {
      t.in[u] = rev ? ends_[u].second : ends_[u].first;
      t.out[u] = rev ? ends_[u].first : ends_[u].second;
    }
  }

  Vec3 entry(const Tour& t, uint32_t u) const { return t.in[u]; }
  Vec3 exit(const Tour& t, uint32_t u) const { return t.out[u]; }
  /// Rapid from point p to the entry of v (nothing to a missing tail).
  double to(const Tour& t, const Vec3& p, uint32_t v) const {
    if (v == tail_ && !to_) return 0;
    return dxy(p, entry(t, v));
  }
  double link(const Tour& t, uint32_t u, uint32_t v) const { return to(t, exit(t, u), v); }
  /// A reversible open contour flips when a stretch holding it is reversed
  /// (so the links inside keep their length); others keep their direction.
  bool flips(uint32_t u) const { return flips_[u]; }
  Vec3 entry_r(const Tour& t, uint32_t u) const { return flips(u) ? exit(t, u) : entry(t, u); }
  Vec3 exit_r(const Tour& t, uint32_t u) const { return flips(u) ? entry(t, u) : exit(t, u); }
  void flip(Tour& t, uint32_t u) const {
    if (!flips(u)) return;
    const char rev = !t.rev[u];
    choose(t, u, rev ? c(u).outline.size() - 1 : 0, rev);
  }
  /// The choices of u as (entry, exit, start vertex, reversed).
  struct Choice {
    Vec3 in, out;
    size_t start;
    char rev;
  };
  void choices(uint32_t u, std::vector<Choice>& out) const {
    out.clear();
    const auto& o = c(u).outline;
    if (c(u).closed) {
      for (size_t i = 0; i < count(u); ++i) out.push_back({o[vertex(u, i)], o[vertex(u, i)], vertex(u, i), 0});
    } else {
      out.push_back({o.front(), o.back(), 0, 0});
      if (c(u).reversible) out.push_back({o.back(), o.front(), o.size() - 1, 1});
    }
  }

  /// K nearest contours by box gap, then box centre distance, then index,
  /// found through the tree of the boxes (cut_order_tree.hpp): the same as
  /// comparing all pairs.
  void build_neighbours() {
    constexpr size_t K = kNeighbours;
    nbrs_.assign(m_, {});
    if (m_ < 2) return;
    std::vector<Vec3> ctr(m_);
    for (size_t u = 0; u < m_; ++u) ctr[u] = box_[u].center();
    const BoxTree tree(box_);
    struct Cand {
      double gap, cd;
      uint32_t v;
      bool operator<(const Cand& o) const { return gap != o.gap ? gap < o.gap : cd != o.cd ? cd < o.cd : v < o.v; }
    };
    using Key = std::pair<double, double>;  // (gap, centre distance), each a lower bound
    std::vector<Cand> best;
    for (uint32_t u = 0; u < m_; ++u) {
      best.clear();
      tree.search<Key>(
          [&](const Box2& boxes, const Box2& centres) {
            return Key{box_[u].gap(boxes), centres.gap(ctr[u])};
          },
          [&](uint32_t v) {
            if (v == u) return;
            const Cand cand{box_[u].gap(box_[v]), dxy(ctr[u], ctr[v]), v};
            if (best.size() == K && !(cand < best.back())) return;
            best.insert(std::upper_bound(best.begin(), best.end(), cand), cand);
            if (best.size() > K) best.pop_back();
          },
          [&](const Key& lower) {
            return best.size() == K && Key{best.back().gap, best.back().cd} < lower;
          });
      for (const auto& b : best) nbrs_[u].push_back(b.v);
    }
  }

  /// The start of u nearest to p (a closed contour's allowed vertices, an
  /// open one's ends as its direction allows); returns the distance.
  double start_nearest(uint32_t u, const Vec3& p, size_t& start, bool& rev) const {
    const auto& o = c(u).outline;
    start = 0, rev = false;
    if (!c(u).closed) {
      double d = dxy(p, o.front());
      if (c(u).reversible && dxy(p, o.back()) < d) d = dxy(p, o.back()), start = o.size() - 1, rev = true;
      return d;
    }
    double d = HUGE_VAL;
    for (size_t q = 0; q < count(u); ++q) {
      const size_t k = vertex(u, q);
      const double dk = dxy(p, o[k]);
      if (dk < d) d = dk, start = k;
    }
    return d;
  }

  /// Best start (closed) or direction (reversible open) of u between the
  /// exit point p and the node v; returns the cost p -> u -> v.
  double best_place(const Tour& t, uint32_t u, const Vec3& p, uint32_t v, size_t& start, char& rev) const {
    const auto& o = c(u).outline;
    double best = HUGE_VAL;
    if (c(u).closed) {
      const bool free_end = v == tail_ && !to_;  // nothing after u
      const Vec3 q = free_end ? Vec3{} : entry(t, v);
      for (size_t i = 0; i < count(u); ++i) {
        const size_t k = vertex(u, i);
        const double lo = dxy(p, o[k]);
        if (lo >= best) continue;
        const double d = lo + (free_end ? 0 : dxy(o[k], q));
        if (d < best) best = d, start = k, rev = 0;
      }
      return best;
    }
    best = dxy(p, o.front()) + to(t, o.back(), v);
    start = 0, rev = 0;
    if (c(u).reversible) {
      const double d = dxy(p, o.back()) + to(t, o.front(), v);
      if (d < best) best = d, start = o.size() - 1, rev = 1;
    }
    return best;
  }

  /// Re-chooses starts and directions for the tour's order: exactly, by a
  /// dynamic programme over the chain of choices, when that is affordable
  /// (sum of products of neighbouring choice counts), else by sweeps of
  /// coordinate descent. True when the tour got shorter.
  bool starts(Tour& t) const {
    double work = 0;
    for (size_t i = 1; i + 1 < t.seq.size(); ++i) {
      const uint32_t u = t.seq[i], v = t.seq[i + 1];
      work += static_cast<double>(count(u)) * static_cast<double>(v == tail_ ? 1 : count(v));
    }
    if (work <= 2e7) return starts_exact(t);
    bool any = false;
    for (int sweep = 0; sweep < 50; ++sweep) {
      bool changed = false;
      for (size_t i = 1; i + 1 < t.seq.size(); ++i) {
        const uint32_t u = t.seq[i];
        if (!c(u).closed && !c(u).reversible) continue;
        const Vec3 p = exit(t, t.seq[i - 1]);
        const uint32_t v = t.seq[i + 1];
        const double now = dxy(p, entry(t, u)) + link(t, u, v);
        size_t s = 0;
        char r = 0;
        const double d = best_place(t, u, p, v, s, r);
        if (d < now - eps_) choose(t, u, s, r), changed = true;
      }
      if (!changed) break;
      any = true;
    }
    return any;
  }

  /// Start choices: the allowed start vertices of a closed contour, the
  /// directions of an open one.
  size_t count(uint32_t u) const {
    if (!c(u).closed) return c(u).reversible ? 2 : 1;
    return c(u).starts.empty() ? nv_[u] : c(u).starts.size();
  }
  /// The i-th allowed start vertex of closed u.
  size_t vertex(uint32_t u, size_t i) const { return c(u).starts.empty() ? i : c(u).starts[i]; }

  bool starts_exact(Tour& t) const {
    if (m_ == 0) return false;
    const double before = cost(t);
    // back[first[i] + k]: the choice of seq[i-1] before choice k of seq[i]
    std::vector<size_t> first(m_ + 2, 0);
    std::vector<uint32_t> back;
    std::vector<Choice> prev = {{from_, from_, 0, 0}}, cur;
    std::vector<double> prev_acc = {0.0}, acc;
    for (size_t i = 1; i <= m_; ++i) {
      choices(t.seq[i], cur);
      first[i] = back.size();
      back.resize(back.size() + cur.size(), 0);
      acc.assign(cur.size(), HUGE_VAL);
      for (size_t k = 0; k < cur.size(); ++k)
        for (size_t q = 0; q < prev.size(); ++q) {
          const double d = prev_acc[q] + dxy(prev[q].out, cur[k].in);
          if (d < acc[k]) acc[k] = d, back[first[i] + k] = static_cast<uint32_t>(q);
        }
      prev.swap(cur);
      prev_acc.swap(acc);
    }
    size_t k = 0;
    double best = HUGE_VAL;
    for (size_t q = 0; q < prev.size(); ++q) {
      const double d = prev_acc[q] + to(t, prev[q].out, tail_);
      if (d < best) best = d, k = q;
    }
    if (!(best < before - eps_)) return false;
    for (size_t i = m_; i >= 1; --i) {
      const uint32_t u = t.seq[i];
      choices(u, cur);
      choose(t, u, cur[k].start, cur[k].rev);
      k = back[first[i] + k];
    }
    return true;
  }

  void positions(const Tour& t, std::vector<size_t>& pos) const {
    for (size_t i = 0; i < t.seq.size(); ++i) pos[t.seq[i]] = i;
  }

  /// Moving seq[i..i+L-1] to just after position j keeps the precedence.
  bool may_move(const Tour& t, const std::vector<size_t>& pos, size_t i, size_t L, size_t j) const {
    for (size_t k = i; k < i + L; ++k) {
      const uint32_t s = t.seq[k];
      if (j >= i + L) {  // forward over [i+L, j]: none of s's outers there
        for (uint32_t o : succs_[s])
          if (pos[o] >= i + L && pos[o] <= j) return false;
      } else {  // backward over [j+1, i-1]: none of s's inners there
        for (uint32_t q : preds_[s])
          if (pos[q] > j && pos[q] < i) return false;
      }
    }
    return true;
  }

  /// Or-opt: a run of 1 to 3 contours moved next to a neighbour of its ends
  /// (a single contour with its start or direction re-chosen there).
  bool or_opt(Tour& t, std::vector<size_t>& pos) const {
    bool any = false;
    positions(t, pos);
    for (size_t L = 1; L <= 3 && L <= m_; ++L) {
      for (uint32_t u0 = 0; u0 < m_; ++u0) {
        const size_t i = pos[u0];
        if (i + L > m_ + 1) continue;  // run would reach the tail
        const uint32_t f = t.seq[i], l = t.seq[i + L - 1];
        const uint32_t p = t.seq[i - 1], n = t.seq[i + L];
        const double gain = link(t, p, f) + link(t, l, n) - link(t, p, n);
        // candidate insertion points j (after seq[j])
        // in ascending order, each once: 0 and m_ bound the neighbours' places
        std::array<size_t, 2 * kNeighbours> near{};
        size_t n_near = 0;
        auto candidate = [&](size_t j) {  // insertion sort of a few
          size_t at = n_near++;
          for (; at > 0 && near[at - 1] > j; --at) near[at] = near[at - 1];
          near[at] = j;
        };
        for (uint32_t c2 : nbrs_[f]) candidate(pos[c2] - 1);
        for (uint32_t c2 : nbrs_[l]) candidate(pos[c2]);
        cands_.clear();
        cands_.push_back(0);
        for (size_t k = 0; k < n_near; ++k)
          if (near[k] != cands_.back()) cands_.push_back(near[k]);
        if (cands_.back() != m_) cands_.push_back(m_);
        double best = -eps_;
        size_t best_j = 0, bs = 0;
        char br = 0;
        bool found = false, best_flip = false;
        // the run reversed (reversible members flipped): its inside changes by
        double inside = 0;
        bool may_flip = L > 1;
        for (size_t k = i; k + 1 < i + L; ++k) {
          inside += dxy(exit_r(t, t.seq[k + 1]), entry_r(t, t.seq[k])) - link(t, t.seq[k], t.seq[k + 1]);
          for (uint32_t o : succs_[t.seq[k]])
            if (pos[o] > k && pos[o] < i + L) may_flip = false;
        }
        for (size_t j : cands_) {
          if (j + 1 >= i && j <= i + L - 1) continue;  // same place or inside the run
          if (j > m_) continue;
          const uint32_t a = t.seq[j], b = t.seq[j + 1];
          double add;
          size_t s = t.start[f];
          char r = t.rev[f];
          if (L == 1 && (c(f).closed || c(f).reversible)) {
            // the boxes bound the detour from below: skip a hopeless place cheaply
            const Vec3 pa = exit(t, a);
            const double lo = box_[f].gap(pa) + (b == tail_ && !to_ ? 0 : box_[f].gap(entry(t, b)));
            if (lo - link(t, a, b) - gain >= best) continue;
            add = best_place(t, f, pa, b, s, r);
          } else {
            add = link(t, a, f) + link(t, l, b);
          }
          const double delta = add - link(t, a, b) - gain;
          if (delta < best && may_move(t, pos, i, L, j))
            best = delta, best_j = j, bs = s, br = r, found = true, best_flip = false;
          if (may_flip) {
            const double dr = dxy(exit(t, a), entry_r(t, l)) + to(t, exit_r(t, f), b) + inside - link(t, a, b) - gain;
            if (dr < best && may_move(t, pos, i, L, j)) best = dr, best_j = j, found = true, best_flip = true;
          }
        }
        if (!found) continue;
        std::vector<uint32_t> run(t.seq.begin() + static_cast<std::ptrdiff_t>(i),
                                  t.seq.begin() + static_cast<std::ptrdiff_t>(i + L));
        t.seq.erase(t.seq.begin() + static_cast<std::ptrdiff_t>(i), t.seq.begin() + static_cast<std::ptrdiff_t>(i + L));
        const size_t at = best_j < i ? best_j + 1 : best_j + 1 - L;
        if (best_flip) {
          std::reverse(run.begin(), run.end());
          for (uint32_t u : run) flip(t, u);
        }
        t.seq.insert(t.seq.begin() + static_cast<std::ptrdiff_t>(at), run.begin(), run.end());
        if (L == 1) choose(t, f, bs, br);
        for (size_t k = std::min(i, at), hi = std::max(i, at) + L; k < hi; ++k) pos[t.seq[k]] = k;
        any = true;
      }
    }
    return any;
  }

  /// Reversing seq[l..r] keeps the precedence.
  bool may_reverse(const Tour& t, const std::vector<size_t>& pos, size_t l, size_t r) const {
    for (size_t k = l; k <= r; ++k)
      for (uint32_t o : succs_[t.seq[k]])
        if (pos[o] >= l && pos[o] <= r) return false;
    return true;
  }

  /// 2-opt: reverse the visiting order of a stretch so that a contour is
  /// joined to one of its neighbours (reversible open contours in it flip,
  /// others keep their direction; the links inside are summed by a Fenwick tree).
  bool two_opt(Tour& t, std::vector<size_t>& pos) const {
    bool any = false;
    // change[k] (2 <= k <= m): the link seq[k-1] -> seq[k] reversed (and
    // flipped) minus as it is; zero unless an open contour that cannot
    // reverse is at either end. Summed over a stretch by a Fenwick tree.
    const size_t len = t.seq.size();
    std::vector<double> change(len, 0), tree(len + 1, 0);
    auto add = [&](size_t k, double v) {
      for (size_t x = k + 1; x <= len; x += x & (~x + 1)) tree[x] += v;
    };
    auto below = [&](size_t k) {  // sum of change[0 .. k)
      double r = 0;
      for (size_t x = k; x > 0; x -= x & (~x + 1)) r += tree[x];
      return r;
    };
    auto value = [&](size_t k) {
      return dxy(exit_r(t, t.seq[k]), entry_r(t, t.seq[k - 1])) - link(t, t.seq[k - 1], t.seq[k]);
    };
    for (size_t k = 2; k <= m_; ++k) {
      change[k] = value(k);
      if (change[k] != 0) add(k, change[k]);
    }
    // the links inside [l, r] reversed minus as they are
    auto inside = [&](size_t l, size_t r) { return below(r + 1) - below(l + 1); };
    positions(t, pos);
    for (uint32_t a = 0; a < m_; ++a) {
      double best = -eps_;
      size_t bl = 0, br = 0;
      for (uint32_t cc : nbrs_[a]) {
        const size_t i = pos[a], j = pos[cc];
        size_t l, r;
        double delta;
        if (j > i + 1) {  // a -> cc: reverse [i+1, j]
          l = i + 1, r = j;
          const uint32_t b = t.seq[l], n = t.seq[r + 1];
          delta =
              dxy(exit(t, a), entry_r(t, cc)) + to(t, exit_r(t, b), n) - link(t, a, b) - link(t, cc, n) + inside(l, r);
        } else if (j + 1 < i) {  // cc -> a: reverse [j, i-1]
          l = j, r = i - 1;
          const uint32_t p = t.seq[l - 1], e = t.seq[r];
          delta = dxy(exit(t, p), entry_r(t, e)) + dxy(exit_r(t, cc), entry(t, a)) - link(t, p, cc) - link(t, e, a) +
                  inside(l, r);
        } else {
          continue;
        }
        if (delta < best && may_reverse(t, pos, l, r)) best = delta, bl = l, br = r;
      }
      if (br == 0) continue;
      std::reverse(t.seq.begin() + static_cast<std::ptrdiff_t>(bl),
                   t.seq.begin() + static_cast<std::ptrdiff_t>(br + 1));
      for (size_t k = bl; k <= br; ++k) {
        flip(t, t.seq[k]);
        pos[t.seq[k]] = k;
      }
      for (size_t k = std::max<size_t>(bl, 2); k <= std::min(br + 1, m_); ++k) {
        const double v = value(k);
        if (v != change[k]) add(k, v - change[k]), change[k] = v;
      }
      any = true;
    }
    return any;
  }

  static constexpr size_t kNeighbours = 10;  // per contour, for the local search
  std::span<const OrderContour> cs_;
  std::vector<size_t> ids_;
  size_t m_;
  uint32_t home_, tail_;
  Vec3 from_;
  std::optional<Vec3> to_;
  double eps_;
  std::vector<std::vector<uint32_t>> preds_, succs_, nbrs_;
  std::vector<Box2> box_;
  std::vector<size_t> nv_;
  std::vector<std::pair<Vec3, Vec3>> ends_;  // first and last point of each outline
  std::vector<char> closed_, flips_;
  mutable std::vector<size_t> cands_;
};

// Up to this many contours in a segment, both starts (the written order
// and nearest neighbour) are improved; above, the shorter one only.
constexpr size_t kBothStartsUpTo = 2000;

Vec3 step_entry(std::span<const OrderContour> cs, const OrderStep& s) { return cs[s.contour].outline[s.start_vertex]; }
Vec3 step_exit(std::span<const OrderContour> cs, const OrderStep& s) {
  const auto& c = cs[s.contour];
  if (c.closed) return c.outline[s.start_vertex];
  return s.reversed ? c.outline.front() : c.outline.back();
}

double rapid_of(std::span<const OrderContour> cs, const std::vector<OrderStep>& steps, Vec3 home) {
  double r = 0;
  Vec3 p = home;
  for (const auto& s : steps) {
    r += dxy(p, step_entry(cs, s));
    p = step_exit(cs, s);
  }
  return r;
}

}  // namespace

CutOrder plan_cut_order(std::span<const OrderContour> contours, Vec3 home, const CutOrderOptions& options) {
  check_input(contours);
  const size_t n = contours.size();
  const double tol = tolerance_of(contours, options);
  CutOrder out;
  out.nesting = nesting_of(contours, tol);

  std::vector<OrderStep> written;
  for (size_t i = 0; i < n; ++i) written.push_back({i, 0, false});
  out.rapid_as_written = rapid_of(contours, written, home);

  // Segments: runs of movable contours between fixed ones.
  std::vector<size_t> seg_of(n, SIZE_MAX), local(n, 0);
  std::vector<std::vector<size_t>> segs(1);
  std::vector<size_t> fixed_after;  // fixed contour that closes segment k (SIZE_MAX: none)
  for (size_t i = 0; i < n; ++i) {
    if (contours[i].movable) {
      seg_of[i] = segs.size() - 1;
      local[i] = segs.back().size();
      segs.back().push_back(i);
    } else {
      fixed_after.push_back(i);
      segs.emplace_back();
    }
  }
  fixed_after.push_back(SIZE_MAX);
  std::vector<std::vector<std::pair<size_t, size_t>>> seg_nest(segs.size());
  for (const auto& [in, o] : out.nesting)
    if (seg_of[in] != SIZE_MAX && seg_of[in] == seg_of[o]) seg_nest[seg_of[in]].emplace_back(local[in], local[o]);

  // Moves must gain more than rounding: 1e-10 of the largest coordinate.
  double scale = std::max({1.0, std::abs(home.x), std::abs(home.y)});
  for (const auto& c : contours)
    for (const auto& p : c.outline) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  const double eps = 1e-10 * scale;
  std::vector<OrderStep> planned, baseline;
  Vec3 from = home;
  for (size_t k = 0; k < segs.size(); ++k) {
    std::optional<Vec3> to;
    const size_t fx = fixed_after[k];
    const OrderStep fixed_step{fx, 0, false};
    if (fx != SIZE_MAX) to = step_entry(contours, fixed_step);
    if (!segs[k].empty()) {
      const Segment seg(contours, segs[k], from, to, seg_nest[k], eps);
      const Tour base = seg.written();
      for (const auto& s : seg.steps(base)) baseline.push_back(s);
      Tour best;
      if (auto ex = seg.exact(options.exact_up_to)) {
        best = std::move(*ex);
      } else {
        Tour a = base;
        Tour b = seg.nearest();
        if (seg.size() <= kBothStartsUpTo) {
          seg.improve(a);
          seg.improve(b);
        } else {  // only the shorter start is improved
          seg.improve(seg.cost(b) < seg.cost(a) ? b : a);
        }
        best = seg.cost(b) < seg.cost(a) ? std::move(b) : std::move(a);
      }
      for (const auto& s : seg.steps(best)) planned.push_back(s);
    }
    if (fx != SIZE_MAX) {
      planned.push_back(fixed_step);
      baseline.push_back(fixed_step);
      from = step_exit(contours, fixed_step);
    }
  }

  out.rapid_baseline = rapid_of(contours, baseline, home);
  out.rapid_planned = rapid_of(contours, planned, home);
  if (out.rapid_planned < out.rapid_baseline - eps) {  // a gain of rounding only keeps the written order
    out.steps = std::move(planned);
  } else {
    out.steps = std::move(baseline);
    out.rapid_planned = out.rapid_baseline;
  }
  bool same = true;
  for (size_t i = 0; i < n && same; ++i)
    same = out.steps[i].contour == i && out.steps[i].start_vertex == 0 && !out.steps[i].reversed;
  out.kept_as_written = same;

  std::vector<size_t> at(n);
  for (size_t i = 0; i < n; ++i) at[out.steps[i].contour] = i;
  for (const auto& [in, o] : out.nesting)
    if (at[in] > at[o]) ++out.unmet_nesting;
  return out;
}

}  // namespace bezcam
