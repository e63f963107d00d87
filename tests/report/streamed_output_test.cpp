// The streamed program (issue 15, item 1): `bezcam convert` prints the
// program to its file piece by piece (write_and_report()) instead of
// holding its text. The text must be the one convert() returns whole, the
// report the one made from that text, and a timeline read back piece by
// piece the one read from the whole text.
#include <algorithm>
#include <gtest/gtest.h>
#include <random>
#include <string>
#include <vector>

#include "bezcam/bezcam.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/report/report.hpp"

using namespace bezcam;

namespace {

Job sample(const std::string& name) { return load_job(std::string(BEZCAM_SOURCE_DIR "/samples/") + name); }

struct Streamed {
  std::string text;
  size_t pieces = 0, largest = 0;
  ProgramReport report;
};

Streamed stream(const ConvertResult& r, const MachineProfile& m) {
  Streamed s;
  s.report = write_and_report(r.program, m, r.plan ? &*r.plan : nullptr, [&](std::string_view piece) {
    s.text += piece;
    ++s.pieces;
    s.largest = std::max(s.largest, piece.size());
  });
  return s;
}

}  // namespace

TEST(StreamedOutput, SameTextAndReportAsInMemory) {
  struct Case {
    const char* sample;
    const char* machine;
    OutputMode output;
  };
  const Case cases[] = {
      {"job-exercises-all.json", "generic", OutputMode::lines},
      {"job-exercises-all.json", "generic", OutputMode::arcs},
      {"job-exercises-all.json", "fanuc", OutputMode::nurbs},
      {"job-exercises-all.json", "linuxcnc", OutputMode::nurbs},
      // Two tools on a machine with tool change position lines: the plan's
      // times are the text's read back.
      {"job-two-tools.json", "fanuc", OutputMode::lines},
      {"job-two-tools.json", "linuxcnc", OutputMode::arcs},
      {"part-flange.json", "generic", OutputMode::arcs},
  };
  size_t read_back = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.sample) + " on " + c.machine + ", " + to_string(c.output));
    const Job job = sample(c.sample);
    const MachineProfile m = load_machine_profile(c.machine);
    ConvertOptions opt;
    opt.output = c.output;
    const ConvertResult whole = convert(job, m, opt);
    const ConvertResult prepared = convert_program(job, m, opt);
    EXPECT_TRUE(prepared.gcode.empty());
    const Streamed s = stream(prepared, m);
    EXPECT_EQ(s.text, whole.gcode);
    const ProgramReport expected = make_report(whole.program, m, whole.gcode, whole.plan ? &*whole.plan : nullptr);
    EXPECT_EQ(report_json(s.report), report_json(expected));
    EXPECT_EQ(s.report.gcode_bytes, whole.gcode.size());
    EXPECT_EQ(s.report.gcode_lines, static_cast<size_t>(std::count(whole.gcode.begin(), whole.gcode.end(), '\n')));
    ASSERT_TRUE(s.report.planned.has_value());
    // Without a plan the report plans the text read back as it streams:
    // the same report as the text's in memory, and the same cycle time as
    // the plan convert gives the header (the tool change position lines
    // counted either way).
    ConvertResult bare = prepared;
    bare.plan.reset();
    const Streamed b = stream(bare, m);
    EXPECT_EQ(report_json(b.report), report_json(make_report(bare.program, m, b.text, nullptr)));
    ASSERT_TRUE(b.report.planned.has_value());
    EXPECT_NEAR(b.report.planned->cycle_time_s, s.report.planned->cycle_time_s, 1e-6);
    ++read_back;
  }
  EXPECT_EQ(read_back, std::size(cases));
}

TEST(StreamedOutput, ALongProgramComesInPiecesNeverWhole) {
  // Many curves at a fine tolerance: a program of some hundred kB.
  std::string text = R"({"bezcam": 1, "units": "mm", "tolerance": 0.001, "machine": "generic", "entities": [)";
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 100);
  for (int i = 0; i < 300; ++i) {
    text += i ? ",\n" : "\n";
    text += R"({"type": "bezier", "points": [)";
    for (int k = 0; k < 4; ++k)
      text += (k ? ", [" : "[") + std::to_string(u(rng)) + ", " + std::to_string(u(rng)) + "]";
    text += "]}";
  }
  text += "]}\n";
  const Job job = parse_job(text, "many.json");
  const MachineProfile m = load_machine_profile("generic");
  const ConvertResult r = convert_program(job, m, {});
  const Streamed s = stream(r, m);
  ASSERT_GT(s.text.size(), size_t{4} << 16);
  EXPECT_GE(s.pieces, s.text.size() >> 16);  // about 64 KiB each
  EXPECT_LT(s.largest, size_t{1} << 17);
  EXPECT_EQ(s.text, write_gcode(r.program, m, r.plan ? &*r.plan : nullptr));
}

TEST(StreamedOutput, TimelineReadInPiecesIsTheTimelineReadWhole) {
  const Job job = sample("job-two-tools.json");
  const MachineProfile m = load_machine_profile("fanuc");
  for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
    ConvertOptions opt;
    opt.output = mode;
    std::string text = convert(job, m, opt).gcode;
    for (const bool last_newline : {true, false}) {
      if (!last_newline) text.pop_back();  // a last line without its newline is read too
      const Timeline whole = read_timeline(text, &m);
      std::mt19937 rng(static_cast<unsigned>(text.size()));
      std::uniform_int_distribution<size_t> len(0, 90);
      TimelineReader reader(&m);
      for (size_t at = 0; at < text.size();) {
        const size_t n = std::min(len(rng), text.size() - at);
        reader.feed(std::string_view(text).substr(at, n));
        at += n;
      }
      const Timeline pieces = reader.finish();
      ASSERT_EQ(pieces.blocks.size(), whole.blocks.size());
      for (size_t i = 0; i < whole.blocks.size(); ++i) {
        EXPECT_EQ(pieces.blocks[i].from, whole.blocks[i].from);
        EXPECT_EQ(pieces.blocks[i].to, whole.blocks[i].to);
        EXPECT_EQ(pieces.blocks[i].feed, whole.blocks[i].feed);
      }
      ASSERT_EQ(pieces.pauses.size(), whole.pauses.size());
      for (size_t i = 0; i < whole.pauses.size(); ++i) {
        EXPECT_EQ(pieces.pauses[i].line, whole.pauses[i].line);
        EXPECT_EQ(pieces.pauses[i].before_block, whole.pauses[i].before_block);
      }
      EXPECT_EQ(pieces.path_tolerance, whole.path_tolerance);
      EXPECT_EQ(plan_motion(pieces, *m.motion).cycle_time_s, plan_motion(whole, *m.motion).cycle_time_s);
    }
  }
}

TEST(StreamedOutput, AnErrorInAPieceIsTheReadersError) {
  // The same refusal, at the same line, wherever the pieces are cut.
  const std::string text = "G21 G90 G17\nG01 X1 F100\nG01 X2 Q\nG01 X3\n";
  std::string whole_error;
  try {
    (void)read_timeline(text);
  } catch (const InputError& e) {
    whole_error = e.what();
  }
  ASSERT_FALSE(whole_error.empty());
  for (size_t cut = 1; cut < text.size(); ++cut) {
    TimelineReader reader;
    std::string error;
    try {
      reader.feed(std::string_view(text).substr(0, cut));
      reader.feed(std::string_view(text).substr(cut));
      (void)reader.finish();
    } catch (const InputError& e) {
      error = e.what();
    }
    EXPECT_EQ(error, whole_error) << "cut at " << cut;
  }
}
