// Resume plunges at the job's plunge feed: the program's header records the
// plunge feed per tool (and per entity where a tool's entities differ), and
// plan_resume() takes it for the tool and entity at the resume line rather
// than the profile's default; --plunge-feed still wins.
#include <gtest/gtest.h>
#include <sstream>

#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/resume.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "support/sample_job.hpp"

namespace bezcam {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// The flange with two tools (T2 for the bolt holes, T1 for the bore and the
// outline), its outline plunging slower than the bore: T1's entities differ.
struct Flange {
  MachineProfile m = load_machine_profile("linuxcnc");
  std::string gcode;
  std::vector<std::string> lines;
  Flange() {
    Job job = test::load_sample(BEZCAM_SOURCE_DIR "/samples/part-flange-tools.json");
    for (Entity& e : job.entities)
      if (e.label() == "outline") e.params.plunge_feed = 120;
    gcode = convert(job, m, ConvertOptions{}).gcode;
    lines = lines_of(gcode);
  }
  // A cutting line of `entity`, a few lines after its first plunge.
  int line_in(const std::string& entity) const {
    bool in = false;
    for (size_t i = 0; i < lines.size(); ++i) {
      if (lines[i].rfind("(entity " + entity + ":", 0) == 0) in = true;
      if (in && lines[i].rfind("G1 Z", 0) == 0) return static_cast<int>(i) + 1 + 5;
    }
    ADD_FAILURE() << "no plunge of " << entity;
    return 0;
  }
  // The preamble's plunge line.
  std::string plunge(const ResumePlan& p) const {
    for (const auto& l : lines_of(p.preamble))
      if (l.rfind("G01 Z", 0) == 0) return l;
    return "";
  }
};

TEST(ResumePlunge, HeaderRecordsThePlungeFeedPerToolAndEntity) {
  const Flange f;
  ASSERT_EQ(f.m.defaults.plunge_feed.value_or(0), 300);  // the profile's differs from the job's
  EXPECT_NE(f.gcode.find("(T2 plunge feed 200 mm/min)\n"), std::string::npos) << f.gcode.substr(0, 800);
  EXPECT_NE(f.gcode.find("(T1 plunge feed 200 mm/min: bore)\n"), std::string::npos);
  EXPECT_NE(f.gcode.find("(T1 plunge feed 120 mm/min: outline)\n"), std::string::npos);
}

TEST(ResumePlunge, PlungesAtTheJobsFeedForTheToolAndEntityThere) {
  const Flange f;
  const ResumePlan bolt = plan_resume(f.gcode, &f.m, f.line_in("bolt-2"));
  EXPECT_EQ(bolt.state.tool, 2);
  EXPECT_NE(f.plunge(bolt).find(" F200"), std::string::npos) << bolt.preamble;
  EXPECT_EQ(bolt.plunge_from, "the program's plunge feed for T2");

  const ResumePlan outline = plan_resume(f.gcode, &f.m, f.line_in("outline"));
  EXPECT_EQ(outline.state.tool, 1);
  EXPECT_NE(f.plunge(outline).find(" F120"), std::string::npos) << outline.preamble;
  EXPECT_EQ(outline.plunge_from, "the program's plunge feed for T1, entity outline");

  const ResumePlan bore = plan_resume(f.gcode, &f.m, f.line_in("bore"));
  EXPECT_NE(f.plunge(bore).find(" F200"), std::string::npos) << bore.preamble;

  // Given, --plunge-feed wins.
  const ResumePlan given = plan_resume(f.gcode, &f.m, f.line_in("outline"), ResumeSettings{std::nullopt, 90.0});
  EXPECT_NE(f.plunge(given).find(" F90"), std::string::npos) << given.preamble;
  EXPECT_EQ(given.plunge_from, "the plunge feed asked for");
}

TEST(ResumePlunge, WithoutAHeaderRecordTheProfilesPlungeFeed) {
  const Flange f;
  std::string bare;
  for (const auto& l : f.lines)
    if (l.find("plunge feed") == std::string::npos) bare += l + "\n";
  const int at = f.line_in("outline") - 3;  // three header lines fewer
  const ResumePlan p = plan_resume(bare, &f.m, at);
  EXPECT_NE(f.plunge(p).find(" F300"), std::string::npos) << p.preamble;
  EXPECT_EQ(p.plunge_from, "machine linuxcnc's plunge_feed");
}

}  // namespace
}  // namespace bezcam
