// Programs a machinist expects (issue "Safe on the shop floor"): a
// clearance height, per-entity start and end lines, the program number, the
// tool list and cycle time in the header, the move to the tool-change
// position, and the post options (moved part, return position, no
// comments, modal NURBS words, precision).
#include <algorithm>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/motion.hpp"
#include "bezcam/machine/planner.hpp"
#include "support/refusal.hpp"

namespace {

using namespace bezcam;

Job job_of(const std::string& job_keys, const std::string& entities) {
  return parse_job(R"({"bezcam": 1, "job": {"feed": 800, "plunge_feed": 200, "safe_z": 5, "cut_z": -1, "tool": 1)" +
                       job_keys + "}, \"entities\": [" + entities + "]}",
                   "t.json");
}

const std::string kCurve = R"({"id": "s", "type": "bezier", "points": [[0,0],[10,8],[20,0]]})";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

size_t index_of(const std::vector<std::string>& lines, const std::string& line) {
  return static_cast<size_t>(std::find(lines.begin(), lines.end(), line) - lines.begin());
}

using test::refusal_of;

}  // namespace

TEST(Clearance, RapidsDownToTheClearancePlaneAndFeedsOnlyTheLastStretch) {
  const Job j = job_of(R"(, "top_z": 2, "clearance": 1)", kCurve);
  const auto lines = lines_of(convert(j, load_machine_profile("generic"), {}).gcode);
  const size_t over = index_of(lines, "X0. Y0.");  // the rapid over the start (G00 is modal)
  ASSERT_LT(over + 2, lines.size());
  EXPECT_EQ(lines[over + 1], "Z3.");             // rapid down to top_z + clearance
  EXPECT_EQ(lines[over + 2], "G01 Z-1. F200.");  // feed from there
  // Without clearance: the plunge feeds from safe Z.
  const auto plain = lines_of(convert(job_of("", kCurve), load_machine_profile("generic"), {}).gcode);
  EXPECT_EQ(plain[index_of(plain, "X0. Y0.") + 1], "G01 Z-1. F200.");
  // At or above safe Z it changes nothing.
  const auto high = lines_of(convert(job_of(R"(, "clearance": 9)", kCurve), load_machine_profile("generic"), {}).gcode);
  EXPECT_EQ(high, plain);
}

TEST(Clearance, APlaneAtOrBelowTheCutIsRefused) {
  const Job j = job_of(R"(, "top_z": -2, "clearance": 0.5)", kCurve);
  const InputError e = refusal_of([&] { convert(j, load_machine_profile("generic"), {}); });
  EXPECT_EQ(e.id(), "job.range");
  EXPECT_EQ(e.where(), "t.json: entities[0].clearance");
  EXPECT_NE(std::string(e.what()).find("not above cut_z"), std::string::npos) << e.what();
  EXPECT_EQ(refusal_of([] { job_of(R"(, "clearance": -1)", kCurve); }).id(), "job.range");
}

TEST(Clearance, SurfacePassesLinkAtTheClearanceAboveTheSurfaceNotAtSafeZ) {
  // A raster over a gently curved patch: between passes the tool lifts to
  // 1 above the patch's top (z = 1), not to safe Z 5.
  const std::string patch = R"({"id": "p", "type": "bezier_patch", "toolpath": {"pattern": "raster", "stepover": 4},
      "points": [[[0,0,0],[0,10,0.5],[0,20,0]], [[10,0,0.5],[10,10,1],[10,20,0.5]], [[20,0,0],[20,10,0.5],[20,20,0]]]})";
  const Job j = job_of(R"(, "clearance": 1)", patch);
  const ConvertResult r = convert(j, load_machine_profile("generic"), {});
  const double top = 1, clear = 2;  // the patch's top is below its highest control point: at most 1
  int at_clear = 0, at_safe = 0;
  for (const Move& mv : r.program.moves) {
    if (!is_rapid(mv)) continue;
    const Motion* m = motion_of(mv);
    if (m->to.z == 5) ++at_safe;
    if (m->to.z < 5) {
      EXPECT_LE(m->to.z, clear);
      EXPECT_GT(m->to.z, top);
      ++at_clear;
    }
  }
  EXPECT_GT(at_clear, 4);  // every link between passes
  EXPECT_LE(at_safe, 4);   // the first approach and the final retract only
  // The validator accepts the links (convert validated them) and the
  // report says where the plane is.
  ASSERT_EQ(r.program.entities.size(), 1u);
  EXPECT_LE(r.program.entities[0].clear_z, clear);
}

