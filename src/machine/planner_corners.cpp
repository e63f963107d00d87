// The planner's corners (planner_builder.hpp): the segments joined in
// order, each corner between blocks taken tangentially, blended by a
// circular arc within the path tolerance, at the speed of an equivalent
// blend where an arc or a curve keeps its shape, or at an exact stop.
#include <algorithm>
#include <cmath>

#include "planner_builder.hpp"

namespace bezcam::planner_detail {

void Builder::build() {
  begin_build(tl.blocks.size());
  for (size_t bi = 0; bi < tl.blocks.size(); ++bi) take_block(bi, tl.blocks[bi]);
  end_build();
}

void Builder::begin_build(size_t blocks) {
  // Reserved once (address space only until used): no reallocation
  // holding the segments twice while a long program grows.
  const size_t most = most_segments + 16;
  if (summary)
    lean.reserve(most);
  else
    segs.reserve(most);
  junction.reserve(most + 1);
  block_count = blocks;
  plan.blocks.reserve(block_count);
}

const MotionBlock& Builder::block(size_t bi) const {
  if (!streamed_) return tl.blocks[bi];
  return bi == current_index_ ? *current_ : last_moving_;
}

void Builder::take_block(size_t bi, const MotionBlock& b) {
  current_ = &b;
  current_index_ = bi;
  {
    bool pause_here = false;
    while (pause_ < tl.pauses.size() && tl.pauses[pause_].before_block <= bi) {
      pause_here = true;
      ++pause_;
    }
    // Build this block's segments aside (one vector for every block),
    // then join them.
    std::vector<PlanSegment>& mine = mine_;
    mine.clear();
    add_block(static_cast<int>(bi), mine);
    // A block that does not move (its end is where it starts) takes no
    // time and makes no corner: controllers drop it.
    if (plan.blocks.back().length <= 1e-9) mine.clear();
    for (size_t k = 0; k < mine.size(); ++k) {
      PlanSegment s = std::move(mine[k]);
      if (segs.empty() || (k == 0 && (stop_before_ || pause_here))) {
        // The first move may start moving (a window of a longer program
        // planned at machine pace: Timeline::start_speed); after a pause
        // the machine is at rest.
        const bool first = segs.empty() && !pause_here;
        if (!segs.empty()) exact_stop_end(Stop::pause);
        cap_segment_time(s);
        junction.push_back(first ? tl.start_speed : 0);
        segs.push_back(std::move(s));
        continue;
      }
      if (k > 0) {  // inside a block: tangent pieces
        cap_segment_time(s);
        junction.push_back(std::min(segs.back().vmax, s.vmax));
        segs.push_back(std::move(s));
        continue;
      }
      // A corner between blocks.
      PlanSegment& prev = segs.back();
      const MotionBlock& pbk = block(static_cast<size_t>(prev.block));
      const double tol = std::min(path_tolerance(bi), path_tolerance(static_cast<size_t>(prev.block)));
      double vj = 0;
      const Vec3 u1 = block_tangent(pbk, true), u2 = block_tangent(b, false);
      const double phi = std::acos(std::clamp(dot(u1, u2), -1.0, 1.0));
      const bool lines = prev.pieces.back().shape == PlanSegment::Shape::line &&
                         s.pieces.front().shape == PlanSegment::Shape::line && prev.pieces.size() == 1 &&
                         s.pieces.size() == 1;
      double kink_scale = -1;  // LinuxCNC: the kink's share of the acceleration
      if (tol <= 0 || phi > kPi - 2 * kPi / 180 || prev.rapid != s.rapid) {
        vj = 0;  // exact stop: asked, a reversal, or between rapid and feed
      } else if (tangent(prev, s, u1, u2, phi, vj, kink_scale)) {
        // vj set
      } else if (lines) {
        junction_pending_ = junction.back();
        const double nominal_prev = dist(pbk.from, pbk.to), nominal_next = dist(b.from, b.to);
        const double r = blend_lines(s, tol, nominal_prev, nominal_next, pbk.line);
        if (r < 0) {
          cap_segment_time(s);
          junction.push_back(std::min(segs.back().vmax, s.vmax));
          segs.push_back(std::move(s));
          continue;
        }
        vj = r;
      } else {
        vj = linuxcnc() && !blend_arc_plane(prev, s, u1, u2) ? -1 : curved_corner(prev, s, pbk, b, u1, u2, phi, tol);
        if (linuxcnc() && kink_scale > 0) {
          // LinuxCNC rates the blend arc (its speed), the kink (at a
          // reduced speed, 10 % less acceleration) and a parabolic blend
          // (at half its speed: it halves both moves' acceleration), and
          // takes the fastest.
          const double v_kink = std::min(prev.vmax, s.vmax) * kKinkRatio / kink_scale;
          const double v_parabolic = parabolic_speed(prev, s, u1, u2, pbk.to, tol, true) / 2;
          const bool arc_best = vj >= v_kink && vj >= v_parabolic;
          if (!arc_best && v_parabolic > v_kink) {
            parabolic_corner(prev, s, u1, u2, pbk.to, tol);
            vj = 0;  // each move plans to stop here; overlap_ times them together
          } else if (!arc_best) {
            vj = v_kink;
            prev.kink_reduce = std::max(prev.kink_reduce, kKinkRatio);
            s.kink_reduce = std::max(s.kink_reduce, kKinkRatio);
          }
        }
        vj = std::max(vj, 0.0);  // no blend elsewhere: a stop (a corner's keeps the acceleration)
      }
      if (vj <= 0) exact_stop_end(tol <= 0 ? Stop::exact_mode : Stop::corner);
      cap_segment_time(s);
      junction.push_back(vj);
      segs.push_back(std::move(s));
    }
    stop_before_ = false;
    if (mine.empty() && pause_here) stop_before_ = true;
    // A summary needs no segment once no blend can reach it (corners
    // change the last two): only its figures are kept, as the program goes.
    if (summary && segs.size() > 2) {
      for (size_t k = 0; k + 2 < segs.size(); ++k) add_lean(segs[k]);
      segs.erase(segs.begin(), segs.end() - 2);
      if (lean.size() >= next_part_at_) time_done_part();
    }
  }
  // Blocks made one at a time: the next corner reads the last block that
  // moved (the one segs ends with).
  if (streamed_ && !segs.empty() && static_cast<size_t>(segs.back().block) == bi) last_moving_ = b;
  current_ = nullptr;
}

void Builder::end_build() {
  if (!segs.empty()) exact_stop_end(Stop::end);
  junction.push_back(0);  // the end
  for (PlanSegment& sg : segs) add_lean(sg);
  if (summary) segs.clear();
}

// A segment that ends in a stop. LinuxCNC plans a move whose end it could
// not blend (the program's end, a pause) with half its acceleration (and
// an arc that no next move finalized with half of that tangentially),
// and a move that stops in exact-stop mode (G61) with 0.9 of it (both
// measured on LinuxCNC 2.9; docs/motion.md). A sharp corner's stop keeps
// the whole acceleration.
void Builder::exact_stop_end(Stop why) {
  if (!linuxcnc() || segs.empty()) return;
  PlanSegment& s = segs.back();
  const bool exact = path_tolerance(static_cast<size_t>(s.block)) <= 0;
  double f = 1;
  if (why == Stop::exact_mode || (exact && why != Stop::corner))
    f = 0.9;
  else if (why == Stop::end || why == Stop::pause)
    f = 0.5;
  if (f == 1) return;
  if (f == 0.5 && s.parabolic) f = 1;  // a parabolic blend halved it already (the arc's share still applies)
  s.overall_accel *= f;
  s.accel = s.curved ? kTangentialShare * s.overall_accel : std::min(s.accel * f, s.overall_accel);
}

// Blends the corner between the last segment of segs (a line) and `next`
// (a line), both in the same mode. Returns the speed limit at the join
// when the corner is not blended by an arc (then the lines keep their
// shape), or -1 when a blend arc was inserted.
double Builder::blend_lines(PlanSegment& next, double tol, double nominal_prev, double nominal_next, int line) {
  PlanSegment& prev = segs.back();
  const Vec3 a = prev.pieces.back().a, c = prev.pieces.back().b, e = next.pieces.front().b;
  const Vec3 u1 = unit(c - a), u2 = unit(e - c);
  const double cosang = std::clamp(dot(u1, u2), -1.0, 1.0);
  const double phi = std::acos(cosang);  // turning angle
  if (phi > kPi - 1e-6) return 0;        // reversal: stop
  const double theta = 0.5 * (kPi - phi);
  const Vec3 normal = unit(cross(u1, u2));
  const double aplane = in_plane(normal, lim.amax), vplane = in_plane(normal, lim.vmax);
  const double an = kNormalShare * aplane;
  const double T = std::min({tol, kToleranceFraction * nominal_prev, kToleranceFraction * nominal_next});
  if (!(T > 0)) return 0;
  const double d_tol = std::cos(theta) * T / (1 - std::sin(theta));
  const double L1 = std::min(prev.pieces.back().length, kBlendFraction * nominal_prev);
  const double L2 = kBlendFraction * next.length;
  const double d_geom = std::min({L1, L2, d_tol});
  const double R_geom = std::tan(theta) * d_geom;
  const double v_goal = std::min(std::max(prev.vmax, next.vmax), vplane);
  const double v_plan = std::min(std::sqrt(an * R_geom), v_goal);
  // How much of the lines the blend takes: no more than a parabolic
  // blend at half the acceleration would need to reach v_plan.
  const double a_par = 0.5 * aplane;
  const double v_tri = std::sqrt(2 * a_par * d_geom);
  const double s_blend = std::min(v_tri, v_plan) / a_par * v_plan;
  const double R_blend = std::min(s_blend / phi, R_geom);
  const double R = std::max(v_plan * v_plan / an, R_blend);
  const double d = std::min(R / std::tan(theta), d_geom);
  if (R <= 1e-12 || R * phi < 1e-9) return 0;
  // Trim the lines.
  PlanSegment::Piece& pl = prev.pieces.back();
  pl.b = c - u1 * d;
  pl.length = std::max(0.0, pl.length - d);
  prev.length = 0;
  for (const auto& q : prev.pieces) prev.length += q.length;
  cap_segment_time(prev);
  PlanSegment::Piece& nl = next.pieces.front();
  nl.a = c + u2 * d;
  nl.length = std::max(0.0, nl.length - d);
  next.length = nl.length;
  // The blend arc.
  PlanSegment blend;
  blend.block = prev.block;
  blend.rapid = prev.rapid;
  blend.blend = true;
  PlanSegment::Piece arc;
  arc.shape = PlanSegment::Shape::arc;
  const Vec3 inward = unit(u2 - u1);
  arc.center = pl.b + unit(inward - u1 * dot(inward, u1)) * R;
  arc.u = unit(pl.b - arc.center);
  arc.w = u1;
  arc.radius = R;
  arc.angle = phi;
  arc.length = R * phi;
  blend.pieces.push_back(arc);
  blend.length = arc.length;
  blend.vmax = v_plan;
  blend.limit = v_plan < v_goal ? SpeedLimit::corner : (prev.vmax >= next.vmax ? prev.limit : next.limit);
  blend.accel = kTangentialShare * aplane;
  if (model.min_segment_periods > 0) {
    const double cap = blend.length / (model.min_segment_periods * period);
    if (cap < blend.vmax) {
      blend.vmax = cap;
      blend.limit = SpeedLimit::segment_time;
    }
  }
  const double dev = R / std::sin(theta) - R;
  if (dev > plan.max_path_deviation) {
    plan.max_path_deviation = dev;
    plan.max_deviation_line = line;
  }
  // A remnant of the previous line too short to run on its own is
  // absorbed into the blend (the blend then starts where the remnant did).
  if (prev.pieces.size() == 1 && prev.length < kGapPeriods * period * blend.vmax && segs.size() >= 1) {
    PlanSegment::Piece remnant = prev.pieces.back();
    blend.pieces.insert(blend.pieces.begin(), remnant);
    blend.length += remnant.length;
    blend.block = prev.block;
    segs.pop_back();
    junction.pop_back();  // the blend takes the remnant's entry
    segs.push_back(std::move(blend));
    junction.push_back(junction_pending_);
  } else {
    segs.push_back(std::move(blend));
    junction.push_back(std::min(segs[segs.size() - 2].vmax, segs.back().vmax));
  }
  return -1;
}

// Whether the two moves meet tangentially enough to pass without a
// blend, and at what speed. Generic: directions within kTangentAngle, at
// the speed a one-period kink allows. LinuxCNC: the acceleration spike
// of turning by the kink within one period, as a share of the axes'
// limits (twice as much at an arc), below kKinkRatio; the moves then
// lose that share of their acceleration. `kink_scale` receives the share.
bool Builder::tangent(PlanSegment& prev, PlanSegment& next, const Vec3& u1, const Vec3& u2, double phi, double& vj,
                      double& kink_scale) const {
  const double vmax = std::min(prev.vmax, next.vmax);
  if (!linuxcnc()) {
    if (phi >= kTangentAngle) return false;
    const double aa = std::min(prev.accel, next.accel);
    const double kink = phi > 0 ? kNormalShare * kKinkShare * aa * period / phi : kInf;
    vj = std::min(vmax, kink);
    return true;
  }
  const double a_inst = vmax / period + next.overall_accel;
  const Vec3 diff = (u2 - u1) * a_inst;
  double spike = 0;
  for (int i = 0; i < 3; ++i) spike = std::max(spike, std::abs(diff[i]) / lim.amax[i]);
  if (prev.curved || next.curved) spike /= kTangentialShare;
  kink_scale = spike;
  if (spike >= kKinkRatio) return false;
  vj = vmax;
  prev.kink_reduce = std::max(prev.kink_reduce, spike);
  next.kink_reduce = std::max(next.kink_reduce, spike);
  return true;
}

bool Builder::blend_arc_plane(const PlanSegment& prev, const PlanSegment& next, const Vec3& u1, const Vec3& u2) const {
  const Vec3 binormal = cross(u1, u2);
  if (norm(binormal) < 1e-12) return true;
  const Vec3 bn = unit(binormal);
  constexpr double kParallel = 1e-6;  // rad
  // The plane of a curved piece: a blend's own; an arc block's plane (a
  // helix too: its corner's directions then leave the plane); curve
  // blocks, which LinuxCNC's interpreter makes into arcs, in XY.
  auto in_plane_of = [&](const PlanSegment::Piece& piece) {
    Vec3 n;
    if (piece.shape == PlanSegment::Shape::arc) {
      n = unit(cross(piece.u, piece.w));
    } else if (piece.shape == PlanSegment::Shape::block) {
      const MotionBlock& b = block(static_cast<size_t>(piece.block));
      n = b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw ? from_plane({0, 0, 1}, b.plane) : Vec3{0, 0, 1};
    } else {
      return true;
    }
    return norm(cross(bn, n)) <= kParallel;
  };
  return in_plane_of(prev.pieces.back()) && in_plane_of(next.pieces.front());
}

double Builder::parabolic_speed(const PlanSegment& prev, const PlanSegment& next, const Vec3& u1, const Vec3& u2,
                                const Vec3& P, double tol, bool rating, double* v_first) const {
  // Both moves take half their acceleration; while LinuxCNC rates the
  // blend, a kink's share (at least the kink ratio) is off it too.
  auto share = [&](const PlanSegment& sg) {
    return (sg.parabolic ? 1.0 : 0.5) * (rating ? 1 - std::max(sg.kink_reduce, kKinkRatio) : 1.0);
  };
  const double a1 = share(prev) * prev.accel, a2 = share(next) * next.accel;
  if (!(a1 > 0) || !(a2 > 0)) return 0;
  // The speed each may reach: over half its length (a blend may take up
  // to that), at its own top speed.
  const double vr1 = std::min(std::sqrt(a1 * 0.5 * prev.length), prev.vmax);
  const double vr2 = std::min(std::sqrt(a2 * 0.5 * next.length), next.vmax);
  if (!(vr1 > 0) || !(vr2 > 0)) return 0;
  const double t_blend = std::min(std::min(prev.length / vr1, next.length / vr2), std::max(vr1 / a1, vr2 / a2));
  double v1 = std::min(vr1, t_blend * a1), v2 = std::min(vr2, t_blend * a2);
  // The angle between the direction the first move ends in and the one
  // the next move starts accelerating in: an arc's leans towards its
  // centre, by the centripetal acceleration of half its speed against its
  // whole acceleration.
  Vec3 w2 = u2;
  if (next.curved && !next.blend && std::isfinite(next.radius) && next.radius > 0) {
    Vec3 inward = next.center - P;
    inward = inward - u2 * dot(inward, u2);
    if (norm(inward) > 1e-12) {
      const double an = 0.25 * next.vmax * next.vmax / next.radius;
      w2 = unit(u2 * (share(next) * next.overall_accel) + unit(inward) * an);
    }
  }
  const double theta = 0.5 * std::acos(std::clamp(-dot(u1, w2), -1.0, 1.0));
  if (std::isfinite(tol) && tol > 0 && std::cos(theta) > std::sin(1e-3)) {
    // Within the path tolerance: decelerating at a1, the corner is passed
    // at 2 T / cos(theta) from its end.
    const double v_tol = 2 * std::sqrt(a1 * tol / std::cos(theta));
    v1 = std::min(v1, v_tol);
    v2 = std::min(v2, v_tol);
  }
  if (v_first) *v_first = v1;
  return std::sin(theta) * 0.5 * (v1 + v2);
}

void Builder::parabolic_corner(PlanSegment& prev, PlanSegment& next, const Vec3& u1, const Vec3& u2, const Vec3& P,
                               double tol) {
  double v_first = 0;
  parabolic_speed(prev, next, u1, u2, P, tol, false, &v_first);
  for (PlanSegment* sg : {&prev, &next}) {
    if (sg->parabolic) continue;
    sg->parabolic = true;
    sg->overall_accel *= 0.5;
    sg->accel *= 0.5;
    if (sg->curved && !sg->blend && std::isfinite(sg->radius) && sg->radius > 0) {
      const PlanSegment::Piece& piece = sg->pieces.front();
      Vec3 n{0, 0, 1};
      if (piece.shape == PlanSegment::Shape::block) {
        const MotionBlock& b = block(static_cast<size_t>(piece.block));
        if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) n = from_plane({0, 0, 1}, b.plane);
      }
      sg->accel = linuxcnc_tangential_share(sg->radius, sg->overall_accel, in_plane(n, lim.vmax)) * sg->overall_accel;
      const double cap = std::sqrt(kNormalShare * sg->overall_accel * sg->radius);
      if (cap < sg->vmax) {
        sg->vmax = cap;
        sg->limit = SpeedLimit::curvature;
      }
    }
  }
  junction.back() = std::min(junction.back(), prev.vmax);
  if (overlap_.size() <= junction.size()) overlap_.resize(junction.size() + 1, 0);
  overlap_[junction.size()] = std::min({v_first, prev.vmax, next.vmax});
}

