// Nesting for the cut-order planner (cam/cut_order.hpp, docs/cut-order.md):
// closed contours are indexed by their bounding boxes (sorted by
// the left edge); a candidate pair survives only when the inner box lies in
// the outer box, and only then are the inner's vertices and segment
// midpoints located in the outer polygon, which is binned in horizontal
// bands so that one location reads the few edges of one band.
#include "cut_order_nesting.hpp"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace bezcam {

namespace cut_order_detail {

namespace {

double ring_area(const OrderContour& c, size_t n) {
  double a = 0;
  for (size_t k = 0; k < n; ++k) {
    const Vec3& p = c.outline[k];
    const Vec3& q = c.outline[(k + 1) % n];
    a += p.x * q.y - q.x * p.y;
  }
  return std::abs(a) / 2;
}

enum class Where { outside, on, inside };

/// A closed polygon for point location with a tolerance, its edges binned
/// in horizontal bands.
class Ring {
 public:
  Ring(const std::vector<Vec3>& pts, size_t n, const Box2& box, double tol) : pts_(&pts), n_(n), box_(box), tol_(tol) {
    nb_ = std::clamp<size_t>(n / 2, 1, 8192);
    const double h = box.hy - box.ly;
    if (!(h > 0)) nb_ = 1;
    inv_h_ = nb_ > 1 ? static_cast<double>(nb_) / h : 0;
    std::vector<uint32_t> count(nb_ + 1, 0);
    auto range = [&](size_t k) {
      const Vec3& a = pts[k];
      const Vec3& b = pts[(k + 1) % n];
      return std::pair{bin(std::min(a.y, b.y) - tol), bin(std::max(a.y, b.y) + tol)};
    };
    for (size_t k = 0; k < n; ++k) {
      const auto [b0, b1] = range(k);
      for (size_t b = b0; b <= b1; ++b) ++count[b + 1];
    }
    for (size_t b = 0; b < nb_; ++b) count[b + 1] += count[b];
    start_ = count;
    edges_.resize(count[nb_]);
    for (size_t k = 0; k < n; ++k) {
      const auto [b0, b1] = range(k);
      for (size_t b = b0; b <= b1; ++b) edges_[count[b]++] = static_cast<uint32_t>(k);
    }
  }

  Where locate(const Vec3& p) const {
    if (p.x < box_.lx - tol_ || p.x > box_.hx + tol_ || p.y < box_.ly - tol_ || p.y > box_.hy + tol_)
      return Where::outside;
    const size_t b = bin(p.y);
    bool in = false;
    const auto& pts = *pts_;
    for (uint32_t i = start_[b]; i < start_[b + 1]; ++i) {
      const size_t k = edges_[i];
      const Vec3& a = pts[k];
      const Vec3& c = pts[(k + 1) % n_];
      if (std::sqrt(dist2_to_segment_xy(p, a, c)) <= tol_) return Where::on;
      if ((a.y > p.y) != (c.y > p.y)) {
        const double x = a.x + (p.y - a.y) * (c.x - a.x) / (c.y - a.y);
        if (p.x < x) in = !in;
      }
    }
    return in ? Where::inside : Where::outside;
  }

 private:
  size_t bin(double y) const {
    if (nb_ == 1) return 0;
    const double t = std::floor((y - box_.ly) * inv_h_);
    if (!(t > 0)) return 0;
    if (t >= static_cast<double>(nb_ - 1)) return nb_ - 1;
    return static_cast<size_t>(t);
  }

