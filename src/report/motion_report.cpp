#include "bezcam/report/motion_report.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "bezcam/gcode/number_format.hpp"
#include "plan_json.hpp"

namespace bezcam {

namespace {

const char* kind_name(BlockKind k) {
  switch (k) {
    case BlockKind::rapid: return "rapid";
    case BlockKind::linear: return "line";
    case BlockKind::arc_cw: return "arc-cw";
    case BlockKind::arc_ccw: return "arc-ccw";
    case BlockKind::nurbs: return "nurbs";
    case BlockKind::bezier: return "bezier";
  }
  return "?";
}

}  // namespace

std::string format_seconds(double s) {
  char b[64];
  if (s < 60) {
    std::snprintf(b, sizeof b, "%.2f s", s);
  } else if (s < 3600) {
    std::snprintf(b, sizeof b, "%d min %04.1f s", static_cast<int>(s / 60), std::fmod(s, 60.0));
  } else {
    const long w = std::lround(s);
    std::snprintf(b, sizeof b, "%ld h %02ld min %02ld s", w / 3600, w / 60 % 60, w % 60);
  }
  return b;
}

std::string motion_report_json(const MotionPlan& plan, const std::string& program, const std::string& machine) {
  const double mm = mm_per_unit(plan.units);
  nlohmann::ordered_json j;
  j["bezcam_motion"] = 1;
  j["program"] = program;
  j["machine"] = machine;
  j["units"] = to_string(plan.units);
  j["period_s"] = plan.period_s;
  detail::put_plan_figures(j, planned_summary(plan));
  j["max_path_deviation_mm"] = detail::round_to(plan.max_path_deviation * mm, 1e-6);
  j["max_path_deviation_line"] = plan.max_deviation_line;
  nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
  for (const PlannedBlock& b : plan.blocks) {
    nlohmann::ordered_json o;
    o["line"] = b.line;
    if (b.first_line != b.line) o["first_line"] = b.first_line;
    o["kind"] = kind_name(b.kind);
    o["length"] = detail::round_to(b.length, 1e-6);
    o["programmed_feed"] = detail::round_to(b.programmed_feed, 1e-3);
    o["peak_feed"] = detail::round_to(b.peak_feed, 1e-3);
    o["time_s"] = detail::round_to(b.time_s, 1e-6);
    if (b.peak_feed < b.programmed_feed * (1 - 1e-6)) o["limit"] = to_string(b.limit);
    if (b.starved) o["starved"] = true;
    if (b.clamped) o["clamped"] = true;
    blocks.push_back(std::move(o));
  }
  j["blocks"] = std::move(blocks);
  return j.dump(1) + "\n";
}

std::string motion_summary_text(const MotionPlan& plan, const std::string& what) {
  const double mm = mm_per_unit(plan.units);
  std::string s = "bezcam: " + what + ": cycle " + format_seconds(plan.cycle_time_s) + " (cutting " +
                  format_seconds(plan.cutting_time_s) + ", rapids " + format_seconds(plan.rapid_time_s);
  if (plan.pause_time_s > 0) s += ", pauses " + format_seconds(plan.pause_time_s);
  s += "); at the programmed feeds with no acceleration " + format_seconds(plan.programmed_feed_time_s) + "\n";
  char b[256];
  std::snprintf(b, sizeof b,
                "  mean feed %.0f %% of programmed; %zu starved block%s; corners within %.4f mm of the program\n",
                plan.mean_feed_ratio * 100, plan.starved_blocks, plan.starved_blocks == 1 ? "" : "s",
                plan.max_path_deviation * mm);
  s += b;
  if (plan.clamped_blocks > 0) {
    int first = 0;
    for (const PlannedBlock& pb : plan.blocks)
      if (pb.clamped) {
        first = pb.line;
        break;
      }
    s += "  warning: " + std::to_string(plan.clamped_blocks) + " block" + (plan.clamped_blocks == 1 ? "" : "s") +
         " ask a feed the axes cannot reach (first at line " + std::to_string(first) +
         "): run at the axes' limit instead\n";
  }
  return s;
}

std::string motion_samples_tsv(const MotionPlan& plan) {
  std::string out = "t\tx\ty\tz\tfeed\n";
  out.reserve(out.size() + 56 * static_cast<size_t>(plan.cycle_time_s / plan.period_s + 2));
  char b[160];
  auto fix = [](double v) { return std::abs(v) < 5e-7 ? 0.0 : v; };
  sample_plan(plan, [&](double t, const Vec3& p, double feed) {
    const int n = std::snprintf(b, sizeof b, "%.6f\t%.6f\t%.6f\t%.6f\t%.3f\n", t, fix(p.x), fix(p.y), fix(p.z),
                                std::abs(feed) < 5e-4 ? 0.0 : feed);
    out.append(b, static_cast<size_t>(n));
  });
  return out;
}

}  // namespace bezcam
