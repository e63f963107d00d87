// Cutting a part, not only a curve (docs/job-format.md): the tool-centre
// path at the tool's radius on its side of the curve (offset.hpp), in the
// direction asked, in equal depth passes, with tangent leads on the waste
// side and holding tabs, each stretch cut by the output mode's emitter with
// its own proof; then the printed path is measured against the part by
// offset_measure.hpp, which shares no code with the offset.
// The stages are PartCut's (part_cut.hpp); this file holds the side, the
// band, the stretches, the passes and the tabs.
#include "part_cut.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "bezcam/error.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/machine/cutter_comp.hpp"
#include "bezcam/warnings.hpp"

namespace bezcam::detail {

namespace {

// The parameter of `b` at arc length `s` from its start.
double param_at_length(const Bezier& b, double s) {
  double lo = 0, hi = 1;
  for (int i = 0; i < 60 && hi - lo > 1e-13; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (length(split(b, mid).first) < s)
      lo = mid;
    else
      hi = mid;
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

}  // namespace

PartCut::PartCut(CutContext& ctx, MotionState& motion, EntityReport& report, double safe_z, double clear_z)
    : c(ctx),
      ms(motion),
      r(report),
      safe(safe_z),
      clear(clear_z),
      ent(ctx.entity),
      cp(ctx.params),
      job(ctx.job),
      p(ctx.program),
      entity(static_cast<int>(ctx.entity.index)) {}

void PartCut::fail(const std::string& key, const std::string& why) const {
  const std::string top = key.substr(0, key.find('.'));
  const JobParams& own = ent.params;
  const bool here = (top == "side" && own.side) || (top == "tool_diameter" && own.tool_diameter) ||
                    (top == "stock_to_leave" && own.stock_to_leave) || (top == "step_down" && own.step_down) ||
                    (top == "tabs" && own.tabs) || (top == "compensation" && own.controller_compensation) ||
                    (top == "tolerance_side" && own.tolerance_side) || (top == "lead" && own.lead) ||
                    (top == "tool" && own.tool);
  const bool in_job =
      !here &&
      ((top == "side" && job.params.side) || (top == "tool_diameter" && job.params.tool_diameter) ||
       (top == "stock_to_leave" && job.params.stock_to_leave) || (top == "step_down" && job.params.step_down) ||
       (top == "tabs" && job.params.tabs) || (top == "compensation" && job.params.controller_compensation) ||
       (top == "tolerance_side" && job.params.tolerance_side) || (top == "lead" && job.params.lead) ||
       (top == "tool" && job.params.tool));
  throw InputError(errc::job_cut,
                   Place::in_json(job.source, (in_job ? std::string("job") : ent.json_path()) + "." + key),
                   (in_job ? "for entity " + ent.label() + ": " : std::string()) + why);
}

std::string PartCut::where(const Vec3& q) {
  return "(" + fmt_num(std::round(q.x * 1000) / 1000) + ", " + fmt_num(std::round(q.y * 1000) / 1000) + ")";
}

void PartCut::check_curve_and_controller() {
  if (ent.curve.dim != 2)
    fail("side",
         "cutting a part needs a curve in the XY plane; this one is 3D: remove the part-cutting keys (side, "
         "step_down, lead, tabs, ...) or give 2D points");
  controller = cp.controller_compensation;
  if (!controller) return;
  // One diameter per D register: the controller reads it there.
  for (const Move& mv : p.moves)
    if (const auto* cc = std::get_if<CompensationMove>(&mv.what))
      if (cc->side != 0 && cc->d == cp.tool && cp.tool_diameter && cc->radius != *cp.tool_diameter / 2)
        fail("tool", "tool " + std::to_string(cp.tool) + " is already compensated with a diameter of " +
                         fmt_num(2 * cc->radius) + " (D" + std::to_string(cp.tool) + "), this entity asks " +
                         fmt_num(*cp.tool_diameter) + ": give it its own tool number");
  if (!c.machine.cutter_compensation)
    fail("compensation", "machine \"" + c.machine.name +
                             "\" has no cutter radius compensation (G41/G42): use \"cam\" "
                             "(the default): bezcam offsets the path itself");
  if (c.output == OutputMode::nurbs)
    fail("compensation",
         std::string("compensation \"controller\" cannot be written as NURBS blocks: ") +
             (c.machine.nurbs == NurbsDialect::linuxcnc
                  ? "LinuxCNC does not compensate G5.2 blocks (it cuts them on the programmed curve)"
                  : "Fanuc refuses G06.2 in G41/G42 (alarm PS1006)") +
             "; use output \"arcs\" or \"lines\", or compensation \"cam\" for exact NURBS blocks of the offset");
}

void PartCut::choose_side() {
  const auto& g = ent.curve;
  scale = std::max(1.0, control_magnitude(g.pieces));
  closed = g.closed || dist(g.pieces.front().front(), g.pieces.back().back()) <= 1e-9 * scale;
  tol = c.tolerance;
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
        fail("side",
             "the curve bounds no area (it runs back over itself), so it has no inside; use \"left\" or \"right\"");
      const bool ccw = area > 0;  // counter-clockwise: the region is on the left
      side = (cp.side == CutSide::inside) == ccw ? 1 : -1;
      break;
    }
  }
  if (controller && cp.side == CutSide::on && cp.tolerance_side != ToleranceSide::left &&
      cp.tolerance_side != ToleranceSide::right)
    fail("compensation",
         "compensation \"controller\" needs a side of the curve for the tool (inside, outside, left or "
         "right); with side \"on\" there is nothing to compensate");
  if (side != 0) {
    if (!cp.tool_diameter)
      fail("tool_diameter", "side \"" +
                                std::string(cp.side == CutSide::left     ? "left"
                                            : cp.side == CutSide::right  ? "right"
                                            : cp.side == CutSide::inside ? "inside"
                                                                         : "outside") +
                                "\" needs the tool's diameter: add \"tool_diameter\" to the entity or the job");
    radius = *cp.tool_diameter / 2 + cp.stock_to_leave;
    if (radius <= 0)
      fail("stock_to_leave", "the offset tool_diameter / 2 + stock_to_leave = " + fmt_num(radius) +
                                 " is not positive; leave less negative stock");
  }
}

// Climb keeps the part on the tool's right (spindle M03), so the tool is on
// the left of its path; conventional the other way.
void PartCut::choose_direction() {
  const auto& g = ent.curve;
  part.assign(g.pieces.begin(), g.pieces.end());
  if (cp.direction == CutDirection::as_drawn) return;
  if (side == 0) {
    const std::string w =
        ent.label() + ": \"direction\" needs a side of the curve (side \"on\" has no part side): cut as drawn";
    p.warnings.push_back(tagged_warning(w, "direction-ignored"));
  } else if ((cp.direction == CutDirection::climb) != (side > 0)) {
    part = reversed(std::span<const Bezier>(part));
    side = -side;
  }
}

void PartCut::choose_band() {
  switch (cp.tolerance_side) {
    case ToleranceSide::both: break;
    case ToleranceSide::waste:
      if (side == 0)
        fail("tolerance_side",
             "\"waste\" needs a side of the curve (inside, outside, left or right); side \"on\" has "
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
  fit = dev_side == 0 ? 0.45 * tol : 0.2 * tol;
  offset_by = radius + dev_side * 0.5 * tol;
  waste = side != 0 ? side : 1;
  // With controller compensation the program carries the part's edge, the
  // controller adds the tool's radius (its D register); the program's path
  // is offset only by the stock to leave and the band's middle.
  tool_r = controller ? *cp.tool_diameter / 2 : 0;
  program_by = offset_by - tool_r;
}

void PartCut::choose_lead() {
  // Under controller compensation there is always a lead (the controller
  // enters and leaves compensation on it), by default a quarter arc of the
  // tool's radius after a line of its diameter; its line must be longer
  // than the tool's radius (LinuxCNC refuses a shorter entry move).
  lead_used = cp.lead;
  if (controller && !lead_used) lead_used = Lead{tool_r, 2 * tool_r};
  if (controller && !(lead_used->length > tool_r))
    fail("lead.length",
         "compensation \"controller\" enters and leaves on the lead's line, which must be longer than the "
         "tool's radius " +
             fmt_num(tool_r) + " (it is " + fmt_num(lead_used->length) + "): make it longer");
  // The leads are designed and checked against the part itself, sampled
  // once for all of them.
  part_curves = {part};
  if (lead_used && side != 0) part_distance.emplace(part_curves, 0.01 * tol);
  // Where the path is on the part's side of the program's path (controller
  // compensation of a negative stock), the waste lies the other way.
  away = (controller ? program_by : offset_by) < 0 ? -1 : 1;
}

void PartCut::build_chains() {
  if (side == 0 || (controller && std::abs(program_by) <= 1e-12 * scale)) {
    chains.push_back(part);
    chain_closed.push_back(closed);
  }
  if (side == 0) return;
  // Arcs and exact blocks follow the offset's arcs: tangent ones, so that
  // the controller runs through their joints.
  const bool tangent = c.output != OutputMode::lines;
  const OffsetResult o = offset_curve(part, closed, {offset_by, side, fit, tangent});
  if (o.chains.empty())
    fail("tool_diameter", "a tool of diameter " + fmt_num(cp.tool_diameter.value_or(0)) +
                              " does not fit: no point is " + fmt_num(offset_by) +
                              " from the whole curve on the side asked (" +
                              (cp.side == CutSide::inside    ? "inside"
                               : cp.side == CutSide::outside ? "outside"
                               : side > 0                    ? "left"
                                                             : "right") +
                              "); use a smaller tool");
  if (controller && o.chains.size() > 1)
    fail("compensation",
         "the tool of diameter " + fmt_num(*cp.tool_diameter) +
             " cannot follow the whole curve in one "
             "path (its offset falls apart into " +
             std::to_string(o.chains.size()) +
             " pieces where the part narrows): a controller's compensation cannot cut that; use \"cam\"");
  // The program's own path under controller compensation: the stock and
  // the band's shift only (the part itself when both are zero).
  OffsetResult prog;
  if (controller && chains.empty())
    prog = offset_curve(part, closed, {std::abs(program_by), program_by > 0 ? side : -side, fit, tangent});
  const OffsetResult& used = controller ? prog : o;
  fit_bound = controller ? (chains.empty() ? prog.bound : 0.0) : o.bound;
  // A lead stays in the path's band: it is cut within half the tolerance,
  // or what the offset's fit leaves of the path's own share where that is
  // less, and comes no nearer the part than the band's near edge plus that
  // (to rounding). Where it joins the path it is no nearer than the path.
  lead_budget = std::min(0.5 * tol, tol - fit_bound - (dev_side == 0 ? 0.0 : 0.5 * tol));
  lead_clear = radius - (dev_side > 0 ? 0 : tol) + lead_budget - 1e-9 * scale;
  for (size_t k = 0; k < used.chains.size(); ++k) {
    std::vector<ArcSeg> chain = used.chains[k];
    if ((cp.lead || controller) && used.closed[k]) chain = start_where_lead_fits(std::move(chain));
    chains.push_back(bezier_pieces(chain));
    chain_closed.push_back(used.closed[k]);
  }
  if (controller && chains.size() != 1)
    fail("compensation", "the path for the controller to compensate falls apart into " + std::to_string(chains.size()) +
                             " pieces; use \"cam\"");
  warn_material_left(o);
}

// Material the tool cannot reach, said with where.
void PartCut::warn_material_left(const OffsetResult& o) {
  double total = 0;
  std::string places;
  size_t shown = 0;
  for (const auto& l : o.left) {
    if (l.depth <= tol) continue;  // within the tolerance: nothing is left
    total += l.length;
    if (shown++ < 3) places += (places.empty() ? "" : ", ") + where(l.from) + " to " + where(l.to);
  }
  if (total <= 0) return;
  const std::string w = ent.label() + ": the tool (offset " + fmt_num(offset_by) + ") cannot reach " +
                        fmt_num(std::round(total * 1000) / 1000) + " " + to_string(job.units) +
                        " of the curve (inner corners and bends tighter than the tool, gaps narrower than it): "
                        "material is left at " +
                        places + (shown > 3 ? " and " + std::to_string(shown - 3) + " more" : "");
  p.warnings.push_back(tagged_warning(w, "material-left"));
  p.moves.push_back({Comment{"material left: " + places + (shown > 3 ? ", ..." : "")}, entity});
  r.left = o.left;
}

// The part's own closed edge under compensation starts in the middle of its
// longest piece (not at a corner, which the tool must roll round).
void PartCut::start_part_edge() {
  if (!(controller && chain_closed.front() && std::abs(program_by) <= 1e-12 * scale)) return;
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

// Depths: equal steps from top_z down to cut_z.
void PartCut::plan_depths() {
  out_tol = tol - fit_bound - (dev_side == 0 ? 0.0 : 0.5 * tol);
  if (out_tol <= 0.05 * tol) throw std::logic_error("offset fit used up the tolerance");
  if (const std::optional<double> step = cp.pass_depth()) {  // step_down, or the flute length
    if (cp.top_z <= cp.cut_z)
      fail("step_down", "passes step down from top_z (" + fmt_num(cp.top_z) + ") to cut_z (" + fmt_num(cp.cut_z) +
                            "), but top_z is not above cut_z: set \"top_z\" to the stock's top");
    const int n = std::max(1, static_cast<int>(std::ceil((cp.top_z - cp.cut_z) / *step - 1e-9)));
    for (int k = 1; k <= n; ++k) depths.push_back(k == n ? cp.cut_z : cp.top_z - (cp.top_z - cp.cut_z) * k / n);
  } else {
    depths.push_back(cp.cut_z);
  }
  tab_top = cp.tabs ? cp.cut_z + cp.tabs->height : 0;
  if (cp.tabs && tab_top >= (cp.pass_depth() ? cp.top_z : safe))
    fail("tabs.height", "tabs " + fmt_num(cp.tabs->height) + " high reach the top of the stock (top_z " +
                            fmt_num(cp.top_z) + "): make them lower than top_z - cut_z");
  dec = c.decimals;
}

// Each stretch is cut by the output mode's emitter, as an entity of its own
// (kept alive for the deferred measurements).
double PartCut::cut(std::vector<Bezier> pieces, double z, double budget, CutEnds ends) {
  Entity& e = c.owned->emplace_back(ent);
  CurveSegment seg;
  seg.kind = "offset";
  seg.degree = 2;
  seg.rational = true;
  e.curve = make_single(seg, std::move(pieces), 2);
  CutParams zp = cp;
  zp.cut_z = z;
  CutContext sub{c.job, e,       c.machine, zp,     c.output, dec, budget, c.measure && measure_pass,
                 p,     c.later, c.report,  c.owned};
  sub.ends = ends;
  EntityReport part_r;
  part_r.label = r.label;
  switch (c.output) {
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
      if (c.machine.nurbs == NurbsDialect::linuxcnc && c.machine.arcs)
        emit_arcs(sub, part_r);
      else
        emit_nurbs(sub, part_r);
      break;
  }
  r.blocks += part_r.blocks;
  r.measured = std::max(r.measured, part_r.measured);
  return part_r.bound;
}

void PartCut::line_to(const Vec3& to, double feed) {
  LineMove l;
  l.to = to;
  l.feed = feed;
  p.moves.push_back({l, entity});
}

// Tabs go on each stretch of the path that holds them. Where the offset
// falls apart (a tool wider than a gap of the part), a stretch too short for
// them is cut without tabs and said; the tabs are refused when even the
// longest stretch cannot hold them.
void PartCut::cut_stretches() {
  r.blocks = 0;
  r.bound = 0;
  std::vector<double> chain_len;
  for (const auto& chain : chains) {
    double len = 0;
    for (const auto& b : chain) len += length(b);
    chain_len.push_back(len);
  }
  const double longest = *std::max_element(chain_len.begin(), chain_len.end());
  tab_span = cp.tabs ? cp.tabs->width + (cp.tool_diameter ? *cp.tool_diameter : 0) : 0;
  if (cp.tabs && cp.tabs->count * tab_span >= longest)
    fail("tabs",
         std::to_string(cp.tabs->count) + " tabs of " + fmt_num(tab_span) +
             " (width + tool diameter) do not fit on a path " + fmt_num(std::round(longest * 1000) / 1000) + " long" +
             (chains.size() > 1 ? " (the longest of its " + std::to_string(chains.size()) + " stretches)" : "") +
             "; use fewer or narrower tabs");
  for (size_t k = 0; k < chains.size(); ++k) {
    const auto& chain = chains[k];
    Stretch st;
    st.s = chain.front().front();
    st.e = chain.back().back();
    const std::vector<double> cuts = tab_cuts(st.s, chain_len[k]);
    leads_of(k, st);
    st.tabs = !cuts.empty();
    st.whole = {chain};
    st.runs = cuts.empty() ? std::vector<std::vector<Bezier>>{chain} : split_at_lengths(chain, cuts);
    for (size_t d = 0; d < depths.size(); ++d) cut_pass(st, d);
  }
}

// Tabs: spans of the path where deep passes rise; the tool's centre rises
// over the tab's width plus the tool's diameter.
std::vector<double> PartCut::tab_cuts(const Vec3& start, double len) {
  std::vector<double> cuts;
  if (!cp.tabs) return cuts;
  if (cp.tabs->count * tab_span >= len) {
    p.warnings.push_back(tagged_warning(ent.label() + ": a stretch of the path " +
                                            fmt_num(std::round(len * 1000) / 1000) + " long from " + where(start) +
                                            " (the offset falls apart where the part is narrower than the tool) "
                                            "is too short for " +
                                            std::to_string(cp.tabs->count) + " tabs of " + fmt_num(tab_span) +
                                            " (width + tool diameter): it is cut without tabs",
                                        "tabs-skipped"));
    return cuts;
  }
  for (int t = 0; t < cp.tabs->count; ++t) {
    const double mid = len * (t + 0.5) / cp.tabs->count;
    cuts.push_back(mid - tab_span / 2);
    cuts.push_back(mid + tab_span / 2);
  }
  return cuts;
}

void PartCut::cut_pass(const Stretch& st, size_t d) {
  const double z = depths[d];
  const double zq = quantize(z, dec);
  measure_pass = d == 0 || d + 1 == depths.size();
  const bool last_pass = d + 1 == depths.size();
  const Vec3 entry = quantize(st.in.empty() ? st.s : st.in.front().front(), dec);
  approach(p, entity, {entry.x, entry.y, zq}, safe, clear, cp.plunge_feed, ms);
  if (controller) p.moves.push_back({CompensationMove{side, cp.tool, tool_r}, entity});
  const size_t in_from = p.moves.size();
  // The lead-in runs on into the path and the path into the lead-out,
  // tangent to each other, at the feed; the tool stops only at the
  // plunge, a step onto or off a tab, and the retract.
  if (!st.in.empty()) lead_bound = std::max(lead_bound, cut(st.in, z, lead_budget, {true, false}));
  const size_t first_move = p.moves.size();
  if (first_move > in_from) r.lead_moves.push_back({in_from, first_move});
  const bool tabbed = st.tabs && z < tab_top;
  // Above the tabs the path is cut whole: split where the tabs lie, it
  // would be printed as several cuts, with pieces as short as the gap
  // between a tab's end and the path's next joint.
  const auto& runs = tabbed ? st.runs : st.whole;
  size_t last_run = runs.size();
  for (size_t run = 0; run < runs.size(); ++run)
    if (!runs[run].empty()) last_run = run;
  // (ended on a tab: a step down before the lead-out)
  const bool step_down = tabbed && runs.size() % 2 == 0;
  for (size_t run = 0; run < runs.size(); ++run) {
    if (runs[run].empty()) continue;
    const bool on_tab = tabbed && run % 2 == 1;
    const double rz = on_tab ? tab_top : z;
    if (tabbed && run > 0) {  // up onto the tab, or back down after it
      const Vec3 at = quantize(runs[run].front().front(), dec);
      line_to({at.x, at.y, quantize(rz, dec)}, cp.plunge_feed);
    }
    const CutEnds ends{!(run == 0 && !st.in.empty()), !(run == last_run && !st.out.empty() && !step_down)};
    out_bound = std::max(out_bound, cut(runs[run], rz, out_tol, ends));
  }
  if (step_down) {  // ended on a tab: back down for the lead-out
    const Vec3 at = quantize(st.e, dec);
    line_to({at.x, at.y, zq}, cp.plunge_feed);
  }
  if (controller && measure_pass) check_compensation(st, first_move, last_pass);
  const size_t path_to = p.moves.size();
  const Vec3 before_out = motion_of(p.moves.back())->to;
  if (controller) {
    // The lead-out's arc compensated, G40, then its line: the exit move.
    lead_bound = std::max(
        lead_bound, cut(std::vector<Bezier>(st.out.begin(), st.out.end() - 1), z, lead_budget, {step_down, false}));
    p.moves.push_back({CompensationMove{0, cp.tool, 0}, entity});
    const Vec3 to = quantize(st.out.back().back(), dec);
    line_to({to.x, to.y, zq}, cp.feed);
  } else if (!st.out.empty()) {
    lead_bound = std::max(lead_bound, cut(st.out, z, lead_budget, {step_down, true}));
  }
  // The last pass's path and its leads, measured against the part once
  // every stretch of it is cut (finish(); the model's reading under
  // compensation).
  if (c.measure && side != 0 && !controller && last_pass) {
    const auto path = printed_path(p.moves, first_move, path_to, quantize(st.s, dec));
    const auto lead_in_path = printed_path(p.moves, in_from, first_move, entry);
    const auto lead_out_path = printed_path(p.moves, path_to, p.moves.size(), before_out);
    last_path.insert(last_path.end(), path.begin(), path.end());
    last_leads.insert(last_leads.end(), lead_in_path.begin(), lead_in_path.end());
    last_leads.insert(last_leads.end(), lead_out_path.begin(), lead_out_path.end());
  }
  if (p.moves.size() > path_to) r.lead_moves.push_back({path_to, p.moves.size()});
  const Vec3 last = motion_of(p.moves.back())->to;
  RapidMove up;
  up.to = {last.x, last.y, safe};
  p.moves.push_back({up, entity});
  ms.pos = up.to;
  ms.pos_known = true;
}

// Whether the controller can compensate the path (a corner or a bend too
// tight for the tool stops it), asked of the model before the program is
// written, on every pass whose numbers differ (tabs split the deep ones):
// its reading is the bound's, and the last pass's is the measured deviation.
void PartCut::check_compensation(const Stretch& st, size_t first_move, bool last_pass) {
  std::vector<PathPiece> path;
  try {
    path = compensated_path(p.moves, first_move, p.moves.size(), quantize(st.s, dec), st.ts, st.te, side, tool_r);
  } catch (const CompensationError& err) {
    fail("compensation",
         std::string("the controller cannot compensate this path: ") + err.what() +
             "; use compensation \"cam\" (bezcam offsets the path, trimming what the tool cannot reach)");
  }
  // Where the controller's tool goes must be within the tolerance of the
  // true offset too: G01 moves that turn by less than 0.05 rad are joined
  // without a corner (LinuxCNC), which can stray further.
  const OffsetReading m = measure_offset(
      part_curves, path, {.r = radius, .side = side, .middle = offset_by - radius, .resolution = 0.01 * tol});
  const double lo = radius - (dev_side > 0 ? 0 : tol), hi = radius + (dev_side < 0 ? 0 : tol);
  const double stray = std::max({lo - m.min_distance, m.max_distance - hi, m.coverage - tol});
  const double reading = std::max({radius - m.min_distance, m.max_distance - radius, m.coverage});
  comp_reading = std::max(comp_reading, reading);
  if (c.measure && last_pass) r.measured = std::max(r.measured, reading);
  if (stray > 0.02 * tol)
    fail("compensation",
         "the controller's compensation of these " + std::string(to_string(c.output)) + " strays " +
             fmt_num(std::round(stray * 1e5) / 1e5) + " " + to_string(job.units) +
             " beyond the tolerance (its tool path lies " + fmt_num(std::round(m.min_distance * 1e5) / 1e5) + " to " +
             fmt_num(std::round(m.max_distance * 1e5) / 1e5) + " from the part, reaching the offset within " +
             fmt_num(std::round(m.coverage * 1e5) / 1e5) +
             "; a controller joins G01 moves that turn by less than 0.05 rad without a corner): use "
             "output \"arcs\" (arcs are compensated exactly) or compensation \"cam\"");
}

// The proven bound: the path's against r, and the leads' against their own
// arcs and lines (their readings are in the measured deviation too). The
// last pass measured against the part on its own: every stretch of the path
// in the band, the material left where the tool reaches read over all of
// them (a part whose offset falls apart is reached by its stretches
// together), and its leads no nearer the part than the band.
void PartCut::finish() {
  r.bound = std::max({fit_bound + out_bound + (dev_side == 0 ? 0.0 : 0.5 * tol), comp_reading, lead_bound});
  if (!last_path.empty()) {
    EntityReport probe;
    c.measure_with(
        probe, [curves = part_curves, path = std::move(last_path), leads = std::move(last_leads), radius = radius,
                side = side, tol = tol, dev_side = dev_side, middle = offset_by - radius, label = r.label] {
          const OffsetReading m =
              measure_offset(curves, path, {.r = radius, .side = side, .middle = middle, .resolution = 0.01 * tol});
          // With a one-sided band the reading is against its middle.
          const double lo = radius - (dev_side > 0 ? 0 : tol), hi = radius + (dev_side < 0 ? 0 : tol);
          const double slack = 0.03 * tol;  // a margin: the band is proven, the readings exact to rounding
          if (m.min_distance < lo - slack || m.max_distance > hi + slack || m.coverage > tol + slack)
            throw std::logic_error("internal check failed: " + label + "'s tool path lies " + fmt_num(m.min_distance) +
                                   " to " + fmt_num(m.max_distance) + " from the part (leaving up to " +
                                   fmt_num(m.coverage) + " of material where it reaches), outside [" + fmt_num(lo) +
                                   ", " + fmt_num(hi) + "]");
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

void PartCut::run() {
  check_curve_and_controller();
  choose_side();
  choose_direction();
  choose_band();
  choose_lead();
  build_chains();
  start_part_edge();
  plan_depths();
  cut_stretches();
  finish();
}

void emit_part(CutContext& c, MotionState& ms, EntityReport& r, double safe, double clear) {
  PartCut(c, ms, r, safe, clear).run();
}

}  // namespace bezcam::detail
