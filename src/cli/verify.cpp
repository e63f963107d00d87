// bezcam verify PROGRAM.nc --machine M [--tools T.json] [--stock BOX]
// [--design JOB.json] [--cell C] [--report R.json] [--image I.png|.svg]
// [--heightmap H.npy] [--hash] [--memory-limit SIZE]
//
// Cuts a program into a Z-dexel stock with the same reader as simulate,
// reports the machined result and, with a design, its gouges and excess.
// Everything is computed before any file is written: a refusal leaves none.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/limits.hpp"
#include "bezcam/stock/heightmap.hpp"
#include "bezcam/verify/machined_program.hpp"
#include "bezcam/verify/verify_report.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "job_input.hpp"
#include "output_file.hpp"
#include "profiles.hpp"
#include "stock_options.hpp"
#include "validators.hpp"

namespace bezcam::cli {

namespace {

// The tools the timeline uses, for the report.
StockTools used_tools(const Timeline& tl, const StockTools& all) {
  StockTools used;
  for (std::size_t i = 0; i < tl.blocks.size(); ++i) {
    if (!is_feed(tl.blocks[i])) continue;
    const int n = i < tl.tools.size() ? tl.tools[i] : 0;
    const ToolShape& s = stock_tool(all, n, tl.blocks[i].line);
    used.emplace(all.count(n) ? n : all.begin()->first, s);
  }
  return used;
}

}  // namespace

CLI::App* setup_verify(CLI::App& app, VerifyArgs& o) {
  auto* s = app.add_subcommand("verify",
                               "Cut a G-code program into a stock (a Z-dexel grid, floors exact for every tool "
                               "shape) and report the machined result; with --design, per entity the largest gouge "
                               "and excess. Exit 0, or 5 when a gouge exceeds the design's tolerance.");
  s->add_option("PROGRAM", o.program, "G-code program")->required();
  s->add_option("--machine", o.machine, "machine profile: a name in machines/ or a .json file (default: generic)");
  s->add_option("--tools", o.tools,
                "tools table (JSON, lengths in mm), e.g. {\"1\": {\"shape\": \"ball\", \"diameter\": 6}}; "
                "overrides the design's tools of the same number");
  s->add_option("--stock", o.stock, "stock box x0,y0,z0,x1,y1,z1 in mm (default: the design's, else the program's)");
  s->add_option("--design", o.design, "the job the program was made from: gouges and excess per entity");
  s->add_option("--cell", o.cell, "cell size in mm (default: the tolerance, at most 4 million columns)")
      ->check(positive_number());
  s->add_option("--report", o.report, "write the report (JSON)");
  s->add_option("--image", o.image, "write a picture of the machined stock (.png or .svg)");
  s->add_option("--heightmap", o.heightmap, "write the floors as a NumPy .npy array (float64, mm)");
  s->add_flag("--hash", o.hash, "print only the hash of the floors rounded to 1 um");
  s->add_option("--memory-limit", o.memory_limit, "largest grid, e.g. 512MiB (default 1GiB)");
  s->add_option("--threads", o.threads, "threads (default: one per core; the result is the same)");
  s->add_flag("-q,--quiet", o.quiet, "print nothing but errors (and the hash with --hash)");
  return s;
}

int run_verify(const VerifyArgs& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const MachineProfile m = load_profile_option(o.machine);
  if (!o.image.empty()) {
    const std::string ext = std::filesystem::path(o.image).extension().string();
    if (ext != ".png" && ext != ".svg")
      throw InputError(errc::usage_option, Place::at_option("--image"),
                       "expected a file name ending in .png or .svg, found \"" + o.image + "\"");
  }
  const std::size_t memory = parse_memory_limit(o.memory_limit);
  std::optional<Job> design;
  if (!o.design.empty()) design = read_job(o.design);
  StockTools tools = design ? design_stock_tools(*design, m) : StockTools{};
  if (!o.tools.empty()) {
    for (auto& [n, t] : stock_tools(read_tool_table_file(o.tools))) tools.insert_or_assign(n, t);
  }
  if (std::filesystem::is_directory(o.program))
    throw IoError(errc::io_read, Place::at_file(o.program), "is a directory, not a G-code file");
  const Timeline tl = read_timeline(read_bounded(o.program, kMaxProgramBytes, "G-code file"), &m);
  std::optional<StockBox> box_given;
  if (!o.stock.empty())
    box_given = parse_stock_box(o.stock);
  else if (design)
    box_given = design_stock_box(*design, m, tools);
  const StockBox box = box_given ? *box_given : program_stock_box(tl, tools);
  try {
    (void)stock_grid_size(box, 1);
  } catch (const Error& e) {
    if (o.stock.empty()) throw;
    throw e.with_option("--stock");
  }
  check_stock_holds_program(box, tl, tools);
  const double tol = design ? design->tolerance * mm_per_unit(design->units) : kDefaultToleranceMm;
  const double cell = o.cell > 0 ? o.cell : default_stock_cell(box, tol);
  StockCutterOptions opt;
  opt.memory_limit = memory;
  opt.threads = o.threads;
  StockCutter cutter = [&] {
    try {
      return StockCutter(box, cell, tools, opt);
    } catch (const Error& e) {
      throw stock_option_error(e);
    }
  }();
  cut_timeline(cutter, tl);
  const DexelGrid& g = cutter.grid();

  VerifyFigures f;
  f.program = o.program;
  f.machine = m.name;
  f.units = tl.units;
  f.box = box;
  f.cell = cell;
  f.nx = g.nx();
  f.ny = g.ny();
  f.memory_bytes = g.memory_bytes();
  f.tools = used_tools(tl, tools);
  f.removed_volume = g.removed_volume();
  f.deepest = g.deepest();
  f.hash = g.hash_hex();
  f.added_error = g.added_error();
  f.blocks = cutter.blocks();
  f.sweep = g.stats();
  f.rapid_cuts = cutter.rapid_cuts();
  f.first_rapid_cut_line = cutter.first_rapid_cut_line();
  if (m.motion) f.cycle_time_s = plan_motion(tl, *m.motion, PlanDetail::summary).cycle_time_s;
  if (design) {
    f.design = check_design(g, *design, m, tools);
    f.design_file = o.design;
  }
  StockImageOptions io;
  if (f.design) io.classes = f.design->classes;
  std::string image;
  if (!o.image.empty()) {
    if (std::filesystem::path(o.image).extension() == ".svg") {
      image = stock_svg(g, io);
    } else {
      const auto png = stock_png(g, io);
      image.assign(png.begin(), png.end());
    }
  }
  f.verify_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!o.report.empty()) write_output(o.report, verify_report_json(f));
  if (!o.image.empty()) write_output(o.image, image);
  if (!o.heightmap.empty()) write_output(o.heightmap, heightmap_npy(g));
  if (o.hash)
    std::cout << f.hash << "\n";
  else if (!o.quiet)
    std::cout << "bezcam verify: " << o.program << " on machine " << m.name << "\n" << verify_summary(f);
  return f.design && f.design->gouged() ? exit_status::gouge : exit_status::ok;
}

}  // namespace bezcam::cli
