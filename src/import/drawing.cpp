// Drawings' contours: where a piece ends, the drawing's size, joining the
// contours that meet end to end (drawing_job.cpp makes the job).
#include "bezcam/import/drawing.hpp"

#include <algorithm>
#include <cmath>

#include "bezcam/import/conic.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"

namespace bezcam::import {
namespace {

bool clamped_end(const Piece& p) {
  const size_t k = p.knots.size(), q = static_cast<size_t>(p.degree);
  if (k < q + 2) return false;
  for (size_t i = k - q - 1; i < k; ++i)
    if (p.knots[i] != p.knots[k - 1]) return false;
  return true;
}
bool clamped_start(const Piece& p) {
  const size_t q = static_cast<size_t>(p.degree);
  if (p.knots.size() < q + 2) return false;
  for (size_t i = 0; i <= q; ++i)
    if (p.knots[i] != p.knots[0]) return false;
  return true;
}

Vec3 start_of(const Piece& p) {
  if (!p.bspline || clamped_start(p)) return p.points.front();
  return evaluate(NurbsCurve::make(p.degree, p.points, p.knots, p.weights), p.knots[static_cast<size_t>(p.degree)]);
}

Piece reversed(Piece p) {
  std::reverse(p.points.begin(), p.points.end());
  std::reverse(p.weights.begin(), p.weights.end());
  if (p.bspline) {
    const double a = p.knots.front(), b = p.knots.back();
    std::reverse(p.knots.begin(), p.knots.end());
    for (double& k : p.knots) k = a + b - k;
  }
  return p;
}
Contour reversed(Contour c) {
  std::reverse(c.pieces.begin(), c.pieces.end());
  for (Piece& p : c.pieces) p = reversed(std::move(p));
  return c;
}
Vec3 c_start(const Contour& c) { return start_of(c.pieces.front()); }
Vec3 c_end(const Contour& c) { return c.pieces.back().end(); }

// Makes `next` start exactly where `prev` ends (they are within the join
// distance): the end control point moves when it is the curve's end,
// otherwise a bridging line of that length is added.
void meet(std::vector<Piece>& pieces, size_t i) {
  Piece& prev = pieces[i - 1];
  Piece& next = pieces[i];
  const Vec3 e = prev.end();
  if (start_of(next) == e) return;
  if (!next.bspline || clamped_start(next)) {
    next.points.front() = e;
    return;
  }
  Piece bridge;
  bridge.points = {e, start_of(next)};
  pieces.insert(pieces.begin() + static_cast<std::ptrdiff_t>(i), bridge);
}

}  // namespace

Vec3 Piece::end() const {
  if (!bspline || clamped_end(*this)) return points.back();
  return evaluate(NurbsCurve::make(degree, points, knots, weights),
                  knots[knots.size() - 1 - static_cast<size_t>(degree)]);
}

double Drawing::size() const {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  bool any = false;
  for (const Contour& c : contours) {
    const auto add = [&](const Vec3& p) {
      any = true;
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    };
    for (const Piece& p : c.pieces)
      for (const Vec3& q : p.points) add(q);
    for (const Vec3& q : c.interpolation.through) add(q);
  }
  if (!any) return 0;
  return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

void scale_drawing(Drawing& d, double s) {
  for (Contour& c : d.contours) {
    for (Piece& p : c.pieces)
      for (Vec3& q : p.points) q = q * s;
    for (Vec3& q : c.interpolation.through) q = q * s;
  }
  for (DrawingText& t : d.texts) {
    t.at = t.at * s;
    if (t.to) *t.to = *t.to * s;
    t.height *= s;
  }
}

std::vector<Gap> nearly_closed(const Drawing& d, double within) {
  std::vector<Gap> out;
  for (const Contour& c : d.contours) {
    if (c.closed || c.is_interpolation || c.pieces.empty()) continue;
    const Vec3 a = c_start(c), b = c_end(c);
    if (dist(a, b) <= within) out.push_back({c.id, dist(a, b), (a + b) * 0.5});
  }
  return out;
}

void join_contours(Drawing& d, double tolerance) {
  const double fixed = 1e-6 * d.size(), eps = std::max(fixed, tolerance);
  std::vector<Gap> gaps;  // of the contour being joined
  const auto near = [&](const Vec3& a, const Vec3& b) { return dist(a, b) <= eps; };
  // Two ends that are made to meet: their gap noted when the default
  // distance would not have joined them.
  const auto joins = [&](const Vec3& a, const Vec3& b) {
    if (dist(a, b) > fixed) gaps.push_back({"", dist(a, b), (a + b) * 0.5});
  };
  std::vector<Contour> out;
  std::vector<bool> used(d.contours.size(), false);
  for (size_t i = 0; i < d.contours.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    Contour chain = d.contours[i];
    if (chain.closed || chain.is_interpolation || chain.pieces.empty()) {
      out.push_back(std::move(chain));
      continue;
    }
    size_t joined = 0;
    gaps.clear();
    for (bool grew = true; grew;) {
      grew = false;
      if (near(c_end(chain), c_start(chain))) break;  // closes: take nothing more
      for (size_t j = i + 1; j < d.contours.size(); ++j) {
        const Contour& c = d.contours[j];
        if (used[j] || c.closed || c.is_interpolation || c.pieces.empty() || c.layer != chain.layer) continue;
        const Vec3 e = c_end(chain), s = c_start(chain);
        if (near(e, c_start(c)) || near(e, c_end(c))) {
          Contour next = near(e, c_start(c)) ? c : reversed(c);
          joins(e, c_start(next));
          for (Piece& p : next.pieces) chain.pieces.push_back(std::move(p));
        } else if (near(s, c_end(c)) || near(s, c_start(c))) {
          Contour prev = near(s, c_end(c)) ? c : reversed(c);
          joins(c_end(prev), s);
          for (Piece& p : chain.pieces) prev.pieces.push_back(std::move(p));
          chain.pieces = std::move(prev.pieces);
        } else {
          continue;
        }
        used[j] = true;
        ++joined;
        grew = true;
      }
    }
    for (size_t k = 1; k < chain.pieces.size(); ++k) meet(chain.pieces, k);
    if (chain.pieces.size() > 1 && near(c_end(chain), c_start(chain))) {
      chain.closed = true;
      // The end meets the start exactly: move the end point, or bridge.
      Piece& last = chain.pieces.back();
      const Vec3 s = c_start(chain);
      joins(last.end(), s);
      if (!(last.end() == s)) {
        if (!last.bspline || clamped_end(last)) {
          last.points.back() = s;
        } else {
          chain.pieces.push_back(line_piece(last.end(), s));
        }
      }
    }
    if (joined) chain.id += "+" + std::to_string(joined);
    for (Gap& g : gaps) {
      g.id = chain.id;
      d.closed_gaps.push_back(g);
    }
    out.push_back(std::move(chain));
  }
  d.contours = std::move(out);
}

}  // namespace bezcam::import
