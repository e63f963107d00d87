// bezcam preview JOB.json -o OUT.svg [--machine NAME|FILE] [--tolerance T]
//                [--output lines|arcs|nurbs] [--no-control] [--deviation]
// bezcam preview [JOB.json] --program FILE.nc -o OUT.svg [--machine ...]
// Draws the true curves, their control polygons and the tool path that
// `convert` would write with the same options, or the motion of any G-code
// program the reader understands (top view, plus an isometric view for 3D
// work), as a self-contained SVG file.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/gcode/best_output.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/gcode/writer.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/kernel/surface.hpp"
#include "bezcam/limits.hpp"
#include "bezcam/report/motion_report.hpp"
#include "bezcam/report/preview_svg.hpp"
#include "bezcam/report/report.hpp"
#include "bezcam/report/setup_sheet.hpp"
#include "commands.hpp"
#include "job_input.hpp"
#include "output_file.hpp"
#include "profiles.hpp"
#include "progress.hpp"

namespace bezcam::cli {

CLI::App* setup_preview(CLI::App& app, PreviewArgs& o) {
  auto* s = app.add_subcommand("preview",
                               "Draw a job's curves, control polygons and tool path as an SVG file "
                               "(top view; isometric view too for 3D work).");
  s->add_option("JOB", o.job, "job file (JSON, curve-file format version 1); optional with --program");
  s->add_option("--program", o.program,
                "draw this G-code program instead of building one (with JOB: against the job's curves)");
  s->add_option("-o,--output-file", o.out, "SVG file to write; written whole or not at all")->required();
  add_conversion_options(s, o.conv, "cutting moves, as for convert: lines, arcs, nurbs or best (not with --program)",
                         true);
  add_tool_diameter_option(s, o.tool_diameters);
  s->add_flag("--no-control", o.no_control, "leave out control polygons and control points");
  s->add_flag("--deviation", o.deviation,
              "colour each cutting block by its measured deviation from the true curve (0 to the tolerance)");
  auto* fd = s->add_flag("--feed", o.feed,
                         "colour the cutting moves by the feed the machine reaches on its motion model (legend in "
                         "units/min; starved blocks dashed red)");
  fd->excludes(s->get_option("--deviation"));
  s->add_option("--width", o.width, "width of the drawing in pixels (default 1200)")->check(CLI::Range(400.0, 20000.0));
  s->add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  s->parse_complete_callback([s, &o] { o.output_given = s->count("--output") > 0; });
  return s;
}

namespace {

std::string read_text(const std::string& path, const char* what) {
  if (std::filesystem::is_directory(path))
    throw IoError(errc::io_read, Place::at_file(path), std::string("is a directory, not a ") + what);
  return read_bounded(path, kMaxProgramBytes, what);  // refused before it is read when too large (limits.hpp)
}

// --feed: the motion planned on the machine's model; the preview draws it
// and says what it found (the cycle time is the header's line).
MotionPlan feed_plan(const MachineProfile& m, const Timeline& tl, PreviewInput& in) {
  if (!m.motion)
    throw InputError(
        errc::usage_option, Place::at_option("--feed"),
        "machine \"" + m.name + "\" has no motion model (key \"motion\", docs/machines.md) to plan the feed with");
  in.machine = m.name;
  return plan_motion(tl, *m.motion);
}

// The note on the feed the plan reaches, its times the cycle's.
void add_feed_note(const MachineProfile& m, const MotionPlan& plan, PreviewInput& in) {
  char b[200];
  std::snprintf(b, sizeof b, "mean feed %.0f %% of programmed; %zu starved block%s", plan.mean_feed_ratio * 100,
                plan.starved_blocks, plan.starved_blocks == 1 ? "" : "s");
  in.notes.push_back("feed reached on the motion model of machine " + m.name + ": " + b + " (of the cycle: cutting " +
                     format_seconds(plan.cutting_time_s) + ", rapids " + format_seconds(plan.rapid_time_s) + ")");
}

// The cycle time of a program read from its text, worded as a program's
// header words it: planned on the machine's motion model when the profile
// has one (as `simulate --program` plans it), else feeds as programmed and
// rapids at the maximum feed.
std::string program_cycle_time(const MachineProfile& m, std::string_view text, std::span<const MotionBlock> motion,
                               Units units) {
  const double s = m.motion ? plan_motion(read_timeline(text, &m), *m.motion, PlanDetail::summary).cycle_time_s
                            : motion_totals(motion, m.max_feed_mm_min / mm_per_unit(units)).time_s();
  return cycle_time_words(m, s, units);
}

// --program: the motion of a G-code file, read line by line with progress
// in bytes; a refusal names the file and the line.
int run_program(const PreviewArgs& o) {
  if (o.output_given)
    throw InputError(errc::usage_preview, Place::at_option("--output"),
                     "--output chooses the moves of a program built from the job; it does not apply to --program, "
                     "which is drawn as written (leave one of them out)");
  std::optional<Job> job;
  if (!o.job.empty()) job = read_job(o.job, o.conv);
  const std::string text = read_text(o.program, "G-code file");
  // The machine, when named, is checked by lint (its findings are shown,
  // not fatal: seeing the path helps to fix it) and gives the rapid rate.
  const bool named = !o.conv.machine.empty() || (job && job->machine);
  MachineProfile m = job ? resolve_profile(*job, o.conv.machine)
                         : load_profile_option(o.conv.machine.empty() ? "generic" : o.conv.machine);
  apply_tool_diameters(m, o.tool_diameters);
  Progress progress("preview", "bytes", text.size(), progress_config(o.quiet));
  GcodeInterpreter reader;
  reader.set_tool_diameters_mm(m.tool_diameters_mm);
  PreviewInput in;
  int line_no = 0;
  size_t pos = 0;
  try {
    while (pos < text.size()) {
      size_t end = text.find('\n', pos);
      if (end == std::string::npos) end = text.size();
      for (auto& b : reader.feed_line(std::string_view(text).substr(pos, end - pos), ++line_no))
        in.motion.push_back(std::move(b));
      pos = end + 1;
      progress.set(std::min(pos, text.size()));
    }
    for (auto& b : reader.finish()) in.motion.push_back(std::move(b));
  } catch (const InputError& e) {
    Place at = e.place();
    at.file = o.program;
    throw InputError(e.id(), std::move(at),
                     e.message() +
                         "; the preview draws only programs the reader accepts (bezcam lint lists every "
                         "finding)");
  }
  progress.finish();
  in.units = reader.state().units;
  const char* u = to_string(in.units);
  if (job && job->units != in.units)
    throw InputError(errc::preview_units, Place::at_file(o.program),
                     std::string("the program is in ") + u + " (" + (in.units == Units::mm ? "G21" : "G20") +
                         ") but the job " + job->source + " is in " + to_string(job->units) +
                         "; compare a program with the job it was made from");
  in.job = job ? &*job : nullptr;
  if (job)
    for (const auto& w : job->warnings) in.warnings.push_back("warning: " + w);
  in.tolerance = o.conv.tolerance > 0 ? o.conv.tolerance : (job ? job->tolerance : 0);
  if (job) {
    // A program far from its job (moved with --offset / --origin, or made
    // for another job) would be drawn beside it and measured as wrong.
    Box3 jb, pb;
    for (const Entity& e : job->entities) {
      if (e.surface)
        jb.add(bounds(*e.surface));
      else if (!e.curve.pieces.empty())
        jb.add(e.curve.bounds());
    }
    for (const auto& tm : in.motion)
      if (is_feed(tm)) pb.add(tm.to);
    if (!jb.empty() && !pb.empty()) {
      const double gx = std::max({0.0, jb.lo.x - pb.hi.x, pb.lo.x - jb.hi.x});
      const double gy = std::max({0.0, jb.lo.y - pb.hi.y, pb.lo.y - jb.hi.y});
      const double gap = std::hypot(gx, gy);
      const double size = std::max({jb.hi.x - jb.lo.x, jb.hi.y - jb.lo.y, in.tolerance});
      if (gap > 0.05 * size) {
        auto box = [&](const Box3& b) {
          return "X " + format_significant(b.lo.x, 6) + " to " + format_significant(b.hi.x, 6) + ", Y " +
                 format_significant(b.lo.y, 6) + " to " + format_significant(b.hi.y, 6);
        };
        const std::string w = "the program's cutting moves lie " + format_significant(gap, 4) + " " + u +
                              " away from the job's geometry (job " + box(jb) + "; program " + box(pb) +
                              "): was it moved (--offset, --origin) or made for another job?";
        in.warnings.push_back("warning: " + w);
        if (!o.quiet) std::cerr << "bezcam: warning: " << w << "\n";
      }
    }
  }
  in.title = "bezcam preview: " + o.program + (job ? " against " + job->source : std::string());
  const double rapid_rate = m.max_feed_mm_min / mm_per_unit(in.units);
  const MotionTotals t = motion_totals(in.motion, rapid_rate);
  in.notes.push_back(std::to_string(line_no) + " lines, " + std::to_string(t.feed_blocks) + " feed and " +
                     std::to_string(t.rapid_blocks) + " rapid blocks; " + format_significant(t.feed_length, 6) + " " +
                     u + " at feed, " + format_significant(t.rapid_length, 6) + " " + u + " rapid");
  in.notes.push_back(program_cycle_time(m, text, in.motion, in.units));
  if (named) {
    const auto findings = lint_gcode(text, m);
    for (size_t i = 0; i < findings.size() && i < 5; ++i)
      in.warnings.push_back("lint for machine " + m.name + ": line " + std::to_string(findings[i].line) + ": " +
                            findings[i].message);
    if (findings.size() > 5) in.warnings.push_back("... and " + std::to_string(findings.size() - 5) + " more findings");
    if (!findings.empty() && !o.quiet)
      std::cerr << "bezcam: warning: " << o.program << " has " << findings.size() << " lint finding"
                << (findings.size() == 1 ? "" : "s") << " for machine " << m.name << " (bezcam lint lists them)\n";
  }
  std::optional<MotionPlan> plan;
  if (o.feed) plan = feed_plan(m, read_timeline(text), in);
  if (plan) {
    add_feed_note(m, *plan, in);
    in.plan = &*plan;
  }
  PreviewOptions popt;
  popt.control = !o.no_control;
  popt.deviation = o.deviation;
  popt.width = o.width;
  const std::string svg = preview_svg(in, popt);
  write_output(o.out, svg);
  if (!o.quiet)
    std::cerr << "bezcam: wrote " << o.out << ": " << in.motion.size() << " motion blocks from " << o.program
              << (o.deviation ? ", coloured by deviation"
                  : o.feed    ? ", coloured by feed"
                              : "")
              << "\n";
  return 0;
}

}  // namespace

int run_preview(const PreviewArgs& o) {
  // No SVG rasteriser is built in: a .png name would get SVG text.
  require_output_extension(o.out, "-o", {".svg"}, "preview writes SVG only (no PNG)");
  if (!o.program.empty()) return run_program(o);
  if (o.job.empty())
    throw InputError(errc::usage_preview, Place::at_option("JOB"),
                     "give a job file to draw, or a G-code program with --program FILE.nc");
  const Job job = read_job(o.job, o.conv);
  const MachineProfile m = resolve_profile(job, o.conv.machine);
  const size_t n = job.entities.size();
  const ProgressConfig pcfg = progress_config(o.quiet);
  Progress progress("preview", "entities", n, pcfg);

  // The same program convert would build, from the same options.
  ConvertOptions copt;
  const bool best = o.conv.output == "best";
  if (best) refuse_best_without_motion(m);
  if (!best) copt.output = parse_output_mode(o.conv.output);
  if (o.conv.tolerance > 0) copt.tolerance = o.conv.tolerance;
  copt.on_entity = [&](size_t done, size_t, const std::string& label) { progress.set(done, label); };
  Program p = best ? convert_best(job, m, copt).result.program : build_program(job, m, copt);
  progress.finish();
  p.warnings = shown_warnings(p.warnings, o.conv);
  refuse_warnings_if_strict(p.warnings, o.conv);

  PreviewInput in;
  in.job = &job;
  in.motion = program_motion(p);
  in.units = p.units;
  in.tolerance = p.tolerance;
  in.program_measured = p.max_measured;
  in.entity_tool.assign(job.entities.size(), -1);
  for (const auto& r : p.entities)
    if (r.entity >= 0 && static_cast<size_t>(r.entity) < in.entity_tool.size()) in.entity_tool[r.entity] = r.tool;
  add_part_cutting(in, p, job.entities.size());  // tool widths, material left
  in.title = "bezcam preview: " + job.source;
  const char* u = to_string(p.units);
  in.notes.push_back(
      "machine " + m.name + ", output " + output_name(p) + ", tolerance " + format_significant(p.tolerance, 6) + " " +
      u + " (largest deviation measured " +
      measured_text(p.max_measured, p.max_bound, p.tolerance, [](double v) { return format_significant(v, 3); }) + " " +
      u + ", proven bound " + format_bound(p.max_bound, 3) + " " + u + ")");
  const ProgramReport rep = make_report(p, m);
  size_t blocks = 0;
  for (const auto& e : p.entities) blocks += e.blocks;
  in.notes.push_back(std::to_string(n) + (n == 1 ? " entity, " : " entities, ") + std::to_string(blocks) +
                     " cutting blocks; " + format_significant(rep.total.feed_length, 6) + " " + u + " at feed, " +
                     format_significant(rep.total.rapid_length, 6) + " " + u + " rapid");
  // The cycle time as the program's header says it.
  SetupSheetInput timed;
  timed.program = &p;
  timed.machine = &m;
  in.notes.push_back(sheet_cycle_time(timed));
  // A program convert would refuse is still drawn (seeing where it leaves
  // the travel helps to fix it), with the refusal in red.
  try {
    validate_program(p, m);
  } catch (const InputError& e) {
    in.warnings.push_back(std::string("convert would refuse this program: ") + e.what());
    if (!o.quiet) {
      std::cerr << "bezcam: warning: convert would refuse this program: " << e.what() << "\n";
    }
  }
  for (const auto& w : p.warnings) in.warnings.push_back("warning: " + w);  // the job's and the program's own

  std::optional<MotionPlan> plan;
  if (o.feed) plan = program_plan(p, m, feed_plan(m, program_timeline(p), in));  // the header's times
  if (plan) {
    add_feed_note(m, *plan, in);
    in.plan = &*plan;
  }
  PreviewOptions popt;
  popt.control = !o.no_control;
  popt.deviation = o.deviation;
  popt.width = o.width;
  // Measuring deviations is a second pass over the entities.
  ProgressConfig mcfg = pcfg;
  mcfg.delay_s = std::max(0.0, pcfg.delay_s - progress.elapsed());
  Progress measuring("preview: measuring deviation", "entities", o.deviation ? n : 0, mcfg);
  popt.on_entity = [&](size_t done, size_t, const std::string& label) { measuring.set(done, label); };
  const std::string svg = preview_svg(in, popt);
  measuring.finish();
  write_output(o.out, svg);
  if (!o.quiet) {
    for (const auto& w : p.warnings) std::cerr << "bezcam: warning: " << w << "\n";
    std::cerr << "bezcam: wrote " << o.out << ": " << n << (n == 1 ? " entity, " : " entities, ") << blocks
              << " cutting blocks for machine " << m.name
              << (o.deviation ? ", coloured by deviation"
                  : o.feed    ? ", coloured by feed"
                              : "")
              << "\n";
  }
  return 0;
}

}  // namespace bezcam::cli
