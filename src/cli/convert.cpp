// bezcam convert JOB.json [-o OUT.nc] [--machine NAME|FILE] [--tolerance T]
//                [--output lines|arcs|nurbs|best] [--compare-outputs] [--report FILE.json] [-q]
#include "bezcam/gcode/convert.hpp"

#include <algorithm>
#include <iostream>

#include "bezcam/error.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/report/report.hpp"
#include "commands.hpp"
#include "job_conversion.hpp"
#include "output_file.hpp"

namespace bezcam::cli {

CLI::App* setup_convert(CLI::App& app, ConvertArgs& o) {
  auto* s = app.add_subcommand("convert", "Write the G-code program for a job (stdout when no -o).");
  s->add_option("JOB", o.job, "job file (JSON, curve-file format version 1)")->required();
  s->add_option("-o,--output-file", o.out, "program file to write; written whole or not at all");
  add_post_options(s, o.post);
  add_conversion_options(s, o.conv,
                         "cutting moves: lines (G01), arcs (G02/G03) or nurbs (exact blocks); best: per entity the "
                         "one of those the machine takes whose moves have the shortest planned time on its motion "
                         "model (ties: the fewest blocks)",
                         true);
  s->add_option("--report", o.report,
                "also write a JSON report (per entity: kind, degree, length, blocks, "
                "deviation measured and proven; lengths and estimated time); written only "
                "with the program");
  s->add_flag("--compare-outputs", o.compare,
              "also convert the job in the other output modes the machine takes (lines, arcs, nurbs) and compare "
              "their cycle times on its motion model, per mode and per entity (the shortest marked), in the "
              "summary and the report");
  s->add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  return s;
}

namespace {

// One output mode's figures for --compare-outputs (`best`: the program
// --output best composed).
ProgramReport::Alternative alternative(OutputMode mode, const ProgramReport& rep, bool best = false) {
  ProgramReport::Alternative a;
  a.output = mode;
  a.best = best;
  a.planned = *rep.planned;
  a.gcode_bytes = rep.gcode_bytes;
  for (const auto& e : rep.entities) a.blocks += e.report.blocks;
  return a;
}

}  // namespace

int run_convert(const ConvertArgs& o) {
  // Both files on stdout would be one unreadable stream; one file for both
  // would lose the program.
  if (!o.report.empty() && (o.report == o.out || (o.report == "-" && o.out == "-")))
    throw InputError(errc::usage_report, Place::at_option("--report"),
                     "the report cannot go to the same place as the program (" +
                         (o.out == "-" ? std::string("standard output") : o.out) +
                         "); give --report another file name, or write the program with -o FILE");
  const JobConversion c = convert_job_file(o.job, o.conv, o.post, o.quiet, "convert");
  const Job& job = c.job;
  const MachineProfile& m = c.machine;
  const ConvertOptions& opt = c.options;
  const ConvertResult& r = c.result;
  const MotionPlan* plan = r.plan ? &*r.plan : nullptr;
  // The other output modes first: a refusal there leaves no program
  // written. Their text is only counted, never kept.
  const bool best = c.best.has_value();
  const std::vector<OutputMode> modes = machine_output_modes(m);
  const bool takes = std::find(modes.begin(), modes.end(), opt.output) != modes.end();
  std::vector<ProgramReport::Alternative> others;
  std::vector<OutputTiming> timed;  // per entity, for the table (best has its own)
  if (o.compare) {
    if (!m.motion)
      throw InputError(errc::usage_option, Place::at_option("--compare-outputs"),
                       "machine \"" + m.name +
                           "\" has no motion model (key \"motion\", docs/machines.md) to compare cycle times with");
    for (OutputMode mode : modes) {
      if (!best && mode == opt.output) continue;
      ConvertOptions other = opt;
      other.output = mode;
      other.entity_output.clear();
      const ConvertResult r2 = convert_program(job, m, other);
      const ProgramReport rep2 =
          write_and_report(r2.program, m, r2.plan ? &*r2.plan : nullptr, [](std::string_view) {});
      if (!rep2.planned) continue;
      others.push_back(alternative(mode, rep2));
      if (!best) timed.push_back(time_output(job, r2.program, m));
    }
    if (!best && takes) timed.push_back(time_output(job, r.program, m));
  }
  // The program streamed to its file as it is printed (renamed into place
  // once whole), the report made from it on the way.
  ProgramReport rep;
  write_output(o.out, [&](const OutputSink& out) { rep = write_and_report(r.program, m, plan, out); });
  if (o.compare) {
    // In the order lines, arcs, nurbs, this mode's where it belongs; best
    // after them.
    if (rep.planned && (best || takes)) others.push_back(alternative(opt.output, rep, best));
    std::stable_sort(others.begin(), others.end(), [](const auto& a, const auto& b) {
      return std::pair(a.best, a.output) < std::pair(b.best, b.output);
    });
    rep.alternatives = std::move(others);
    if (!best && timed.size() > 1) rep.choice = choose_outputs(job, m, std::move(timed));
  }
  if (best) rep.choice = c.best;
  if (!o.report.empty()) write_output(o.report, report_json(rep));
  if (!o.quiet) {
    // The job's warnings and the program's own (e.g. an output mode replaced).
    for (const auto& w : r.program.warnings) std::cerr << "bezcam: warning: " << w << "\n";
    if (!r.program.order_summary.empty()) std::cerr << "bezcam: " << r.program.order_summary << "\n";
    std::cerr << report_text(rep);
    if (o.out != "-")
      std::cerr << "bezcam: wrote " << o.out << (o.report.empty() || o.report == "-" ? "" : " and " + o.report) << "\n";
  }
  return 0;
}

}  // namespace bezcam::cli
