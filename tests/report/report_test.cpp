// Reports: lengths and times from the motion (closed forms on hand-made
// programs), agreement with the program's own per-entity figures, and the
// JSON and human forms.
#include "bezcam/report/report.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"

namespace bezcam {
namespace {

enum class Kind { rapid, linear };
Move mv(Kind k, Vec3 to, double f, int entity, unsigned axes = 7) {
  Motion m;
  m.to = to;
  m.feed = f;
  m.axes = axes;
  if (k == Kind::rapid) return {RapidMove{m}, entity};
  return {LineMove{m}, entity};
}

// A 10 x 10 square cut at depth 1 after a retract and a rapid 10 away.
Program square_program() {
  Program p;
  p.machine = "test";
  p.units = Units::mm;
  p.tolerance = 0.01;
  p.moves = {mv(Kind::rapid, {0, 0, 5}, 0, 0, 4),    mv(Kind::rapid, {0, 0, 5}, 0, 0),
             mv(Kind::rapid, {10, 0, 5}, 0, 0),      mv(Kind::linear, {10, 0, -1}, 60, 0),
             mv(Kind::linear, {20, 0, -1}, 600, 0),  mv(Kind::linear, {20, 10, -1}, 600, 0),
             mv(Kind::linear, {10, 10, -1}, 600, 0), mv(Kind::linear, {10, 0, -1}, 600, 0),
             mv(Kind::rapid, {10, 0, 5}, 0, 0)};
  EntityReport r;
  r.label = "square";
  r.type = "path";
  r.degree = 1;
  r.length = 40;
  r.blocks = 4;
  r.entity = 0;
  p.entities.push_back(r);
  return p;
}

TEST(MotionTotals, LengthsAndTimesOfAHandMadeProgram) {
  const auto m = program_motion(square_program());
  const MotionTotals t = motion_totals(m, 1200);
  EXPECT_DOUBLE_EQ(t.feed_length, 6 + 40);
  EXPECT_DOUBLE_EQ(t.rapid_length, 10 + 6);  // the first retract's start is unknown: no travel
  EXPECT_EQ(t.feed_blocks, 5u);
  EXPECT_EQ(t.rapid_blocks, 4u);
  // 6 mm at 60 mm/min is 6 s; 40 mm at 600 mm/min is 4 s; 16 mm at 1200 mm/min is 0.8 s.
  EXPECT_DOUBLE_EQ(t.feed_time_s, 10);
  EXPECT_DOUBLE_EQ(t.rapid_time_s, 0.8);
  EXPECT_DOUBLE_EQ(t.time_s(), 10.8);
  // Per entity: everything belongs to entity 0; nothing to entity 1.
  EXPECT_DOUBLE_EQ(motion_totals(m, 1200, 0).feed_length, 46);
  EXPECT_EQ(motion_totals(m, 1200, 1).feed_blocks, 0u);
}

TEST(Report, RapidRateIsTheProfilesMaximumFeedInProgramUnits) {
  MachineProfile prof;
  prof.name = "slow";
  prof.max_feed_mm_min = 2540;
  Program p = square_program();
  p.units = Units::inch;
  const ProgramReport r = make_report(p, prof, "G20\nG00 X1\n");
  EXPECT_DOUBLE_EQ(r.rapid_rate, 100);  // 2540 mm/min = 100 inch/min
  EXPECT_NE(r.rapid_rate_basis.find("\"slow\""), std::string::npos);
  EXPECT_EQ(r.gcode_lines, 2u);
  EXPECT_EQ(r.gcode_bytes, 11u);
  ASSERT_EQ(r.entities.size(), 1u);
  EXPECT_DOUBLE_EQ(r.entities[0].motion.feed_length, 46);
}

Job load_sample(const std::string& name) { return load_job(std::string(BEZCAM_SOURCE_DIR "/samples/") + name); }

TEST(Report, AgreesWithTheBuiltProgram) {
  const Job job = load_sample("path-closed-teardrop.json");
  const MachineProfile m = load_machine_profile("generic");
  const Program p = build_program(job, m, ConvertOptions{});
  const ProgramReport r = make_report(p, m);
  ASSERT_EQ(r.entities.size(), 1u);
  const auto& e = r.entities[0];
  EXPECT_EQ(e.report.label, "teardrop");
  EXPECT_EQ(e.report.type, "path");
  EXPECT_EQ(e.report.degree, 3);
  EXPECT_EQ(e.report.blocks, p.entities[0].blocks);
  EXPECT_EQ(e.report.measured, p.max_measured);
  EXPECT_LE(e.report.measured, job.tolerance);
  // The cut is a polygon within the tolerance of the curve, crossing it
  // (band vertices lie outside the curve, chord middles inside): its
  // length is the curve's to within a few 1e-4 (a chord of length c whose
  // points stray by h <= tolerance differs from its arc by about
  // 8 h^2 / (3 c)). With the plunge from safe_z 5 to cut_z -1.
  const double cut = e.motion.feed_length - 6;
  EXPECT_NEAR(cut, e.report.length, 3e-4 * e.report.length);
  EXPECT_EQ(e.motion.feed_blocks, e.report.blocks + 1);
  // The start is the first vertex, so the only rapid travel is the final retract.
  EXPECT_DOUBLE_EQ(r.total.rapid_length, 6);
  EXPECT_NEAR(r.total.feed_time_s, 60 * (6.0 / 300 + cut / 1000), 1e-9);
  EXPECT_DOUBLE_EQ(r.rapid_rate, 20000);
}

TEST(Report, JsonHoldsEveryFigure) {
  const Job job = load_sample("job-exercises-all.json");
  const MachineProfile m = load_machine_profile("generic");
  const Program p = build_program(job, m, ConvertOptions{});
  const ProgramReport r = make_report(p, m, "%\nG21\n");
  const auto j = nlohmann::json::parse(report_json(r));
  EXPECT_EQ(j["bezcam_report"], 1);
  EXPECT_EQ(j["machine"], "generic");
  EXPECT_EQ(j["units"], "mm");
  EXPECT_EQ(j["output"], "lines");
  ASSERT_EQ(j["entities"].size(), job.entities.size());
  std::set<size_t> seen;
  for (size_t i = 0; i < job.entities.size(); ++i) {
    const auto& x = j["entities"][i];  // in the cut order; `index` is the job's
    const size_t k = x["index"].get<size_t>();
    ASSERT_LT(k, job.entities.size());
    EXPECT_TRUE(seen.insert(k).second);
    EXPECT_EQ(x["label"], job.entities[k].id);
    EXPECT_EQ(x["kind"], "bezier");
    EXPECT_EQ(x["degree"], job.entities[k].curve.max_degree());
    EXPECT_NEAR(x["length"].get<double>(), job.entities[k].curve.length(), 1e-9 * job.entities[k].curve.length());
    EXPECT_EQ(x["blocks"], p.entities[i].blocks);
    EXPECT_DOUBLE_EQ(x["measured_deviation"].get<double>(), p.entities[i].measured);
    EXPECT_DOUBLE_EQ(x["proven_bound"].get<double>(), p.entities[i].bound);
    EXPECT_LE(x["measured_deviation"].get<double>(), x["proven_bound"].get<double>());
    EXPECT_GT(x["motion"]["feed_time_s"].get<double>(), 0);
  }
  const auto& prog = j["program"];
  EXPECT_DOUBLE_EQ(prog["feed_length"].get<double>(), r.total.feed_length);
  EXPECT_DOUBLE_EQ(prog["rapid_length"].get<double>(), r.total.rapid_length);
  EXPECT_DOUBLE_EQ(prog["estimated_time_s"].get<double>(), r.total.time_s());
  EXPECT_EQ(prog["gcode_lines"], 2);
  // What the cut order saved, the figures the header's note gives.
  ASSERT_TRUE(p.order.has_value());
  const auto& o = j["order"];
  EXPECT_EQ(o["mode"], "shortest");
  EXPECT_EQ(o["nested_contours"], p.order->nested);
  EXPECT_DOUBLE_EQ(o["rapid_xy_as_written"].get<double>(), p.order->rapid_as_written);
  EXPECT_DOUBLE_EQ(o["rapid_xy_planned"].get<double>(), p.order->rapid_planned);
  EXPECT_DOUBLE_EQ(o["rapid_xy_saved"].get<double>(), p.order->rapid_as_written - p.order->rapid_planned);
  EXPECT_GT(o["rapid_xy_saved"].get<double>(), 0);
  // The entities' motion adds up to the program's (every block is tagged).
  double feed = 0;
  for (const auto& x : j["entities"]) feed += x["motion"]["feed_length"].get<double>();
  EXPECT_NEAR(feed, r.total.feed_length, 1e-9);
}

TEST(Report, TextIsShortAndNamesEveryEntityUpToTheLimit) {
  const Job job = load_sample("job-exercises-all.json");
  const MachineProfile m = load_machine_profile("generic");
  const ProgramReport r = make_report(build_program(job, m, ConvertOptions{}), m);
  const std::string full = report_text(r);
  std::istringstream in(full);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  ASSERT_EQ(lines.size(), 1 + 9 + 2u);
  EXPECT_EQ(lines[0].rfind("bezcam: 9 entities, ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find("for machine generic (output lines, tolerance 0.01 mm)"), std::string::npos);
  EXPECT_EQ(lines[1].rfind("  seed-ex-1: bezier, degree 2, length 2.17831 mm, ", 0), 0u) << lines[1];
  EXPECT_EQ(lines[10].rfind("  program: ", 0), 0u);
  // The cuts along the curves beside their exact path's bound.
  EXPECT_EQ(lines[11].rfind("  cutting along the curves ", 0), 0u) << lines[11];
  EXPECT_NE(lines[11].find("; the exact path's bound on this machine "), std::string::npos) << lines[11];
  const std::string short_form = report_text(r, 2);
  EXPECT_NE(short_form.find("  ... and 7 more entities"), std::string::npos) << short_form;
  EXPECT_EQ(short_form.find("seed-ex-3"), std::string::npos);
}

TEST(Report, ExactOutputMeasuresWithinTheMeasurementsResolution) {
  // fanuc prints the B-spline's own knots and points: the proven bound is
  // rounding only, far below what the measurement resolves. The report says
  // the deviation is below the bound, not a figure above it.
  const Job job = load_sample("curve-bspline-wave.json");
  const MachineProfile m = load_machine_profile("fanuc");
  ConvertOptions opt;
  opt.output = OutputMode::nurbs;
  const ProgramReport r = make_report(build_program(job, m, opt), m);
  EXPECT_DOUBLE_EQ(r.measurement_resolution, 1e-3 * job.tolerance);
  const auto j = nlohmann::json::parse(report_json(r));
  EXPECT_DOUBLE_EQ(j["measurement_resolution"].get<double>(), r.measurement_resolution);
  for (const auto& x : j["entities"]) {
    EXPECT_LT(x["proven_bound"].get<double>(), 1e-6 * job.tolerance);
    EXPECT_LE(x["measured_deviation"].get<double>(), x["proven_bound"].get<double>() + r.measurement_resolution);
  }
  const std::string text = report_text(r);
  std::smatch rt;
  ASSERT_TRUE(std::regex_search(text, rt, std::regex(R"(deviation below ([^ ]+) mm \(proven bound ([^ ]+) mm\))")))
      << text;
  EXPECT_LE(std::stod(rt[1].str()), std::stod(rt[2].str())) << rt[0];
  // The program's header says the same, in significant digits: a bound of
  // 1e-14 is not "0." (the coordinate formatter's text).
  const std::string gcode = convert(job, m, opt).gcode;
  std::smatch mt;
  ASSERT_TRUE(std::regex_search(gcode, mt,
                                std::regex(R"(largest deviation measured below ([^ ]+) mm, proven bound ([^ ]+) mm)")))
      << gcode.substr(0, 300);
  EXPECT_LE(std::stod(mt[1].str()), std::stod(mt[2].str())) << mt[0];
  const double bound = std::stod(mt[2].str());
  EXPECT_GT(bound, 0.0) << mt[1];
  EXPECT_LT(bound, 1e-6 * job.tolerance) << mt[1];
  EXPECT_NE(mt[1].str().back(), '.') << mt[1];
}

TEST(FormatSignificant, TrimsAndRounds) {
  EXPECT_EQ(format_significant(0.009876543, 3), "0.00988");
  EXPECT_EQ(format_significant(123.456, 6), "123.456");
  EXPECT_EQ(format_significant(2.5, 6), "2.5");
  EXPECT_EQ(format_significant(0, 3), "0");
  EXPECT_EQ(format_significant(20000, 6), "20000");
}

TEST(Report, TheExactPathsBoundAndEachModesRatioToIt) {
  // The same job in lines and arcs: the same bound (the exact path's), each
  // plan's time along the curves at or above it, the ratios in the JSON.
  const Job job = load_sample("job-exercises-all.json");
  const MachineProfile m = load_machine_profile("linuxcnc");
  ProgramReport lines, arcs;
  for (OutputMode mode : {OutputMode::lines, OutputMode::arcs}) {
    ConvertOptions o;
    o.output = mode;
    const ConvertResult c = convert(job, m, o);
    (mode == OutputMode::lines ? lines : arcs) = make_report(c.program, m, c.gcode, c.plan ? &*c.plan : nullptr);
  }
  ASSERT_GT(lines.path_bound_s, 0);
  EXPECT_EQ(lines.path_bound_s, arcs.path_bound_s);
  ASSERT_TRUE(lines.planned && arcs.planned);
  lines.alternatives = {{OutputMode::lines, 0, 0, *lines.planned}, {OutputMode::arcs, 0, 0, *arcs.planned}};
  const auto j = nlohmann::json::parse(report_json(lines));
  const double bound = j["program"]["path_bound_s"].get<double>();
  EXPECT_LE(bound, lines.path_bound_s);  // rounded down
  EXPECT_GT(bound, lines.path_bound_s - 1e-6);
  double sum = 0;
  for (const auto& e : j["entities"]) sum += e["time_bound_s"].get<double>();
  EXPECT_NEAR(sum, bound, 1e-5);
  for (const auto& a : j["compare_outputs"]) {
    const double path = a["planned"]["path_time_s"].get<double>();
    EXPECT_GE(path, bound);
    EXPECT_NEAR(a["planned"]["path_bound_ratio"].get<double>(), path / bound, 1e-5);
  }
  const std::string text = report_text(lines);
  EXPECT_NE(text.find("path/bound"), std::string::npos) << text;
}

}  // namespace
}  // namespace bezcam
