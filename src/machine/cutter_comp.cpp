// Cutter radius compensation: the tool-centre path a controller derives
// from a G41/G42 program (see cutter_comp.hpp for the rules).
#include "bezcam/machine/cutter_comp.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "bezcam/error.hpp"

namespace bezcam {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

Vec3 flat(Vec3 v) { return {v.x, v.y, 0}; }
double cross2(const Vec3& a, const Vec3& b) { return a.x * b.y - a.y * b.x; }
double dot2(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y; }
Vec3 left_of(const Vec3& t) { return {-t.y, t.x, 0}; }
Vec3 unit2(const Vec3& v) {
  const double l = std::hypot(v.x, v.y);
  return l > 0 ? Vec3{v.x / l, v.y / l, 0} : Vec3{};
}
double len2(const Vec3& v) { return std::hypot(v.x, v.y); }
std::string line_of(const MotionBlock& b) { return b.line > 0 ? " (line " + std::to_string(b.line) + ")" : ""; }
std::string xy_text(const Vec3& p) {
  return "X" + fmt_num(std::round(p.x * 1e4) / 1e4) + " Y" + fmt_num(std::round(p.y * 1e4) / 1e4);
}

// Unit tangent of a line or arc at its start or end (XY).
Vec3 tangent(const MotionBlock& b, bool at_end) {
  if (!is_arc(b)) return unit2(b.to - b.from);
  const Vec3 rad = unit2((at_end ? b.to : b.from) - b.center);
  return b.kind == BlockKind::arc_ccw ? left_of(rad) : left_of(rad) * -1.0;
}

// How an arc's radius changes with the tool on `side`: the centre is on the
// left of a counter-clockwise arc.
double radius_change(const MotionBlock& b, int side, double r) {
  return -side * r * (b.kind == BlockKind::arc_ccw ? 1.0 : -1.0);
}

// The offset of a move near one of its ends, as a line (point, direction)
// or a circle (centre, radius).
struct Prim {
  bool circle = false;
  Vec3 p, d;  // line
  Vec3 c;     // circle
  double R = 0;
};

Prim offset_prim(const MotionBlock& b, bool at_end, int side, double r) {
  Prim q;
  if (is_arc(b)) {
    q.circle = true;
    q.c = flat(b.center);
    q.R = len2((at_end ? b.to : b.from) - b.center) + radius_change(b, side, r);
  } else {
    q.d = tangent(b, at_end);
    q.p = flat(at_end ? b.to : b.from) + left_of(q.d) * (side * r);
  }
  return q;
}

// Intersections of two offset primitives (XY).
std::vector<Vec3> intersect(const Prim& a, const Prim& b) {
  std::vector<Vec3> out;
  if (!a.circle && !b.circle) {
    const double den = cross2(a.d, b.d);
    if (std::abs(den) < 1e-14) return out;
    const double s = cross2(b.p - a.p, b.d) / den;
    out.push_back(a.p + a.d * s);
    return out;
  }
  if (a.circle != b.circle) {  // line and circle
    const Prim& l = a.circle ? b : a;
    const Prim& c = a.circle ? a : b;
    const Vec3 f = l.p - c.c;
    const double bq = dot2(f, l.d), cq = dot2(f, f) - c.R * c.R;
    double disc = bq * bq - cq;
    if (disc < -1e-12 * (c.R * c.R + 1)) return out;
    disc = std::sqrt(std::max(disc, 0.0));
    out.push_back(l.p + l.d * (-bq - disc));
    out.push_back(l.p + l.d * (-bq + disc));
    return out;
  }
  const Vec3 dv = b.c - a.c;  // two circles
  const double d = len2(dv);
  if (d < 1e-14) return out;
  const double x = (d * d + a.R * a.R - b.R * b.R) / (2 * d);
  double h2 = a.R * a.R - x * x;
  if (h2 < -1e-12 * (a.R * a.R + 1)) return out;
  const double h = std::sqrt(std::max(h2, 0.0));
  const Vec3 u = dv * (1 / d), m = a.c + u * x;
  out.push_back(m + left_of(u) * h);
  out.push_back(m - left_of(u) * h);
  return out;
}

// Angle swept from `from` to `to` about `c` in the arc's direction, in [0, 2 pi).
double sweep_between(const MotionBlock& arc, const Vec3& from, const Vec3& to) {
  const double a0 = std::atan2(from.y - arc.center.y, from.x - arc.center.x);
  const double a1 = std::atan2(to.y - arc.center.y, to.x - arc.center.x);
  double s = arc.kind == BlockKind::arc_ccw ? a1 - a0 : a0 - a1;
  while (s < 0) s += kTwoPi;
  while (s >= kTwoPi) s -= kTwoPi;
  return s;
}

// The programmed sweep of an arc block, in (0, 2 pi] (equal ends: a circle).
double programmed_sweep(const MotionBlock& arc) {
  const double s = sweep_between(arc, arc.from, arc.to);
  return s <= 1e-12 ? kTwoPi : s;
}

// Whether `b` moves in X or Y.
bool moves_in_xy(const MotionBlock& b) {
  if (b.kind == BlockKind::nurbs || b.kind == BlockKind::bezier) return true;
  if (is_arc(b)) return true;
  return b.from.x != b.to.x || b.from.y != b.to.y;
}

}  // namespace