TEST(EntityLines, BeforeAndAfterArePrintedAroundTheEntityWithPlaceholdersReplaced) {
  const Job j =
      job_of(R"J(, "spindle_rpm": 9000, "before": ["(start {entity} with T{tool} at {rpm} rpm, Z{cut_z})", "M62 P1"],
                         "after": "M63 P1")J",
             kCurve);
  const auto lines = lines_of(convert(j, load_machine_profile("generic"), {}).gcode);
  const size_t b = index_of(lines, "(start s with T1 at 9000 rpm, Z-1)");
  const size_t a = index_of(lines, "M63 P1");
  ASSERT_LT(b, lines.size());
  ASSERT_LT(a, lines.size());
  EXPECT_EQ(lines[b + 1], "M62 P1");
  EXPECT_EQ(lines[b + 2], "G00 Z5.");                               // then the approach
  EXPECT_EQ(lines[a - 1].rfind("G00 Z5.", 0), 0u) << lines[a - 1];  // after the retract
}

TEST(EntityLines, AnUnknownPlaceholderOrALineBreakIsRefusedNamingTheLine) {
  InputError e = refusal_of([] { job_of(R"J(, "before": ["M62 P1", "(T{tol})"])J", kCurve); });
  EXPECT_EQ(e.id(), "job.template");
  EXPECT_EQ(e.where(), "t.json: job.before[1]");
  EXPECT_NE(std::string(e.what()).find("did you mean {tool}?"), std::string::npos) << e.what();
  e = refusal_of([] { job_of(R"(, "after": "M5\nM30")", kCurve); });
  EXPECT_EQ(e.id(), "job.template");
  EXPECT_NE(std::string(e.what()).find("line break"), std::string::npos) << e.what();
}

TEST(Header, ProgramNumberToolListAndCycleTime) {
  const Job j = parse_job(R"({"bezcam": 1, "job": {"program_number": 42, "feed": 600},
      "entities": [{"id": "a", "type": "bezier", "points": [[0,0],[60,0]]},
                   {"id": "b", "type": "bezier", "points": [[0,10],[60,10]], "tool": 2},
                   {"id": "c", "type": "bezier", "points": [[0,20],[60,20]]}]})",
                          "t.json");
  const auto fanuc = lines_of(convert(j, load_machine_profile("fanuc"), {}).gcode);
  EXPECT_EQ(fanuc[1], "O0042 (BEZCAM)");
  const auto generic = lines_of(convert(j, load_machine_profile("generic"), {}).gcode);
  EXPECT_LT(index_of(generic, "(program 42)"), generic.size());  // no O word there: a comment
  EXPECT_LT(index_of(generic, "(T1: a, c)"), generic.size());
  EXPECT_LT(index_of(generic, "(T2: b)"), generic.size());
  // 180 mm at 600 mm/min is 18 s of cutting, plus plunges and rapids.
  const auto t = std::find_if(generic.begin(), generic.end(),
                              [](const std::string& l) { return l.rfind("(estimated cycle time ", 0) == 0; });
  ASSERT_NE(t, generic.end());
  // The machine's motion model plans it (machine/planner.hpp): more than the
  // feeds alone, since it accelerates, stops at corners and changes tools.
  const MachineProfile g = load_machine_profile("generic");
  const ConvertResult r = convert(j, g, {});
  const double s = plan_motion(program_timeline(r.program), *g.motion).cycle_time_s;
  EXPECT_GT(s, motion_totals(program_motion(r.program), 1e5).time_s());
  EXPECT_GT(s, 18 + g.motion->tool_change_s);
  EXPECT_NE(t->find(std::to_string(std::lround(s)) + " s on the motion model of machine generic"), std::string::npos)
      << *t << " vs " << s;
  // The caller's number wins.
  ConvertOptions o;
  o.program_number = 7;
  EXPECT_EQ(lines_of(convert(j, load_machine_profile("fanuc"), o).gcode)[1], "O0007 (BEZCAM)");
}

TEST(ToolChange, TheMachineGoesToTheToolChangePositionAndComesBackAtSafeZ) {
  const Job j = parse_job(R"({"bezcam": 1, "entities": [{"type": "bezier", "points": [[0,0],[60,0]]},
      {"type": "bezier", "points": [[0,10],[60,10]], "tool": 2}]})",
                          "t.json");
  const auto l = lines_of(convert(j, load_machine_profile("linuxcnc"), {}).gcode);
  const size_t t2 = index_of(l, "T2 M6");
  ASSERT_LT(t2, l.size());
  EXPECT_EQ(l[t2 - 1], "G53 G0 Z0");
  EXPECT_EQ(l[t2 - 2], "M5");
  // The next approach sets Z before any XY move.
  const auto next_xy = std::find_if(l.begin() + static_cast<long>(t2), l.end(),
                                    [](const std::string& s) { return s.find('X') != std::string::npos; });
  const auto z = std::find_if(l.begin() + static_cast<long>(t2), l.end(),
                              [](const std::string& s) { return s.rfind("G0 Z", 0) == 0; });
  EXPECT_LT(z, next_xy);
}

