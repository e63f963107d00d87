// --output best (gcode/best_output.hpp): per entity the output mode with
// the shortest planned time, ties to the fewest blocks, composed from the
// moves the single modes make; the program planned whole is never slower
// than any single mode's, as the report plans both.
#include "bezcam/gcode/best_output.hpp"

#include <gtest/gtest.h>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/report/report.hpp"
#include "support/sample_job.hpp"

namespace bezcam {
namespace {

// A program's cycle as `convert` prints it (the report's plan).
double printed_cycle(const ConvertResult& r, const MachineProfile& m) {
  const ProgramReport rep = write_and_report(r.program, m, r.plan ? &*r.plan : nullptr, [](std::string_view) {});
  EXPECT_TRUE(rep.planned);
  return rep.planned ? rep.planned->cycle_time_s : 0;
}

// The moves that cut entity `e` (its approach, cut and retract).
std::vector<Move> moves_of(const Program& p, int e) {
  std::vector<Move> out;
  for (const Move& mv : p.moves)
    if (mv.entity == e && motion_of(mv)) out.push_back(mv);
  return out;
}

bool same_motion(const Move& a, const Move& b) {
  if (a.what.index() != b.what.index()) return false;
  const Motion* x = motion_of(a);
  const Motion* y = motion_of(b);
  if (x->to != y->to || x->feed != y->feed) return false;
  if (const auto* arc = std::get_if<ArcMove>(&a.what)) {
    const auto& other = std::get<ArcMove>(b.what);
    return arc->center == other.center && arc->ccw == other.ccw;
  }
  if (const auto* cv = std::get_if<CurveMove>(&a.what)) {
    const auto& other = std::get<CurveMove>(b.what);
    return cv->shape->ctrl == other.shape->ctrl && cv->shape->weights == other.shape->weights &&
           cv->shape->knots == other.shape->knots;
  }
  return true;
}

struct Case {
  const char* sample;
  const char* machine;
};

class BestOutputOnSamples : public testing::TestWithParam<Case> {};

TEST_P(BestOutputOnSamples, NeverSlowerThanAModeAndEachEntityAsItsShortestModeCutsIt) {
  const Job job = test::load_sample(std::string(BEZCAM_SOURCE_DIR "/samples/") + GetParam().sample);
  const MachineProfile m = load_machine_profile(GetParam().machine);
  const BestConversion best = convert_best(job, m, {});
  const OutputChoice& c = best.choice;
  ASSERT_FALSE(c.entities.empty());
  EXPECT_TRUE(best.result.program.best);
  const double composed = printed_cycle(best.result, m);
  EXPECT_NEAR(c.cycle_time_s, composed, 1e-9);
  std::map<OutputMode, ConvertResult> single;
  for (OutputMode mode : machine_output_modes(m)) {
    ConvertOptions o;
    o.output = mode;
    single[mode] = convert_program(job, m, o);
    const double cycle = printed_cycle(single[mode], m);
    EXPECT_LE(composed, cycle) << to_string(mode);
    // The mode weighed as `convert --output MODE` prints it.
    bool weighed = false;
    for (const OutputTiming& t : c.modes)
      if (t.output == mode) {
        weighed = true;
        EXPECT_NEAR(t.cycle_time_s, cycle, 1e-9) << to_string(mode);
      }
    EXPECT_TRUE(weighed) << to_string(mode);
  }
  EXPECT_EQ(c.modes.size(), single.size());
  for (const EntityChoice& e : c.entities) {
    // The per-entity minimum: nothing shorter by more than a tie, nothing
    // tied with fewer blocks.
    const OutputTiming* chosen = nullptr;
    for (const OutputTiming& t : c.modes)
      if (t.output == e.output) chosen = &t;
    ASSERT_TRUE(chosen);
    for (const OutputTiming& t : c.modes) {
      if (!t.entity_moves[e.entity]) continue;
      const double dt = t.entity_time_s[e.entity] - chosen->entity_time_s[e.entity];
      EXPECT_GE(dt, -kOutputTie) << e.label << " " << to_string(t.output);
      if (std::abs(dt) <= kOutputTie) EXPECT_GE(t.entity_blocks[e.entity], chosen->entity_blocks[e.entity]) << e.label;
    }
    // Composed, not invented: the entity's moves and bound are those of
    // the program in its mode.
    const OutputMode got = c.output_of(e.entity);
    const auto want = moves_of(single[got].program, static_cast<int>(e.entity));
    const auto have = moves_of(best.result.program, static_cast<int>(e.entity));
    ASSERT_EQ(have.size(), want.size()) << e.label;
    for (size_t i = 0; i < have.size(); ++i) ASSERT_TRUE(same_motion(have[i], want[i])) << e.label << " move " << i;
    for (const EntityReport& r : best.result.program.entities) {
      if (r.entity != static_cast<int>(e.entity)) continue;
      EXPECT_EQ(r.output, got) << e.label;
      for (const EntityReport& s : single[got].program.entities)
        if (s.entity == r.entity && s.label == r.label) {
          EXPECT_EQ(r.bound, s.bound) << e.label;
          EXPECT_EQ(r.blocks, s.blocks) << e.label;
        }
    }
  }
  EXPECT_LE(best.result.program.max_measured, best.result.program.tolerance);
  EXPECT_LE(best.result.program.max_bound, best.result.program.tolerance);
}

INSTANTIATE_TEST_SUITE_P(Samples, BestOutputOnSamples,
                         testing::Values(Case{"part-flange.json", "fanuc"}, Case{"part-flange.json", "linuxcnc"},
                                         Case{"part-flange.json", "grbl"}, Case{"job-exercises-all.json", "fanuc"},
                                         Case{"job-exercises-all.json", "linuxcnc"},
                                         Case{"job-exercises-all.json", "grbl"}, Case{"part-plate.json", "fanuc"}),
                         [](const auto& info) {
                           std::string n = std::string(info.param.sample) + "_" + info.param.machine;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

TEST(BestOutput, TiesGoToTheFewestBlocks) {
  // Constructed timings for a job of two entities: within the tie, the
  // mode with fewer blocks; beyond it, the shorter time.
  const Job job = test::load_sample(BEZCAM_SOURCE_DIR "/samples/part-flange.json");
  const MachineProfile m = load_machine_profile("fanuc");
  const auto timing = [&](OutputMode mode, double t0, size_t b0, double t1, size_t b1) {
    OutputTiming t;
    t.output = mode;
    t.entity_time_s.assign(job.entities.size(), 0);
    t.entity_blocks.assign(job.entities.size(), 0);
    t.entity_moves.assign(job.entities.size(), 0);
    t.entity_time_s[0] = t0, t.entity_blocks[0] = b0, t.entity_moves[0] = 1;
    t.entity_time_s[1] = t1, t.entity_blocks[1] = b1, t.entity_moves[1] = 1;
    return t;
  };
  const OutputChoice c = choose_outputs(
      job, m,
      {timing(OutputMode::nurbs, 10 + 0.5 * kOutputTie, 40, 20 - 2 * kOutputTie, 90),
       timing(OutputMode::lines, 10, 200, 20, 200), timing(OutputMode::arcs, 10 + 0.9 * kOutputTie, 30, 20, 20)});
  ASSERT_EQ(c.entities.size(), 2u);
  EXPECT_EQ(c.entities[0].output, OutputMode::arcs);   // all three tied: the fewest blocks
  EXPECT_EQ(c.entities[1].output, OutputMode::nurbs);  // shorter by more than a tie, more blocks
  // The modes in the order lines, arcs, nurbs.
  ASSERT_EQ(c.modes.size(), 3u);
  EXPECT_EQ(c.modes[0].output, OutputMode::lines);
  EXPECT_EQ(c.modes[2].output, OutputMode::nurbs);
}

TEST(BestOutput, NoNurbsOnAMachineWithoutNurbsWords) {
  const MachineProfile m = load_machine_profile("grbl");
  ASSERT_EQ(m.nurbs, NurbsDialect::none);
  const auto modes = machine_output_modes(m);
  EXPECT_EQ(std::count(modes.begin(), modes.end(), OutputMode::nurbs), 0);
  for (const char* sample : {"part-flange.json", "job-exercises-all.json", "curve-nurbs-circle.json"}) {
    const Job job = test::load_sample(std::string(BEZCAM_SOURCE_DIR "/samples/") + sample);
    const BestConversion b = convert_best(job, m, {});
    for (const OutputTiming& t : b.choice.modes) EXPECT_NE(t.output, OutputMode::nurbs) << sample;
    for (const EntityReport& r : b.result.program.entities) EXPECT_NE(r.output, OutputMode::nurbs) << sample;
    for (const Move& mv : b.result.program.moves) EXPECT_FALSE(std::holds_alternative<CurveMove>(mv.what)) << sample;
    EXPECT_TRUE(b.choice.nurbs_note.empty());
  }
}

TEST(BestOutput, NurbsOnOffsetPartsIsExplainedWhereItLoses) {
  const Job job = test::load_sample(BEZCAM_SOURCE_DIR "/samples/part-flange.json");
  // Fanuc: G06.2 spans of the offsets' arcs, more blocks than arcs.
  const BestConversion fanuc = convert_best(job, load_machine_profile("fanuc"), {});
  EXPECT_NE(fanuc.choice.nurbs_note.find("nurbs loses on the"), std::string::npos) << fanuc.choice.nurbs_note;
  EXPECT_NE(fanuc.choice.nurbs_note.find("blocks against"), std::string::npos) << fanuc.choice.nurbs_note;
  // LinuxCNC: the offsets are arcs in nurbs output too.
  const BestConversion lcnc = convert_best(job, load_machine_profile("linuxcnc"), {});
  EXPECT_NE(lcnc.choice.nurbs_note.find("are cut in arcs in nurbs output too"), std::string::npos)
      << lcnc.choice.nurbs_note;
  // A job without offsets: no word about them.
  const Job curves = test::load_sample(BEZCAM_SOURCE_DIR "/samples/curve-nurbs-circle.json");
  EXPECT_TRUE(convert_best(curves, load_machine_profile("fanuc"), {}).choice.nurbs_note.empty());
}

TEST(BestOutput, TheHeaderSaysBestAndWhatEachEntityGot) {
  const Job job = test::load_sample(BEZCAM_SOURCE_DIR "/samples/part-flange.json");
  const MachineProfile m = load_machine_profile("grbl");
  const BestConversion b = convert_best(job, m, {});
  const std::string text = write_gcode(b.result.program, m, b.result.plan ? &*b.result.plan : nullptr);
  EXPECT_NE(text.find(", output best)"), std::string::npos) << text.substr(0, 400);
  const size_t note = text.find("(output best, per entity the mode with the shortest planned time:");
  ASSERT_NE(note, std::string::npos) << text.substr(0, 800);
  const std::string line = text.substr(note, text.find('\n', note) - note);
  for (const EntityChoice& e : b.choice.entities) {
    EXPECT_NE(line.find(e.label), std::string::npos) << line;
    EXPECT_NE(text.find("(entity " + e.label + ": "), std::string::npos);
  }
  EXPECT_NE(text.find(std::string(", 2D, ") + to_string(b.choice.entities.front().output) + ")"), std::string::npos);
}

TEST(BestOutput, RefusedWithoutAMotionModel) {
  const Job job = test::load_sample(BEZCAM_SOURCE_DIR "/samples/part-flange.json");
  MachineProfile m = load_machine_profile("generic");
  m.motion.reset();
  try {
    convert_best(job, m, {});
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "usage.output");
    EXPECT_NE(std::string(e.what()).find("no motion model"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace bezcam
