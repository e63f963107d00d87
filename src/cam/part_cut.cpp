// Cutting a part, not only a curve (docs/job-format.md): the tool-centre
// path at the tool's radius on its side of the curve (offset.hpp), in the
// direction asked, in equal depth passes, with tangent leads on the waste
// side and holding tabs, each stretch cut by the output mode's emitter with
// its own proof; then the printed path is measured against the part by
// offset_measure.hpp, which shares no code with the offset.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/machine/cutter_comp.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/exact_blocks.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/offset.hpp"
#include "bezcam/flatten/offset_measure.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "cut_emitters.hpp"

namespace bezcam::detail {

namespace {

constexpr double kPi = std::numbers::pi;
// How many of a closed path's longest stretches are tried for its start
// where a lead fits there.
constexpr size_t kLeadStarts = 16;

Vec3 unit_tangent(const Bezier& b, double t) {
  Vec3 d = derivative(b, t);
  if (std::hypot(d.x, d.y) == 0) d = t < 0.5 ? b.points[1] - b.points[0] : b.back() - b.points[b.points.size() - 2];
  const double l = std::hypot(d.x, d.y);
  return l > 0 ? Vec3{d.x / l, d.y / l, 0} : Vec3{1, 0, 0};
}

// The parameter of `b` at arc length `s` from its start.
double param_at_length(const Bezier& b, double s) {
  double lo = 0, hi = 1;
  for (int i = 0; i < 60 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (length(split(b, mid).first) < s) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

// Cuts the pieces into runs at the lengths `at` (increasing, inside (0, L));
// run k ends at at[k] (empty runs keep the count when two cuts meet).
std::vector<std::vector<Bezier>> split_at_lengths(std::span<const Bezier> pieces, const std::vector<double>& at) {
  std::vector<std::vector<Bezier>> runs(1);
  size_t k = 0;
  double start = 0;  // length along the path where `b` starts
  for (const Bezier& whole : pieces) {
    Bezier b = whole;
    double blen = length(b);
    bool left = true;  // some of b is still to place
    while (left && k < at.size() && at[k] <= start + blen) {
      const double t = param_at_length(b, at[k] - start);
      if (t >= 1 - 1e-12) {
        runs.back().push_back(b);
        start += blen;
        left = false;
      } else if (t > 1e-12) {
        auto [l, r] = split(b, t);
        l.points.back() = r.points.front();  // one shared point, exactly
        runs.back().push_back(l);
        start += length(l);
        b = r;
        blen = length(b);
      }
      runs.emplace_back();
      ++k;
    }
    if (left) {
      runs.back().push_back(b);
      start += blen;
    }
  }
  return runs;
}

// The direction of travel where a lead joins the path at `p`: at right
// angles to the normal from the part's nearest point to p, which points to
// the waste when `away` is +1 (the path runs on the waste side of the part)
// and from it when -1; the waste (+1 left, -1 right of travel) is on the
// tool's side. Where p lies on the part (a program's path under controller
// compensation with no offset), the path's own direction `along`.
Vec3 lead_direction(PartDistance& part, const Vec3& p, const Vec3& along, int waste, int away, double scale) {
  const Vec3 q = part.nearest(p);
  const double dx = p.x - q.x, dy = p.y - q.y, l = std::hypot(dx, dy);
  if (!(l > 1e-6 * scale)) return along;
  const Vec3 w{away * dx / l, away * dy / l, 0};  // towards the waste
  return Vec3{w.y, -w.x, 0} * waste;
}

// A quarter arc and a line on the waste side (+1 left, -1 right of travel).
std::vector<Bezier> lead_in(const Vec3& s, const Vec3& t, int waste, const Lead& l) {
  const Vec3 w = Vec3{-t.y, t.x, 0} * waste;
  const Vec3 c = s + w * l.radius, p1 = s - t * l.radius + w * l.radius;
  std::vector<ArcSeg> segs;
  if (l.length > 0) segs.push_back(ArcSeg::line(p1 + w * l.length, p1));
  segs.push_back(ArcSeg::make_arc(p1, s, c, waste * kPi / 2));
  segs.back().b = s;
  return bezier_pieces(segs);
}
std::vector<Bezier> lead_out(const Vec3& e, const Vec3& t, int waste, const Lead& l) {
  const Vec3 w = Vec3{-t.y, t.x, 0} * waste;
  const Vec3 c = e + w * l.radius, p2 = e + t * l.radius + w * l.radius;
  std::vector<ArcSeg> segs{ArcSeg::make_arc(e, p2, c, waste * kPi / 2)};
  segs.back().a = e;
  if (l.length > 0) segs.push_back(ArcSeg::line(p2, p2 + w * l.length));
  return bezier_pieces(segs);
}

// The printed path of moves [from, to) from `cur`, in XY, as the controller
// draws it: lines, arcs from their printed numbers, curve blocks as their
// Bézier pieces (Z-only moves leave nothing).
std::vector<PathPiece> printed_path(const std::vector<Move>& moves, size_t from, size_t to, Vec3 cur) {
  std::vector<PathPiece> out;
  auto xy = [](const Vec3& p) { return Vec3{p.x, p.y, 0}; };
  for (size_t i = from; i < to; ++i) {
    const Move& mv = moves[i];
    if (const auto* l = std::get_if<LineMove>(&mv.what)) {
      if (l->to.x != cur.x || l->to.y != cur.y) out.push_back(PathPiece::line(xy(cur), xy(l->to)));
      cur = l->to;
    } else if (const auto* a = std::get_if<ArcMove>(&mv.what)) {
      out.push_back(PathPiece::of(PrintedArc{xy(cur), xy(a->to), xy(a->center), a->ccw}));
      cur = a->to;
    } else if (const auto* c = std::get_if<CurveMove>(&mv.what)) {
      std::vector<Vec3> ctrl;
      for (const auto& p : c->ctrl) ctrl.push_back(xy(p));
      std::vector<Bezier> pieces;
      if (c->form == CurveMove::Form::bezier) pieces.push_back(Bezier::make(ctrl, {}, 2));
      else pieces = to_bezier(NurbsCurve::make(c->order - 1, ctrl, c->knots, c->weights, 2));
      for (const Bezier& b : pieces) out.push_back(PathPiece::of(b));
      cur = c->to;
    } else if (const auto* m = motion_of(mv)) {
      cur = m->to;
    }
  }
  return out;
}

// The tool centre's path under controller compensation (cutter_comp.hpp)
// for the moves [from, to) of a stretch from `cur`, entered and left by the
// leads, whose ends run along `ts` and `te`, in XY: the corners the
// controller turns between the leads and the stretch included, the leads
// themselves not.
std::vector<PathPiece> compensated_path(const std::vector<Move>& moves, size_t from, size_t to, Vec3 cur,
                                        const Vec3& ts, const Vec3& te, int side, double r) {
  Program run;
  LineMove start;
  start.to = cur;
  run.moves.push_back({start});
  for (size_t i = from; i < to; ++i) run.moves.push_back(moves[i]);
  auto blocks = program_motion(run);
  blocks.erase(blocks.begin());  // the move to the start
  if (blocks.empty()) return {};
  CutterComp comp;
  comp.on(side, r);
  MotionBlock entry, exit;
  entry.from = cur - ts * (2 * r + 1);
  entry.to = cur;
  exit.from = blocks.back().to;
  exit.to = exit.from + te * (2 * r + 1);
  std::vector<MotionBlock> tool;
  auto add = [&](std::vector<MotionBlock> bs) { tool.insert(tool.end(), bs.begin(), bs.end()); };
  add(comp.push(entry));
  for (const auto& b : blocks) add(comp.push(b));
  add(comp.push(exit));  // completes the last move and its corner, holds the exit
  std::vector<PathPiece> out;
  auto xy = [](const Vec3& p) { return Vec3{p.x, p.y, 0}; };
  for (size_t i = 1; i < tool.size(); ++i) {  // not the entry
    const MotionBlock& b = tool[i];
    if (b.kind == BlockKind::linear || b.kind == BlockKind::rapid) {
      if (b.from.x != b.to.x || b.from.y != b.to.y) out.push_back(PathPiece::line(xy(b.from), xy(b.to)));
    } else if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) {
      out.push_back(PathPiece::of(PrintedArc{xy(b.from), xy(b.to), xy(b.center), b.kind == BlockKind::arc_ccw}));
    } else {
      for (Bezier piece : block_to_bezier(b)) {
        for (Vec3& q : piece.points) q = xy(q);
        piece.dim = 2;
        out.push_back(PathPiece::of(piece));
      }
    }
  }
  return out;
}

// Chords of even size along each piece, for a controller that compensates
// the polyline: a short chord left at a joint by the greedy flattening is
// one the controller's offset would swallow on the inside of a bend
// (LinuxCNC stops: "Straight feed in concave corner cannot be reached by the
// tool without gouging"). The greedy chords of a piece, t_0 < ... < t_n,
// with the last one a fraction f of a full one, are spread over the piece
// as n chords of (n - 1 + f) / n greedy chords each (or n + 1); each is
// proven as the flattener proves its own (chord_deviation() plus the
// rounding of its ends), and a piece where that fails keeps its greedy
// chords. Returns the polyline; `bound` gets its proven deviation.
std::vector<Vec3> even_chords(std::span<const Bezier> pieces, double tol, int dec, double& bound) {
  std::vector<Vec3> out;
  bound = 0;
  for (size_t k = 0; k < pieces.size(); ++k) {
    const Bezier& b = pieces[k];
    std::vector<double> ts;
    std::vector<Vec3> greedy;
    const double gb = flatten_pieces(std::span<const Bezier>(&b, 1), FlattenOptions{.tolerance = tol, .decimals = dec, .on_curve = true}, [&](const FlatVertex& v) {
      ts.push_back(v.t);
      greedy.push_back(v.point);
    });
    ts.front() = 0;
    ts.back() = 1;
    const size_t n = ts.size() - 1;
    std::vector<Vec3> chosen = greedy;
    double chosen_bound = gb;
    if (n >= 2) {
      const double f = std::clamp(std::sqrt(chord_deviation(b, ts[n - 1], 1) / tol), 0.05, 1.0);
      const double total = static_cast<double>(n - 1) + f;
      auto at = [&](double x) {  // the parameter at x greedy chords from the start
        const size_t j = static_cast<size_t>(std::floor(x));
        if (j >= n - 1) return ts[n - 1] + std::min(1.0, (x - static_cast<double>(n - 1)) / f) * (1 - ts[n - 1]);
        return ts[j] + (x - static_cast<double>(j)) * (ts[j + 1] - ts[j]);
      };
      for (size_t m = n; m <= n + 1; ++m) {
        std::vector<double> s(m + 1);
        for (size_t i = 0; i <= m; ++i) s[i] = i == m ? 1.0 : at(total * static_cast<double>(i) / static_cast<double>(m));
        std::vector<Vec3> exact(m + 1), printed(m + 1);
        for (size_t i = 0; i <= m; ++i) {
          exact[i] = i == 0 ? b.front() : i == m ? b.back() : evaluate(b, s[i]);
          printed[i] = dec < 0 ? exact[i] : quantize(exact[i], dec);
        }
        double worst = 0;
        bool ok = true;
        for (size_t i = 0; i < m && ok; ++i) {
          const double moved = std::max(dist(printed[i], exact[i]), dist(printed[i + 1], exact[i + 1]));
          const double dev = chord_deviation(b, s[i], s[i + 1], tol - moved) + moved;
          ok = s[i + 1] > s[i] && dev <= tol;
          worst = std::max(worst, dev);
        }
        if (ok) {
          chosen = printed;
          chosen.front() = greedy.front();  // the piece's ends as the flattener prints them
          chosen.back() = greedy.back();
          chosen_bound = worst;
          break;
        }
      }
    }
    out.insert(out.end(), chosen.begin() + (out.empty() ? 0 : 1), chosen.end());
    bound = std::max(bound, chosen_bound);
  }
  return out;
}

std::string where(const Vec3& p) { return "(" + fmt_num(std::round(p.x * 1000) / 1000) + ", " + fmt_num(std::round(p.y * 1000) / 1000) + ")"; }

}  // namespace

void emit_part(CutContext& c, MotionState& ms, EntityReport& r, double safe, double clear) {
  const Entity& ent = c.entity;
  const CutParams& cp = c.params;
  const Job& job = c.job;
  Program& p = c.program;
  const int entity = static_cast<int>(ent.index);
  // The refusal names the key where it was set: the entity's, else the job's.
  auto fail = [&](const std::string& key, const std::string& why) -> void {
    const std::string top = key.substr(0, key.find('.'));
    const JobParams& own = ent.params;
    const bool here = (top == "side" && own.side) || (top == "tool_diameter" && own.tool_diameter) ||
                      (top == "stock_to_leave" && own.stock_to_leave) || (top == "step_down" && own.step_down) ||
                      (top == "tabs" && own.tabs) || (top == "compensation" && own.controller_compensation) ||
                      (top == "tolerance_side" && own.tolerance_side) || (top == "lead" && own.lead) || (top == "tool" && own.tool);
    const bool in_job = !here && ((top == "side" && job.params.side) || (top == "tool_diameter" && job.params.tool_diameter) ||
                                  (top == "stock_to_leave" && job.params.stock_to_leave) ||
                                  (top == "step_down" && job.params.step_down) || (top == "tabs" && job.params.tabs) ||
                                  (top == "compensation" && job.params.controller_compensation) ||
                                  (top == "tolerance_side" && job.params.tolerance_side) || (top == "lead" && job.params.lead) ||
                                  (top == "tool" && job.params.tool));
    throw InputError(errc::job_cut, Place::in_json(job.source, (in_job ? std::string("job") : ent.json_path()) + "." + key),
                     (in_job ? "for entity " + ent.label() + ": " : std::string()) + why);
  };
  const auto& g = ent.curve;
  if (g.dim != 2)
    fail("side", "cutting a part needs a curve in the XY plane; this one is 3D: remove the part-cutting keys (side, "
                 "step_down, lead, tabs, ...) or give 2D points");
  const bool controller = cp.controller_compensation;
  if (controller) {
    // One diameter per D register: the controller reads it there.
    for (const Move& mv : p.moves)
      if (const auto* cc = std::get_if<CompensationMove>(&mv.what))
        if (cc->side != 0 && cc->d == cp.tool && cp.tool_diameter && cc->radius != *cp.tool_diameter / 2)
          fail("tool", "tool " + std::to_string(cp.tool) + " is already compensated with a diameter of " +
                           fmt_num(2 * cc->radius) + " (D" + std::to_string(cp.tool) + "), this entity asks " +
                           fmt_num(*cp.tool_diameter) + ": give it its own tool number");
    if (!c.machine.cutter_compensation)
      fail("compensation", "machine \"" + c.machine.name + "\" has no cutter radius compensation (G41/G42): use \"cam\" "
                           "(the default): bezcam offsets the path itself");
    if (p.output == OutputMode::nurbs)
      fail("compensation", std::string("compensation \"controller\" cannot be written as NURBS blocks: ") +
                               (c.machine.nurbs == NurbsDialect::linuxcnc
                                    ? "LinuxCNC does not compensate G5.2 blocks (it cuts them on the programmed curve)"
                                    : "Fanuc refuses G06.2 in G41/G42 (alarm PS1006)") +
                               "; use output \"arcs\" or \"lines\", or compensation \"cam\" for exact NURBS blocks of the offset");
  }
  const double scale = std::max(1.0, control_magnitude(g.pieces));
  const bool closed = g.closed || dist(g.pieces.front().front(), g.pieces.back().back()) <= 1e-9 * scale;
  const double tol = c.tolerance;

  // Side of the tool relative to the drawn direction (+1 left, -1 right, 0 on).
  int side = 0;
  switch (cp.side) {
    case CutSide::on: side = 0; break;
    case CutSide::left: side = 1; break;
    case CutSide::right: side = -1; break;
    case CutSide::inside:
    case CutSide::outside: {
      if (!closed)
        fail("side", std::string("\"") + (cp.side == CutSide::inside ? "inside" : "outside") +
                         "\" needs a closed curve (it bounds no region: its ends are " +
                         fmt_num(dist(g.pieces.front().front(), g.pieces.back().back())) +
                         " apart); use \"left\" or \"right\", or close the curve");
      const double area = signed_area(g.pieces);
      if (std::abs(area) <= 1e-12 * scale * scale)
        fail("side", "the curve bounds no area (it runs back over itself), so it has no inside; use \"left\" or \"right\"");
      const bool ccw = area > 0;  // counter-clockwise: the region is on the left
      side = (cp.side == CutSide::inside) == ccw ? 1 : -1;
      break;
    }
  }
  if (controller && cp.side == CutSide::on && cp.tolerance_side != ToleranceSide::left && cp.tolerance_side != ToleranceSide::right)
    fail("compensation", "compensation \"controller\" needs a side of the curve for the tool (inside, outside, left or "
                         "right); with side \"on\" there is nothing to compensate");
  double radius = 0;
  if (side != 0) {
    if (!cp.tool_diameter)
      fail("tool_diameter", "side \"" + std::string(cp.side == CutSide::left ? "left" : cp.side == CutSide::right ? "right" : cp.side == CutSide::inside ? "inside" : "outside") +
                                "\" needs the tool's diameter: add \"tool_diameter\" to the entity or the job");
    radius = *cp.tool_diameter / 2 + cp.stock_to_leave;
    if (radius <= 0)
      fail("stock_to_leave", "the offset tool_diameter / 2 + stock_to_leave = " + fmt_num(radius) +
                                 " is not positive; leave less negative stock");
  }
  // Direction: climb keeps the part on the tool's right (spindle M03), so
  // the tool is on the left of its path; conventional the other way.
  std::vector<Bezier> part(g.pieces.begin(), g.pieces.end());
  if (cp.direction != CutDirection::as_drawn) {
    if (side == 0) {
      const std::string w = ent.label() + ": \"direction\" needs a side of the curve (side \"on\" has no part side): cut as drawn";
      p.warnings.push_back(w);
    } else if ((cp.direction == CutDirection::climb) != (side > 0)) {
      part = reversed(std::span<const Bezier>(part));
      side = -side;
    }
  }
  // Where the deviation may lie and what is left of the tolerance.
  int dev_side = 0;  // +1: only away from the part (the offset's side), -1: only towards it
  switch (cp.tolerance_side) {
    case ToleranceSide::both: break;
    case ToleranceSide::waste:
      if (side == 0)
        fail("tolerance_side", "\"waste\" needs a side of the curve (inside, outside, left or right); side \"on\" has "
                               "no waste side: use \"left\" or \"right\"");
      dev_side = 1;
      break;
    case ToleranceSide::left:
    case ToleranceSide::right: {
      const int want = cp.tolerance_side == ToleranceSide::left ? 1 : -1;  // relative to travel
      if (side == 0) {
        side = want;  // a curve cut on-line, deviating to one side only
        dev_side = 1;
      } else {
        dev_side = want == side ? 1 : -1;
      }
      break;
    }
  }
  const double fit = dev_side == 0 ? 0.45 * tol : 0.2 * tol;
  const double offset_by = radius + dev_side * 0.5 * tol;  // the band's middle
  const int waste = side != 0 ? side : 1;

  // With controller compensation the program carries the part's edge, the
  // controller adds the tool's radius (its D register); the program's path
  // is offset only by the stock to leave and the band's middle.
  const double tool_r = controller ? *cp.tool_diameter / 2 : 0;
  const double program_by = offset_by - tool_r;
  // The lead: under controller compensation there is always one (the
  // controller enters and leaves compensation on it), by default a quarter
  // arc of the tool's radius after a line of its diameter; its line must be
  // longer than the tool's radius (LinuxCNC refuses a shorter entry move).
  std::optional<Lead> lead_used = cp.lead;
  if (controller && !lead_used) lead_used = Lead{tool_r, 2 * tool_r};
  if (controller && !(lead_used->length > tool_r))
    fail("lead.length", "compensation \"controller\" enters and leaves on the lead's line, which must be longer than the "
                        "tool's radius " + fmt_num(tool_r) + " (it is " + fmt_num(lead_used->length) + "): make it longer");
  // The leads are designed and checked against the part itself, sampled
  // once for all of them.
  const std::vector<std::vector<Bezier>> part_curves{part};
  std::optional<PartDistance> part_distance;
  if (lead_used && side != 0) part_distance.emplace(part_curves, 0.01 * tol);
  // A lead stays in the path's band: it is cut within half the tolerance,
  // or what the offset's fit leaves of the path's own share where that is
  // less, and comes no nearer the part than the band's near edge plus that
  // (to rounding). Where it joins the path it is no nearer than the path.
  // Both are known once the offset's fit is.
  double lead_budget = 0, lead_clear = 0;
  // Where the path is on the part's side of the program's path (controller
  // compensation of a negative stock), the waste lies the other way.
  const int away = (controller ? program_by : offset_by) < 0 ? -1 : 1;
  // The tool centre's lead at a path end (under compensation the
  // programmed lead is the tool's radius larger and the line's outer end,
  // where the tool stands before G41 and after G40, is not offset).
  auto lead_path = [&](const Vec3& at, const Vec3& t, bool lead_in_end, const Lead& x) {
    const Vec3 w = Vec3{-t.y, t.x, 0} * waste;
    std::vector<PathPiece> pieces;
    for (const Bezier& b : lead_in_end ? lead_in(at + w * tool_r, t, waste, x) : lead_out(at + w * tool_r, t, waste, x))
      pieces.push_back(PathPiece::of(b));
    if (controller) {
      const Lead programmed{x.radius + tool_r, x.length};
      const auto shape = lead_in_end ? lead_in(at, t, waste, programmed) : lead_out(at, t, waste, programmed);
      const Vec3 outer = lead_in_end ? shape.front().front() : shape.back().back();
      pieces.push_back(PathPiece::line(outer, outer));
    }
    return pieces;
  };
  // How much room the lead leaves: how near it comes to the part, less
  // what it must keep (lead_clear, or what the path's own end keeps where
  // that is less: that is the path's reading, measured on its own).
  auto room = [&](const Vec3& at, const Vec3& t, bool lead_in_end, const Lead& x) {
    const Vec3 centre = at + Vec3{-t.y, t.x, 0} * (waste * tool_r);
    const double own = dist(centre, part_distance->nearest(centre)) - 1e-9 * scale;
    return part_distance->min_distance(lead_path(at, t, lead_in_end, x)) - std::min(lead_clear, own);
  };
  auto lead_fits = [&](const Vec3& at, const Vec3& t, const Lead& x) {
    return room(at, t, true, x) >= 0 && room(at, t, false, x) >= 0;
  };
  std::vector<std::vector<Bezier>> chains;
  std::vector<bool> chain_closed;
  double fit_bound = 0;
  if (side == 0 || (controller && std::abs(program_by) <= 1e-12 * scale)) {
    chains.push_back(part);
    chain_closed.push_back(closed);
  }
  if (side != 0) {
    const OffsetResult o = offset_curve(part, closed, {offset_by, side, fit});
    if (o.chains.empty())
      fail("tool_diameter", "a tool of diameter " + fmt_num(cp.tool_diameter.value_or(0)) + " does not fit: no point is " +
                                fmt_num(offset_by) + " from the whole curve on the side asked (" +
                                (cp.side == CutSide::inside ? "inside" : cp.side == CutSide::outside ? "outside" : side > 0 ? "left" : "right") +
                                "); use a smaller tool");
    if (controller && o.chains.size() > 1)
      fail("compensation", "the tool of diameter " + fmt_num(*cp.tool_diameter) + " cannot follow the whole curve in one "
                           "path (its offset falls apart into " + std::to_string(o.chains.size()) +
                           " pieces where the part narrows): a controller's compensation cannot cut that; use \"cam\"");
    // The program's own path under controller compensation: the stock and
    // the band's shift only (the part itself when both are zero).
    OffsetResult prog;
    if (controller && chains.empty())
      prog = offset_curve(part, closed, {std::abs(program_by), program_by > 0 ? side : -side, fit});
    const OffsetResult& used = controller ? prog : o;
    fit_bound = controller ? (chains.empty() ? prog.bound : 0.0) : o.bound;
    lead_budget = std::min(0.5 * tol, tol - fit_bound - (dev_side == 0 ? 0.0 : 0.5 * tol));
    lead_clear = radius - (dev_side > 0 ? 0 : tol) + lead_budget - 1e-9 * scale;
    for (size_t k = 0; k < used.chains.size(); ++k) {
      std::vector<ArcSeg> chain = used.chains[k];
      // A closed path with leads starts in the middle of its longest
      // stretch where the lead fits: the lead (a quarter arc back along the
      // path) needs room, which a corner of a pocket does not give, nor a
      // bend of the part tighter than the lead.
      if ((cp.lead || controller) && used.closed[k]) {
        std::vector<size_t> order(chain.size());
        for (size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return chain[x].length() > chain[y].length(); });
        size_t longest = order.front();
        for (size_t i = 0; part_distance && i < order.size() && i < kLeadStarts; ++i) {
          const Vec3 at = chain[order[i]].point(0.5);
          if (lead_fits(at, lead_direction(*part_distance, at, chain[order[i]].tangent(0.5), waste, away, scale), *lead_used)) {
            longest = order[i];
            break;
          }
        }
        std::vector<ArcSeg> turned{chain[longest].sub(0.5, 1)};
        for (size_t i = 1; i < chain.size(); ++i) turned.push_back(chain[(longest + i) % chain.size()]);
        turned.push_back(chain[longest].sub(0, 0.5));
        turned.back().a = turned[turned.size() - 2].b;
        turned.back().b = turned.front().a;
        chain = std::move(turned);
      }
      chains.push_back(bezier_pieces(chain));
      chain_closed.push_back(used.closed[k]);
    }
    if (controller && chains.size() != 1)
      fail("compensation", "the path for the controller to compensate falls apart into " + std::to_string(chains.size()) +
                           " pieces; use \"cam\"");
    // Material the tool cannot reach, said with where.
    double total = 0;
    std::string places;
    size_t shown = 0;
    for (const auto& l : o.left) {
      if (l.depth <= tol) continue;  // within the tolerance: nothing is left
      total += l.length;
      if (shown++ < 3) places += (places.empty() ? "" : ", ") + where(l.from) + " to " + where(l.to);
    }
    if (total > 0) {
      const std::string w = ent.label() + ": the tool (offset " + fmt_num(offset_by) + ") cannot reach " +
                            fmt_num(std::round(total * 1000) / 1000) + " " + to_string(job.units) +
                            " of the curve (inner corners and bends tighter than the tool, gaps narrower than it): "
                            "material is left at " + places + (shown > 3 ? " and " + std::to_string(shown - 3) + " more" : "");
      p.warnings.push_back(w);
      p.moves.push_back({Comment{"material left: " + places + (shown > 3 ? ", ..." : "")}, entity});
      r.left = o.left;
    }
  }
  // The part's own closed edge under compensation starts in the middle of
  // its longest piece (not at a corner, which the tool must roll round).
  if (controller && chain_closed.front() && std::abs(program_by) <= 1e-12 * scale) {
    auto& ch = chains.front();
    size_t longest = 0;
    for (size_t i = 1; i < ch.size(); ++i)
      if (length(ch[i]) > length(ch[longest])) longest = i;
    auto [a, b] = split(ch[longest], 0.5);
    a.points.back() = b.points.front();
    std::vector<Bezier> turned{b};
    for (size_t i = 1; i < ch.size(); ++i) turned.push_back(ch[(longest + i) % ch.size()]);
    turned.push_back(a);
    turned.back().points.front() = turned[turned.size() - 2].points.back();
    ch = std::move(turned);
  }
  const double out_tol = tol - fit_bound - (dev_side == 0 ? 0.0 : 0.5 * tol);
  if (out_tol <= 0.05 * tol) throw std::logic_error("offset fit used up the tolerance");

