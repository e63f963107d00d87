// The preview's page through the executable: its header gives the cycle
// time the program's header, the report and the sheet give, and no text of the header or the legend
// runs off the page.
#include <functional>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <regex>

#include "bezcam/gcode/number_format.hpp"
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

TEST(PreviewPage, GivesTheCycleTimeOfTheProgramsHeaderAsReportAndSheetDo) {
  testproc::TempDir dir;
  for (const char* machine : {"linuxcnc", "fanuc", "generic", "grbl"})
    for (const char* job : {"samples/part-flange.json", "samples/part-lettering.json"}) {
      SCOPED_TRACE(std::string(job) + " on " + machine);
      const fs::path nc = dir / "p.nc", svg = dir / "p.svg";
      const fs::path report = dir / "r.json", html = dir / "s.html";
      ASSERT_EQ(
          bezcam({"convert", job, "--machine", machine, "-o", nc.string(), "--report", report.string(), "-q"}).status,
          0);
      const auto header = cycle_times(testproc::slurp(nc));
      ASSERT_EQ(header.size(), 1u);
      // The report's and the sheet's are the same (the tool change
      // position lines of a program with two tools included).
      const auto rep = nlohmann::json::parse(testproc::slurp(report));
      if (rep["program"].contains("planned"))
        EXPECT_EQ("cycle time " + bezcam::format_clock(rep["program"]["planned"]["cycle_time_s"].get<double>()),
                  header[0]);
      ASSERT_EQ(bezcam({"sheet", job, "--machine", machine, "-o", html.string(), "-q"}).status, 0);
      for (const auto& t : cycle_times(testproc::slurp(html))) EXPECT_EQ(t, header[0]);
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

// The width of `s` in a sans-serif font, from above: per character at
// least its advance in DejaVu Sans (Debian's default sans-serif, the
// widest of the common ones), bold 12 % wider.
double width_from_above(const std::string& s, double size, bool bold) {
  double em = 0;
  for (unsigned char ch : s) {
    if ((ch & 0xC0) == 0x80) continue;
    const std::string c(1, static_cast<char>(ch));
    if (ch >= 0x80 || std::string("mwMW%@").find(c) != std::string::npos)
      em += 1.0;
    else if (std::string("=+<>#&~^*").find(c) != std::string::npos)
      em += 0.85;
    else if (std::string(" ijlftrI.,:;'|!()[]{}-/\\\"`").find(c) != std::string::npos)
      em += 0.42;
    else if (std::isupper(ch))
      em += 0.8;
    else
      em += 0.65;
  }
  return em * size * (bold ? 1.12 : 1.0);
}

// Every text of the page's header and legend lies inside the viewBox.
void expect_texts_inside(const fs::path& svg) {
  const auto root = testxml::parse(testproc::slurp(svg));
  std::istringstream vb(root.attr("viewBox"));
  double x0, y0, w, h;
  vb >> x0 >> y0 >> w >> h;
  size_t checked = 0;
  std::function<void(const testxml::Element&, double, bool)> walk = [&](const testxml::Element& e, double size,
                                                                        bool bold) {
    if (e.has("font-size")) size = std::stod(e.attr("font-size"));
    if (e.has("font-weight")) bold = e.attr("font-weight") == "bold";
    if (e.name == "text") {
      const double x = std::stod(e.attr("x")), y = std::stod(e.attr("y"));
      const double tw = width_from_above(e.text, size, bold);
      const std::string anchor = e.attr("text-anchor");
      const double left = anchor == "end" ? x - tw : anchor == "middle" ? x - tw / 2 : x;
      EXPECT_GE(left, x0) << "\"" << e.text << "\" at x " << x;
      EXPECT_LE(left + tw, x0 + w) << "\"" << e.text << "\" at x " << x << ", " << tw << " px wide";
      EXPECT_GE(y - size, y0) << e.text;
      EXPECT_LE(y, y0 + h) << e.text;
      ++checked;
    }
    for (const auto& c : e.children) walk(c, size, bold);
  };
  for (const char* part : {"header", "legend"})
    for (const auto* g : root.by_class(part)) walk(*g, 12, false);
  EXPECT_GT(checked, 8u);
}

TEST(PreviewPage, HeaderAndLegendFitOnThePage) {
  testproc::TempDir dir;
  const std::vector<std::string> plate{"samples/plate-layer0.dxf",
                                       "--machine",
                                       "linuxcnc",
                                       "--set",
                                       "side=outside",
                                       "--set",
                                       "tool=1",
                                       "--set",
                                       "tool_diameter=6",
                                       "--set",
                                       "cut_z=-6",
                                       "--set",
                                       "step_down=2",
                                       "--set",
                                       "circle<4:tool=2",
                                       "--set",
                                       "circle<4:tool_diameter=2",
                                       "--set",
                                       R"(<outside>:tabs={"count": 4, "width": 5, "height": 1.5})"};
  const std::vector<std::vector<std::string>> jobs{
      {"samples/part-flange.json"}, {"samples/part-lettering.json"}, {"samples/part-flange-tools.json"}, plate};
  for (const auto& job : jobs)
    for (const char* view : {"", "--deviation", "--feed"})
      for (const char* width : {"1200", "400"}) {
        SCOPED_TRACE(job[0] + " " + view + " --width " + width);
        const fs::path svg = dir / "p.svg";
        std::vector<std::string> args{"preview"};
        args.insert(args.end(), job.begin(), job.end());
        args.insert(args.end(), {"-o", svg.string(), "-q", "--width", width});
        if (*view) args.push_back(view);
        const auto r = bezcam(args);
        ASSERT_EQ(r.status, 0) << r.err;
        expect_texts_inside(svg);
      }
}

}  // namespace