  const std::vector<Vec3>* pts_;
  size_t n_;
  Box2 box_;
  double tol_;
  size_t nb_ = 1;
  double inv_h_ = 0;
  std::vector<uint32_t> start_, edges_;
};

}  // namespace

size_t vertex_count(const OrderContour& c) {
  const size_t n = c.outline.size();
  if (c.closed && n >= 2 && c.outline.front().x == c.outline.back().x && c.outline.front().y == c.outline.back().y)
    return n - 1;
  return n;
}

double tolerance_of(std::span<const OrderContour> cs, const CutOrderOptions& o) {
  if (o.touch_tolerance > 0) return o.touch_tolerance;
  double m = 1;
  for (const auto& c : cs)
    for (const auto& p : c.outline) m = std::max({m, std::abs(p.x), std::abs(p.y)});
  return 1e-9 * m;
}

void check_input(std::span<const OrderContour> cs) {
  for (size_t i = 0; i < cs.size(); ++i) {
    if (cs[i].outline.empty())
      throw std::invalid_argument("cut order: contour " + std::to_string(i) + " has no vertex");
    for (const auto& p : cs[i].outline)
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw std::invalid_argument("cut order: contour " + std::to_string(i) + " has a non-finite coordinate");
    if (!cs[i].starts.empty() && !cs[i].closed)
      throw std::invalid_argument("cut order: contour " + std::to_string(i) + " is open but lists start vertices");
    for (size_t k : cs[i].starts)
      if (k >= vertex_count(cs[i]))
        throw std::invalid_argument("cut order: contour " + std::to_string(i) + " lists start vertex " +
                                    std::to_string(k) + ", past its last distinct vertex");
  }
}

std::vector<std::pair<size_t, size_t>> nesting_of(std::span<const OrderContour> cs, double tol) {
  const size_t n = cs.size();
  std::vector<Box2> box(n);
  std::vector<size_t> nv(n);
  std::vector<double> area(n, 0);
  for (size_t i = 0; i < n; ++i) {
    for (const auto& p : cs[i].outline) box[i].add(p);
    nv[i] = vertex_count(cs[i]);
    if (cs[i].closed) area[i] = ring_area(cs[i], nv[i]);
  }
  // The closed contours that can enclose, by the left edge of their box.
  std::vector<size_t> outers;
  for (size_t i = 0; i < n; ++i)
    if (cs[i].closed && nv[i] >= 3 && area[i] > 0) outers.push_back(i);
  std::sort(outers.begin(), outers.end(),
            [&](size_t a, size_t b) { return box[a].lx != box[b].lx ? box[a].lx < box[b].lx : a < b; });
  std::vector<std::optional<Ring>> ring(n);
  std::vector<std::pair<size_t, size_t>> out;
  for (size_t a = 0; a < n; ++a) {
    const auto end = std::upper_bound(outers.begin(), outers.end(), box[a].lx + tol,
                                      [&](double x, size_t b) { return x < box[b].lx; });
    for (auto it = outers.begin(); it != end; ++it) {
      const size_t b = *it;
      if (b == a || !box[b].contains(box[a], tol)) continue;
      if (cs[a].closed && !(area[a] < area[b] || (area[a] == area[b] && a < b))) continue;
      if (!ring[b]) ring[b].emplace(cs[b].outline, nv[b], box[b], tol);
      const Ring& r = *ring[b];
      const auto& pa = cs[a].outline;
      // No vertex outside, then no segment midpoint outside (a segment that
      // leaves B: B concave, or A crossing it between vertices). All of A
      // on B's boundary counts as inside.
      bool outside = false;
      for (size_t k = 0; k < nv[a] && !outside; ++k) outside = r.locate(pa[k]) == Where::outside;
      const size_t segs = cs[a].closed ? nv[a] : nv[a] - 1;
      for (size_t k = 0; k < segs && !outside; ++k)
        outside = r.locate((pa[k] + pa[(k + 1) % nv[a]]) * 0.5) == Where::outside;
      if (outside) continue;
      out.emplace_back(a, b);  // inside, or wholly on the boundary
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace cut_order_detail

std::vector<std::pair<size_t, size_t>> find_nesting(std::span<const OrderContour> contours,
                                                    const CutOrderOptions& options) {
  cut_order_detail::check_input(contours);
  return cut_order_detail::nesting_of(contours, cut_order_detail::tolerance_of(contours, options));
}

}  // namespace bezcam