  // Depths: equal steps from top_z down to cut_z.
  std::vector<double> depths;
  if (cp.step_down) {
    if (cp.top_z <= cp.cut_z)
      fail("step_down", "passes step down from top_z (" + fmt_num(cp.top_z) + ") to cut_z (" + fmt_num(cp.cut_z) +
                            "), but top_z is not above cut_z: set \"top_z\" to the stock's top");
    const int n = std::max(1, static_cast<int>(std::ceil((cp.top_z - cp.cut_z) / *cp.step_down - 1e-9)));
    for (int k = 1; k <= n; ++k) depths.push_back(k == n ? cp.cut_z : cp.top_z - (cp.top_z - cp.cut_z) * k / n);
  } else {
    depths.push_back(cp.cut_z);
  }
  const double tab_top = cp.tabs ? cp.cut_z + cp.tabs->height : 0;
  if (cp.tabs && tab_top >= (cp.step_down ? cp.top_z : safe))
    fail("tabs.height", "tabs " + fmt_num(cp.tabs->height) + " high reach the top of the stock (top_z " +
                            fmt_num(cp.top_z) + "): make them lower than top_z - cut_z");

  // Each stretch is cut by the output mode's emitter, as an entity of its own
  // (kept alive for the deferred measurements).
  const int dec = c.decimals;
  // Passes print the same XY numbers (only Z differs): the emitters'
  // measurements run on the first pass and on the last (tabs split it).
  bool measure_pass = true;
  auto cut = [&](std::vector<Bezier> pieces, double z, double budget) {
    Entity& e = c.owned->emplace_back(ent);
    CurveSegment seg;
    seg.kind = "offset";
    seg.degree = 2;
    seg.rational = true;
    e.curve = make_single(seg, std::move(pieces), 2);
    CutParams zp = cp;
    zp.cut_z = z;
    CutContext sub{c.job, e, c.machine, zp, dec, budget, c.measure && measure_pass, p, c.later, c.report, c.owned};
    EntityReport part_r;
    part_r.label = r.label;
    switch (p.output) {
      case OutputMode::lines:
        if (controller) {
          double bound = 0;
          auto poly = even_chords(sub.entity.curve.pieces, budget, dec, bound);
          emit_polyline(sub, part_r, std::move(poly), bound);
        } else {
          emit_lines(sub, part_r);
        }
        break;
      case OutputMode::arcs: emit_arcs(sub, part_r); break;
      case OutputMode::nurbs:
        // An offset is lines and arcs: LinuxCNC's exact form of an arc is
        // G02/G03 (one line, where G5.2 takes four); Fanuc's G06.2 takes a
        // whole run of arcs as one rational block.
        if (c.machine.nurbs == NurbsDialect::linuxcnc && c.machine.arcs) emit_arcs(sub, part_r);
        else emit_nurbs(sub, part_r);
        break;
    }
    r.blocks += part_r.blocks;
    r.measured = std::max(r.measured, part_r.measured);
    return part_r.bound;
  };
  auto line_to = [&](const Vec3& to, double feed) {
    LineMove l;
    l.to = to;
    l.feed = feed;
    p.moves.push_back({l, entity});
  };

