// --output arcs and --output nurbs end to end: job -> program -> text, per
// dialect (the words, their order and decimals), fallbacks and refusals.
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"

namespace bezcam {
namespace {

Job job_of(const std::string& entity, const std::string& extra = "") {
  return parse_job(R"({"bezcam": 1, "tolerance": 0.01, )" + extra +
                       R"("job": {"feed": 600, "plunge_feed": 200, "safe_z": 5, "cut_z": -0.5},
                           "entities": [)" +
                       entity + "]}",
                   "t.json");
}
const std::string kSemicircle = R"({"id": "semi", "type": "bezier", "points": [[-3,0],[-3,4],[3,4],[3,0]]})";
const std::string kQuarter =
    R"({"id": "q", "type": "bezier", "points": [[10,0],[10,10],[0,10]], "weights": [1, 0.7071067811865476, 1]})";
const std::string kQuartic = R"({"id": "q4", "type": "bezier", "points": [[0,-1],[1,1],[0,0],[-1,0],[0,1]]})";
const std::string kTwisted = R"({"id": "c3", "type": "bezier", "points": [[0,0,0],[1,0,0],[1,1,0],[1,1,1]]})";

// LinuxCNC's words with a planner that gives arcs the acceleration of
// lines: arcs and exact blocks all along (no lines where the tool changes
// speed, docs/motion.md), for the tests of the words themselves.
MachineProfile words_of(const std::string& machine) {
  MachineProfile m = load_machine_profile(machine);
  if (m.motion) m.motion->planner = MotionModel::Planner::generic;
  return m;
}

ConvertResult run(const Job& j, const MachineProfile& m, OutputMode mode) {
  ConvertOptions o;
  o.output = mode;
  return convert(j, m, o);
}

ConvertResult run(const Job& j, const std::string& machine, OutputMode mode) { return run(j, words_of(machine), mode); }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

size_t count_matching(const std::string& text, const std::regex& re) {
  size_t n = 0;
  for (const auto& l : lines_of(text)) n += std::regex_search(l, re);
  return n;
}

TEST(OutputArcs, SemicircleBecomesFewG02ArcsWithIJOnly) {
  for (const char* m : {"generic", "fanuc", "linuxcnc", "grbl"}) {
    SCOPED_TRACE(m);
    const auto arcs = run(job_of(kSemicircle), m, OutputMode::arcs);
    const auto lines = run(job_of(kSemicircle), m, OutputMode::lines);
    const std::regex arc_re(R"((^|\s)G0?2 X-?[0-9.]+ Y-?[0-9.]+ I-?[0-9.]+ J-?[0-9.]+( F[0-9.]+)?$)");
    const size_t n = count_matching(arcs.gcode, arc_re);
    EXPECT_GE(n, 3u);
    // A third of the lines at most (tangent arcs: one more than free ones here).
    EXPECT_EQ(arcs.program.entities[0].blocks * 3 <= lines.program.entities[0].blocks, true)
        << arcs.program.entities[0].blocks << " vs " << lines.program.entities[0].blocks;
    EXPECT_EQ(arcs.gcode.find(" K"), std::string::npos);  // never the K word in G17
    EXPECT_LE(arcs.program.max_bound, 0.01);
    EXPECT_LE(arcs.program.max_measured, arcs.program.max_bound + 1e-5);
  }
}

TEST(OutputArcs, RefusedByAMachineWithoutArcs) {
  MachineProfile m = load_machine_profile("generic");
  m.arcs = false;
  m.name = "no-arcs";
  ConvertOptions o;
  o.output = OutputMode::arcs;
  try {
    convert(job_of(kSemicircle), m, o);
    FAIL() << "expected a refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "usage.output");
    EXPECT_NE(e.message().find("\"no-arcs\" does not take arcs"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("lines output"), std::string::npos) << e.message();
  }
}

TEST(OutputArcs, NonPlanarCurveTakesHelicalArcsOnlyWhereTheySaveBlocks) {
  // A twisted cubic is no helix: band lines (as in lines output) need
  // fewer blocks than helical arcs would, and are written.
  const auto r = run(job_of(kTwisted), "generic", OutputMode::arcs);
  EXPECT_EQ(count_matching(r.gcode, std::regex(R"(G0?[23] )")), 0u);
  EXPECT_LE(run(job_of(kTwisted), "generic", OutputMode::lines).program.entities[0].blocks,
            r.program.entities[0].blocks);
  // A ramp round a quarter circle (z falling 2 over it) is nearly a
  // helix: helical arcs (G02/G03 with Z), a handful where lines need dozens,
  // within the tolerance by the independent measurement.
  const std::string ramp =
      R"({"id": "ramp", "type": "bezier", "points": [[10,0,0],[10,10,-1],[0,10,-2]], "weights": [1, 0.7071067811865476, 1]})";
  for (const char* m : {"generic", "fanuc", "linuxcnc", "grbl"}) {
    SCOPED_TRACE(m);
    const auto a = run(job_of(ramp), m, OutputMode::arcs), l = run(job_of(ramp), m, OutputMode::lines);
    const size_t helical =
        count_matching(a.gcode, std::regex(R"((^|\s)G0?3 X-?[0-9.]+ Y-?[0-9.]+ Z-?[0-9.]+ I-?[0-9.]+ J-?[0-9.]+)"));
    EXPECT_GE(helical, 1u) << a.gcode;
    EXPECT_LT(a.program.entities[0].blocks * 3, l.program.entities[0].blocks)
        << a.program.entities[0].blocks << " vs " << l.program.entities[0].blocks;
    EXPECT_LE(a.program.max_bound, 0.01);
    EXPECT_GT(a.program.max_measured, 0);
    EXPECT_LE(a.program.max_measured, a.program.max_bound * (1 + 1e-3));
    // Round Z: G17, as the program begins.
    EXPECT_EQ(count_matching(a.gcode, std::regex(R"((^|\s)G1[89]$)")), 0u) << a.gcode;
  }
  EXPECT_EQ(count_matching(r.gcode, std::regex(R"((^|\s)G1[89]$)")), 0u) << r.gcode;
}

// The plane word alone on its line (after a line number, if any).
const std::regex kG18(R"(^(N\d+ )?G18$)"), kG19(R"(^(N\d+ )?G19$)"), kG17(R"(^(N\d+ )?G17$)");

// Checks that the helical arcs of `a` are in the plane `g` (18 or 19): the
// plane word before the first arc and G17 after the last, the arcs with
// both ends and the centre words of that plane only, fewer than half the
// blocks of lines output `l`, within the tolerance by the independent
// measurement.
void expect_arcs_in_plane(const ConvertResult& a, const ConvertResult& l, int g) {
  const auto ls = lines_of(a.gcode);
  const std::regex arc(R"((^|\s)G0?[23] )");
  const std::regex words(g == 18
                             ? R"((^|\s)G0?[23] X-?[0-9.]+ Y-?[0-9.]+ Z-?[0-9.]+ I-?[0-9.]+ K-?[0-9.]+( F[0-9.]+)?$)"
                             : R"((^|\s)G0?[23] Y-?[0-9.]+ Z-?[0-9.]+ J-?[0-9.]+ K-?[0-9.]+( F[0-9.]+)?$)");
  const std::regex& plane_word = g == 18 ? kG18 : kG19;
  size_t first = ls.size(), last = 0, arcs = 0;
  for (size_t i = 0; i < ls.size(); ++i)
    if (std::regex_search(ls[i], arc)) {
      first = std::min(first, i);
      last = i;
      ++arcs;
      EXPECT_TRUE(std::regex_search(ls[i], words)) << ls[i];
    }
  ASSERT_GE(arcs, 4u) << a.gcode;
  size_t selected = ls.size();
  for (size_t i = 0; i < first; ++i)
    if (std::regex_search(ls[i], plane_word)) selected = i;
  EXPECT_LT(selected, first) << a.gcode;
  for (size_t i = selected + 1; i < last; ++i) EXPECT_FALSE(std::regex_search(ls[i], kG17)) << ls[i];
  bool back = false;
  for (size_t i = last + 1; i < ls.size(); ++i) back = back || std::regex_search(ls[i], kG17);
  EXPECT_TRUE(back) << a.gcode;
  EXPECT_LT(a.program.entities[0].blocks * 2, l.program.entities[0].blocks)
      << a.program.entities[0].blocks << " vs " << l.program.entities[0].blocks;
  EXPECT_LE(a.program.max_bound, 0.01);
  EXPECT_GT(a.program.max_measured, 0);
  EXPECT_LE(a.program.max_measured, a.program.max_bound * (1 + 1e-3));
}

TEST(OutputArcs, CurveTurningRoundYTakesHelicalG18Arcs) {
  // Half a turn of a helix round Y (radius 10, Y rising 20): it spreads
  // less along Z (10) than along X (20), so G17 is tried first and fails;
  // G18 follows it in a few arcs.
  const double k = 10 * 4.0 / 3 * (std::sqrt(2.0) - 1);
  const std::string groove =
      R"({"id": "groove", "type": "path", "segments": [{"type": "bezier", "points": [[-10,0,0],[-10,3.3333333333333335,)" +
      std::to_string(-k) + R"(],[)" + std::to_string(-k) +
      R"(,6.666666666666667,-10],[0,10,-10]]}, {"type": "bezier", "points": [[0,10,-10],[)" + std::to_string(k) +
      R"(,13.333333333333334,-10],[10,16.666666666666668,)" + std::to_string(-k) + R"(],[10,20,0]]}]})";
  for (const char* m : {"generic", "fanuc", "linuxcnc", "grbl"}) {
    SCOPED_TRACE(m);
    expect_arcs_in_plane(run(job_of(groove), m, OutputMode::arcs), run(job_of(groove), m, OutputMode::lines), 18);
  }
}

TEST(OutputArcs, CurveInAPlaneXConstTakesG19Arcs) {
  // An arch in the plane x = 3: no helix, plain arcs of G19 (X stays).
  const std::string arch = R"({"id": "arch", "type": "bezier", "points": [[3,0,0],[3,0,-8],[3,20,-8],[3,20,0]]})";
  for (const char* m : {"generic", "fanuc", "linuxcnc", "grbl"}) {
    SCOPED_TRACE(m);
    expect_arcs_in_plane(run(job_of(arch), m, OutputMode::arcs), run(job_of(arch), m, OutputMode::lines), 19);
  }
}

TEST(OutputNurbs, FanucBlockIsWordedAsTheDialectPageSays) {
  const auto r = run(job_of(kSemicircle), "fanuc", OutputMode::nurbs);
  const auto ls = lines_of(r.gcode);
  auto at =
      std::find_if(ls.begin(), ls.end(), [](const std::string& l) { return l.find("G06.2") != std::string::npos; });
  ASSERT_NE(at, ls.end());
  // Line numbers, start word, rank, the first point (= the current position)
  // with its knot and weight, then the feed.
  EXPECT_TRUE(std::regex_match(*at, std::regex(R"(N\d+ G06.2 P4 K0\. X-3\. Y0\. Z-0\.5 R1\. F600\.)"))) << *at;
  EXPECT_TRUE(std::regex_match(at[1], std::regex(R"(N\d+ K0\. X-3\. Y4\. Z-0\.5 R1\.)"))) << at[1];
  EXPECT_TRUE(std::regex_match(at[3], std::regex(R"(N\d+ K0\. X3\. Y0\. Z-0\.5 R1\.)"))) << at[3];
  for (int k = 4; k < 8; ++k) EXPECT_TRUE(std::regex_match(at[k], std::regex(R"(N\d+ K1\.)"))) << at[k];
  // The move after the block names its word (any G00/G01 ends the mode).
  EXPECT_TRUE(std::regex_match(at[8], std::regex(R"(N\d+ G00 Z5\.)"))) << at[8];
  EXPECT_LT(r.program.max_bound, 1e-12);        // exact: integer points, only floating point
  EXPECT_EQ(r.program.entities[0].blocks, 8u);  // 4 points + 4 knots
}

TEST(OutputNurbs, FanucG063IsWordedLikeTheSeedsListing) {
  const auto r = run(job_of(kQuarter), "fanuc-g063", OutputMode::nurbs);
  const std::regex point(R"(K\d+\.\d{6} X-?\d+\.\d{3} Y-?\d+\.\d{3} Z-?\d+\.\d{3} R\d+\.\d{3})");
  EXPECT_EQ(count_matching(r.gcode, point), 3u);
  EXPECT_NE(r.gcode.find("G06.3 P3 K0.000000 X10.000 Y0.000 Z-0.500 R1.000 F600."), std::string::npos) << r.gcode;
  EXPECT_NE(r.gcode.find("K0.000000 X10.000 Y10.000 Z-0.500 R0.707\n"), std::string::npos);
  EXPECT_EQ(count_matching(r.gcode, std::regex(R"(^K1\.000000$)")), 3u);
  // Three weight decimals move the arc by at most a few micrometres: proven.
  EXPECT_GT(r.program.max_bound, 0);
  EXPECT_LT(r.program.max_bound, 0.001);
}

TEST(OutputNurbs, LinuxcncUsesG5G51AndG52) {
  const auto semi = run(job_of(kSemicircle), "linuxcnc", OutputMode::nurbs);
  EXPECT_NE(semi.gcode.find("G5 X3. Y0. I0. J4. P0. Q4. F600.\n"), std::string::npos) << semi.gcode;
  const auto para = run(job_of(R"({"type": "bezier", "points": [[0,0],[1,2],[2,0]]})"), "linuxcnc", OutputMode::nurbs);
  EXPECT_NE(para.gcode.find("G5.1 X2. Y0. I1. J2. F600.\n"), std::string::npos) << para.gcode;
  const auto q = run(job_of(kQuarter), "linuxcnc", OutputMode::nurbs);
  EXPECT_NE(q.gcode.find("G5.2 P1. L3 F600.\nX10. Y10. P0.7071\nX0. Y10. P1.\nG5.3\n"), std::string::npos) << q.gcode;
  // The next motion after G5.3 names its word again.
  const auto after = q.gcode.substr(q.gcode.find("G5.3\n") + 5);
  EXPECT_EQ(after.rfind("G0 Z5.", 0), 0u) << after;
}

TEST(OutputNurbs, DegreeReductionIsSaidInAComment) {
  for (const char* m : {"fanuc", "linuxcnc"}) {
    const auto r = run(job_of(kQuartic), m, OutputMode::nurbs);
    EXPECT_NE(r.gcode.find("(not exact: degree 4 reduced to"), std::string::npos) << r.gcode;
    EXPECT_LE(r.program.max_bound, 0.01);
    EXPECT_GT(r.program.max_bound, 0);
  }
}

TEST(OutputNurbs, LinuxcncNonPlanarFallsBackToLinesAndSaysWhy) {
  const auto r = run(job_of(kTwisted, R"("tolerance": 0.001, )"), "linuxcnc", OutputMode::nurbs);
  EXPECT_EQ(count_matching(r.gcode, std::regex(R"(^G5(\.\d)?\s)")), 0u);  // G5, G5.1, G5.2 (not G54)
  EXPECT_NE(r.gcode.find("(not exact: z varies"), std::string::npos) << r.gcode;
  const auto f = run(job_of(kTwisted, R"("tolerance": 0.001, )"), "fanuc", OutputMode::nurbs);
  EXPECT_NE(f.gcode.find("G06.2 P4 K0. X0. Y0. Z0. R1."), std::string::npos) << f.gcode;
}

TEST(OutputNurbs, MachinesWithoutNurbsFallBackAndSaySoInTheHeader) {
  const auto g = run(job_of(kSemicircle), "grbl", OutputMode::nurbs);
  EXPECT_NE(g.gcode.find("(machine grbl has no NURBS words: nurbs output cuts with arcs [G02/G03] and G01 lines)"),
            std::string::npos)
      << g.gcode;
  EXPECT_EQ(g.program.warnings.size(), 1u);
  EXPECT_GE(count_matching(g.gcode, std::regex(R"(^G2 )")), 3u);
  // The same program as --output arcs, but for the header.
  const auto a = run(job_of(kSemicircle), "grbl", OutputMode::arcs);
  EXPECT_EQ(g.program.moves.size(), a.program.moves.size());
  // Neither NURBS nor arcs: lines.
  MachineProfile m = load_machine_profile("generic");
  m.arcs = false;
  ConvertOptions o;
  o.output = OutputMode::nurbs;
  const auto l = convert(job_of(kSemicircle), m, o);
  EXPECT_NE(l.gcode.find("cuts with G01 lines)"), std::string::npos);
  EXPECT_EQ(count_matching(l.gcode, std::regex(R"(G0?[23] )")), 0u);
}

}  // namespace
}  // namespace bezcam
