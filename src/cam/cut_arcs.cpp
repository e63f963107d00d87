// --output arcs: G02/G03 in G17 with I/J (helical ones in G17, G18 or G19
// for a curve that climbs), G01 where no arc fits.
#include <algorithm>
#include <stdexcept>

#include "bezcam/error.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "cut_emitters.hpp"
#include "measure_path.hpp"
#include "speed_stretches.hpp"

namespace bezcam::detail {

void append_line(CutContext& c, const Vec3& to, std::vector<Vec3>& path, size_t& blocks) {
  if (!path.empty() && to == path.back()) return;
  LineMove l;
  l.to = cut_point(c, to);
  l.feed = c.params.feed;
  c.program.moves.push_back({l, static_cast<int>(c.entity.index)});
  path.push_back(to);
  ++blocks;
}

namespace {

// A cut that goes on from a tangent move starts along the move's printed
// direction when it is within this angle (radians) of the curve's.
constexpr double kContinueAngle = 0.05;

}  // namespace

Vec3 incoming_direction(const CutContext& c, std::span<const Bezier> pieces) {
  if (c.ends.from_rest || pieces.empty()) return {};
  const Vec3 along = end_direction(pieces, false);
  const Vec3 start = cut_point(c, quantize(pieces.front().front(), c.decimals));
  const auto& moves = c.program.moves;
  size_t k = moves.size();
  while (k > 0 && !motion_of(moves[k - 1])) --k;
  if (k == 0) return {};
  const Motion* last = motion_of(moves[k - 1]);
  if (!(last->feed > 0) || std::abs(last->to.x - start.x) + std::abs(last->to.y - start.y) > 0 ||
      std::abs(last->to.z - start.z) > 1e-9 * (1 + std::abs(start.z)))
    return {};
  Vec3 d;
  if (const auto* a = std::get_if<ArcMove>(&moves[k - 1].what)) {
    if (a->plane != Plane::xy) return {};
    const Vec3 r = a->to - a->center;
    d = a->ccw ? Vec3{-r.y, r.x, 0} : Vec3{r.y, -r.x, 0};
  } else if (std::holds_alternative<LineMove>(moves[k - 1].what)) {
    size_t j = k - 1;
    while (j > 0 && !motion_of(moves[j - 1])) --j;
    if (j == 0) return {};
    d = last->to - motion_of(moves[j - 1])->to;
    if (std::abs(d.z) > 0) return {};
  } else {
    return {};
  }
  d.z = 0;
  const double l = std::hypot(d.x, d.y);
  if (!(l > 0)) return {};
  d = d / l;
  const double turn = std::atan2(std::abs(d.x * along.y - d.y * along.x), d.x * along.x + d.y * along.y);
  return turn <= kContinueAngle ? d : Vec3{};
}

double append_arcs_or_lines(CutContext& c, std::span<const Bezier> pieces, std::vector<Vec3>& path, size_t& blocks,
                            Vec3* direction) {
  const int entity = static_cast<int>(c.entity.index);
  Vec3 from = quantize(pieces.front().front(), c.decimals);
  if (path.empty()) path.push_back(from);
  auto push_line = [&](const Vec3& to) { append_line(c, to, path, blocks); };
  if (!c.machine.arcs) {
    FlattenOptions fo{c.tolerance, c.decimals};
    bool first = true;
    return flatten_pieces(pieces, fo, [&](const FlatVertex& v) {
      if (!first) push_line(v.point);
      first = false;
    });
  }
  ArcFitOptions ao;
  ao.tolerance = c.tolerance;
  ao.decimals = c.decimals;
  // The tolerance on both sides (the default): inner span ends may leave the
  // curve, as lines output's vertices do; one-sided tolerances reach here
  // only on the curve's own path and keep every end on it.
  ao.band = c.params.tolerance_side == ToleranceSide::both;
  // The controller's radius check is in its own units: the program's.
  ao.radius_tolerance = c.machine.arc_tolerance_mm / mm_per_unit(c.job.units);
  // Arcs that meet tangentially: a controller's planner runs through their
  // joints instead of slowing down at each (docs/motion.md).
  ao.tangent = true;
  if (direction) ao.start_direction = *direction;
  // `pl`: the arcs' plane (G18 and G19 for helical arcs only).
  auto emit = [&](const FitMove& f, Plane pl) {
    if (f.kind == FitKind::line) {
      push_line(f.to);
    } else {
      ArcMove am;
      am.to = cut_point(c, f.to);
      am.center = cut_point(c, f.center);
      am.ccw = f.kind == FitKind::arc_ccw;
      am.plane = pl;
      am.feed = c.params.feed;
      c.program.moves.push_back({am, entity});
      // The measured path follows the arc in its own plane.
      const PrintedArc a{from, f.to, f.center, f.kind == FitKind::arc_ccw, pl};
      const auto pts = sample_arc(a, kSampleShare * c.tolerance);
      path.insert(path.end(), pts.begin() + 1, pts.end());
      ++blocks;
    }
    from = f.to;
  };
  // A curve that climbs (a piece whose z varies) gets no plain arcs; it may
  // get helical ones (G02/G03 whose third coordinate runs linearly with the
  // angle, the bound proven in 3D), which follow a ramp or a helix in a few
  // blocks where lines need dozens: G17 around Z, G18 around Y, G19 around
  // X. The band lines and the helical fit in the plane whose axis the
  // curve's control hull spreads least along (least_climb_plane(), the
  // surface emitter's choice) are made; when that fit does not beat the
  // lines (a half turn round Y spreads less along Z than along X), the two
  // other planes are tried too. The fewest blocks are written, lines on a
  // tie: they win on a climb that is not helix-like. On climbing cubics this
  // finds the blocks that fitting in all three planes always finds, in far
  // less time; on twisted cubics, where the first plane seldom beats the
  // lines, the other planes are what finds the fewer blocks.
  if (std::any_of(pieces.begin(), pieces.end(), [](const Bezier& b) { return !planar_xy(b); })) {
    ArcFitResult best = fit_arcs(pieces, ao);
    const size_t lines = best.moves.size();
    const Plane first = least_climb_plane(pieces);
    const auto try_plane = [&](Plane pl) {
      ArcFitResult h = fit_helical_arcs(pieces, ao, pl);
      if (h.moves.size() < best.moves.size()) best = std::move(h);
    };
    try_plane(first);
    if (best.moves.size() == lines)
      for (const Plane pl : {Plane::xy, Plane::zx, Plane::yz})
        if (pl != first) try_plane(pl);
    for (const FitMove& f : best.moves) emit(f, best.plane);
    return best.bound;
  }
  return fit_arcs(pieces, ao, [&](const FitMove& f) {
    if (direction) *direction = move_tangent(from, f, false);  // the direction the move ends in
    emit(f, Plane::xy);
  });
}

void emit_arcs(CutContext& c, EntityReport& r) {
  if (!c.machine.arcs)
    throw InputError(errc::usage_output, Place::at_setting("output"),
                     "machine profile \"" + c.machine.name +
                         "\" does not take arcs (\"arcs\": false), so arcs output cannot be honoured; choose "
                         "lines output, or a profile that takes G02/G03");
  const auto& pieces = c.entity.curve.pieces;
  std::vector<Vec3> path;
  r.blocks = 0;
  const size_t first = c.program.moves.size();
  // (going on from a tangent move: its direction, which the chain continues)
  Vec3 incoming = incoming_direction(c, pieces);
  r.bound = append_arcs_or_lines(c, pieces, path, r.blocks, &incoming);
  const auto& mm = c.machine.motion;
  if (mm && arcs_accelerate_slower(*mm) && c.params.tolerance_side == ToleranceSide::both &&
      std::all_of(pieces.begin(), pieces.end(), [](const Bezier& b) { return planar_xy(b); })) {
    // This controller gives arcs less acceleration than lines: the arcs
    // where the tool cruises at the feed, lines where it changes speed
    // (docs/motion.md, "Arcs where the tool cruises"), when that is faster.
    std::vector<Vec3> cruise_path;
    double cruise_bound = 0;
    const auto kept = keep_faster_cut(c, pieces, first, r.blocks, [&]() -> std::optional<size_t> {
      size_t n = 0;
      cruise_bound = append_cruise(c, pieces, cruise_path, n, [&](std::span<const Bezier> run, Vec3& dir) {
        return append_arcs_or_lines(c, run, cruise_path, n, &dir);
      });
      return n;
    });
    if (kept) {
      path = std::move(cruise_path);
      r.blocks = *kept;
      r.bound = cruise_bound;
    }
  }
  if (c.measure)
    c.measure_with(r, [pieces = std::span<const Bezier>(pieces), path = std::move(path), tol = c.tolerance,
                       bound = r.bound, label = r.label] {
      // The sampled path lies within kSampleShare of the drawn one.
      const double m = measure_printed(pieces, path, tol, bound, kSampleShare * tol);
      if (m > tol)
        throw std::logic_error("internal check failed: " + label + " deviates by " + fmt_num(m) +
                               " beyond the tolerance " + fmt_num(tol));
      return m;
    });
}

}  // namespace bezcam::detail
