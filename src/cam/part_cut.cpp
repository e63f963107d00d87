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

#include "bezcam/error.hpp"
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

// The printed path of moves [from, to) as a dense XY polyline from `cur`.
std::vector<Vec3> dense_path(const std::vector<Move>& moves, size_t from, size_t to, Vec3 cur, double sag) {
  std::vector<Vec3> out{Vec3{cur.x, cur.y, 0}};
  auto add = [&](const Vec3& p) { out.push_back({p.x, p.y, 0}); };
  for (size_t i = from; i < to; ++i) {
    const Move& mv = moves[i];
    if (const auto* l = std::get_if<LineMove>(&mv.what)) {
      if (l->to.x != cur.x || l->to.y != cur.y) add(l->to);
      cur = l->to;
    } else if (const auto* a = std::get_if<ArcMove>(&mv.what)) {
      const PrintedArc arc{Vec3{cur.x, cur.y, 0}, Vec3{a->to.x, a->to.y, 0}, Vec3{a->center.x, a->center.y, 0}, a->ccw};
      const auto pts = sample_arc(arc, sag);
      for (size_t k = 1; k < pts.size(); ++k) add(pts[k]);
      cur = a->to;
    } else if (const auto* c = std::get_if<CurveMove>(&mv.what)) {
      std::vector<Vec3> ctrl;
      for (const auto& p : c->ctrl) ctrl.push_back({p.x, p.y, 0});
      std::vector<Bezier> pieces;
      if (c->form == CurveMove::Form::bezier) pieces.push_back(Bezier::make(ctrl, {}, 2));
      else pieces = to_bezier(NurbsCurve::make(c->order - 1, ctrl, c->knots, c->weights, 2));
      const auto pts = flatten(pieces, {.tolerance = sag, .decimals = -1, .on_curve = true}).points;
      for (size_t k = 1; k < pts.size(); ++k) add(pts[k]);
      cur = c->to;
    } else if (const auto* m = motion_of(mv)) {
      cur = m->to;
    }
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
                      (top == "tolerance_side" && own.tolerance_side) || (top == "lead" && own.lead);
    const bool in_job = !here && ((top == "side" && job.params.side) || (top == "tool_diameter" && job.params.tool_diameter) ||
                                  (top == "stock_to_leave" && job.params.stock_to_leave) ||
                                  (top == "step_down" && job.params.step_down) || (top == "tabs" && job.params.tabs) ||
                                  (top == "compensation" && job.params.controller_compensation) ||
                                  (top == "tolerance_side" && job.params.tolerance_side));
    throw InputError(errc::job_cut, Place::in_json(job.source, (in_job ? std::string("job") : ent.json_path()) + "." + key),
                     (in_job ? "for entity " + ent.label() + ": " : std::string()) + why);
  };
  const auto& g = ent.curve;
  if (g.dim != 2)
    fail("side", "cutting a part needs a curve in the XY plane; this one is 3D: remove the part-cutting keys (side, "
                 "step_down, lead, tabs, ...) or give 2D points");
  if (cp.controller_compensation)
    fail("compensation", std::string("compensation \"controller\" (G41/G42) is not written by this version of bezcam; ") +
                             "use \"cam\" (the default): bezcam offsets the path itself, with a proven bound");
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

  std::vector<std::vector<Bezier>> chains;
  std::vector<bool> chain_closed;
  double fit_bound = 0;
  if (side == 0) {
    chains.push_back(part);
    chain_closed.push_back(closed);
  } else {
    const OffsetResult o = offset_curve(part, closed, {offset_by, side, fit});
    if (o.chains.empty())
      fail("tool_diameter", "a tool of diameter " + fmt_num(cp.tool_diameter.value_or(0)) + " does not fit: no point is " +
                                fmt_num(offset_by) + " from the whole curve on the side asked (" +
                                (cp.side == CutSide::inside ? "inside" : cp.side == CutSide::outside ? "outside" : side > 0 ? "left" : "right") +
                                "); use a smaller tool");
    fit_bound = o.bound;
    for (size_t k = 0; k < o.chains.size(); ++k) {
      std::vector<ArcSeg> chain = o.chains[k];
      // A closed path with leads starts in the middle of its longest
      // stretch: the lead (a quarter arc back along the path) needs room,
      // which a corner of a pocket does not give.
      if (cp.lead && o.closed[k]) {
        size_t longest = 0;
        for (size_t i = 1; i < chain.size(); ++i)
          if (chain[i].length() > chain[longest].length()) longest = i;
        std::vector<ArcSeg> turned{chain[longest].sub(0.5, 1)};
        for (size_t i = 1; i < chain.size(); ++i) turned.push_back(chain[(longest + i) % chain.size()]);
        turned.push_back(chain[longest].sub(0, 0.5));
        turned.back().a = turned[turned.size() - 2].b;
        turned.back().b = turned.front().a;
        chain = std::move(turned);
      }
      chains.push_back(bezier_pieces(chain));
      chain_closed.push_back(o.closed[k]);
    }
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
      case OutputMode::lines: emit_lines(sub, part_r); break;
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
  double out_bound = 0;
  // The proven bound, known once every stretch is cut; the deferred
  // measurements read it.
  auto final_bound = std::make_shared<double>(0);
  for (size_t k = 0; k < chains.size(); ++k) {
    const auto& chain = chains[k];
    double len = 0;
    for (const auto& b : chain) len += length(b);
    // Tabs: spans of the path where deep passes rise; the tool's centre
    // rises over the tab's width plus the tool's diameter.
    std::vector<double> cuts;
    if (cp.tabs) {
      const double span = cp.tabs->width + (cp.tool_diameter ? *cp.tool_diameter : 0);
      if (cp.tabs->count * span >= len)
        fail("tabs", std::to_string(cp.tabs->count) + " tabs of " + fmt_num(span) +
                         " (width + tool diameter) do not fit on a path " + fmt_num(std::round(len * 1000) / 1000) +
                         " long; use fewer or narrower tabs");
      for (int t = 0; t < cp.tabs->count; ++t) {
        const double mid = len * (t + 0.5) / cp.tabs->count;
        cuts.push_back(mid - span / 2);
        cuts.push_back(mid + span / 2);
      }
    }
    const Vec3 s = chain.front().front(), e = chain.back().back();
    const Vec3 ts = unit_tangent(chain.front(), 0), te = unit_tangent(chain.back(), 1);
    std::vector<Bezier> in, out;
    if (cp.lead) {
      in = lead_in(s, ts, waste, *cp.lead);
      out = lead_out(e, te, waste, *cp.lead);
      // A lead that reaches into the part (a pocket too small for it, a
      // part too near) would cut it: said, with how near it comes.
      if (side != 0) {
        for (const auto* lead : {&in, &out}) {
          const auto pts = flatten(*lead, {.tolerance = 0.01 * tol, .decimals = -1, .on_curve = true}).points;
          const std::vector<std::vector<Bezier>> curves{part};
          const double near = measure_offset(curves, pts, radius, 0, tol, 0.05 * tol).min_distance;
          if (near < radius - tol)
            p.warnings.push_back(ent.label() + ": the lead-" + (lead == &in ? "in" : "out") +
                                 (near < 1e-3 ? std::string(" crosses the curve") : " comes within " + fmt_num(std::round(near * 1000) / 1000) + " of the curve") +
                                 ", nearer than the tool's radius " + fmt_num(radius) +
                                 ": it cuts into the part; make the lead shorter or its radius smaller");
        }
      }
    }
    const auto runs = cuts.empty() ? std::vector<std::vector<Bezier>>{chain} : split_at_lengths(chain, cuts);
    for (size_t d = 0; d < depths.size(); ++d) {
      const double z = depths[d];
      const double zq = quantize(z, dec);
      measure_pass = d == 0 || d + 1 == depths.size();
      const Vec3 entry = quantize(in.empty() ? s : in.front().front(), dec);
      approach(p, entity, {entry.x, entry.y, zq}, safe, clear, cp.plunge_feed, ms);
      if (!in.empty()) cut(in, z, 0.5 * tol);
      const size_t first_move = p.moves.size();
      const bool tabbed = cp.tabs && z < tab_top;
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
      // The last pass's path, measured against the part on its own.
      if (c.measure && side != 0 && d + 1 == depths.size()) {
        const Vec3 from = quantize(s, dec);
        auto path = dense_path(p.moves, first_move, p.moves.size(), from, 0.001 * tol);
        std::vector<std::vector<Bezier>> curves{part};
        EntityReport probe;
        c.measure_with(probe, [curves = std::move(curves), path = std::move(path), radius, side, tol, dev_side,
                               label = r.label, bound = final_bound] {
          OffsetReading m = measure_offset(curves, path, radius, side, tol, 0.01 * tol);
          // Readings are good to the resolution: one above the proven bound
          // is asked again ten times finer (a true excess survives).
          auto reading = [&](const OffsetReading& x) {
            return std::max({radius - x.min_distance, x.max_distance - radius, x.coverage});
          };
          if (reading(m) > *bound) {
            const bool near = std::max(radius - m.min_distance, m.max_distance - radius) > *bound;
            const OffsetReading f = measure_offset(curves, path, radius, side, tol, 0.001 * tol, near);
            m.coverage = f.coverage;
            if (near) m.min_distance = f.min_distance, m.max_distance = f.max_distance;
          }
          // With a one-sided band the reading is against its middle.
          const double lo = radius - (dev_side > 0 ? 0 : tol), hi = radius + (dev_side < 0 ? 0 : tol);
          const double slack = 0.03 * tol;  // the measurement's resolution and sampling
          if (m.min_distance < lo - slack || m.max_distance > hi + slack || m.coverage > tol + slack)
            throw std::logic_error("internal check failed: " + label + "'s tool path lies " + fmt_num(m.min_distance) +
                                   " to " + fmt_num(m.max_distance) + " from the part (reaching the offset within " +
                                   fmt_num(m.coverage) + "), outside [" + fmt_num(lo) + ", " + fmt_num(hi) + "]");
          return reading(m);
        });
        r.measured = std::max(r.measured, probe.measured);
      }
      if (!out.empty()) cut(out, z, 0.5 * tol);
      const Vec3 last = motion_of(p.moves.back())->to;
      RapidMove up;
      up.to = {last.x, last.y, safe};
      p.moves.push_back({up, entity});
      ms.pos = up.to;
      ms.pos_known = true;
    }
  }
  r.bound = fit_bound + out_bound + (dev_side == 0 ? 0.0 : 0.5 * tol);
  *final_bound = r.bound;
  r.offset = radius;
  r.tool_width = cp.tool_diameter.value_or(0);
}

}  // namespace bezcam::detail
