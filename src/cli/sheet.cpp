// bezcam sheet JOB.json|DRAWING --machine M -o SHEET.html [conversion and
//              program options as for convert]
// The setup sheet of the program convert would write with the same
// options: one self-contained HTML page (report/setup_sheet.hpp).
#include <iostream>
#include <optional>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/report/preview_svg.hpp"
#include "bezcam/report/report.hpp"
#include "bezcam/report/setup_sheet.hpp"
#include "commands.hpp"
#include "job_conversion.hpp"
#include "output_file.hpp"

namespace bezcam::cli {

CLI::App* setup_sheet(CLI::App& app, SheetArgs& o) {
  auto* s = app.add_subcommand("sheet",
                               "Write the setup sheet of a job's program as one self-contained HTML page: picture, "
                               "stock and origin, tools, operations, times, guarantees.");
  s->add_option("JOB", o.job, "job file (JSON) or drawing (.svg, .dxf), as for convert")->required();
  s->add_option("-o,--output-file", o.out, "HTML file to write; written whole or not at all")->required();
  add_post_options(s, o.post);
  add_conversion_options(s, o.conv, "cutting moves of the program the sheet describes: lines, arcs, nurbs or best",
                         true);
  s->add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  return s;
}

namespace {

// The program's header comment lines as printed: everything before the
// first line of the program itself (G21/G20 G90 G17).
class HeaderLines {
 public:
  void add(std::string_view piece) {
    if (done_) return;
    text_ += piece;
    size_t start = 0;
    for (size_t nl = text_.find('\n'); nl != std::string::npos; nl = text_.find('\n', start)) {
      const std::string line = text_.substr(start, nl - start);
      start = nl + 1;
      if (line.find("G90 G17") != std::string::npos) {
        done_ = true;
        break;
      }
      lines_.push_back(line);
    }
    text_.erase(0, start);
  }
  const std::vector<std::string>& lines() const { return lines_; }

 private:
  std::string text_;
  std::vector<std::string> lines_;
  bool done_ = false;
};

// The part's picture: the program's tool path over the true curves, as
// `bezcam preview` draws it (without control polygons).
std::string picture(const Job& job, const Program& p, const MachineProfile& m) {
  PreviewInput in;
  in.job = &job;
  in.motion = program_motion(p);
  in.units = p.units;
  in.tolerance = p.tolerance;
  in.program_measured = p.max_measured;
  in.machine = m.name;
  in.entity_tool.assign(job.entities.size(), -1);
  for (const auto& r : p.entities)
    if (r.entity >= 0 && static_cast<size_t>(r.entity) < in.entity_tool.size()) in.entity_tool[r.entity] = r.tool;
  add_part_cutting(in, p, job.entities.size());
  in.title = job.source + " on machine " + m.name;
  PreviewOptions popt;
  popt.control = false;
  popt.width = 1000;
  return preview_svg(in, popt);
}

}  // namespace

int run_sheet(const SheetArgs& o) {
  require_output_extension(o.out, "-o", {".html", ".htm"}, "sheet writes one HTML page");
  const JobConversion c = convert_job_file(o.job, o.conv, o.post, o.quiet, "sheet");
  const Job& job = c.job;
  const MachineProfile& m = c.machine;
  const ConvertResult& r = c.result;
  // The header and the report as convert makes them (the program's text
  // is counted, never kept); the full plan only for the time of each tool.
  HeaderLines header;
  const ProgramReport rep =
      write_and_report(r.program, m, r.plan ? &*r.plan : nullptr, [&](std::string_view s) { header.add(s); });
  std::optional<MotionPlan> full;
  if (m.motion) full = plan_motion(program_timeline(r.program), *m.motion, PlanDetail::full);
  SetupSheetInput in;
  in.job = &job;
  in.program = &r.program;
  in.machine = &m;
  in.report = &rep;
  in.plan = full ? &*full : nullptr;
  in.picture_svg = picture(job, r.program, m);
  in.header = header.lines();
  in.title = job.source;
  write_output(o.out, setup_sheet_html(in));
  if (!o.quiet) {
    for (const auto& w : r.program.warnings) std::cerr << "bezcam: warning: " << w << "\n";
    const size_t tools = sheet_tools(in).size(), ops = r.program.entities.size();
    std::cerr << "bezcam: wrote " << o.out << ": " << tools << (tools == 1 ? " tool, " : " tools, ") << ops
              << (ops == 1 ? " operation; " : " operations; ") << sheet_cycle_time(in) << "\n";
  }
  return 0;
}

}  // namespace bezcam::cli
