// The stated limits of the post-processor and the G-code reader
// (limits.hpp, docs/limits.md): pathological but valid inputs finish or are
// refused quickly, with an error naming the place. "Quickly" is checked by
// ctest's TIMEOUT for *Limits* tests (CMakeLists.txt), not by assertions.
#include "bezcam/limits.hpp"

#include <cmath>
#include <functional>
#include <gtest/gtest.h>
#include <string>

#include "bezcam/cam/program_limits.hpp"
#include "bezcam/error.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/job/job_json.hpp"

using namespace bezcam;

namespace {

struct Refusal {
  std::string id, where, message;
};

Refusal refusal_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return {e.id(), e.where(), e.message()};
  }
  return {};
}

const MachineProfile& generic() {
  static const MachineProfile m = load_machine_profile("generic");
  return m;
}

Refusal convert_refusal(const std::string& text, ConvertOptions opt = {}) {
  return refusal_of([&] { convert(parse_job(text, "job.json"), generic(), opt); });
}

std::string job(const std::string& head, const std::string& entities) {
  return R"({"bezcam": 1, )" + head + R"("entities": [)" + entities + "]}";
}

// A Fanuc NURBS block of n control points (rank 4, clamped uniform knots),
// its first point at the current position.
std::string long_nurbs_block(size_t n) {
  std::string p = "G21 G90 G17\nT1 M06\nS1000 M03\nG00 X0. Y0. Z0.\nG01 F100.\nG06.2 P4 K0. X0. Y0. Z0. R1.\n";
  p.reserve(n * 28);
  for (size_t i = 1; i < n; ++i) {
    const size_t k = i <= 3 ? 0 : i - 3;
    p += "K" + std::to_string(k) + ". X" + std::to_string(i % 100) + ". Y" + std::to_string(i % 7) + ".\n";
  }
  for (int i = 0; i < 4; ++i) p += "K" + std::to_string(n - 3) + ".\n";
  return p + "M30\n";
}

}  // namespace

