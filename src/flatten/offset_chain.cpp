// Chaining the kept pieces of a cut offset path (offset_chain.hpp): linking
// each piece to the next, following the links, and cutting out the loops
// and slivers a small kink of the arc spline leaves.
#include "offset_chain.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace bezcam::flatten_detail {

namespace {

struct Chainer {
  const std::vector<ArcSeg>& kept;
  bool closed;
  ChainTolerances tol;
  std::vector<int> next, prev;
  std::vector<bool> used;

  Chainer(const std::vector<ArcSeg>& k, bool c, const ChainTolerances& t)
      : kept(k), closed(c), tol(t), next(k.size(), -1), prev(k.size(), -1), used(k.size(), false) {}

  void link_pieces();
  void append(std::vector<ArcSeg>& chain, const ArcSeg& s) const;
  std::vector<ArcSeg> follow(size_t from, bool& loop);
  void excise(std::vector<ArcSeg>& ch) const;
  bool close_where_back(std::vector<ArcSeg>& chain) const;
  void walk(size_t from, OffsetResult& res);
};

// Each piece's successor: the nearest start within `link` of its end, the
// next one along the raw path first (an open curve's path does not wrap).
void Chainer::link_pieces() {
  const size_t k = kept.size();
  for (size_t i = 0; i < k; ++i) {
    int best = -1;
    double best_d = tol.link;
    for (size_t step = 1; step <= k; ++step) {
      const size_t j = (i + step) % k;
      if (!closed && j <= i) break;
      if (prev[j] >= 0) continue;
      const double d = dist(kept[i].b, kept[j].a);
      if (d <= best_d) {
        best = static_cast<int>(j);
        best_d = d;
        if (d <= tol.eps) break;
      }
    }
    if (best >= 0 && best != static_cast<int>(i)) {
      next[i] = best;
      prev[static_cast<size_t>(best)] = static_cast<int>(i);
    } else if (best == static_cast<int>(i)) {
      next[i] = best;
      prev[i] = best;
    }
  }
}

// Appends s (which starts where the chain ends) to the chain.
void Chainer::append(std::vector<ArcSeg>& chain, const ArcSeg& s) const {
  // A crumb (a kink's sliver, a touch) is absorbed by its neighbour.
  if (!chain.empty() && s.length() <= 1e3 * tol.eps) {
    ArcSeg& last = chain.back();
    if (last.arc) {
      last = ArcSeg::make_arc(last.a, s.b, last.c, last.sweep);
    } else {
      last.b = s.b;
    }
  } else if (!chain.empty() && chain.back().arc == s.arc && !s.arc &&
             std::abs(cross(chain.back().tangent(0), s.tangent(0)).z) < 1e-12 &&
             dot(chain.back().tangent(0), s.tangent(0)) > 0) {
    // one line on (a line that turns back is a spur the tool goes into)
    chain.back().b = s.b;
  } else {
    chain.push_back(s);
  }
}

// The chain from `from` along the links, each piece starting exactly where
// the one before ends; `loop`: it came back to `from`.
std::vector<ArcSeg> Chainer::follow(size_t from, bool& loop) {
  std::vector<ArcSeg> chain;
  size_t i = from;
  loop = false;
  while (!used[i]) {
    used[i] = true;
    ArcSeg s = kept[i];
    if (!chain.empty()) s.a = chain.back().b;  // the shared crossing, exactly
    append(chain, s);
    if (next[i] < 0) break;
    i = static_cast<size_t>(next[i]);
    if (i == from) {
      loop = true;
      break;
    }
  }
  if (chain.size() > 1 && chain.front().length() <= 1e3 * tol.eps) {
    chain[1].a = chain.front().a;
    if (chain[1].arc) chain[1] = ArcSeg::make_arc(chain[1].a, chain[1].b, chain[1].c, chain[1].sweep);
    chain.erase(chain.begin());
  }
  if (loop && !chain.empty()) chain.back().b = chain.front().a;
  return chain;
}

// A loop of the chain that closes on itself within the fit is cut out: at
// a small kink of A the two offsets overshoot their crossing, and the
// overshoots with the join between them are valid within the
// floating-point margin, so the chain ran past the crossing, back and on
// again. Every point taken out is a valid one, and the chain stays
// continuous (the loop starts and ends at one point).
void Chainer::excise(std::vector<ArcSeg>& ch) const {
  std::vector<ArcSeg> out;
  for (ArcSeg s : ch) {
    if (!out.empty()) s.a = out.back().b;
    out.push_back(s);
    double around = 0;
    for (size_t q = out.size(); q-- > 0;) {
      around += out[q].length();
      if (around > tol.fit) break;
      if (dist(out[q].a, out.back().b) <= tol.link) {
        out.erase(out.begin() + static_cast<std::ptrdiff_t>(q), out.end());
        break;
      }
    }
  }
  ch = std::move(out);
}

// A chain that comes back to its start and runs on into such crumbs (or
// starts in them) is closed where it comes back; returns whether it was.
bool Chainer::close_where_back(std::vector<ArcSeg>& chain) const {
  bool loop = false;
  double around = 0;
  for (size_t q = chain.size() - 1; q > 1 && (around += chain[q].length()) <= tol.fit; --q)
    if (dist(chain[q - 1].b, chain.front().a) <= tol.link) {
      chain.erase(chain.begin() + static_cast<std::ptrdiff_t>(q), chain.end());
      loop = true;
      break;
    }
  around = 0;
  for (size_t q = 0; !loop && q + 2 < chain.size() && (around += chain[q].length()) <= tol.fit; ++q)
    if (dist(chain[q + 1].a, chain.back().b) <= tol.link) {
      chain.erase(chain.begin(), chain.begin() + static_cast<std::ptrdiff_t>(q + 1));
      loop = true;
    }
  if (loop) chain.back().b = chain.front().a;
  return loop;
}

void Chainer::walk(size_t from, OffsetResult& res) {
  bool loop = false;
  std::vector<ArcSeg> chain = follow(from, loop);
  excise(chain);
  if (!loop && chain.size() > 2) loop = close_where_back(chain);
  // A closed chain is read again from its middle, for a loop over its start.
  if (loop && chain.size() > 2) {
    std::rotate(chain.begin(), chain.begin() + static_cast<std::ptrdiff_t>(chain.size() / 2), chain.end());
    excise(chain);
    if (!chain.empty()) chain.back().b = chain.front().a;
  }
  double len = 0;
  for (const auto& s : chain) len += s.length();
  // A sliver shorter than the fit is a crumb of a crossing (at a small
  // kink of A): every point of it is valid, but it cuts nothing.
  if (len > std::max(1e3 * tol.eps, tol.fit)) {
    res.chains.push_back(std::move(chain));
    res.closed.push_back(loop);
  }
}

}  // namespace

void chain_pieces(const std::vector<ArcSeg>& kept, bool closed, const ChainTolerances& tol, OffsetResult& res) {
  Chainer c(kept, closed, tol);
  c.link_pieces();
  const size_t k = kept.size();
  for (size_t i = 0; i < k; ++i)
    if (c.prev[i] < 0 && !c.used[i]) c.walk(i, res);
  for (size_t i = 0; i < k; ++i)
    if (!c.used[i]) c.walk(i, res);
}

}  // namespace bezcam::flatten_detail