void CutterComp::on(int side, double radius) {
  if (side_ != 0)
    throw CompensationError(std::string(side > 0 ? "G41" : "G42") +
                            " while cutter compensation is already on: cancel it with G40 first");
  if (!(radius > 0))
    throw CompensationError("the tool radius for cutter compensation is " + fmt_num(radius) + ", not positive");
  side_ = side;
  r_ = radius;
  entering_ = true;
}

std::vector<MotionBlock> CutterComp::off() {
  std::vector<MotionBlock> out;
  if (pending_) out = release(nullptr);
  side_ = 0;
  entering_ = false;
  return out;
}

// Ends the pending move: at its corner with `next` (null: at its own offset
// end, G40), and sets where the next move starts.
std::vector<MotionBlock> CutterComp::release(const MotionBlock* next) {
  MotionBlock p = *pending_;
  pending_.reset();
  const Vec3 B = flat(p.to);
  const Vec3 t1 = tangent(p, true);
  const Vec3 e1 = B + left_of(t1) * (side_ * r_);  // its offset end
  Vec3 end = e1, next_start = e1;
  std::optional<MotionBlock> corner;
  if (next) {
    // The corner, judged as LinuxCNC's interpreter judges it: by the angle
    // beta between the tool's offset at the end of this move and the offset
    // the next move needs (> 0: the tool is on the outside). Within
    // kStraight of 0 there is no corner: the next move starts where the
    // tool stands. Beyond it, outside: an arc round the corner point;
    // inside (or turning back): both offsets end where they cross.
    constexpr double kStraight = 0.05;  // radians (LinuxCNC: TOLERANCE_CONCAVE_CORNER)
    const Vec3 t2 = tangent(*next, false);
    const Vec3 s2 = B + left_of(t2) * (side_ * r_);
    const Vec3 n_old = left_of(t1) * side_, n_new = left_of(t2) * side_;
    double beta = -side_ * std::atan2(cross2(n_old, n_new), dot2(n_old, n_new));
    if (beta < -std::numbers::pi / 2) beta += kTwoPi;
    auto tool_inside = [&](const MotionBlock& a) {
      return is_arc(a) && ((side_ > 0) == (a.kind == BlockKind::arc_ccw));
    };
    bool concave = beta < -kStraight || beta > std::numbers::pi + kStraight;
    if (!concave && beta > std::numbers::pi - kStraight)  // turning back: stay on the tool's side
      concave = is_arc(*next) ? !tool_inside(*next) : (is_arc(p) && !tool_inside(p));
    if (concave) {
      const auto xs = intersect(offset_prim(p, true, side_, r_), offset_prim(*next, false, side_, r_));
      if (xs.empty())
        throw CompensationError("cutter compensation cannot follow the inside corner at " + xy_text(B) +
                                ": with the tool radius " + fmt_num(r_) +
                                " the offset moves do not meet (a move too short or an arc too tight for the tool)");
      Vec3 best = xs.front();
      for (const auto& x : xs)
        if (len2(x - B) < len2(best - B)) best = x;
      end = next_start = best;
    } else if (beta > kStraight) {
      // The tool is on the outside: it rolls round the corner point.
      MotionBlock a;
      a.kind = side_ > 0 ? BlockKind::arc_cw : BlockKind::arc_ccw;
      a.from = {e1.x, e1.y, p.to.z};
      a.to = {s2.x, s2.y, p.to.z};
      a.center = {B.x, B.y, p.to.z};
      a.feed = next->kind == BlockKind::rapid || !(next->feed > 0) ? p.feed : next->feed;
      a.line = a.first_line = next->first_line ? next->first_line : next->line;
      a.entity = next->entity;
      corner = a;
      next_start = s2;
    }
  }
  // The compensated move may not run backwards: that is a gouge.
  const Vec3 start = flat(pending_start_);
  if (!is_arc(p)) {
    if (dot2(end - start, t1) <= 0 && len2(end - start) > 1e-9 * std::max(1.0, r_))
      throw CompensationError("cutter compensation would gouge: the move to " + xy_text(p.to) + line_of(p) +
                              " is too short for the tool radius " + fmt_num(r_) + " on the inside of its corners");
  } else {
    const double rad = len2(flat(p.to) - flat(p.center)) + radius_change(p, side_, r_);
    if (rad <= 1e-9 * std::max(1.0, r_))
      throw CompensationError("the arc to " + xy_text(p.to) + line_of(p) +
                              " has a radius not larger than the tool radius " + fmt_num(r_) +
                              " on its inside: the tool cannot follow it");
    const double want = programmed_sweep(p);
    const double got = sweep_between(p, start, end);
    // Past its programmed end only by the wrap of a reversal (a start a
    // hair off the arc's own start angle is the controller's to absorb).
    if (got > want + 1e-6 && got > 0.5 * (want + kTwoPi) && len2(end - start) > 1e-9 * std::max(1.0, r_))
      throw CompensationError("cutter compensation would gouge: the arc to " + xy_text(p.to) + line_of(p) +
                              " is too short for the tool radius " + fmt_num(r_) + " on the inside of its corners");
  }
  p.from = {start.x, start.y, p.from.z};
  p.to = {end.x, end.y, p.to.z};
  std::vector<MotionBlock> out{p};
  for (auto z : held_) {
    z.from.x = z.to.x = end.x;
    z.from.y = z.to.y = end.y;
    out.push_back(z);
  }
  held_.clear();
  if (corner) {
    corner->from.z = corner->to.z = corner->center.z = out.back().to.z;
    out.push_back(*corner);
  }
  pending_start_ = next_start;
  if (!next) exit_from_ = next_start;
  return out;
}

