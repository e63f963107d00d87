// The preview's page through the executable: its header gives the cycle
// time the program's header gives.
#include <gtest/gtest.h>
#include <regex>

#include "support/mini_xml.hpp"
#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;
using testproc::run;

testproc::Result bezcam(const std::vector<std::string>& args) {
  return run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, BEZCAM_SOURCE_DIR);
}

// Every cycle time a text states ("estimated cycle time 2 min 51 s").
std::vector<std::string> cycle_times(const std::string& text) {
  static const std::regex re(R"(cycle time (\d+ h )?(\d+ min )?\d+ s)");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
    out.push_back(it->str());
  return out;
}

std::string all_text(const testxml::Element& e) {
  std::string s = e.text + "\n";
  for (const auto& c : e.children) s += all_text(c);
  return s;
}

TEST(PreviewPage, GivesTheCycleTimeOfTheProgramsHeader) {
  testproc::TempDir dir;
  for (const char* machine : {"linuxcnc", "fanuc", "generic", "grbl"})
    for (const char* job : {"samples/part-flange.json", "samples/part-lettering.json"}) {
      SCOPED_TRACE(std::string(job) + " on " + machine);
      const fs::path nc = dir / "p.nc", svg = dir / "p.svg";
      ASSERT_EQ(bezcam({"convert", job, "--machine", machine, "-o", nc.string(), "-q"}).status, 0);
      const auto header = cycle_times(testproc::slurp(nc));
      ASSERT_EQ(header.size(), 1u);
      for (const char* colour : {"", "--feed"}) {
        std::vector<std::string> args{"preview", job, "--machine", machine, "-o", svg.string(), "-q"};
        if (*colour) args.push_back(colour);
        ASSERT_EQ(bezcam(args).status, 0);
        const auto root = testxml::parse(testproc::slurp(svg));
        // The header and the legend state one cycle time: the program's.
        std::string said;
        for (const char* part : {"header", "legend"})
          for (const auto* g : root.by_class(part)) said += all_text(*g);
        const auto preview = cycle_times(said);
        ASSERT_FALSE(preview.empty()) << said;
        for (const auto& t : preview) EXPECT_EQ(t, header[0]) << said;
        EXPECT_EQ(said.find("about "), std::string::npos) << said;
      }
    }
}

}  // namespace
