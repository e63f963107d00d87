#include "bezcam/report/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <future>
#include <nlohmann/json.hpp>
#include <optional>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/report/motion_report.hpp"
#include "output_choice.hpp"
#include "plan_json.hpp"

namespace bezcam {

void GcodeCounts::add(std::string_view piece) {
  if (piece.empty()) return;
  bytes += piece.size();
  newlines += static_cast<size_t>(std::count(piece.begin(), piece.end(), '\n'));
  last = piece.back();
}

namespace {

// The program's and each entity's lengths and feed times (rapid times are
// added with the rate, in make_report()).
struct ProgramTotals {
  MotionTotals total;
  std::vector<MotionTotals> by_entity;
};

// The totals in one pass over the blocks as they are made, none kept (a
// pass per entity would make a job of many entities quadratic), each block
// measured once; the sums in block order, as motion_totals() makes them.
ProgramTotals program_totals(const Program& p) {
  ProgramTotals r;
  const auto add = [](MotionTotals& t, const MotionTotals& one) {
    t.feed_length += one.feed_length;
    t.rapid_length += one.rapid_length;
    t.feed_time_s += one.feed_time_s;
    t.feed_blocks += one.feed_blocks;
    t.rapid_blocks += one.rapid_blocks;
  };
  for_each_motion_block(p, [&](const MotionBlock& b, size_t) {
    const MotionTotals one = motion_totals(std::span(&b, 1), 0);
    add(r.total, one);
    if (b.entity < 0) return;
    if (r.by_entity.size() <= static_cast<size_t>(b.entity)) r.by_entity.resize(b.entity + 1);
    add(r.by_entity[b.entity], one);
  });
  return r;
}

ProgramReport report_of(const Program& p, const MachineProfile& m, const GcodeCounts& text, const MotionPlan* plan,
                        const Timeline* read_back, ProgramTotals totals);

}  // namespace

ProgramReport make_report(const Program& p, const MachineProfile& m, std::string_view gcode, const MotionPlan* plan) {
  GcodeCounts counts;
  counts.add(gcode);
  // The printed program, read back as the controller reads it; without
  // text, the program's moves.
  std::optional<Timeline> back;
  if (m.motion && !plan && !gcode.empty()) {
    const MachineProfile set_up = with_compensation_registers(m, p);
    back = read_timeline(gcode, &set_up);
  }
  return make_report(p, m, counts, plan, back ? &*back : nullptr);
}

ProgramReport write_and_report(const Program& p, const MachineProfile& m, const MotionPlan* plan,
                               const GcodeSink& sink) {
  // The moves' totals need no text: summed on another core while the text
  // is written (both only read the program).
  std::future<ProgramTotals> totals = std::async(std::launch::async, [&p] { return program_totals(p); });
  GcodeCounts counts;
  std::optional<MachineProfile> set_up;
  std::optional<TimelineReader> back;
  if (m.motion && !plan) back.emplace(&set_up.emplace(with_compensation_registers(m, p)));
  write_gcode(p, m, plan, [&](std::string_view piece) {
    counts.add(piece);
    if (back) back->feed(piece);
    sink(piece);
  });
  std::optional<Timeline> tl;
  if (back && counts.bytes) tl = back->finish();
  return report_of(p, m, counts, plan, tl ? &*tl : nullptr, totals.get());
}

ProgramReport make_report(const Program& p, const MachineProfile& m, const GcodeCounts& text, const MotionPlan* plan,
                          const Timeline* read_back) {
  return report_of(p, m, text, plan, read_back, program_totals(p));
}

namespace {

ProgramReport report_of(const Program& p, const MachineProfile& m, const GcodeCounts& text, const MotionPlan* plan,
                        const Timeline* read_back, ProgramTotals totals) {
  ProgramReport r;
  r.job = p.job_name;
  r.machine = p.machine;
  r.units = p.units;
  r.output = p.output;
  r.output_name = output_name(p);
  r.tolerance = p.tolerance;
  r.decimals = p.decimals;
  r.max_measured = p.max_measured;
  r.max_bound = p.max_bound;
  r.measurement_resolution = kMeasureResolution * p.tolerance;
  r.warnings = p.warnings;
  r.order = p.order;
  // The profile has no rapid rate of its own: its maximum feed is the
  // fastest the machine is known to move.
  r.rapid_rate = m.max_feed_mm_min / mm_per_unit(p.units);
  r.rapid_rate_basis = "the maximum feed of machine \"" + m.name + "\" (max_feed_mm_min " + fmt_num(m.max_feed_mm_min) +
                       "); the controller's true rapid rate may differ";
  r.total = totals.total;
  const std::vector<MotionTotals>& by_entity = totals.by_entity;
  const auto timed = [&](MotionTotals t) {
    if (r.rapid_rate > 0) t.rapid_time_s = 60 * t.rapid_length / r.rapid_rate;
    return t;
  };
  r.total = timed(r.total);
  for (const EntityReport& e : p.entities)
    r.entities.push_back(
        {e, timed(e.entity >= 0 && static_cast<size_t>(e.entity) < by_entity.size() ? by_entity[e.entity]
                                                                                    : MotionTotals{})});
  if (m.motion && plan) {
    r.planned = planned_summary(*plan);  // the program's one plan (convert())
  } else if (m.motion) {
    r.planned =
        planned_summary(read_back ? plan_motion(*read_back, *m.motion) : plan_motion(program_timeline(p), *m.motion));
  }
  if (r.planned) r.path_bound_s = exact_path_bound_s(p);
  r.gcode_bytes = text.bytes;
  r.gcode_lines = text.lines();
  return r;
}

}  // namespace

ProgramReport::Planned planned_summary(const MotionPlan& plan) {
  ProgramReport::Planned q;
  q.cycle_time_s = plan.cycle_time_s;
  q.cutting_time_s = plan.cutting_time_s;
  q.rapid_time_s = plan.rapid_time_s;
  q.pause_time_s = plan.pause_time_s;
  q.programmed_feed_time_s = plan.programmed_feed_time_s;
  q.mean_feed_ratio = plan.mean_feed_ratio;
  q.max_path_deviation = plan.max_path_deviation;
  q.starved_blocks = plan.starved_blocks;
  q.clamped_blocks = plan.clamped_blocks;
  q.path_time_s = plan.path_time_s;
  return q;
}

namespace {

// `bound`: the exact paths' time-optimal bound (0: none).
nlohmann::ordered_json planned_json(const ProgramReport::Planned& q, double bound) {
  nlohmann::ordered_json j;
  detail::put_plan_figures(j, q);
  j["max_path_deviation"] = detail::round_to(q.max_path_deviation, 1e-9);
  if (bound > 0 && q.path_time_s > 0) {
    j["path_time_s"] = detail::round_to(q.path_time_s, 1e-6);
    j["path_bound_ratio"] = detail::round_to(q.path_time_s / bound, 1e-6);
  }
  return j;
}

// A lower bound rounded down to `q`, so that the figure written stays one.
double floor_to(double v, double q) { return std::floor(v / q) / std::round(1 / q); }

// A pocket's certificate (cam/pocket_check.hpp); `keep` is r + stock.
nlohmann::ordered_json pocket_json(const PocketCertificate& c, double keep) {
  auto point = [](const Vec3& p) { return nlohmann::ordered_json::array({p.x, p.y}); };
  nlohmann::ordered_json j;
  j["uncut_area"] = c.uncut_area;
  j["uncut_limit"] = c.uncut_limit;
  if (c.uncut_area > 0) j["uncut_at"] = point(c.uncut_at), j["uncut_z"] = c.uncut_z;
  j["covered"] = c.covered();
  j["unreachable_area"] = c.unreachable_area;
  auto& places = j["unreachable"] = nlohmann::ordered_json::array();
  for (const auto& u : c.unreachable) places.push_back({{"at", point(u.at)}, {"area", u.area}});
  j["reachable_area"] = c.reachable_area;
  j["region_area"] = c.region_area;
  j["wall_distance"] = c.wall_distance;
  j["wall_distance_asked"] = keep;
  j["wall_at"] = point(c.wall_at);
  j["largest_engagement_deg"] = c.engagement_deg;
  j["engagement_at"] = point(c.engagement_at);
  j["rapids_through_material"] = c.rapids_in_material;
  j["check_cell"] = c.cell;
  return j;
}

nlohmann::ordered_json totals_json(const MotionTotals& t) {
  nlohmann::ordered_json j;
  j["feed_length"] = t.feed_length;
  j["rapid_length"] = t.rapid_length;
  j["feed_blocks"] = t.feed_blocks;
  j["rapid_blocks"] = t.rapid_blocks;
  j["feed_time_s"] = t.feed_time_s;
  j["rapid_time_s"] = t.rapid_time_s;
  j["estimated_time_s"] = t.time_s();
  return j;
}

}  // namespace

std::string report_json(const ProgramReport& r) {
  nlohmann::ordered_json j;
  j["bezcam_report"] = 1;
  j["job"] = r.job;
  j["machine"] = r.machine;
  j["units"] = to_string(r.units);
  j["output"] = r.output_name;
  j["tolerance"] = r.tolerance;
  j["decimals"] = r.decimals;
  j["max_measured_deviation"] = r.max_measured;
  j["max_proven_bound"] = r.max_bound;
  j["measurement_resolution"] = r.measurement_resolution;
  auto& ents = j["entities"] = nlohmann::ordered_json::array();
  for (const auto& e : r.entities) {
    nlohmann::ordered_json x;
    x["index"] = e.report.entity;
    x["label"] = e.report.label;
    x["kind"] = e.report.type;
    x["degree"] = e.report.degree;
    x["length"] = e.report.length;
    x["blocks"] = e.report.blocks;
    if (r.output_name != to_string(r.output)) x["output"] = to_string(e.report.output);
    x["measured_deviation"] = e.report.measured;
    x["proven_bound"] = e.report.bound;
    if (e.report.time_bound_s > 0) x["time_bound_s"] = floor_to(e.report.time_bound_s, 1e-6);
    x["motion"] = totals_json(e.motion);
    if (e.report.pocket) x["pocket"] = pocket_json(*e.report.pocket, e.report.offset);
    ents.push_back(std::move(x));
  }
  auto& prog = j["program"] = totals_json(r.total);
  prog["rapid_rate"] = r.rapid_rate;
  prog["rapid_rate_basis"] = r.rapid_rate_basis;
  prog["time_note"] = "feeds and rapids at their rates; acceleration, dwells and tool changes not counted";
  if (r.gcode_bytes > 0) {
    prog["gcode_lines"] = r.gcode_lines;
    prog["gcode_bytes"] = r.gcode_bytes;
  }
  if (r.planned) {
    // The estimate that counts: the machine's motion model (docs/motion.md).
    auto& pl = prog["planned"] = planned_json(*r.planned, r.path_bound_s);
    pl["basis"] = "the motion model of machine \"" + r.machine +
                  "\": acceleration, corners blended within its tolerance, block rate, tool changes and dwells";
    if (r.path_bound_s > 0) {
      prog["path_bound_s"] = floor_to(r.path_bound_s, 1e-6);
      prog["path_bound_basis"] =
          "the shortest time the machine could follow the exact curves cut along their line, from rest to rest at "
          "their feeds within its axes' velocity and acceleration (no jerk); rapids, plunges, retracts and pauses "
          "not counted";
    }
  }
  if (!r.alternatives.empty()) {
    auto& alt = j["compare_outputs"] = nlohmann::ordered_json::array();
    for (const auto& a : r.alternatives) {
      nlohmann::ordered_json x;
      x["output"] = a.best ? "best" : to_string(a.output);
      x["cutting_blocks"] = a.blocks;
      x["gcode_bytes"] = a.gcode_bytes;
      x["planned"] = planned_json(a.planned, r.path_bound_s);
      alt.push_back(std::move(x));
    }
  }
  if (r.choice) j["output_choice"] = detail::output_choice_json(r);
  if (r.order) {
    auto& o = j["order"];
    o["mode"] = "shortest";
    o["nested_contours"] = r.order->nested;
    o["rapid_xy_as_written"] = r.order->rapid_as_written;
    o["rapid_xy_planned"] = r.order->rapid_planned;
    o["rapid_xy_saved"] = r.order->rapid_as_written - r.order->rapid_planned;
    o["tool_changes_as_written"] = r.order->tool_changes_as_written;
    o["tool_changes_planned"] = r.order->tool_changes_planned;
  }
  j["warnings"] = r.warnings;
  return j.dump(2) + "\n";
}

std::string report_text(const ProgramReport& r, size_t max_entities) {
  const std::string u = std::string(" ") + to_string(r.units);
  auto measured = [&](double m, double bound) {
    return measured_text(m, bound, r.tolerance, [](double v) { return format_significant(v, 3); }) + u;
  };
  size_t blocks = 0;
  for (const auto& e : r.entities) blocks += e.report.blocks;
  const size_t n = r.entities.size();
  std::string s = "bezcam: " + std::to_string(n) + (n == 1 ? " entity, " : " entities, ") + std::to_string(blocks) +
                  " cutting block" + (blocks == 1 ? "" : "s") + " for machine " + r.machine + " (output " +
                  r.output_name + ", tolerance " + format_significant(r.tolerance, 6) + u + ")\n";
  for (size_t i = 0; i < n && i < max_entities; ++i) {
    const EntityReport& e = r.entities[i].report;
    s += "  " + e.label + ": " + e.type + ", degree " + std::to_string(e.degree) + ", length " +
         format_significant(e.length, 6) + u + ", " + std::to_string(e.blocks) + " block" + (e.blocks == 1 ? "" : "s") +
         (r.output_name != to_string(r.output) ? std::string(" in ") + to_string(e.output) : "") + ", deviation " +
         measured(e.measured, e.bound) + " (proven bound " + format_bound(e.bound, 3) + u + ")\n";
    if (e.pocket)
      for (const auto& line :
           certificate_lines(e.label, *e.pocket, e.tool_width / 2, e.offset - e.tool_width / 2, to_string(r.units)))
        s += "    " + line + "\n";
  }
  if (n > max_entities)
    s += "  ... and " + std::to_string(n - max_entities) + " more entit" + (n - max_entities == 1 ? "y" : "ies") +
         "; the largest deviation measured is " + measured(r.max_measured, r.max_bound) + "\n";
  const double t = r.total.time_s();
  char tbuf[64];
  if (t < 60)
    std::snprintf(tbuf, sizeof tbuf, "%.1f s", t);
  else if (t < 3600)
    std::snprintf(tbuf, sizeof tbuf, "%d min %02d s", int(t / 60), int(std::fmod(t, 60)));
  else
    std::snprintf(tbuf, sizeof tbuf, "%d h %02d min", int(t / 3600), int(std::fmod(t, 3600) / 60));
  s += "  program: " + format_significant(r.total.feed_length, 6) + u + " at feed, " +
       format_significant(r.total.rapid_length, 6) + u + " rapid";
  if (r.planned) {
    const auto& q = *r.planned;
    char b[160];
    std::snprintf(b, sizeof b, "; mean feed %.0f %% of programmed, %zu starved block%s", q.mean_feed_ratio * 100,
                  q.starved_blocks, q.starved_blocks == 1 ? "" : "s");
    s += "; cycle " + format_seconds(q.cycle_time_s) + " on machine " + r.machine + "'s motion model (" +
         format_seconds(q.programmed_feed_time_s) + " at the programmed feeds with no acceleration)" + b + "\n";
    if (r.path_bound_s > 0 && q.path_time_s > 0) {
      std::snprintf(b, sizeof b, " (x%.3f)", q.path_time_s / r.path_bound_s);
      s += "  cutting along the curves " + format_time(q.path_time_s) + "; the exact path's bound on this machine " +
           format_time(r.path_bound_s, true) + b + "\n";
    }
  } else {
    s += std::string("; about ") + tbuf + " (rapids at " + format_significant(r.rapid_rate, 6) + u +
         "/min, no acceleration: machine " + r.machine + " has no motion model)\n";
  }
  s += detail::output_choice_text(r, max_entities);
  s += detail::alternatives_text(r);
  return s;
}

}  // namespace bezcam
