#include "bezcam/kernel/curve.hpp"

#include <cmath>

#include "bezcam/error.hpp"

namespace bezcam {

const char* to_string(Continuity c) {
  switch (c) {
    case Continuity::none: return "none";
    case Continuity::C0: return "C0";
    case Continuity::G1: return "G1";
    case Continuity::C1: return "C1";
    case Continuity::C2: return "C2";
  }
  return "?";
}

namespace {
bool close_vec(const Vec3& a, const Vec3& b, double rel) {
  const double s = std::max({norm(a), norm(b), 1e-300});
  return norm(a - b) <= rel * s;
}
}  // namespace

Continuity joint_continuity(const Bezier& a, const Bezier& b, double tol) {
  if (dist(a.back(), b.front()) > tol) return Continuity::none;
  const Vec3 d1a = derivative(a, 1), d1b = derivative(b, 0);
  const double na = norm(d1a), nb = norm(d1b);
  if (na == 0 || nb == 0) return Continuity::C0;  // no tangent defined
  // Tangent directions within 1e-7 rad.
  if (norm(cross(d1a / na, d1b / nb)) > 1e-7 || dot(d1a, d1b) <= 0) return Continuity::C0;
  if (!close_vec(d1a, d1b, 1e-9)) return Continuity::G1;
  if (!close_vec(second_derivative(a, 1), second_derivative(b, 0), 1e-9)) return Continuity::C1;
  return Continuity::C2;
}

int CurveGeometry::max_degree() const {
  int d = 0;
  for (const auto& s : segments) d = std::max(d, s.degree);
  return d;
}
bool CurveGeometry::rational() const {
  for (const auto& s : segments)
    if (s.rational) return true;
  return false;
}
double CurveGeometry::length() const {
  double l = 0;
  for (const auto& p : pieces) l += bezcam::length(p);
  return l;
}
Box3 CurveGeometry::bounds() const {
  Box3 b;
  for (const auto& p : pieces) b.add(bezcam::bounds(p));
  return b;
}

CurveGeometry make_single(CurveSegment seg, std::vector<Bezier> pieces, int dim) {
  seg.first_piece = 0;
  seg.piece_count = pieces.size();
  CurveGeometry g;
  g.kind = seg.kind;
  g.dim = dim;
  g.segments = {seg};
  g.pieces = std::move(pieces);
  // Joints inside one segment (e.g. B-spline knots) are not reported.
  return g;
}

CurveGeometry make_path(std::vector<CurveSegment> segs, std::vector<Bezier> pieces, bool closed, int dim) {
  CurveGeometry g;
  g.kind = "path";
  g.dim = dim;
  g.closed = closed;
  const double tol = 1e-9 * std::max(control_magnitude(pieces), 1.0);
  for (size_t i = 1; i < segs.size(); ++i) {
    const Bezier& end = pieces[segs[i - 1].first_piece + segs[i - 1].piece_count - 1];
    const Bezier& start = pieces[segs[i].first_piece];
    const Continuity c = joint_continuity(end, start, tol);
    if (c == Continuity::none)
      throw InputError(errc::path_joint, Place::at_json("segments[" + std::to_string(i) + "]"),
                       "expected to start where segments[" + std::to_string(i - 1) + "] ends (" +
                           fmt_num(end.back().x) + ", " + fmt_num(end.back().y) +
                           (dim == 3 ? ", " + fmt_num(end.back().z) : std::string()) + "), found a start at (" +
                           fmt_num(start.front().x) + ", " + fmt_num(start.front().y) +
                           (dim == 3 ? ", " + fmt_num(start.front().z) : std::string()) + "), " +
                           fmt_num(dist(end.back(), start.front())) + " away");
    g.joints.push_back(c);
  }
  if (closed) {
    const Continuity c = joint_continuity(pieces.back(), pieces.front(), tol);
    if (c == Continuity::none) {
      const Vec3 a = pieces.back().back(), b = pieces.front().front();
      auto pt = [&](const Vec3& p) {
        return "(" + fmt_num(p.x) + ", " + fmt_num(p.y) + (dim == 3 ? ", " + fmt_num(p.z) : std::string()) + ")";
      };
      throw InputError(errc::path_not_closed, Place::at_json("closed"),
                       "the path is marked closed but its last segment ends at " + pt(a) + ", " + fmt_num(dist(a, b)) +
                           " away from the start of segments[0] at " + pt(b) +
                           "; make them meet, or set \"closed\": false");
    }
    g.joints.push_back(c);
  }
  g.segments = std::move(segs);
  g.pieces = std::move(pieces);
  return g;
}

}  // namespace bezcam
