// Holes (docs/holes.md): which entities are holes, the circle a closed
// curve is, and drilling in a canned cycle whose motion the program holds
// move for move as the reader runs the printed cycle
// (gcode/canned_cycles.cpp), so that validation, the motion plan and the
// cycle time see every peck, and a profile without canned cycles prints
// that motion as G00/G01 moves.
#include "hole_cut.hpp"

#include <cmath>
#include <numbers>

#include "bezcam/error.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/limits.hpp"

namespace bezcam::detail {

namespace {

bool is_hole(const CutParams& cp) {
  return cp.pocket.operation == Operation::drill || cp.pocket.operation == Operation::bore;
}

bool closed_curve(std::span<const Bezier> pieces, bool closed) {
  if (pieces.empty()) return false;
  const double scale = std::max(1.0, control_magnitude(pieces));
  return closed || dist(pieces.front().front(), pieces.back().back()) <= 1e-9 * scale;
}

// The least-squares circle (Kåsa's: x² + y² + D x + E y + F = 0) through
// points of the pieces, about their mean for conditioning.
std::optional<HoleShape> least_squares_circle(std::span<const Bezier> pieces) {
  std::vector<Vec3> pts;
  for (const Bezier& b : pieces)
    for (int k = 0; k < 16; ++k) pts.push_back(evaluate(b, k / 16.0));
  Vec3 mean;
  for (const Vec3& p : pts) mean = mean + p;
  mean = mean * (1.0 / static_cast<double>(pts.size()));
  double a[3][3] = {}, rhs[3] = {};
  for (const Vec3& p : pts) {
    const double x = p.x - mean.x, y = p.y - mean.y, row[3] = {x, y, 1}, w = -(x * x + y * y);
    for (int i = 0; i < 3; ++i) {
      rhs[i] += row[i] * w;
      for (int j = 0; j < 3; ++j) a[i][j] += row[i] * row[j];
    }
  }
  const auto det = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(a);
  if (!(std::abs(d) > 0)) return std::nullopt;
  double sol[3];
  for (int c = 0; c < 3; ++c) {
    double m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = j == c ? rhs[i] : a[i][j];
    sol[c] = det(m) / d;
  }
  const double cx = -sol[0] / 2, cy = -sol[1] / 2, rr = cx * cx + cy * cy - sol[2];
  if (!(rr > 0)) return std::nullopt;
  return HoleShape{{mean.x + cx, mean.y + cy, 0}, 2 * std::sqrt(rr), 0};
}

// "entities[N].KEY" when the entity gives KEY, "job.KEY" when the job does,
// else the entity.
std::string key_at(const Entity& e, bool entity_has, bool job_has, const char* key) {
  if (entity_has) return e.json_path() + "." + key;
  if (job_has) return std::string("job.") + key;
  return e.json_path();
}

}  // namespace

std::optional<HoleShape> fit_circle(std::span<const Bezier> pieces, bool closed, double tolerance) {
  if (!closed_curve(pieces, closed)) return std::nullopt;
  for (const Bezier& b : pieces)
    for (const Vec3& p : b.points)
      if (p.z != 0) return std::nullopt;
  std::optional<HoleShape> h = least_squares_circle(pieces);
  if (!h) return std::nullopt;
  const double r = *h->diameter / 2;
  // Each piece in eight spans, each against the arc about the centre
  // between its ends (a spiral where the ends' radii differ): the proven
  // distance to that arc plus the ends' distance from the circle bounds
  // the distance to the circle. The spans turn one way, once round.
  int turn = 0;
  double swept = 0, bound = 0;
  for (const Bezier& b : pieces)
    for (int k = 0; k < 8; ++k) {
      const double t0 = k / 8.0, t1 = (k + 1) / 8.0;
      const Vec3 s = evaluate(b, t0), e = evaluate(b, t1);
      const double cross = (s.x - h->centre.x) * (e.y - h->centre.y) - (s.y - h->centre.y) * (e.x - h->centre.x);
      const int dir = cross > 0 ? 1 : cross < 0 ? -1 : 0;
      if (dir == 0 || (turn != 0 && dir != turn)) return std::nullopt;
      turn = dir;
      const Arc arc{s, e, h->centre, dir > 0, Plane::xy};
      const double ends = std::max(std::abs(dist_xy(s, h->centre) - r), std::abs(dist_xy(e, h->centre) - r));
      if (ends > tolerance) return std::nullopt;
      const double d = arc_span_deviation(b, t0, t1, arc, -1, tolerance * 1e-3);
      if (!(d + ends <= tolerance)) return std::nullopt;
      bound = std::max(bound, d + ends);
      swept += arc.sweep();
    }
  if (std::abs(swept - 2 * std::numbers::pi) > 1e-6) return std::nullopt;
  h->bound = bound;
  return h;
}

std::optional<Vec3> hole_centre(const Entity& e, const CutParams& cp) {
  if (!is_hole(cp)) return std::nullopt;
  if (e.point) return *e.point;
  if (e.surface || !closed_curve(e.curve.pieces, e.curve.closed)) return std::nullopt;
  if (const auto h = least_squares_circle(e.curve.pieces)) return h->centre;
  return std::nullopt;
}

namespace {

// A drilled hole's cycle, as the checks of docs/holes.md leave it.
struct Drill {
  HoleShape shape;
  CannedCycle cycle;
  std::optional<double> diameter;  // the drill's
};

// The shape of the hole an entity makes: its point, or the circle its
// closed curve is; refused naming the entity otherwise.
HoleShape shape_of(const CutContext& c) {
  const Entity& e = c.entity;
  if (e.point) return {*e.point, std::nullopt, 0};
  const std::string op = c.params.pocket.operation == Operation::bore ? "bore" : "drill";
  if (e.surface || e.curve.pieces.empty())
    throw InputError(errc::job_hole, Place::in_json(c.job.source, e.json_path() + ".operation"),
                     "a " + e.type + " cannot be a hole: " + op + " a point or a circle");
  if (auto h = fit_circle(e.curve.pieces, e.curve.closed, c.tolerance)) return *h;
  throw InputError(errc::job_hole, Place::in_json(c.job.source, e.json_path() + ".operation"),
                   "\"" + op + "\" makes a hole at a point or a circle, and " + e.label() +
                       " is not a closed curve within the tolerance (" + fmt_num(c.tolerance) + " " +
                       to_string(c.job.units) +
                       ") of a circle: give it \"operation\": \"pocket\" or \"profile\", or draw the hole as a "
                       "circle or a point");
}

// The checks and numbers of a drilled hole (docs/holes.md).
Drill plan_drill(const CutContext& c, double safe) {
  const Job& job = c.job;
  const Entity& e = c.entity;
  const CutParams& cp = c.params;
  const std::string u = to_string(job.units);
  const auto at = [&](const std::string& path) { return Place::in_json(job.source, path); };
  const auto key = [&](auto member, const char* name) {
    return key_at(e, (e.params.*member).has_value(), (job.params.*member).has_value(), name);
  };
  const auto drill_key = [&](auto member, const char* name) {
    return key_at(e, (e.params.drill.*member).has_value(), (job.params.drill.*member).has_value(), name);
  };
  Drill d;
  d.shape = shape_of(c);
  const ToolEntry* t = job.tools.empty() ? nullptr : job.tools.find(cp.tool);
  const std::string tool = "tool " + std::to_string(cp.tool);
  if (t && t->shape != ToolType::drill && !t->center_cutting)
    throw InputError(errc::job_hole, at(key(&JobParams::tool, "tool")),
                     tool + " is a " + to_string(t->shape) +
                         " that does not cut at its centre: it cannot drill; pick a drill, or give the tool "
                         "\"center_cutting\": true");
  d.diameter = t ? std::optional<double>(t->diameter) : cp.tool_diameter;
  if (d.shape.diameter) {
    const double want = *d.shape.diameter;
    if (!d.diameter)
      throw InputError(errc::job_hole, at(e.json_path()),
                       e.label() + " is a circle of diameter " + fmt_num(want) + " " + u +
                           ": give the drill's diameter (\"tool_diameter\", or a tool table) so that bezcam can "
                           "check that it drills this hole");
    if (std::abs(*d.diameter - want) > c.tolerance)
      throw InputError(errc::job_hole,
                       at(t ? key(&JobParams::tool, "tool") : key(&JobParams::tool_diameter, "tool_diameter")),
                       e.label() + " is a circle of diameter " + fmt_num(want) + " " + u + ", and " + tool +
                           " drills " + fmt_num(*d.diameter) + " " + u +
                           (t ? " (" + tool_entry_path("tools", std::to_string(t->number)) + ".diameter)"
                              : std::string(" (tool_diameter)")) +
                           ", beyond the tolerance " + fmt_num(c.tolerance) + " " + u +
                           ": pick a drill of the circle's diameter, or bore it (\"operation\": \"bore\")");
  }
  // The tip below the full diameter: (D / 2) / tan(point angle / 2).
  double tip = 0;
  if (t && t->shape == ToolType::drill && t->point_angle)
    tip = t->diameter / 2 / std::tan(*t->point_angle * std::numbers::pi / 360);
  const bool to_tip = cp.drill.to_tip.value_or(false);
  const double bottom = quantize(to_tip ? cp.cut_z : cp.cut_z - tip, c.decimals);
  if (t && t->flute_length && cp.top_z - bottom > *t->flute_length * (1 + 1e-9))
    throw InputError(errc::job_hole, at(key(&JobParams::cut_z, "cut_z")),
                     "the hole " + e.label() + " is " + fmt_num(cp.top_z - bottom) + " " + u + " deep (top_z " +
                         fmt_num(cp.top_z) + " to the tip at " + fmt_num(bottom) +
                         (to_tip ? "" : ", the point included") + "), deeper than the flutes of " + tool + ", " +
                         fmt_num(*t->flute_length) + " " + u + " (" +
                         tool_entry_path("tools", std::to_string(t->number)) +
                         ".flute_length): the chips cannot get out; drill it with a longer drill, or less deep");
  double r = cp.drill.retract_z ? *cp.drill.retract_z : cp.clearance ? cp.top_z + *cp.clearance : cp.safe_z;
  r = quantize(r, c.decimals);
  const std::string rk = drill_key(&DrillKeys::retract_z, "retract_z");
  if (r > safe)
    throw InputError(errc::job_hole, at(rk),
                     "the R plane z = " + fmt_num(r) + " is above safe_z (" + fmt_num(safe) +
                         "): the cycle starts at safe Z; give retract_z at most safe_z");
  if (r < cp.top_z)
    throw InputError(errc::job_hole, at(rk),
                     "the R plane z = " + fmt_num(r) + " is below top_z (" + fmt_num(cp.top_z) +
                         "): the drill would rapid into the stock; give retract_z at or above top_z");
  if (!(r > bottom))
    throw InputError(errc::job_hole, at(key(&JobParams::cut_z, "cut_z")),
                     "the hole's bottom z = " + fmt_num(bottom) + " is not below the R plane (" + fmt_num(r) + ")");
  const double q = quantize(cp.drill.peck.value_or(0), c.decimals);
  const double dwell = quantize(cp.drill.dwell.value_or(0), 3);
  const bool chip_break = cp.drill.chip_break.value_or(false);
  if (cp.drill.peck && *cp.drill.peck > 0 && !(q > 0))
    throw InputError(errc::job_hole, at(drill_key(&DrillKeys::peck, "peck")),
                     "a peck of " + fmt_num(*cp.drill.peck) + " " + u + " prints as 0: give a larger peck, or 0");
  if (chip_break && !(q > 0))
    throw InputError(errc::job_hole, at(drill_key(&DrillKeys::chip_break, "chip_break")),
                     "chip_break (G73) breaks the chip between pecks: give a \"peck\" > 0 too");
  if (q > 0 && dwell > 0)
    throw InputError(errc::job_hole, at(drill_key(&DrillKeys::dwell, "dwell")),
                     "a dwell at the bottom is G82, which does not peck (G83 and G73 take no dwell): give either "
                     "\"peck\" or \"dwell\"");
  if (q > 0 && 4 + 3 * std::ceil((r - bottom) / q) > static_cast<double>(kMaxCycleMoves))
    throw InputError(errc::job_hole, at(drill_key(&DrillKeys::peck, "peck")),
                     "a peck of " + fmt_num(q) + " " + u +
                         " makes more moves than a controller expands from one "
                         "cycle (docs/limits.md): give a larger peck");
  CannedCycle& cy = d.cycle;
  cy.at = quantize(Vec3{d.shape.centre.x, d.shape.centre.y, 0}, c.decimals);
  cy.code = q > 0 ? (chip_break ? 73 : 83) : dwell > 0 ? 82 : 81;
  cy.r = r;
  cy.z = bottom;
  cy.q = q;
  cy.p = dwell;
  cy.feed = cp.plunge_feed;
  return d;
}

// The motion of the cycle from `pos` (its Z the initial level), move for
// move as the reader runs it (gcode/canned_cycles.cpp: position across at
// the drill's height, rapid to R, pecks, feed to the bottom, dwell, back).
void expand_cycle(CutContext& c, MotionState& ms, const CannedCycle& cy) {
  Program& p = c.program;
  const int entity = static_cast<int>(c.entity.index);
  const MachineProfile& m = c.machine;
  const double delta = (cy.code == 73 ? m.cycles.g73_retract_mm : m.cycles.g83_clearance_mm) / mm_per_unit(p.units);
  const double initial = ms.pos.z, clear = cy.to_r ? cy.r : initial;
  bool known = ms.pos_known;
  const auto go = [&](bool rapid, double z, double dwell = 0) {
    const Vec3 to = quantize(Vec3{cy.at.x, cy.at.y, z}, c.decimals);
    if (rapid && known && to == ms.pos) return;
    Move mv{RapidMove{}, entity, true};
    if (!rapid) {
      LineMove l;
      l.to = to;
      l.feed = cy.feed;
      mv.what = l;
    } else {
      RapidMove rm;
      rm.to = to;
      mv.what = rm;
    }
    p.moves.push_back(mv);
    if (dwell > 0) p.moves.push_back(Move{Dwell{dwell}, entity, true});
    ms.pos = to;
    known = true;
  };
  go(true, initial);
  go(true, cy.r);
  if (cy.code == 73 || cy.code == 83)
    for (double depth = cy.r - cy.q; depth > cy.z; depth -= cy.q) {
      go(false, depth);
      if (cy.code == 83) go(true, cy.r);
      go(true, depth + delta);
    }
  go(false, cy.z, cy.p);
  go(true, clear);
  ms.pos_known = true;
}

// The drilled hole: the cycle, its motion, and its report.
void emit_drill(CutContext& c, MotionState& ms, EntityReport& r, double safe, bool prev_joins, bool next_joins) {
  Program& p = c.program;
  const int entity = static_cast<int>(c.entity.index);
  Drill d = plan_drill(c, safe);
  d.cycle.to_r = prev_joins || next_joins;
  if (!prev_joins && (!ms.pos_known || ms.pos.z != safe)) {
    RapidMove up;
    up.to = {ms.pos_known ? ms.pos.x : 0, ms.pos_known ? ms.pos.y : 0, safe};
    if (!ms.pos_known) up.axes = kAxisZ;
    p.moves.push_back({up, entity});
    ms.pos = up.to;
  }
  // An unknown XY (after the tool change position) is where the cycle's
  // first move takes the drill: across at the initial level.
  p.moves.push_back({d.cycle, entity});
  expand_cycle(c, ms, d.cycle);
  if (d.cycle.r < safe) r.clear_z = d.cycle.r;
  if (d.cycle.to_r && !next_joins) {
    RapidMove up;
    up.to = {ms.pos.x, ms.pos.y, safe};
    p.moves.push_back({up, entity});
    ms.pos = up.to;
  }
  r.blocks = 1;
  r.tool_width = d.diameter.value_or(0);
  // The hole's axis where the centre is, up to the printed digits; a
  // circle's centre within its proven distance from the curve.
  r.measured = dist_xy(d.cycle.at, d.shape.centre);
  r.bound = d.shape.bound + max_rounding_displacement(c.decimals, 2);
}

}  // namespace

bool holes_join(const Job& job, const MachineProfile& m, const Entity& e, const Entity* next, int decimals) {
  if (!next) return false;
  try {
    const CutParams a = cut_params(job, e, m), b = cut_params(job, *next, m);
    if (a.pocket.operation != Operation::drill || b.pocket.operation != Operation::drill) return false;
    if (!a.after.empty() || !b.before.empty()) return false;
    if (a.tool != b.tool || a.spindle_rpm != b.spindle_rpm || a.coolant != b.coolant ||
        quantize(a.safe_z, decimals) != quantize(b.safe_z, decimals))
      return false;
    const auto r_of = [&](const CutParams& cp) {
      return quantize(cp.drill.retract_z ? *cp.drill.retract_z
                      : cp.clearance     ? cp.top_z + *cp.clearance
                                         : cp.safe_z,
                      decimals);
    };
    return r_of(a) == r_of(b) && r_of(a) < quantize(a.safe_z, decimals);
  } catch (const InputError&) {
    return false;  // refused when its turn comes
  }
}

bool cut_hole(CutContext& c, MotionState& ms, double safe, bool prev_joins, bool next_joins, bool arcs) {
  const CutParams& cp = c.params;
  const Entity& e = c.entity;
  if (!is_hole(cp)) {
    if (e.point)
      throw InputError(errc::job_operation,
                       Place::in_json(c.job.source, e.json_path() + (e.params.pocket.operation ? ".operation" : "")),
                       "a point is a hole: give it \"operation\": \"drill\" (or the job's \"operation\")");
    return false;
  }
  Program& p = c.program;
  const int entity = static_cast<int>(e.index);
  change_tool_and_spindle(p, c.machine, cp, safe, ms, -1);
  EntityReport r;
  r.label = e.label();
  r.entity = entity;
  r.type = e.type;
  r.tool = cp.tool;
  r.length = e.curve.pieces.empty() ? 0 : e.curve.length();
  r.degree = e.curve.pieces.empty() ? 0 : e.curve.max_degree();
  const bool drill = cp.pocket.operation == Operation::drill;
  p.moves.push_back({Comment{"entity " + e.label() + ": " + e.type + ", " + (drill ? "drilled" : "bored")}});
  for (const auto& line : cp.before)
    p.moves.push_back({Verbatim{expand_entity_template(line, e, cp, p.decimals)}, entity});
  if (drill) {
    emit_drill(c, ms, r, safe, prev_joins, next_joins);
  } else {
    const HoleShape h = shape_of(c);
    const double clear = cp.clearance ? std::min(safe, quantize(cp.top_z + *cp.clearance, p.decimals)) : safe;
    emit_bore(c, ms, r, h, safe, clear, arcs);
  }
  for (const auto& line : cp.after)
    p.moves.push_back({Verbatim{expand_entity_template(line, e, cp, p.decimals)}, entity});
  p.max_measured = std::max(p.max_measured, r.measured);
  p.max_bound = std::max(p.max_bound, r.bound);
  p.entities.push_back(r);
  return true;
}

}  // namespace bezcam::detail
