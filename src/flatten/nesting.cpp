// Nesting of closed curves by the even-odd rule (flatten/nesting.hpp).
#include "bezcam/flatten/nesting.hpp"

#include <algorithm>
#include <cmath>

#include "bezcam/flatten/flatten_curve.hpp"

namespace bezcam {
namespace {

std::vector<Bezier> in_xy(const std::vector<Bezier>& pieces) {
  std::vector<Bezier> out = pieces;
  for (Bezier& b : out) {
    b.dim = 2;
    for (Vec3& p : b.points) p.z = 0;
  }
  return out;
}

enum class Where { outside, on, inside };

// One closed curve, flattened on demand ever finer, for locating points.
class Curve {
 public:
  explicit Curve(const std::vector<Bezier>& pieces) : pieces_(in_xy(pieces)) {
    for (const Bezier& b : pieces_) box_.add(bounds(b));
    size_ = box_.empty() ? 0 : std::max(box_.hi.x - box_.lo.x, box_.hi.y - box_.lo.y);
  }
  const Box3& box() const { return box_; }
  double size() const { return size_; }
  const std::vector<Bezier>& pieces() const { return pieces_; }

  /// Sample points: the vertices of a flattening to 1e-3 of the size, and
  /// the middle of every piece.
  std::vector<Vec3> samples() const {
    FlattenOptions o;
    o.tolerance = 1e-3 * size_;
    o.on_curve = true;
    std::vector<Vec3> s = flatten(pieces_, o).points;
    for (const Bezier& b : pieces_) s.push_back(evaluate(b, 0.5));
    return s;
  }

  /// |area| of the polygon of the coarsest level.
  double area() {
    const Level& l = level(0);
    double a = 0;
    for (size_t k = 0; k + 1 < l.pts.size(); ++k) a += l.pts[k].x * l.pts[k + 1].y - l.pts[k + 1].x * l.pts[k].y;
    return std::abs(a) / 2;
  }

  Where locate(const Vec3& p) {
    if (p.x < box_.lo.x || p.x > box_.hi.x || p.y < box_.lo.y || p.y > box_.hi.y) return Where::outside;
    const double margin = 1e-12 * size_;
    for (int k = 0; k < kLevels; ++k) {
      const Level& l = level(k);
      double d2 = HUGE_VAL;
      bool odd = false;
      for (size_t i = 0; i + 1 < l.pts.size(); ++i) {
        const Vec3& a = l.pts[i];
        const Vec3& c = l.pts[i + 1];
        d2 = std::min(d2, dist2_to_segment_xy(p, a, c));
        if ((a.y > p.y) != (c.y > p.y) && p.x < a.x + (p.y - a.y) * (c.x - a.x) / (c.y - a.y)) odd = !odd;
      }
      const double far = l.bound + margin;
      if (d2 > far * far) return odd ? Where::inside : Where::outside;
    }
    return Where::on;
  }

 private:
  static constexpr int kLevels = 4;  // 1e-3, 1e-5, 1e-7, 1e-9 of the size
  struct Level {
    std::vector<Vec3> pts;  // closed: the last vertex is the first
    double bound = 0;
    bool made = false;
  };
  const Level& level(int k) {
    Level& l = levels_[static_cast<size_t>(k)];
    if (!l.made) {
      FlattenOptions o;
      o.tolerance = 1e-3 * size_ * std::pow(1e-2, k);
      o.on_curve = true;
      FlattenResult r = flatten(pieces_, o);
      l.pts = std::move(r.points);
      if (!l.pts.empty()) l.pts.push_back(l.pts.front());  // the closing chord, whatever the ends' rounding
      l.bound = r.bound;
      l.made = true;
    }
    return l;
  }

  std::vector<Bezier> pieces_;
  Box3 box_;
  double size_ = 0;
  Level levels_[kLevels];
};

bool overlap(const Box3& a, const Box3& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}

}  // namespace

Nesting nest_closed_curves(std::span<const std::vector<Bezier>> curves) {
  const size_t n = curves.size();
  std::vector<Curve> cs;
  cs.reserve(n);
  for (const auto& c : curves) cs.emplace_back(c);
  std::vector<std::vector<Vec3>> samples(n);
  for (size_t i = 0; i < n; ++i)
    if (cs[i].size() > 0) samples[i] = cs[i].samples();
  // around[i]: the curves curve i lies inside.
  std::vector<std::vector<size_t>> around(n);
  Nesting out;
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = 0; j < n; ++j) {
      if (i == j || cs[i].size() == 0 || cs[j].size() == 0 || !overlap(cs[i].box(), cs[j].box())) continue;
      size_t in = 0, outside = 0;
      for (const Vec3& p : samples[i]) {
        const Where w = cs[j].locate(p);
        in += w == Where::inside;
        outside += w == Where::outside;
        if (in && outside) break;
      }
      if (in && outside) {
        out.crossing.emplace_back(std::min(i, j), std::max(i, j));
      } else if (in) {
        around[i].push_back(j);
      }
    }
  }
  std::sort(out.crossing.begin(), out.crossing.end());
  out.crossing.erase(std::unique(out.crossing.begin(), out.crossing.end()), out.crossing.end());
  // Two curves each inside the other (self-crossing curves): the smaller
  // one is the inner.
  const auto has = [&](size_t a, size_t b) {
    return std::find(around[a].begin(), around[a].end(), b) != around[a].end();
  };
  for (size_t i = 0; i < n; ++i)
    for (size_t k = 0; k < around[i].size();) {
      const size_t j = around[i][k];
      if (j > i && has(j, i)) {
        const bool i_inner = cs[i].area() <= cs[j].area();
        auto& drop = i_inner ? around[j] : around[i];
        drop.erase(std::find(drop.begin(), drop.end(), i_inner ? i : j));
        if (!i_inner) continue;  // around[i][k] is now the next one
      }
      ++k;
    }
  out.depth.assign(n, 0);
  out.parent.assign(n, std::nullopt);
  for (size_t i = 0; i < n; ++i) out.depth[i] = static_cast<int>(around[i].size());
  for (size_t i = 0; i < n; ++i)
    for (const size_t j : around[i])
      if (!out.parent[i] || out.depth[j] > out.depth[*out.parent[i]]) out.parent[i] = j;
  return out;
}

}  // namespace bezcam
