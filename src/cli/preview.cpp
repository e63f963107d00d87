// bezcam preview JOB.json -o OUT.svg [--machine NAME|FILE] [--tolerance T]
//                [--output lines|arcs|nurbs] [--no-control] [--deviation]
// Draws the true curves, their control polygons and the tool path that
// `convert` would write with the same options (top view, plus an isometric
// view for 3D work), as a self-contained SVG file.
#include <iostream>

#include "bezcam/error.hpp"
#include "bezcam/post/convert.hpp"
#include "bezcam/post/preview_svg.hpp"
#include "bezcam/post/report.hpp"
#include "command.hpp"
#include "progress.hpp"

namespace bezcam::cli {
namespace {

struct Options {
  std::string job, out, machine, output = "lines";
  double tolerance = 0, width = 1200;
  bool no_control = false, deviation = false, quiet = false;
} o;

CLI::App* add(CLI::App& app) {
  auto* s = app.add_subcommand("preview", "Draw a job's curves, control polygons and tool path as an SVG file "
                                          "(top view; isometric view too for 3D work).");
  s->add_option("JOB", o.job, "job file (JSON, curve-file format version 1)")->required();
  s->add_option("-o,--output-file", o.out, "SVG file to write; written whole or not at all")->required();
  s->add_option("--machine", o.machine, "machine profile: a name in machines/ or a .json file "
                                        "(default: the job's \"machine\", else generic)");
  s->add_option("--tolerance", o.tolerance, "chord tolerance in the job's units, overriding the job's")
      ->check(CLI::PositiveNumber);
  s->add_option("--output", o.output, "cutting moves, as for convert: lines, arcs or nurbs")
      ->check(CLI::IsMember({"lines", "arcs", "nurbs"}));
  s->add_flag("--no-control", o.no_control, "leave out control polygons and control points");
  s->add_flag("--deviation", o.deviation,
              "colour each cutting block by its measured deviation from the true curve (0 to the tolerance)");
  s->add_option("--width", o.width, "width of the drawing in pixels (default 1200)")->check(CLI::Range(400.0, 20000.0));
  s->add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  return s;
}

int run() {
  const Job job = load_job(o.job);
  const MachineProfile m = resolve_profile(job, o.machine);
  const size_t n = job.entities.size();
  Progress progress("preview", "entities", o.deviation ? 2 * n : n, progress_config(o.quiet));

  // The same program convert would build, from the same options.
  ConvertOptions copt;
  copt.output = parse_output_mode(o.output);
  if (o.tolerance > 0) copt.tolerance = o.tolerance;
  copt.on_entity = [&](size_t done, size_t, const std::string& label) { progress.set(done, label); };
  const Program p = build_program(job, m, copt);

  PreviewInput in;
  in.job = &job;
  in.motion = program_motion(p);
  in.units = p.units;
  in.tolerance = p.tolerance;
  in.title = "bezcam preview: " + job.source;
  const char* u = to_string(p.units);
  in.notes.push_back("machine " + m.name + ", output " + to_string(p.output) + ", tolerance " +
                     format_significant(p.tolerance, 6) + " " + u + " (largest deviation measured " +
                     format_significant(p.max_measured, 3) + " " + u + ", proven bound " +
                     format_significant(p.max_bound, 3) + " " + u + ")");
  const ProgramReport rep = make_report(p, m);
  size_t blocks = 0;
  for (const auto& e : p.entities) blocks += e.blocks;
  in.notes.push_back(std::to_string(n) + (n == 1 ? " entity, " : " entities, ") + std::to_string(blocks) +
                     " cutting blocks; " + format_significant(rep.total.feed_length, 6) + " " + u + " at feed, " +
                     format_significant(rep.total.rapid_length, 6) + " " + u + " rapid; about " +
                     format_duration(rep.total.time_s()) + " (rapids at " + format_significant(rep.rapid_rate, 6) +
                     " " + u + "/min)");
  // A program convert would refuse is still drawn (seeing where it leaves
  // the travel helps to fix it), with the refusal in red.
  try {
    validate_program(p, m);
  } catch (const InputError& e) {
    in.warnings.push_back(std::string("convert would refuse this program: ") + e.what());
    if (!o.quiet) {
      progress.clear();
      std::cerr << "bezcam: warning: convert would refuse this program: " << e.what() << "\n";
    }
  }
  for (const auto& w : job.warnings) in.warnings.push_back("warning: " + w);

  PreviewOptions popt;
  popt.control = !o.no_control;
  popt.deviation = o.deviation;
  popt.width = o.width;
  popt.on_entity = [&](size_t done, size_t, const std::string& label) { progress.set(n + done, label); };
  const std::string svg = preview_svg(in, popt);
  write_output_atomically(o.out, svg);
  progress.finish();
  if (!o.quiet) {
    for (const auto& w : job.warnings) std::cerr << "bezcam: warning: " << w << "\n";
    std::cerr << "bezcam: wrote " << o.out << ": " << n << (n == 1 ? " entity, " : " entities, ") << blocks
              << " cutting blocks for machine " << m.name << (o.deviation ? ", coloured by deviation" : "") << "\n";
  }
  return 0;
}

Command cmd{"preview", add, run};
RegisterCommand reg(&cmd);

}  // namespace
}  // namespace bezcam::cli