TEST(Limits, ATolerancePrecisionCannotHonourIsRefusedNamingTheEntity) {
  // 1e-9 mm on coordinates of 1e5 mm: the smallest meaningful tolerance
  // there is 1e-7 mm.
  const std::string text =
      job(R"("tolerance": 1e-9, )", R"({"id": "far", "type": "bezier", "points": [[0,0],[50000,10000],[100000,0]]})");
  Refusal r = convert_refusal(text);
  EXPECT_EQ(r.id, "limit.tolerance-precision");
  EXPECT_EQ(r.where, "job.json: tolerance");
  EXPECT_NE(r.message.find("far (job.json: entities[0])"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("reach 1e+05"), std::string::npos) << r.message;
  ConvertOptions opt;
  opt.tolerance = 1e-9;
  r = convert_refusal(job("", R"({"type": "bezier", "points": [[0,0],[50000,10000],[100000,0]]})"), opt);
  EXPECT_EQ(r.id, "limit.tolerance-precision");
  // The library names the setting the caller passed, never a CLI flag.
  EXPECT_EQ(r.where, "tolerance");
}

TEST(Limits, ASegmentCountExplosionIsRefusedBeforeFlattening) {
  // A cubic B-spline zig-zagging through 10^5 points, 3e6 mm long, at
  // 0.001 mm: millions of segments.
  std::string pts, knots = "0,0,0";
  for (int i = 0; i < 100'000; ++i) pts += (i ? ",[" : "[") + std::to_string(10 * i) + (i % 2 ? ",40]" : ",0]");
  for (int i = 0; i <= 100'000 - 3; ++i) knots += "," + std::to_string(i);
  knots += ",99997,99997,99997";
  const std::string text = job(R"("tolerance": 0.001, )", R"({"type": "bspline", "degree": 3, "points": [)" + pts +
                                                              R"(], "knots": [)" + knots + "]}");
  const Job j = parse_job(text, "job.json");
  ASSERT_GT(estimate_segments(j.entities[0].curve.pieces, 0.001 - 0.0005 * std::sqrt(2.0)), double(kMaxProgramLines));
  for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
    ConvertOptions opt;
    opt.output = mode;
    const Refusal r = refusal_of([&] { convert(j, generic(), opt); });
    EXPECT_EQ(r.id, "limit.segments") << to_string(mode);
    EXPECT_EQ(r.where, "job.json: entities[0]");
    EXPECT_NE(r.message.find("lines a program may hold"), std::string::npos) << r.message;
  }
}

TEST(Limits, ALongSmoothCurveAtAMicronFinishes) {
  // A full circle 10^5 mm around (radius 15915 mm) at 0.001 mm: about 12000
  // segments, well within the limits, cut and measured; the bound holds.
  // (10^6 mm takes ten times as long; the explosion test above shows what
  // happens when the count runs away.)
  const double R = 1e5 / (2 * std::acos(-1.0)), w = std::sqrt(0.5);
  auto q = [&](double x0, double y0, double x1, double y1, double x2, double y2) {
    return R"({"type": "bezier", "weights": [1, )" + fmt_num(w) + R"(, 1], "points": [[)" + fmt_num(x0) + "," +
           fmt_num(y0) + "],[" + fmt_num(x1) + "," + fmt_num(y1) + "],[" + fmt_num(x2) + "," + fmt_num(y2) + "]]}";
  };
  const std::string circle = R"({"type": "path", "closed": true, "segments": [)" + q(R, 0, R, R, 0, R) + "," +
                             q(0, R, -R, R, -R, 0) + "," + q(-R, 0, -R, -R, 0, -R) + "," + q(0, -R, R, -R, R, 0) + "]}";
  const Job j = parse_job(job(R"("tolerance": 0.001, )", circle), "job.json");
  const Program p = build_program(j, generic(), {});
  EXPECT_LE(p.max_bound, 0.001);
  EXPECT_LE(p.max_measured, 0.001);
  EXPECT_GT(p.moves.size(), 5'000u);
  EXPECT_LT(program_lines(p), kMaxProgramLines);
}

TEST(Limits, DegreeSixtyConvertsToLinesAndArcs) {
  std::string pts;
  for (int k = 0; k <= 60; ++k)
    pts += (k ? ",[" : "[") + std::to_string(k) + "," + fmt_num(10 * std::sin(0.7 * k)) + "]";
  const Job j = parse_job(job("", R"({"type": "bezier", "points": [)" + pts + "]}"), "job.json");
  for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs}) {
    ConvertOptions opt;
    opt.output = mode;
    const ConvertResult r = convert(j, generic(), opt);
    EXPECT_LE(r.program.max_measured, j.tolerance) << to_string(mode);
    EXPECT_LE(r.program.max_bound, j.tolerance) << to_string(mode);
  }
}

TEST(Limits, AProgramOverTheLineLimitIsRefusedNamingTheEntity) {
  // Line counting: an exact-curve block prints a line per control point and
  // per knot-only block.
  Program p;
  CurveMove nurbs;
  nurbs.shape->form = CurveMove::Form::nurbs;
  nurbs.shape->ctrl.resize(5);
  nurbs.shape->order = 4;
  p.moves = {Move{}, Move{nurbs}, Move{}};
  EXPECT_EQ(program_lines(p), 1u + 9u + 1u);
  EXPECT_EQ(program_lines(p, 2), 1u);
  // An entity that takes the program past the limit is named.
  const Job j = parse_job(job("", R"({"id": "a", "type": "bezier", "points": [[0,0],[1,1]]},
                                     {"id": "b", "type": "bezier", "points": [[0,0],[1,1]]})"),
                          "job.json");
  ProgramLength length;
  std::get<CurveMove>(p.moves[1].what)
      .shape->ctrl.resize(kMaxProgramLines - 20);  // one huge block, not millions of moves
  length.after_entity(p, j, j.entities[0]);
  EXPECT_EQ(length.lines(), kMaxProgramLines - 20 + 4 + 2);
  nurbs.shape->ctrl.resize(30);
  p.moves.push_back({nurbs});
  const Refusal r = refusal_of([&] { length.after_entity(p, j, j.entities[1]); });
  EXPECT_EQ(r.id, "limit.program-length");
  EXPECT_EQ(r.where, "job.json: entities[1]");
  EXPECT_NE(r.message.find("with b the program reaches"), std::string::npos) << r.message;
}

TEST(Limits, ATinyStepoverOnAPatchIsRefusedNamingTheEntity) {
  const std::string patch =
      R"({"type": "bezier_patch", "points": [[[0,0,0],[0,100,0]],[[100,0,0],[100,100,10]]],
          "toolpath": {"stepover": 0.004}})";
  const Refusal r = convert_refusal(job(R"("tolerance": 0.001, "job": {"safe_z": 20}, )", patch));
  EXPECT_EQ(r.id, "toolpath.too-many-passes");
  EXPECT_EQ(r.where, "job.json: entities[0].toolpath.stepover");
}