namespace {

// The arc at a corner: its centre and radius, whether the corner lies on
// its outer side (LinuxCNC's convexity), and the most of its sweep a blend
// may take (0: not an arc).
struct ArcEnd {
  Vec3 center;
  double radius = 0;
  bool convex = false;
  double phi_max = 0;
  bool arc_block = false;  // a G2/G3 block: its circle is known exactly
};

// The angle between two directions.
double angle_between(const Vec3& x, const Vec3& y) { return std::acos(std::clamp(dot(unit(x), unit(y)), -1.0, 1.0)); }

// The length of the blend circle of centre C and radius R from `from` to
// `to` (where it touches the moves); -1 where C strays more than `tol`
// from the corner P.
double blend_length(const Vec3& P, const Vec3& C, const Vec3& from, const Vec3& to, double R, double tol) {
  if (norm(C - P) - R > tol) return -1;
  return R * angle_between(from - C, to - C);
}

// The length of the circle of radius R tangent to both arcs at the corner
// P (inside an arc where the corner is convex to it, outside otherwise),
// in the corner's plane (normal `binormal`), the one nearer P; -1 where it
// does not exist, strays more than `tol` from P, or takes more of an arc
// than its share.
double arc_arc_blend_length(const Vec3& P, const Vec3& binormal, const ArcEnd& a, const ArcEnd& b, double R,
                            double tol) {
  const double d1 = (a.convex ? -R : R) + a.radius, d2 = (b.convex ? -R : R) + b.radius;
  const Vec3 c12 = b.center - a.center;
  const double cx = norm(c12);
  if (!(cx > 1e-12)) return -1;
  const Vec3 uc = c12 / cx, across = unit(cross(binormal, uc));
  const double Cx = (d2 * d2 - d1 * d1 - cx * cx) / (-2 * cx);
  const double Cy = std::sqrt(std::max(0.0, d1 * d1 - Cx * Cx));
  const Vec3 c1 = a.center + uc * Cx + across * Cy, c2 = a.center + uc * Cx - across * Cy;
  const Vec3 C = norm(c1 - P) <= norm(c2 - P) ? c1 : c2;
  if (angle_between(P - a.center, C - a.center) > a.phi_max || angle_between(P - b.center, C - b.center) > b.phi_max)
    return -1;
  return blend_length(P, C, a.center + unit(C - a.center) * a.radius, b.center + unit(C - b.center) * b.radius, R, tol);
}

// The length of the circle of radius R tangent to the line through P along
// u (before P when `line_first`, after it otherwise: LinuxCNC solves both
// for the distance along the line nearer P in size) and to the arc, on the
// side the corner turns to; -1 where it does not exist, strays more than
// `tol` from P, or takes more of the arc than its share.
double line_arc_blend_length(const Vec3& P, const Vec3& u, const Vec3& binormal, bool line_first, const ArcEnd& arc,
                             double R, double tol) {
  const Vec3 n = unit(cross(binormal, u));
  const double d = (arc.convex ? -R : R) + arc.radius;
  const Vec3 r = arc.center - P;
  const double cu = dot(r, u), cn = dot(r, n);
  const double disc = d * d - (R - cn) * (R - cn);
  if (disc < 0) return -1;
  const double dL = std::min(std::abs(-cu + std::sqrt(disc)), std::abs(-cu - std::sqrt(disc)));
  const Vec3 on_line = P + u * (line_first ? -dL : dL);
  const Vec3 C = on_line + n * R;
  if (angle_between(P - arc.center, C - arc.center) > arc.phi_max) return -1;
  return blend_length(P, C, on_line, arc.center + unit(C - arc.center) * arc.radius, R, tol);
}

// LinuxCNC's circle for an arc at the corner P where its tangent is u: an
// arc block's centre moved along u by its spiral (end radius - start
// radius) per radian, through P; other curves as they are.
ArcEnd spiral_fit(const PlanSegment& sg, const MotionBlock& b, const Vec3& P, const Vec3& u) {
  ArcEnd e{sg.center, sg.radius};
  if ((b.kind != BlockKind::arc_cw && b.kind != BlockKind::arc_ccw) || !(arc_sweep(b) > 0)) return e;
  Vec3 c = to_plane(b.center, b.plane);
  c.z = to_plane(P, b.plane).z;  // in P's plane
  const Arc a = block_arc(b);
  e.center = from_plane(c, b.plane) + u * ((a.r_end() - a.r_start()) / arc_sweep(b));
  e.radius = norm(P - e.center);
  e.arc_block = true;
  return e;
}

}  // namespace

