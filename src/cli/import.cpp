// bezcam import DRAWING.svg|.dxf [-o JOB.json] [--layer NAME]... [--set KEY=VALUE]...
// Writes the job a drawing is read as, every number to full double
// precision, so that it can be edited (feeds, side ...) and converted.
#include <iostream>

#include "bezcam/error.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "commands.hpp"
#include "job_input.hpp"
#include "output_file.hpp"

namespace bezcam::cli {

CLI::App* setup_import(CLI::App& app, ImportArgs& o) {
  auto* s = app.add_subcommand("import",
                               "Write the job (JSON) a drawing (.svg, .dxf) is read as: exact curves, "
                               "ids from the drawing (stdout when no -o).");
  s->add_option("DRAWING", o.drawing, "an SVG or DXF drawing")->required();
  s->add_option("-o,--output-file", o.out, "job file to write; written whole or not at all");
  add_drawing_options(s, o.conv);
  s->add_flag("-q,--quiet", o.quiet, "print nothing but errors");
  s->footer(
      "SVG: path commands and shapes, transforms applied, lengths in mm (96 user units per inch), y up. "
      "DXF: LINE, ARC, CIRCLE, ELLIPSE, (LW)POLYLINE with bulges, SPLINE, INSERT, TEXT and MTEXT (in their "
      "styles' fonts); $INSUNITS; entities meeting end to end are joined into one path. See docs/import.md.");
  return s;
}

int run_import(const ImportArgs& o) {
  if (!import::is_drawing(o.drawing))
    throw InputError(errc::import_not_a_drawing, Place::at_file(o.drawing),
                     "expected a drawing named .svg or .dxf, found another name (a job file needs no import)");
  const import::ImportOptions io = import_options(o.conv);
  const import::Drawing d = import::read_drawing(o.drawing, read_options(o.conv));
  const std::string text = import::job_json(d, io);
  // The job must read back (the same checks convert makes of the file)
  // before a byte is written.
  std::vector<std::string> warnings;
  const Job job = import::to_job(d, io, &warnings);
  write_output(o.out, text);
  if (!o.quiet) {
    print_warnings(warnings);
    if (o.out != "-")
      std::cerr << "bezcam: wrote " << o.out << ": " << job.entities.size() << " entit"
                << (job.entities.size() == 1 ? "y" : "ies") << " from " << o.drawing << "\n";
  }
  return 0;
}

}  // namespace bezcam::cli
