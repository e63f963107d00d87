// A bored hole (docs/holes.md): an end mill down a helix inside the
// circle, a full circle at the bottom, back to the centre and up. The tool
// centre's circle is r - R - stock_to_leave about the circle's centre,
// its radius printed no larger than that (the wall is never cut into by
// the rounding); the helix drops at most `step_down` (and the flute
// length) per turn, at the entry angle (3 degrees by default).
#include <cmath>
#include <numbers>

#include "bezcam/error.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "hole_cut.hpp"

namespace bezcam::detail {

namespace {

// The tool centre's circle: its centre and radius as printed.
struct BoreCircle {
  Vec3 centre;
  double radius = 0;
  double shortfall = 0;  // the radius asked minus the radius printed
};

BoreCircle plan_circle(const CutContext& c, const HoleShape& h, double tool_d) {
  const double want = *h.diameter / 2 - tool_d / 2 - c.params.stock_to_leave;
  BoreCircle b;
  b.centre = quantize(Vec3{h.centre.x, h.centre.y, 0}, c.decimals);
  b.radius = quantize(want, c.decimals);
  // Above by more than the arithmetic's error: one printed unit less.
  if (b.radius > want + 1e-9 * std::max(1.0, want))
    b.radius = quantize(b.radius - std::pow(10.0, -c.decimals), c.decimals);
  b.shortfall = std::abs(want - b.radius);
  return b;
}

double tool_diameter(const CutContext& c, const HoleShape& h) {
  const Job& job = c.job;
  const Entity& e = c.entity;
  const CutParams& cp = c.params;
  const std::string u = to_string(job.units);
  const ToolEntry* t = job.tools.empty() ? nullptr : job.tools.find(cp.tool);
  const std::string tool = "tool " + std::to_string(cp.tool);
  const std::string tool_at = e.params.tool ? e.json_path() + ".tool" : job.params.tool ? "job.tool" : e.json_path();
  if (!h.diameter)
    throw InputError(errc::job_hole, Place::in_json(job.source, e.json_path() + ".operation"),
                     "a bore cuts a circle, and " + e.label() +
                         " is a point: draw the hole as a circle, or drill it (\"operation\": \"drill\")");
  if (t && (t->shape == ToolType::drill || t->shape == ToolType::vee))
    throw InputError(errc::job_hole, Place::in_json(job.source, tool_at),
                     tool + " is a " + to_string(t->shape) +
                         ", which cannot cut sideways round a bore: pick an end mill, or drill the hole");
  const std::optional<double> d = t ? std::optional<double>(t->diameter) : cp.tool_diameter;
  if (!d)
    throw InputError(errc::job_hole, Place::in_json(job.source, e.json_path()),
                     "a bore needs the tool's diameter: give \"tool_diameter\" or a tool table");
  const double room = *h.diameter / 2 - *d / 2 - cp.stock_to_leave;
  if (!(room > c.tolerance))
    throw InputError(errc::job_hole,
                     Place::in_json(job.source, t ? tool_at
                                                  : (e.params.tool_diameter     ? e.json_path() + ".tool_diameter"
                                                     : job.params.tool_diameter ? std::string("job.tool_diameter")
                                                                                : e.json_path())),
                     e.label() + " is a circle of diameter " + fmt_num(*h.diameter) + " " + u + ", no larger than " +
                         tool + " (" + fmt_num(*d) + " " + u +
                         (cp.stock_to_leave > 0 ? " and the stock to leave" : "") +
                         "): the tool cannot move round inside it; bore it with a smaller end mill, or drill it");
  if (!(cp.cut_z < cp.top_z))
    throw InputError(errc::job_hole, Place::in_json(job.source, e.json_path() + ".cut_z"),
                     "the bore's bottom cut_z = " + fmt_num(cp.cut_z) + " is not below top_z = " + fmt_num(cp.top_z));
  return *d;
}

}  // namespace

void emit_bore(CutContext& c, MotionState& ms, EntityReport& r, const HoleShape& h, double safe, double clear,
               bool arcs) {
  Program& p = c.program;
  const CutParams& cp = c.params;
  const int entity = static_cast<int>(c.entity.index);
  const double tool_d = tool_diameter(c, h);
  const BoreCircle b = plan_circle(c, h, tool_d);
  const double top = quantize(cp.top_z, c.decimals), bottom = quantize(cp.cut_z, c.decimals);
  const bool ccw = cp.direction != CutDirection::conventional;
  const double angle =
      cp.pocket.entry && cp.pocket.entry->kind == PocketEntry::Kind::helix ? cp.pocket.entry->angle : 3;
  double drop = 2 * std::numbers::pi * b.radius * std::tan(angle * std::numbers::pi / 180);
  if (const auto pass = cp.pass_depth()) drop = std::min(drop, *pass);
  if (cp.flute_length) drop = std::min(drop, *cp.flute_length);
  const int turns = std::max(1, static_cast<int>(std::ceil((top - bottom) / drop - 1e-9)));
  // Chords of the circle within half the tolerance in lines mode.
  const double sag = c.tolerance / 2;
  const int chords = arcs ? 1
                          : std::max(2, static_cast<int>(std::ceil(
                                            std::numbers::pi / (2 * std::acos(std::max(-1.0, 1 - sag / b.radius))))));
  const Vec3 start{b.centre.x + b.radius, b.centre.y, top};
  approach(p, entity, start, safe, clear, cp.plunge_feed, ms);
  Vec3 at = start;
  double measured = 0;
  size_t blocks = 0;
  const auto point = [&](double theta, double z) {
    const double a = ccw ? theta : -theta;
    return quantize(Vec3{b.centre.x + b.radius * std::cos(a), b.centre.y + b.radius * std::sin(a), z}, c.decimals);
  };
  // Half a turn from `at` (angle k pi) to angle (k + 1) pi, z from z0 to z1.
  const auto half = [&](int k, double z0, double z1, double feed) {
    for (int j = 1; j <= chords; ++j) {
      const double s = static_cast<double>(j) / chords;
      Vec3 to = point((k + s) * std::numbers::pi, z0 + (z1 - z0) * s);
      if (j == chords) to = point((k + 1) * std::numbers::pi, z1);  // the half turns' ends exactly opposite
      measured = std::max(measured, std::abs(dist_xy(to, b.centre) - b.radius));
      if (arcs) {
        ArcMove m;
        m.to = to;
        m.center = {b.centre.x, b.centre.y, to.z};
        m.ccw = ccw;
        m.feed = feed;
        p.moves.push_back({m, entity});
      } else {
        // The chord's middle is nearer the centre than the circle by its sagitta.
        const Vec3 mid{(at.x + to.x) / 2, (at.y + to.y) / 2, 0};
        measured = std::max(measured, b.radius - dist_xy(mid, b.centre));
        LineMove l;
        l.to = to;
        l.feed = feed;
        p.moves.push_back({l, entity});
      }
      at = to;
      ++blocks;
    }
  };
  for (int k = 0; k < 2 * turns; ++k)
    half(k, quantize(top + (bottom - top) * k / (2 * turns), c.decimals),
         quantize(top + (bottom - top) * (k + 1) / (2 * turns), c.decimals), cp.plunge_feed);
  half(0, bottom, bottom, cp.feed);
  half(1, bottom, bottom, cp.feed);
  LineMove in;
  in.to = {b.centre.x, b.centre.y, bottom};
  in.feed = cp.feed;
  p.moves.push_back({in, entity});
  RapidMove up;
  up.to = {b.centre.x, b.centre.y, safe};
  p.moves.push_back({up, entity});
  ms.pos = up.to;
  ms.pos_known = true;
  if (b.radius > tool_d / 2 + c.tolerance)
    p.warnings.push_back(c.entity.label() + ": the bore leaves a core of diameter " +
                         fmt_num(2 * (b.radius - tool_d / 2)) + " " + to_string(c.job.units) +
                         " standing (the circle is more than twice the tool's diameter): it falls out of a hole "
                         "that goes through; clear a blind one as a pocket (\"operation\": \"pocket\")");
  r.blocks = blocks + 1;
  r.tool_width = tool_d;
  r.offset = tool_d / 2 + cp.stock_to_leave;
  if (clear < safe) r.clear_z = clear;
  // Against the tool centre's circle asked for: the printed radius's
  // shortfall, the printed points' rounding, the chords' sagitta, and the
  // circle's own distance from the drawn curve.
  const double sagitta = arcs ? 0 : b.radius * (1 - std::cos(std::numbers::pi / (2 * chords)));
  r.measured = measured + b.shortfall + dist_xy(b.centre, h.centre);
  r.bound = h.bound + b.shortfall + dist_xy(b.centre, h.centre) + sagitta + max_rounding_displacement(c.decimals, 2);
}

}  // namespace bezcam::detail
