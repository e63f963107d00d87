// bezcam convert JOB.json [-o OUT.nc] [--machine NAME|FILE] [--tolerance T]
//                [--output lines|arcs|nurbs]
#include <iostream>

#include "bezcam/post/convert.hpp"
#include "command.hpp"

namespace bezcam::cli {
namespace {

struct Options {
  std::string job, out = "-", machine, output = "lines";
  double tolerance = 0;
  bool quiet = false;
} o;

CLI::App* add(CLI::App& app) {
  auto* s = app.add_subcommand("convert", "Write the G-code program for a job (stdout when no -o).");
  s->add_option("JOB", o.job, "job file (JSON, curve-file format version 1)")->required();
  s->add_option("-o,--output-file", o.out, "program file to write; written whole or not at all");
  s->add_option("--machine", o.machine, "machine profile: a name in machines/ or a .json file "
                                        "(default: the job's \"machine\", else generic)");
  s->add_option("--tolerance", o.tolerance, "chord tolerance in the job's units, overriding the job's")
      ->check(CLI::PositiveNumber);
  s->add_option("--output", o.output, "cutting moves: lines (G01), arcs (G02/G03) or nurbs (exact blocks)")
      ->check(CLI::IsMember({"lines", "arcs", "nurbs"}));
  s->add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  return s;
}

int run() {
  const Job job = load_job(o.job);
  const MachineProfile m = resolve_profile(job, o.machine);
  ConvertOptions opt;
  opt.output = parse_output_mode(o.output);
  if (o.tolerance > 0) opt.tolerance = o.tolerance;
  const ConvertResult r = convert(job, m, opt);
  write_output_atomically(o.out, r.gcode);
  if (!o.quiet) {
    for (const auto& w : job.warnings) std::cerr << "bezcam: warning: " << w << "\n";
    const auto& p = r.program;
    size_t blocks = 0;
    for (const auto& e : p.entities) blocks += e.blocks;
    std::cerr << "bezcam: " << p.entities.size() << " entit" << (p.entities.size() == 1 ? "y" : "ies") << ", "
              << blocks << " cutting blocks for machine " << m.name << "; tolerance " << p.tolerance << " "
              << to_string(p.units) << ", largest deviation measured " << p.max_measured << " (bound "
              << p.max_bound << ")" << (o.out == "-" ? "" : "; wrote " + o.out) << "\n";
  }
  return 0;
}

Command cmd{"convert", add, run};
RegisterCommand reg(&cmd);

}  // namespace
}  // namespace bezcam::cli