TEST(PostOptions, AMovedPartIsTheSameProgramMovedAndKeepsItsProvenDeviation) {
  const Job j = job_of("", kCurve);
  const MachineProfile m = load_machine_profile("generic");
  for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs}) {
    ConvertOptions o;
    o.output = mode;
    const ConvertResult a = convert(j, m, o);
    o.offset = {100.25, -3.5, 0};
    const ConvertResult b = convert(j, m, o);
    ASSERT_EQ(a.program.moves.size(), b.program.moves.size());
    for (size_t i = 0; i < a.program.moves.size(); ++i) {
      const Motion* ma = motion_of(a.program.moves[i]);
      const Motion* mb = motion_of(b.program.moves[i]);
      ASSERT_EQ(!ma, !mb);
      if (!ma) continue;
      if (ma->axes & kAxisX) EXPECT_NEAR(mb->to.x, ma->to.x + 100.25, 1e-12);
      if (ma->axes & kAxisY) EXPECT_NEAR(mb->to.y, ma->to.y - 3.5, 1e-12);
      EXPECT_EQ(mb->to.z, ma->to.z);
    }
    EXPECT_EQ(a.program.max_measured, b.program.max_measured);
    EXPECT_NE(b.gcode.find("(the part is moved by X100.25 Y-3.5)"), std::string::npos);
  }
  // An offset finer than the decimals is rounded, and said.
  ConvertOptions o;
  o.offset = {0.00049, 0, 0};
  EXPECT_EQ(convert(j, m, o).program.offset.x, 0);
  o.offset = {1.23456, 0, 0};
  const ConvertResult r = convert(j, m, o);
  EXPECT_DOUBLE_EQ(r.program.offset.x, 1.235);
  EXPECT_NE(r.gcode.find("rounded to 3 decimals"), std::string::npos);
}

TEST(PostOptions, ReturnToEndsWhereAsked) {
  ConvertOptions o;
  o.return_to = Vec3{0, 200, 20};
  const ConvertResult r = convert(job_of("", kCurve), load_machine_profile("generic"), o);
  const auto motion = program_motion(r.program);
  ASSERT_FALSE(motion.empty());
  EXPECT_EQ(motion.back().to, (Vec3{0, 200, 20}));
  // Up first (20 is above safe Z), then across: never across below safe Z.
  const auto l = lines_of(r.gcode);
  const size_t across = index_of(l, "X0. Y200.");
  ASSERT_LT(across, l.size());
  EXPECT_EQ(l[across - 1], "Z20.");
}

TEST(PostOptions, NoCommentsAndModalNurbsWords) {
  const Job j = job_of("", R"({"type": "bspline", "degree": 3, "points": [[0,0],[10,10],[20,0],[30,10],[40,0]],
                                     "knots": [0,0,0,0,0.5,1,1,1,1]})");
  MachineProfile m = load_machine_profile("fanuc");
  ConvertOptions o;
  o.output = OutputMode::nurbs;
  const std::string full = convert(j, m, o).gcode;
  m.comments = false;
  m.modal = true;
  const std::string bare = convert(j, m, o).gcode;
  EXPECT_EQ(bare.find('('), bare.find("(BEZCAM)"));  // only the profile's raw header line
  // Every G06.2 point after the first left out Z and R (all 0 and 1 here).
  size_t points = 0;
  for (const auto& l : lines_of(bare)) {
    if (l.find(" K") == std::string::npos || l.find("G06.2") != std::string::npos) continue;
    if (l.find(" X") == std::string::npos) continue;  // the closing knots
    ++points;
    EXPECT_EQ(l.find(" Z"), std::string::npos) << l;
    EXPECT_EQ(l.find(" R"), std::string::npos) << l;
  }
  EXPECT_GE(points, 4u);
  // Both read back as the same motion.
  const auto a = read_gcode(full, &m), b = read_gcode(bare, &m);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].to, b[i].to);
    EXPECT_EQ(a[i].ctrl, b[i].ctrl);
    EXPECT_EQ(a[i].weights, b[i].weights);
    EXPECT_EQ(a[i].knots, b[i].knots);
  }
}
