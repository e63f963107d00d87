// The setup sheet's figures, from the program the G-code is printed from:
// its tools, its cycle time and its chord error, said as the program's
// header says them.
#include "bezcam/report/setup_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/gcode/writer.hpp"
#include "bezcam/machine/motion.hpp"

namespace bezcam {

double sheet_cycle_seconds(const SetupSheetInput& in) {
  const Program& p = *in.program;
  const MachineProfile& m = *in.machine;
  if (m.motion)  // as the header gives it (gcode/convert.hpp)
    return program_cycle_time_s(p, m,
                                in.plan ? *in.plan : plan_motion(program_timeline(p), *m.motion, PlanDetail::summary));
  return motion_totals(program_motion(p), m.max_feed_mm_min / mm_per_unit(p.units)).time_s();
}

std::string sheet_cycle_time(const SetupSheetInput& in) {
  return cycle_time_words(*in.machine, sheet_cycle_seconds(in), in.program->units);
}

std::string sheet_chord_error(const Program& p) {
  const char* u = to_string(p.units);
  const auto sig = [](double v) { return format_significant(v, 4); };
  return "tolerance " + format_significant(p.tolerance, 6) + " " + u + "; largest deviation measured " +
         measured_text(p.max_measured, p.max_bound, p.tolerance, sig) + " " + u + ", proven bound " +
         format_bound(p.max_bound, 4) + " " + u + ", rounding included";
}

std::vector<SheetTool> sheet_tools(const SetupSheetInput& in) {
  const Program& p = *in.program;
  const Job& job = *in.job;
  const std::vector<MotionBlock> motion = program_motion(p);
  // Per entity: its deepest cutting point and its time.
  const size_t n = job.entities.size();
  std::vector<double> deepest(n, std::numeric_limits<double>::infinity()), time(n, 0.0);
  for (const MotionBlock& b : motion) {
    if (b.entity < 0 || static_cast<size_t>(b.entity) >= n || !is_feed(b)) continue;
    double z = std::min(b.from.z, b.to.z);
    if (b.kind != BlockKind::linear)  // curved blocks may dip between their ends
      for (int i = 1; i < 16; ++i) z = std::min(z, evaluate_block(b, i / 16.0).z);
    deepest[static_cast<size_t>(b.entity)] = std::min(deepest[static_cast<size_t>(b.entity)], z);
  }
  const bool planned = in.plan && in.plan->blocks.size() == in.plan->motion.size();
  if (planned) {
    for (size_t i = 0; i < in.plan->motion.size(); ++i)
      if (const int e = in.plan->motion[i].entity; e >= 0 && static_cast<size_t>(e) < n)
        time[static_cast<size_t>(e)] += in.plan->blocks[i].time_s;
  } else {
    const double rapid = in.machine->max_feed_mm_min / mm_per_unit(p.units);
    for (size_t e = 0; e < n; ++e) time[e] = motion_totals(motion, rapid, static_cast<int>(e)).time_s();
  }

  std::vector<SheetTool> out;
  for (const EntityReport& r : p.entities) {
    auto it = std::find_if(out.begin(), out.end(), [&](const SheetTool& t) { return t.number == r.tool; });
    if (it == out.end()) {
      SheetTool t;
      t.number = r.tool;
      t.top_z = -std::numeric_limits<double>::infinity();
      t.deepest_z = std::numeric_limits<double>::infinity();
      const auto jt =
          std::find_if(p.tools.begin(), p.tools.end(), [&](const JobTool& j) { return j.number == r.tool; });
      if (jt != p.tools.end()) {
        t.shape = to_string(jt->shape);
        t.diameter = jt->diameter;
        if (jt->entry) {
          t.corner_radius = jt->entry->corner_radius;
          t.angle = jt->entry->angle ? jt->entry->angle : jt->entry->point_angle;
          t.flute_length = jt->entry->flute_length;
        }
      } else {
        t.shape = to_string(ToolType::flat);
      }
      out.push_back(t);
      it = out.end() - 1;
    }
    it->entities.push_back(r.label);
    if (r.entity < 0 || static_cast<size_t>(r.entity) >= n) continue;
    const size_t e = static_cast<size_t>(r.entity);
    it->top_z = std::max(it->top_z, cut_params(job, job.entities[e], *in.machine).top_z);
    it->deepest_z = std::min(it->deepest_z, deepest[e]);
    it->time_s += time[e];
  }
  for (SheetTool& t : out) {
    if (!std::isfinite(t.top_z)) t.top_z = 0;
    if (!std::isfinite(t.deepest_z)) t.deepest_z = t.top_z;
  }
  return out;
}

}  // namespace bezcam
