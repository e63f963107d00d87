#include "pocket_area.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cmath>
#include <numbers>
#include <numeric>

namespace bezcam {

namespace bg = boost::geometry;
using BPoint = bg::model::d2::point_xy<double>;
using BPoly = bg::model::polygon<BPoint>;  // clockwise outer rings, closed
using BMulti = bg::model::multi_polygon<BPoly>;
using BRing = BPoly::ring_type;

namespace detail {

struct Area::Impl {
  BMulti m;
};

namespace {

double loop_area(const std::vector<Vec3>& l) {
  double a = 0;
  for (size_t i = 0, n = l.size(); i < n; ++i) a += l[i].x * l[(i + 1) % n].y - l[(i + 1) % n].x * l[i].y;
  return a / 2;
}

bool inside_loop(const std::vector<Vec3>& l, const Vec3& p) {
  bool in = false;
  for (size_t i = 0, n = l.size(), j = n - 1; i < n; j = i++)
    if ((l[i].y > p.y) != (l[j].y > p.y) && p.x < (l[j].x - l[i].x) * (p.y - l[i].y) / (l[j].y - l[i].y) + l[i].x)
      in = !in;
  return in;
}

BRing to_ring(const std::vector<Vec3>& l) {
  BRing r;
  for (const Vec3& v : l) r.push_back(BPoint(v.x, v.y));
  if (!l.empty()) r.push_back(BPoint(l.front().x, l.front().y));
  return r;
}

std::vector<Vec3> from_ring(const BRing& r) {
  std::vector<Vec3> l;
  for (size_t i = 0; i + 1 < r.size(); ++i) l.push_back({r[i].x(), r[i].y(), 0});
  return l;
}

// Even-odd loops as polygons: a loop inside an even number of others is an
// outer ring, inside an odd number a hole of the smallest loop around it.
BMulti to_multi(const PocketLoops& loops) {
  std::vector<size_t> order(loops.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> area(loops.size());
  for (size_t i = 0; i < loops.size(); ++i) area[i] = std::abs(loop_area(loops[i]));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return area[a] > area[b]; });
  std::vector<int> depth(loops.size(), 0);
  std::vector<long> parent(loops.size(), -1), poly_of(loops.size(), -1);
  BMulti m;
  for (size_t k = 0; k < order.size(); ++k) {
    const size_t i = order[k];
    if (loops[i].size() < 3) continue;
    for (size_t q = 0; q < k; ++q) {
      const size_t j = order[q];
      if (loops[j].size() < 3 || !inside_loop(loops[j], loops[i].front())) continue;
      ++depth[i];
      parent[i] = static_cast<long>(j);  // the last found is the smallest around it
    }
    if (depth[i] % 2 == 0) {
      BPoly p;
      p.outer() = to_ring(loops[i]);
      poly_of[i] = static_cast<long>(m.size());
      m.push_back(p);
    } else if (parent[i] >= 0 && poly_of[static_cast<size_t>(parent[i])] >= 0) {
      m[static_cast<size_t>(poly_of[static_cast<size_t>(parent[i])])].inners().push_back(to_ring(loops[i]));
    }
  }
  bg::correct(m);
  return m;
}

// Boost simplifies the input by |d| / 1000 before offsetting (Douglas-
// Peucker): that much off the walls would be unaccounted for. This
// distance simplifies within `sag` instead, which the caller's margin holds.
class BoundedDistance : public bg::strategy::buffer::distance_symmetric<double> {
 public:
  BoundedDistance(double d, double sag) : distance_symmetric(d), sag_(sag) {}
  double simplify_distance() const { return sag_; }

 private:
  double sag_;
};

int points_per_circle(double d, double sag) {
  const double a = std::acos(std::max(-1.0, 1 - sag / std::max(std::abs(d), 1e-12)));
  const double n = std::ceil(std::numbers::pi / std::max(a, 1e-6));
  return static_cast<int>(std::clamp(n, 8.0, 4096.0));
}

}  // namespace

Area::Area() : impl_(std::make_shared<Impl>()) {}
Area::Area(const PocketLoops& loops) : impl_(std::make_shared<Impl>(Impl{to_multi(loops)})) {}
Area::Area(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Area Area::eroded(double d, double sag) const {
  auto out = std::make_shared<Impl>();
  if (impl_->m.empty()) return Area(out);
  const int n = points_per_circle(d, sag);
  const BoundedDistance dist(-d, sag);
  bg::strategy::buffer::join_round join(n);
  bg::strategy::buffer::end_round end(n);
  bg::strategy::buffer::point_circle circle(n);
  bg::strategy::buffer::side_straight side;
  bg::buffer(impl_->m, out->m, dist, side, join, end, circle);
  // Slivers the offset leaves where the area vanishes: none holds a tool.
  const double tiny = 1e-9 * std::max(1.0, d * d);
  std::erase_if(out->m, [&](const BPoly& p) { return std::abs(bg::area(p)) <= tiny; });
  return Area(out);
}

PocketLoops Area::loops() const { return rings(); }

std::vector<Area> Area::pieces() const {
  std::vector<Area> out;
  for (const BPoly& p : impl_->m) {
    auto one = std::make_shared<Impl>();
    one->m.push_back(p);
    out.push_back(Area(one));
  }
  return out;
}

bool Area::empty() const { return impl_->m.empty(); }
double Area::area() const { return std::abs(bg::area(impl_->m)); }

std::vector<std::vector<Vec3>> Area::rings() const {
  std::vector<std::vector<Vec3>> out;
  for (const BPoly& p : impl_->m) {
    out.push_back(from_ring(p.outer()));
    for (const BRing& h : p.inners()) out.push_back(from_ring(h));
  }
  return out;
}

bool Area::covers(const Vec3& a, const Vec3& b) const {
  bg::model::linestring<BPoint> l;
  l.push_back(BPoint(a.x, a.y));
  l.push_back(BPoint(b.x, b.y));
  return bg::covered_by(l, impl_->m);
}

bool Area::covers_polygon(const std::vector<Vec3>& closed) const {
  BPoly p;
  p.outer() = to_ring(closed);
  bg::correct(p);
  return bg::covered_by(p, impl_->m);
}

bool Area::covers(const Vec3& p) const { return bg::covered_by(BPoint(p.x, p.y), impl_->m); }

}  // namespace detail

PocketLoops offset_region(const PocketLoops& loops, double d, double sag) {
  return detail::Area(loops).eroded(d, sag).loops();
}

double region_area(const PocketLoops& loops) { return detail::Area(loops).area(); }

}  // namespace bezcam