TEST(Limits, ALongIdIsCutInTheProgramsComment) {
  const std::string id(10'000, 'x');
  const ConvertResult r =
      convert(parse_job(job("", R"({"id": ")" + id + R"(", "type": "bezier", "points": [[0,0],[1,1]]})"), "job.json"),
              generic(), {});
  size_t longest = 0, start = 0;
  while (start < r.gcode.size()) {
    const size_t end = r.gcode.find('\n', start);
    longest = std::max(longest, (end == std::string::npos ? r.gcode.size() : end) - start);
    start = end == std::string::npos ? r.gcode.size() : end + 1;
  }
  EXPECT_LE(longest, kMaxCommentBytes + 2);  // the text and its parentheses
  EXPECT_NE(r.gcode.find("xxx...)"), std::string::npos);
  EXPECT_NO_THROW(read_gcode(r.gcode, &generic()));
}

TEST(Limits, TheReaderRefusesAnOverlongLine) {
  const std::string text = "G21 G90 G17\nG00 X1. (" + std::string(kMaxLineBytes, 'c') + ")\nM30\n";
  const Refusal r = refusal_of([&] { read_gcode(text); });
  EXPECT_EQ(r.id, "gcode.line-too-long");
  EXPECT_EQ(r.where, "line 2");
  EXPECT_NE(r.message.find("more than the 4096"), std::string::npos) << r.message;
  const auto findings = lint_gcode(text, generic());
  ASSERT_FALSE(findings.empty());
  EXPECT_EQ(findings[0].id, "gcode.line-too-long");
  EXPECT_EQ(findings[0].line, 2);
  // A line of exactly 4096 characters (and its CR LF) is read.
  const std::string at_limit = "G21 G90 G17\nG00 X1. (" + std::string(kMaxLineBytes - 10, 'c') + ")\r\nM30\n";
  EXPECT_NO_THROW(read_gcode(at_limit));
}

TEST(Limits, TheReaderRefusesAProgramOverTheLineLimitAndLintStopsThere) {
  const std::string text(kMaxReadLines + 5, '\n');
  const Refusal r = refusal_of([&] { read_gcode(text); });
  EXPECT_EQ(r.id, "gcode.program-too-long");
  EXPECT_EQ(r.where, "line 2000001");
  const auto findings = lint_gcode(text, generic());
  ASSERT_EQ(findings.size(), 1u);  // one finding, not one per line beyond
  EXPECT_EQ(findings[0].id, "gcode.program-too-long");
  // More bytes than the reader takes: refused before the first line.
  EXPECT_EQ(refusal_of([&] { read_gcode(std::string(kMaxProgramBytes + 1, ' ')); }).id, "gcode.program-too-large");
}

TEST(Limits, ANumberTooLargeForADoubleIsRefusedNotReadAsZero) {
  // Found while hardening: from_chars leaves the value alone when it is out
  // of range, so X followed by 400 nines read as X0: another program.
  const std::string text = "G21 G90 G17\nG00 X" + std::string(400, '9') + " Y1.\nM30\n";
  const Refusal r = refusal_of([&] { read_gcode(text); });
  EXPECT_EQ(r.id, "gcode.number");
  EXPECT_EQ(r.where, "line 2");
  EXPECT_NE(r.message.find("too large"), std::string::npos) << r.message;
  // The largest that fits is read as itself.
  const auto blocks = read_gcode("G21 G90 G17\nG00 X1" + std::string(300, '0') + ". Y1.\nM30\n");
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].to.x, 1e300);
}

TEST(Limits, ANurbsBlockOfManyPointsIsReadInLinearTime) {
  // Found while hardening: each line copied the open block's points, so a
  // block of n points cost n^2 (200000 points: hours). Now it is linear.
  const size_t n = 200'000;
  const std::string text = long_nurbs_block(n);
  const auto blocks = read_gcode(text);
  ASSERT_EQ(blocks.size(), 2u);  // the G00 and the NURBS block
  EXPECT_EQ(blocks[1].ctrl.size(), n);
  EXPECT_EQ(blocks[1].knots.size(), n + 4);
  for (const auto& f : lint_gcode(text, load_machine_profile("fanuc"))) ADD_FAILURE() << f.line << ": " << f.message;
}

TEST(Limits, ARefusedLineInsideANurbsBlockLeavesTheBlockAsItWas) {
  // Lines inside a block append to its lists without copying them: a
  // refused line must be undone exactly, whether it appended (a point with a
  // decreasing knot) or completed and cleared the block (a knot-only line
  // whose block leaves the travel).
  const MachineProfile fanuc = load_machine_profile("fanuc");
  GcodeInterpreter f(&fanuc);
  int no = 0;
  for (const char* l :
       {"G21 G90 G17", "G00 X0. Y0. Z0.", "G01 F100.", "G06.2 P4 K0. X0. Y0. Z0. R1.", "K0. X1. Y1.", "K0. X2. Y0."})
    f.feed_line(l, ++no);
  // A point whose knot decreases: refused after its point was appended.
  EXPECT_EQ(refusal_of([&] { f.feed_line("K-1. X3. Y1.", ++no); }).id, "gcode.knot-order");
  f.feed_line("K0. X3. Y1.", ++no);
  // The last control point lies beyond the travel (10 m): the block is
  // refused on its last knot-only line, after it was completed.
  f.feed_line("K1. X20000. Y0.", ++no);
  for (int k = 0; k < 3; ++k) f.feed_line("K2.", ++no);
  const Refusal r = refusal_of([&] { f.feed_line("K2.", ++no); });
  EXPECT_EQ(r.id, "gcode.travel");
  // Undone exactly: the same line is refused the same way again...
  EXPECT_EQ(refusal_of([&] { f.feed_line("K2.", ++no); }).id, "gcode.travel");
  // ... and the block still has its 5 points and 8 knots: a program that
  // ends here is missing its last knot-only block.
  const Refusal open = refusal_of([&] { f.finish(); });
  EXPECT_EQ(open.id, "gcode.nurbs-open");
  EXPECT_NE(open.message.find("it has 5 control points and 3 of its 4 knot-only K blocks"), std::string::npos)
      << open.message;
}
