// bezcam check JOB.json: validates and describes a job without writing G-code.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/best_output.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/import/drawing.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/job_json.hpp"
#include "commands.hpp"
#include "job_input.hpp"
#include "profiles.hpp"

namespace bezcam::cli {

CLI::App* setup_check(CLI::App& app, CheckArgs& o) {
  auto* s = app.add_subcommand("check",
                               "Validate a job and print what it holds (entities, degrees, lengths, "
                               "continuity at path joints); writes no G-code.");
  s->add_option("JOB", o.job, "job file (JSON)")->required();
  add_post_options(s, o.post);
  add_conversion_options(s, o.conv, "the output mode convert would use: lines, arcs, nurbs or best", true);
  s->footer(
      "check runs every validation convert runs for the machine (the job's, --machine, else generic): "
      "travel, feeds, safe Z, decimals against the tolerance, the proven and measured deviation; "
      "only the program is not written.");
  return s;
}

namespace {

// `v` (> 0) rounded up to 3 significant digits: a tolerance no smaller.
double up3(double v) {
  const double p = std::pow(10.0, 2 - std::floor(std::log10(v)));
  return std::ceil(v * p) / p;
}

// What a drawing held, per layer: elements read (by kind) and skipped.
void print_drawing(const import::Drawing& d) {
  const auto list = [](const std::map<std::string, size_t>& m) {
    std::string text;
    for (const auto& [kind, n] : m) text += (text.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
    return text;
  };
  std::cout << d.source << ": " << (d.format == "svg" ? "SVG" : "DXF") << " drawing, " << d.contours.size()
            << " contour" << (d.contours.size() == 1 ? "" : "s") << " after joining";
  if (!d.texts.empty()) std::cout << ", " << d.texts.size() << " text" << (d.texts.size() == 1 ? "" : "s");
  std::cout << "\n";
  for (const auto& [name, l] : d.layers) {
    std::cout << (d.format == "svg" ? std::string("  document") : "  layer \"" + name + "\"") << ": read "
              << (l.read.empty() ? std::string("nothing") : list(l.read));
    if (!l.skipped.empty()) std::cout << "; skipped " << list(l.skipped);
    std::cout << "\n";
  }
  // Open contours whose ends nearly meet (within 1 % of the drawing's
  // size): the gap, where it is, and the option that closes it.
  for (const import::Gap& g : import::nearly_closed(d, 0.01 * d.size()))
    std::cout << "  nearly closed: \"" << g.id << "\", its ends " << std::setprecision(3) << g.size << " mm apart at ("
              << std::setprecision(6) << g.at.x << ", " << g.at.y << "); --join-tolerance " << std::setprecision(3)
              << up3(g.size) << " closes it\n";
}

}  // namespace

int run_check(const CheckArgs& o) {
  import::Drawing drawing;
  const Job job = read_job(o.job, o.conv, &drawing);
  if (!drawing.format.empty()) print_drawing(drawing);
  const char* u = to_string(job.units);
  std::cout << job.source << ": bezcam format " << job.version << ", units " << u << ", tolerance " << job.tolerance
            << " " << u << (job.machine ? ", machine " + *job.machine : std::string()) << "\n";
  for (const auto& e : job.entities) {
    const auto& g = e.curve;
    std::cout << e.json_path() << (e.id.empty() ? "" : " \"" + e.id + "\"") << ": " << e.type;
    if (!e.glyph.empty()) std::cout << " \"" << e.glyph << "\"";    // a glyph's contour (job/text.hpp)
    if (e.point) std::cout << " at " << fmt_point(*e.point, 2, 6);  // a hole (docs/holes.md)
    if (!g.pieces.empty()) {
      std::cout << ", " << g.dim << "D, degree " << g.max_degree() << (g.rational() ? ", rational" : "") << ", "
                << g.pieces.size() << " Bézier piece" << (g.pieces.size() == 1 ? "" : "s") << ", length "
                << std::setprecision(6) << g.length() << " " << u;
      const Box3 b = g.bounds();
      std::cout << ", bounds " << fmt_point(b.lo, g.dim, 6) << " to " << fmt_point(b.hi, g.dim, 6);
      if (g.closed) std::cout << ", closed";
    }
    if (e.surface) {  // bezier_patch, coons_patch, curve_on_surface
      const SurfaceGeometry& s = *e.surface;
      const Box3 b = bounds(s);
      std::cout << (e.type == "curve_on_surface" ? ", on a " + s.kind : std::string()) << ", degree " << s.degree_u()
                << " x " << s.degree_v() << (s.rational() ? ", rational" : "") << ", " << s.grid.cells.size()
                << " Bézier cell" << (s.grid.cells.size() == 1 ? "" : "s") << ", bounds " << fmt_point(b.lo, 3, 6)
                << " to " << fmt_point(b.hi, 3, 6);
      if (e.type == "curve_on_surface")
        std::cout << ", curve of " << e.uv_curve.pieces.size() << " piece" << (e.uv_curve.pieces.size() == 1 ? "" : "s")
                  << " in (u, v)" << (e.uv_curve.closed ? ", closed" : "");
      else
        std::cout << ", toolpath " << e.toolpath.pattern << " along " << e.toolpath.direction
                  << (e.toolpath.stepover ? ", stepover " + fmt_num(*e.toolpath.stepover) : std::string());
    }
    std::cout << "\n";
    if (g.kind == "path" && e.type == "path") {
      for (size_t i = 0; i < g.segments.size(); ++i)
        std::cout << "  segments[" << i << "]: " << g.segments[i].kind << ", degree " << g.segments[i].degree
                  << (g.segments[i].rational ? ", rational" : "") << "\n";
      for (size_t j = 0; j < g.joints.size(); ++j) {
        const size_t a = j, b = (j + 1) % g.segments.size();
        std::cout << "  joint segments[" << a << "] -> segments[" << b << "]"
                  << (j + 1 == g.segments.size() ? " (closing)" : "") << ": " << to_string(g.joints[j]) << "\n";
      }
    }
  }
  // Everything convert checks, short of writing: a job check accepts is a
  // job convert accepts for the same machine and settings.
  MachineProfile m = resolve_profile(job, o.conv.machine);
  ConvertOptions opt;
  const bool best = o.conv.output == "best";
  if (!best) opt.output = parse_output_mode(o.conv.output);
  if (o.conv.tolerance > 0) opt.tolerance = o.conv.tolerance;
  apply_post_options(o.post, job, m, opt);
  std::vector<std::string> warnings;
  const auto fmt_sig = [](double v) { return format_significant(v, 3); };
  try {
    if (best) refuse_best_without_motion(m);
    // What convert writes, text included.
    const ConvertResult r = [&] {
      if (!best) return convert(job, m, opt);
      ConvertResult b = convert_best(job, m, opt).result;
      b.gcode = write_gcode(b.program, m, b.plan ? &*b.plan : nullptr);
      return b;
    }();
    warnings = shown_warnings(r.program.warnings, o.conv);
    refuse_warnings_if_strict(warnings, o.conv);
    std::cout << "machine " << m.name << ", " << o.conv.output << ": " << r.program.entities.size() << " entit"
              << (r.program.entities.size() == 1 ? "y" : "ies") << " cut, deviation measured "
              << fmt_sig(r.program.max_measured) << ", proven below " << format_bound(r.program.max_bound, 3) << " "
              << u << " (tolerance " << fmt_sig(r.program.tolerance) << ")\n";
    if (best) std::cout << r.program.notes.back() << "\n";  // what each entity got
  } catch (const Error& e) {
    // The job's own warnings count even when the machine refuses it
    // (with --strict they are the refusal).
    if (e.id() != "usage.strict") print_warnings(job.warnings);
    throw;
  }
  print_warnings(warnings);
  std::cout << "ok: " << job.entities.size() << " entit" << (job.entities.size() == 1 ? "y" : "ies")
            << " valid for machine " << m.name << "\n";
  return 0;
}

}  // namespace bezcam::cli