std::vector<MotionBlock> CutterComp::push(const MotionBlock& b) {
  const bool xy = moves_in_xy(b);
  if (side_ == 0) {
    if (idle()) return {b};
    MotionBlock x = b;
    x.from.x = exit_from_->x;
    x.from.y = exit_from_->y;
    if (!xy) {
      x.to.x = exit_from_->x;
      x.to.y = exit_from_->y;
      return {x};
    }
    if (b.kind != BlockKind::linear && b.kind != BlockKind::rapid)
      throw CompensationError("the move after G40 leaves cutter compensation and must be a straight line (G00 or G01)");
    exit_from_.reset();
    return {x};
  }
  if (b.kind == BlockKind::nurbs || b.kind == BlockKind::bezier)
    throw CompensationError(
        "a NURBS or spline block cannot be cut in cutter compensation (G41/G42): "
        "cancel it with G40, or let the CAM offset the path");
  if (!xy) {
    if (pending_) {
      held_.push_back(b);
      return {};
    }
    MotionBlock x = b;  // before the entry: where the tool stands
    if (exit_from_) x.from.x = x.to.x = exit_from_->x, x.from.y = x.to.y = exit_from_->y;
    return {x};
  }
  if (entering_) {
    if (is_arc(b))
      throw CompensationError(
          "the move after G41/G42 enters cutter compensation and must be a straight line, not an arc");
    Vec3 from = b.from;
    if (exit_from_) from.x = exit_from_->x, from.y = exit_from_->y;
    if (len2(b.to - from) <= r_)
      throw CompensationError("the entry move into cutter compensation is " + fmt_num(len2(b.to - from)) +
                              " long, not longer than the tool radius " + fmt_num(r_));
    exit_from_.reset();
    entering_ = false;
    pending_ = b;
    pending_->from = from;
    pending_start_ = from;
    return {};
  }
  std::vector<MotionBlock> out = release(&b);
  pending_ = b;
  return out;
}

}  // namespace bezcam
