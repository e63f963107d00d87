// Cutting a part, measured from the text: every part sample (entities with
// `side`, passes, tabs, ...), for generic, fanuc and linuxcnc, in lines, arcs
// and nurbs output, is written, read back by the G-code reader (lint clean),
// and the last pass of every entity is measured against the part curve by
// the independent offset measurement (flatten/offset_measure.hpp): with
// `tolerance_side: "waste"` every point at least r and at most r + tolerance
// from the part, otherwise within the tolerance of r, and every point of the
// true offset within the tolerance of the path. Leads leave the band by
// design, so the band is read on the samples with their leads removed; with
// leads the program must still never come nearer the part than r.
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <iostream>
#include <map>

#include "bezcam/error.hpp"
#include "bezcam/flatten/offset_measure.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/lint.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/cutting_runs.hpp"
#include "support/sample_job.hpp"

namespace bezcam {
namespace {

namespace fs = std::filesystem;

std::vector<std::pair<fs::path, Job>> part_samples() {
  std::vector<std::pair<fs::path, Job>> out;
  for (const auto& e : fs::directory_iterator(BEZCAM_SOURCE_DIR "/samples")) {
    if (e.path().extension() != ".json" || e.path().filename().string().rfind("part-", 0) != 0) continue;
    out.emplace_back(e.path(), test::load_sample(e.path()));
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

using test::cutting_runs;

// XY points of a run read back (curved blocks sampled by the reader's
// evaluation, chords within `eps`).
std::vector<Vec3> xy_path(const std::vector<MotionBlock>& run, double eps) {
  std::vector<Vec3> out;
  for (const auto& b : run) {
    if (out.empty()) out.push_back({b.from.x, b.from.y, 0});
    if (b.kind == BlockKind::linear) {
      out.push_back({b.to.x, b.to.y, 0});
      continue;
    }
    // Length: the control polygon's (curves) or radius x sweep (arcs).
    double len = 0;
    if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) len = dist(b.from, b.center) * arc_sweep(b);
    for (size_t k = 1; k < b.ctrl.size(); ++k) len += dist(b.ctrl[k - 1], b.ctrl[k]);
    // Chords of `eps`: a sagitta of eps^2 / (8 R), under 1e-5 mm here.
    const int n = std::max(16, static_cast<int>(std::ceil(len / eps)));
    for (int k = 1; k <= n; ++k) {
      const Vec3 p = evaluate_block(b, static_cast<double>(k) / n);
      out.push_back({p.x, p.y, 0});
    }
  }
  return out;
}

// Orientation by the shoelace formula on points of the curve (its own,
// not the offset code's).
double area(const std::vector<Bezier>& pieces) {
  std::vector<Vec3> pts;
  for (const auto& b : pieces)
    for (int k = 0; k < 64; ++k) pts.push_back(evaluate(b, k / 64.0));
  double a = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    const Vec3& p = pts[i];
    const Vec3& q = pts[(i + 1) % pts.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return a / 2;
}

struct Expect {
  double r = 0;
  int side = 1;
  bool waste = false, one_side = false;
  double middle = 0;  // a one-sided band's middle, less r
};

Expect expected(const Job& job, const Entity& e, const MachineProfile& m) {
  const CutParams cp = cut_params(job, e, m);
  Expect x;
  x.r = cp.tool_diameter ? *cp.tool_diameter / 2 + cp.stock_to_leave : 0;
  switch (cp.side) {
    case CutSide::left: x.side = 1; break;
    case CutSide::right: x.side = -1; break;
    case CutSide::inside: x.side = area(e.curve.pieces) > 0 ? 1 : -1; break;
    case CutSide::outside: x.side = area(e.curve.pieces) > 0 ? -1 : 1; break;
    case CutSide::on: x.side = cp.tolerance_side == ToleranceSide::right ? -1 : 1; break;
  }
  x.waste = cp.tolerance_side == ToleranceSide::waste;
  x.one_side = cp.side == CutSide::on && cp.tolerance_side != ToleranceSide::both;
  int away = x.waste || x.one_side ? 1 : 0;  // the band's side: +1 away from the part
  if (!x.one_side && (cp.tolerance_side == ToleranceSide::left || cp.tolerance_side == ToleranceSide::right))
    away = (cp.tolerance_side == ToleranceSide::left ? 1 : -1) == x.side ? 1 : -1;
  x.middle = away * 0.5 * job.tolerance;
  return x;
}

size_t passes(const Job& job, const Entity& e, const MachineProfile& m) {
  const CutParams cp = cut_params(job, e, m);
  const std::optional<double> step = cp.pass_depth();  // step_down, or the tool's flute length
  if (!step) return 1;
  return static_cast<size_t>(std::ceil((cp.top_z - cp.cut_z) / *step - 1e-9));
}

TEST(PartRoundTrip, EveryPartSampleInEveryModeKeepsItsBandFromThePart) {
  const auto samples = part_samples();
  ASSERT_GE(samples.size(), 3u);
  std::map<std::string, std::map<std::string, size_t>> blocks;  // sample -> profile/mode -> cutting blocks
  for (const char* name : {"generic", "fanuc", "linuxcnc"}) {
    const MachineProfile m = load_machine_profile(name);
    for (const auto& [file, original] : samples) {
      for (bool leads : {false, true}) {
        Job job = original;
        // A pocket's passes are checked by its certificate and by
        // tests/cam/pocket_test.cpp, holes by tests/cam/holes_test.cpp and
        // tests/gcode/drill_output_test.cpp; this test reads profiles.
        std::erase_if(job.entities, [&](const Entity& e) {
          const auto op = cut_params(original, e, m).pocket.operation;
          return op == Operation::pocket || op == Operation::drill || op == Operation::bore;
        });
        for (size_t i = 0; i < job.entities.size(); ++i) job.entities[i].index = i;
        if (!leads) {
          job.params.lead.reset();
          for (auto& e : job.entities) e.params.lead.reset();
        }
        for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
          if (leads && mode != OutputMode::arcs) continue;  // the leads' check needs one mode
          // generic has no NURBS words: its nurbs output is its arcs output.
          if (m.nurbs == NurbsDialect::none && mode == OutputMode::nurbs) continue;
          SCOPED_TRACE(file.filename().string() + " for " + name + ", --output " + to_string(mode) +
                       (leads ? ", with leads" : ", leads removed"));
          ConvertOptions opt;
          opt.output = mode;
          opt.measure = false;  // measured here, from the text
          const ConvertResult r = convert(job, m, opt);
          std::vector<MotionBlock> read;
          ASSERT_NO_THROW(read = read_gcode(r.gcode, &m));
          const auto findings = lint_gcode(r.gcode, m);
          EXPECT_TRUE(findings.empty()) << findings.front().line << ": " << findings.front().message;
          const auto runs = cutting_runs(read);
          size_t want = 0;
          for (const auto& rep : r.program.entities)
            want += passes(job, job.entities[static_cast<size_t>(rep.entity)], m);
          ASSERT_EQ(runs.size(), want);
          size_t at = 0, cut = 0;
          const double tol = r.program.tolerance;
          for (const auto& rep : r.program.entities) {
            const Entity& e = job.entities[static_cast<size_t>(rep.entity)];
            at += passes(job, e, m);
            const auto& run = runs[at - 1];  // the last pass
            cut += rep.blocks;
            const Expect x = expected(job, e, m);
            const std::vector<std::vector<Bezier>> curves{e.curve.pieces};
            // Drop the plunge (straight down onto the path).
            const std::vector<MotionBlock> moves(run.begin() + 1, run.end());
            const auto path = xy_path(moves, 0.02);
            const OffsetReading o =
                measure_offset(curves, path, {.r = x.r, .side = x.side, .middle = x.middle, .resolution = 5e-3 * tol});
            const double res = 1e-2 * tol;  // the reading's resolution, twice
            if (x.waste || x.one_side) {
              // Never into the part, even by the chord error.
              EXPECT_GE(o.min_distance, x.r - res) << e.label();
              if (!leads) EXPECT_LE(o.max_distance, x.r + tol + res) << e.label();
            } else if (!leads) {
              EXPECT_GE(o.min_distance, x.r - tol - res) << e.label();
              EXPECT_LE(o.max_distance, x.r + tol + res) << e.label();
            }
            EXPECT_LE(o.coverage, tol + res) << e.label();
          }
          if (!leads) blocks[file.stem().string()][std::string(name) + " " + to_string(mode)] = cut;
        }
      }
    }
  }
  std::cout << "[ blocks   ] cutting blocks of the part samples (all passes, leads removed):\n";
  for (const auto& [sample, per] : blocks) {
    std::cout << "[ blocks   ]   " << sample << ":";
    for (const auto& [what, n] : per) std::cout << " " << what << " " << n << ";";
    std::cout << "\n";
  }
}

// Controller compensation (G41/G42 D-): the program carries the part's
// edge; the reader, given the diameters the D registers hold, makes of it
// the tool centre's path as the controller does (cutter_comp.hpp, the model
// LinuxcncRs274 checks against LinuxCNC's interpreter). That path, measured
// against the part by the independent offset measurement, never comes
// nearer than r (the sample leaves its tolerance on the waste side) and
// reaches every point of the true offset within the tolerance. The leads
// (always there: compensation is entered and left on them) go away from the
// part, so the farthest reading is not a band here.
TEST(PartRoundTrip, ControllerCompensationPutsTheToolCentreOnTheOffset) {
  const fs::path file = BEZCAM_SOURCE_DIR "/samples/controller-comp/flange-g41.json";
  const Job job = test::load_sample(file);
  for (const char* name : {"generic", "fanuc", "linuxcnc"}) {
    const MachineProfile m = load_machine_profile(name);
    SCOPED_TRACE(std::string(name) + ", --output arcs");
    ConvertOptions opt;
    opt.output = OutputMode::arcs;
    const ConvertResult r = convert(job, m, opt);
    EXPECT_NE(r.gcode.find("G41 D1"), std::string::npos);
    EXPECT_NE(r.gcode.find("G41 D2"), std::string::npos);
    // The header says what each register must hold, before the first G41.
    const size_t d1 = r.gcode.find("D1: tool radius 3 mm"), d2 = r.gcode.find("D2: tool radius 1.5 mm");
    EXPECT_LT(d1, r.gcode.find("G41 D"));
    EXPECT_LT(d2, r.gcode.find("G41 D"));
    EXPECT_EQ(r.gcode.find("diameter 6 mm", d1), d1 + std::string("D1: tool radius 3 mm [").size());
    // Without the registers the reader refuses, naming the line.
    try {
      (void)read_gcode(r.gcode, &m);
      ADD_FAILURE() << "read without the D registers";
    } catch (const InputError& e) {
      EXPECT_EQ(e.id(), "gcode.cutter-comp");
    }
    MachineProfile set_up = m;
    set_up.tool_diameters_mm = {{1, 6.0}, {2, 3.0}};
    const auto read = read_gcode(r.gcode, &set_up);
    const auto runs = cutting_runs(read);
    size_t at = 0;
    const double tol = r.program.tolerance;
    for (const auto& rep : r.program.entities) {
      const Entity& e = job.entities[static_cast<size_t>(rep.entity)];
      at += passes(job, e, m);
      ASSERT_LE(at, runs.size());
      const auto& run = runs[at - 1];
      const Expect x = expected(job, e, m);
      ASSERT_TRUE(x.waste);
      const std::vector<std::vector<Bezier>> curves{e.curve.pieces};
      const std::vector<MotionBlock> moves(run.begin() + 1, run.end());  // not the plunge
      const OffsetReading o = measure_offset(curves, xy_path(moves, 0.02),
                                             {.r = x.r, .side = x.side, .middle = x.middle, .resolution = 5e-3 * tol});
      const double res = 1e-2 * tol;
      EXPECT_GE(o.min_distance, x.r - res) << e.label();
      EXPECT_LE(o.coverage, tol + res) << e.label();
    }
    // NURBS blocks are not compensated by these controllers: refused.
    if (m.nurbs != NurbsDialect::none) {
      opt.output = OutputMode::nurbs;
      try {
        (void)convert(job, m, opt);
        ADD_FAILURE() << "nurbs output under controller compensation";
      } catch (const InputError& e) {
        EXPECT_EQ(e.id(), "job.cut");
        EXPECT_NE(std::string(e.what()).find("job.compensation"), std::string::npos) << e.what();
      }
    }
  }
}

}  // namespace
}  // namespace bezcam