// A corner where an arc or a curve meets another move: the speed of a
// blend arc within the tolerance between the secants of the arcs' ends
// (each arc lends at most a part of its sweep: 2/3 of the one before,
// 1/3 of the one after, and half of it for a line), the shape kept.
// -1 when no blend fits.
double Builder::curved_corner(const PlanSegment& prev, const PlanSegment& next, const MotionBlock& pbk,
                              const MotionBlock& nbk, const Vec3& u1, const Vec3& u2, double phi, double tol) {
  const Vec3 P = pbk.to;
  const double theta_tan = 0.5 * (kPi - phi);
  double theta = theta_tan, L1, L2;
  ArcEnd end1 = spiral_fit(prev, pbk, P, u1), end2 = spiral_fit(next, nbk, P, u2);
  if (prev.curved && std::isfinite(prev.radius)) {
    const bool convex = dot(P - prev.center, u2) < 0;
    const double phi_max = std::min(prev.angle * 2 / 3, convex ? theta_tan : kPi / 2);
    if (convex) theta = std::min(theta, theta_tan - phi_max / 4);
    L1 = convex ? std::sin(phi_max / 4) * prev.radius : phi_max * prev.radius;
    end1.convex = convex;
    end1.phi_max = phi_max;
  } else {
    L1 = std::min(prev.length, kBlendFraction * plan.blocks[static_cast<size_t>(prev.block)].length);
  }
  if (next.curved && std::isfinite(next.radius)) {
    const bool convex = dot(P - next.center, u1) >= 0;
    const double phi_max = std::min(next.angle / 3, convex ? theta_tan : kPi / 2);
    if (convex) theta = std::min(theta, theta_tan - phi_max / 4);
    L2 = convex ? std::sin(phi_max / 4) * next.radius : phi_max * next.radius;
    end2.convex = convex;
    end2.phi_max = phi_max;
  } else {
    L2 = kBlendFraction * next.length;
  }
  if (theta < kMinBlendTheta) return -1;
  const double turn = kPi - 2 * theta;
  if (turn <= 0) return std::min(prev.vmax, next.vmax);
  Vec3 normal = cross(u1, u2);
  normal = norm(normal) > 1e-9 ? unit(normal) : Vec3{0, 0, 1};
  const double aplane = in_plane(normal, lim.amax), vplane = in_plane(normal, lim.vmax);
  const double an = kNormalShare * aplane;
  const double T = std::min({tol, kToleranceFraction * plan.blocks[static_cast<size_t>(prev.block)].length,
                             kToleranceFraction * plan.blocks[static_cast<size_t>(next.block)].length});
  if (!(T > 0)) return -1;
  const double d_tol = std::cos(theta) * T / (1 - std::sin(theta));
  const double d_geom = std::min({L1, L2, d_tol});
  const double R_geom = std::tan(theta) * d_geom;
  const double v_goal = std::min(std::max(prev.vmax, next.vmax), vplane);
  const double v_plan = std::min(std::sqrt(an * R_geom), v_goal);
  // The blend's own length caps it like any segment.
  const double a_par = 0.5 * aplane;
  const double s_blend = std::min(std::sqrt(2 * a_par * d_geom), v_plan) / a_par * v_plan;
  const double R = std::max(v_plan * v_plan / an, std::min(s_blend / turn, R_geom));
  double v = v_plan;
  // (A curve block's arcs are LinuxCNC's interpreter's, known only
  // approximately here: their corners keep the estimate below.)
  const bool exact1 = end1.phi_max > 0 ? end1.arc_block : !prev.curved;
  const bool exact2 = end2.phi_max > 0 ? end2.arc_block : !next.curved;
  if (linuxcnc() && (end1.phi_max > 0 || end2.phi_max > 0) && exact1 && exact2) {
    // LinuxCNC places the blend circle tangent to both moves: it must stay
    // within the tolerance and within each arc's share, and it is as long
    // as the turn between the points where it touches them (an arc's own
    // turn along its stretch counts); a blend runs at most its length in
    // one period.
    const Vec3 bn = cross(u1, u2);
    double len = -1;
    if (norm(bn) > 1e-12) {
      if (end1.phi_max > 0 && end2.phi_max > 0)
        len = arc_arc_blend_length(P, unit(bn), end1, end2, R, T);
      else
        len = end1.phi_max > 0 ? line_arc_blend_length(P, u2, unit(bn), false, end1, R, T)
                               : line_arc_blend_length(P, u1, unit(bn), true, end2, R, T);
    }
    if (len < 0) return -1;
    v = std::min(v, len / period);
  } else if (model.min_segment_periods > 0) {
    v = std::min(v, R * turn / (model.min_segment_periods * period));
  }
  const double dev = R / std::sin(theta) - R;
  if (dev > plan.max_path_deviation) {
    plan.max_path_deviation = dev;
    plan.max_deviation_line = pbk.line;
  }
  return std::min({v, prev.vmax, next.vmax});
}

}  // namespace bezcam::planner_detail