  r.blocks = 0;
  r.bound = 0;
  double out_bound = 0, lead_bound = 0;
  // Under controller compensation the tool path is the controller's: its
  // reading on bezcam's model of it (cutter_comp.hpp) joins the bound.
  double comp_reading = 0;
  // The last pass of each stretch of the path as the tool's centre goes,
  // and its leads.
  std::vector<PathPiece> last_path, last_leads;
  // Tabs go on each stretch of the path that holds them. Where the offset
  // falls apart (a tool wider than a gap of the part), a stretch too short
  // for them is cut without tabs and said; the tabs are refused when even
  // the longest stretch cannot hold them.
  std::vector<double> chain_len;
  for (const auto& chain : chains) {
    double len = 0;
    for (const auto& b : chain) len += length(b);
    chain_len.push_back(len);
  }
  const double longest = *std::max_element(chain_len.begin(), chain_len.end());
  const double tab_span = cp.tabs ? cp.tabs->width + (cp.tool_diameter ? *cp.tool_diameter : 0) : 0;
  if (cp.tabs && cp.tabs->count * tab_span >= longest)
    fail("tabs", std::to_string(cp.tabs->count) + " tabs of " + fmt_num(tab_span) +
                     " (width + tool diameter) do not fit on a path " + fmt_num(std::round(longest * 1000) / 1000) +
                     " long" + (chains.size() > 1 ? " (the longest of its " + std::to_string(chains.size()) + " stretches)" : "") +
                     "; use fewer or narrower tabs");
  for (size_t k = 0; k < chains.size(); ++k) {
    const auto& chain = chains[k];
    const double len = chain_len[k];
    // Tabs: spans of the path where deep passes rise; the tool's centre
    // rises over the tab's width plus the tool's diameter.
    std::vector<double> cuts;
    if (cp.tabs && cp.tabs->count * tab_span >= len) {
      p.warnings.push_back(ent.label() + ": a stretch of the path " + fmt_num(std::round(len * 1000) / 1000) + " long from " +
                           where(chain.front().front()) + " (the offset falls apart where the part is narrower than the tool) "
                           "is too short for " + std::to_string(cp.tabs->count) + " tabs of " + fmt_num(tab_span) +
                           " (width + tool diameter): it is cut without tabs");
    } else if (cp.tabs) {
      const double span = tab_span;
      for (int t = 0; t < cp.tabs->count; ++t) {
        const double mid = len * (t + 0.5) / cp.tabs->count;
        cuts.push_back(mid - span / 2);
        cuts.push_back(mid + span / 2);
      }
    }
    const Vec3 s = chain.front().front(), e = chain.back().back();
    // The direction the leads join the path in: at right angles to the
    // part's nearest point (the tool's centre stands on that normal,
    // whatever the path's last piece does where a clipped offset ends),
    // turned so that the waste is on the tool's side.
    Vec3 ts = unit_tangent(chain.front(), 0), te = unit_tangent(chain.back(), 1);
    if (part_distance) {
      ts = lead_direction(*part_distance, s, ts, waste, away, scale);
      te = lead_direction(*part_distance, e, te, waste, away, scale);
    }
    std::vector<Bezier> in, out;
    if (lead_used) {
      Lead l = *lead_used;
      if (part_distance) {
        // A lead that would come nearer the part than the path (a pocket
        // too small for it, a part too near) is made shorter, its line
        // first; one whose arc alone does not fit is refused, with the
        // radius that fits there.
        for (const bool lead_in_end : {true, false}) {
          const Vec3& at = lead_in_end ? s : e;
          const Vec3& t = lead_in_end ? ts : te;
          if (room(at, t, lead_in_end, l) >= 0) continue;
          if (!controller && room(at, t, lead_in_end, Lead{l.radius, 0}) >= 0) {
            double ok = 0, bad = l.length;
            for (int i = 0; i < 30; ++i) {
              const double mid = 0.5 * (ok + bad);
              (room(at, t, lead_in_end, Lead{l.radius, mid}) >= 0 ? ok : bad) = mid;
            }
            l.length = ok;
            continue;
          }
          double ok = 0, bad = l.radius;
          for (int i = 0; i < 30; ++i) {
            const double mid = 0.5 * (ok + bad);
            (room(at, t, lead_in_end, Lead{mid, controller ? l.length : 0}) >= 0 ? ok : bad) = mid;
          }
          const double fits = std::floor(ok * 1000) / 1000;
          const double near = part_distance->min_distance(lead_path(at, t, lead_in_end, l));
          fail("lead", std::string("the lead-") + (lead_in_end ? "in" : "out") + " at " + where(at) +
                           " would cut into the part: it comes within " + fmt_num(std::round(std::max(near, 0.0) * 1000) / 1000) +
                           " of the curve, where the path keeps at least " +
                           fmt_num(std::round((radius - (dev_side > 0 ? 0 : tol)) * 1e4) / 1e4) +
                           (fits > 0 ? "; a lead of radius " + fmt_num(fits) + (controller ? "" : " and no line") +
                                           " fits there: make it smaller"
                                     : "; no lead fits there (the path ends where the tool touches the part on both "
                                       "sides): remove the lead from this entity"));
        }
        if (l.length < lead_used->length)
          p.warnings.push_back(ent.label() + ": the lead's line is made " + fmt_num(std::floor(l.length * 1000) / 1000) +
                               " long, not " + fmt_num(lead_used->length) + ", at " + where(s) +
                               (k > 0 || chains.size() > 1 ? " (stretch " + std::to_string(k + 1) + ")" : std::string()) +
                               ": a longer one would cut into the part");
      }
      // Under compensation the programmed lead arc is the tool's radius
      // larger: the tool's centre runs on the arc of the radius asked.
      const Lead programmed{l.radius + tool_r, l.length};
      in = lead_in(s, ts, waste, programmed);
      out = lead_out(e, te, waste, programmed);
    }
    const auto runs = cuts.empty() ? std::vector<std::vector<Bezier>>{chain} : split_at_lengths(chain, cuts);
    for (size_t d = 0; d < depths.size(); ++d) {
      const double z = depths[d];
      const double zq = quantize(z, dec);
      measure_pass = d == 0 || d + 1 == depths.size();
      const bool last_pass = d + 1 == depths.size();
      const Vec3 entry = quantize(in.empty() ? s : in.front().front(), dec);
      approach(p, entity, {entry.x, entry.y, zq}, safe, clear, cp.plunge_feed, ms);
      if (controller) p.moves.push_back({CompensationMove{side, cp.tool, tool_r}, entity});
      const size_t in_from = p.moves.size();
      if (!in.empty()) lead_bound = std::max(lead_bound, cut(in, z, lead_budget));
      const size_t first_move = p.moves.size();
      const bool tabbed = !cuts.empty() && z < tab_top;
      for (size_t run = 0; run < runs.size(); ++run) {
        if (runs[run].empty()) continue;
        const bool on_tab = tabbed && run % 2 == 1;
        const double rz = on_tab ? tab_top : z;
        if (tabbed && run > 0) {  // up onto the tab, or back down after it
          const Vec3 at = quantize(runs[run].front().front(), dec);
          line_to({at.x, at.y, quantize(rz, dec)}, cp.plunge_feed);
        }
        out_bound = std::max(out_bound, cut(runs[run], rz, out_tol));
      }
      if (tabbed && runs.size() % 2 == 0) {  // ended on a tab: back down for the lead-out
        const Vec3 at = quantize(e, dec);
        line_to({at.x, at.y, zq}, cp.plunge_feed);
      }
      // Whether the controller can compensate the path (a corner or a bend
      // too tight for the tool stops it), asked of the model before the
      // program is written, on every pass whose numbers differ (tabs split
      // the deep ones): its reading is the bound's, and the last pass's is
      // the measured deviation.
      if (controller && measure_pass) {
        std::vector<PathPiece> path;
        try {
          path = compensated_path(p.moves, first_move, p.moves.size(), quantize(s, dec), ts, te, side, tool_r);
        } catch (const CompensationError& err) {
          fail("compensation", std::string("the controller cannot compensate this path: ") + err.what() +
                                   "; use compensation \"cam\" (bezcam offsets the path, trimming what the tool cannot reach)");
        }
        // Where the controller's tool goes must be within the tolerance of
        // the true offset too: G01 moves that turn by less than 0.05 rad
        // are joined without a corner (LinuxCNC), which can stray further.
        const OffsetReading m =
            measure_offset(part_curves, path, {.r = radius, .side = side, .middle = offset_by - radius, .resolution = 0.01 * tol});
        const double lo = radius - (dev_side > 0 ? 0 : tol), hi = radius + (dev_side < 0 ? 0 : tol);
        const double stray = std::max({lo - m.min_distance, m.max_distance - hi, m.coverage - tol});
        const double reading = std::max({radius - m.min_distance, m.max_distance - radius, m.coverage});
        comp_reading = std::max(comp_reading, reading);
        if (c.measure && last_pass) r.measured = std::max(r.measured, reading);
        if (stray > 0.02 * tol)
          fail("compensation", "the controller's compensation of these " + std::string(to_string(p.output)) +
                                   " strays " + fmt_num(std::round(stray * 1e5) / 1e5) + " " + to_string(job.units) +
                                   " beyond the tolerance (its tool path lies " + fmt_num(std::round(m.min_distance * 1e5) / 1e5) +
                                   " to " + fmt_num(std::round(m.max_distance * 1e5) / 1e5) + " from the part, reaching the offset within " +
                                   fmt_num(std::round(m.coverage * 1e5) / 1e5) +
                                   "; a controller joins G01 moves that turn by less than 0.05 rad without a corner): use "
                                   "output \"arcs\" (arcs are compensated exactly) or compensation \"cam\"");
      }
      const size_t path_to = p.moves.size();
      const Vec3 before_out = motion_of(p.moves.back())->to;
      if (controller) {
        // The lead-out's arc compensated, G40, then its line: the exit move.
        lead_bound = std::max(lead_bound, cut(std::vector<Bezier>(out.begin(), out.end() - 1), z, lead_budget));
        p.moves.push_back({CompensationMove{0, cp.tool, 0}, entity});
        const Vec3 to = quantize(out.back().back(), dec);
        line_to({to.x, to.y, zq}, cp.feed);
      } else if (!out.empty()) {
        lead_bound = std::max(lead_bound, cut(out, z, lead_budget));
      }
      // The last pass's path and its leads, measured against the part once
      // every stretch of it is cut (below; the model's reading above under
      // compensation).
      if (c.measure && side != 0 && !controller && last_pass) {
        const auto path = printed_path(p.moves, first_move, path_to, quantize(s, dec));
        const auto lead_in_path = printed_path(p.moves, in_from, first_move, entry);
        const auto lead_out_path = printed_path(p.moves, path_to, p.moves.size(), before_out);
        last_path.insert(last_path.end(), path.begin(), path.end());
        last_leads.insert(last_leads.end(), lead_in_path.begin(), lead_in_path.end());
        last_leads.insert(last_leads.end(), lead_out_path.begin(), lead_out_path.end());
      }
      const Vec3 last = motion_of(p.moves.back())->to;
      RapidMove up;
      up.to = {last.x, last.y, safe};
      p.moves.push_back({up, entity});
      ms.pos = up.to;
      ms.pos_known = true;
    }
  }
  // The proven bound: the path's against r, and the leads' against their
  // own arcs and lines (their readings are in the measured deviation too).
  r.bound = std::max({fit_bound + out_bound + (dev_side == 0 ? 0.0 : 0.5 * tol), comp_reading, lead_bound});
  // The last pass measured against the part on its own: every stretch of
  // the path in the band, the material left where the tool reaches read
  // over all of them (a part whose offset falls apart is reached by its
  // stretches together), and its leads no nearer the part than the band.
  if (!last_path.empty()) {
    EntityReport probe;
    c.measure_with(probe, [curves = part_curves, path = std::move(last_path), leads = std::move(last_leads), radius, side,
                           tol, dev_side, middle = offset_by - radius, label = r.label] {
      const OffsetReading m =
          measure_offset(curves, path, {.r = radius, .side = side, .middle = middle, .resolution = 0.01 * tol});
      // With a one-sided band the reading is against its middle.
      const double lo = radius - (dev_side > 0 ? 0 : tol), hi = radius + (dev_side < 0 ? 0 : tol);
      const double slack = 0.03 * tol;  // a margin: the band is proven, the readings exact to rounding
      if (m.min_distance < lo - slack || m.max_distance > hi + slack || m.coverage > tol + slack)
        throw std::logic_error("internal check failed: " + label + "'s tool path lies " + fmt_num(m.min_distance) +
                               " to " + fmt_num(m.max_distance) + " from the part (leaving up to " + fmt_num(m.coverage) +
                               " of material where it reaches), outside [" + fmt_num(lo) + ", " + fmt_num(hi) + "]");
      if (!leads.empty()) {
        PartDistance to_part(curves, 0.01 * tol);
        const double near = to_part.min_distance(leads);
        if (near < lo - slack)
          throw std::logic_error("internal check failed: " + label + "'s leads come within " + fmt_num(near) +
                                 " of the part, nearer than " + fmt_num(lo));
      }
      return std::max({radius - m.min_distance, m.max_distance - radius, m.coverage});
    });
    r.measured = std::max(r.measured, probe.measured);
  }
  r.offset = radius;
  r.tool_width = cp.tool_diameter.value_or(0);
}

}  // namespace bezcam::detail
