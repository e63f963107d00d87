// `bezcam sheet`: the setup sheet's figures are the program's own (the
// cycle time and the chord error read as the header of the program convert
// writes with the same options, one row per tool of the header), a refused
// job writes nothing, a drawing takes convert's settings, and the page
// renders in a real browser (Debian's chromium, headless).
#include <filesystem>
#include <gtest/gtest.h>
#include <regex>

#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;
using testproc::run;

const std::map<std::string, std::string> kQuietProgress{{"BEZCAM_PROGRESS", "off"}};

testproc::Result bezcam(const std::vector<std::string>& args) {
  return run(BEZCAM_EXE, args, kQuietProgress, BEZCAM_SOURCE_DIR);
}

// The header's comment lines of a program, without line numbers and with
// the brackets the writer puts for nested parentheses turned back.
std::vector<std::string> header_comments(const std::string& nc) {
  std::vector<std::string> out;
  std::istringstream in(nc);
  for (std::string line; std::getline(in, line);) {
    if (line.find("G90 G17") != std::string::npos) break;
    const size_t open = line.find('('), close = line.rfind(')');
    if (open == std::string::npos || close == std::string::npos) continue;
    std::string c = line.substr(open + 1, close - open - 1);
    for (char& ch : c) ch = ch == '[' ? '(' : ch == ']' ? ')' : ch;
    out.push_back(c);
  }
  return out;
}

std::string starting(const std::vector<std::string>& lines, const std::string& prefix) {
  for (const auto& l : lines)
    if (l.rfind(prefix, 0) == 0) return l;
  return "";
}

// The text of the element with id `id` (a <p>, no markup inside).
std::string element_text(const std::string& html, const std::string& id) {
  const std::string open = "id=\"" + id + "\">";
  const size_t at = html.find(open);
  if (at == std::string::npos) return "";
  const size_t from = at + open.size();
  return html.substr(from, html.find('<', from) - from);
}

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

struct Case {
  std::string job;
  std::vector<std::string> options;
};

TEST(SheetCommand, CycleTimeChordErrorAndToolsAreTheProgramHeaders) {
  const Case cases[] = {
      {"samples/part-flange-tools.json", {"--machine", "fanuc"}},  // tool table, tool change moves
      {"samples/part-flange.json", {"--machine", "linuxcnc", "--output", "arcs"}},
      {"samples/job-two-tools.json", {"--machine", "grbl", "--tolerance", "0.02"}},
      {"samples/curve-semicircle.json", {}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.job);
    testproc::TempDir dir;
    std::vector<std::string> conv{"convert", c.job, "-o", (dir / "p.nc").string(), "-q"};
    std::vector<std::string> sheet{"sheet", c.job, "-o", (dir / "s.html").string()};
    conv.insert(conv.end(), c.options.begin(), c.options.end());
    sheet.insert(sheet.end(), c.options.begin(), c.options.end());
    const auto cr = bezcam(conv);
    ASSERT_EQ(cr.status, 0) << cr.err;
    const auto sr = bezcam(sheet);
    ASSERT_EQ(sr.status, 0) << sr.err;
    const auto header = header_comments(testproc::slurp(dir / "p.nc"));
    const std::string html = testproc::slurp(dir / "s.html");

    const std::string cycle = starting(header, "estimated cycle time ");
    ASSERT_FALSE(cycle.empty());
    EXPECT_EQ(element_text(html, "cycle-time"), cycle);
    EXPECT_NE(sr.err.find(cycle), std::string::npos) << sr.err;  // the summary says it too
    const std::string chord = starting(header, "tolerance ");
    ASSERT_FALSE(chord.empty());
    EXPECT_EQ(element_text(html, "chord-error"), chord);

    // One row per tool the header lists (a job of one unnumbered tool lists none).
    size_t header_tools = 0;
    for (const auto& l : header) header_tools += std::regex_search(l, std::regex("^T[0-9]+: "));
    const size_t rows = count(html, "<tr class=\"tool\"");
    EXPECT_EQ(rows, std::max<size_t>(header_tools, 1));
    for (const auto& l : header)
      if (std::smatch m; std::regex_search(l, m, std::regex("^T([0-9]+): ")))
        EXPECT_NE(html.find("data-tool=\"" + m[1].str() + "\""), std::string::npos) << l;
    // Self-contained: nothing fetched, the picture inline.
    EXPECT_EQ(count(html, "<svg"), 1u);
    EXPECT_EQ(html.find("http://www.w3.org/1999/xhtml"), std::string::npos);
    EXPECT_EQ(html.find("src="), std::string::npos);
    EXPECT_EQ(html.find("<link"), std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(dir.files(), (std::vector<std::string>{"p.nc", "s.html"}));
  }
}

TEST(SheetCommand, OperationsFollowTheCuttingOrderWithTheirFeeds) {
  testproc::TempDir dir;
  const auto r =
      bezcam({"sheet", "samples/part-flange-tools.json", "--machine", "fanuc", "-o", (dir / "s.html").string(), "-q"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::string html = testproc::slurp(dir / "s.html");
  // The holes first (order shortest), the outline last: as the program cuts them.
  std::vector<std::string> order;
  const std::regex row("<tr class=\"operation\" data-entity=\"[0-9]+\"><td>[0-9]+</td><td>([^<]+)<");
  for (std::sregex_iterator it(html.begin(), html.end(), row), end; it != end; ++it) order.push_back((*it)[1]);
  ASSERT_EQ(order.size(), 6u);
  EXPECT_EQ(order.back(), "outline");
  EXPECT_NE(html.find(">800<br><small>plunge 200<"), std::string::npos);
  EXPECT_NE(html.find("18000 rpm"), std::string::npos);
  EXPECT_NE(html.find("bull nose end mill"), std::string::npos);
  EXPECT_NE(html.find("r 0.5 mm"), std::string::npos);  // the bull's corner radius
  EXPECT_NE(html.find("Z0 on the stock top"), std::string::npos);
  EXPECT_NE(html.find("X0 at the part's centre; Y0 at the part's centre"), std::string::npos);
  // Beyond the part's +-36.7487: the outline is cut outside with a 6 mm tool, its leads further out.
  EXPECT_NE(html.find("The tools reach</th><td>X -49.096 to 42.756, Y -42.756 to 42.756 mm (about, tool edges "
                      "included)"),
            std::string::npos);
}

TEST(SheetCommand, ARefusedJobWritesNothingAsConvertRefusesIt) {
  testproc::TempDir dir;
  const fs::path out = dir / "s.html";
  testproc::write_file(out, "old sheet");
  // Moved out of the machine's travel: convert's refusal, word for word.
  const auto c = bezcam({"convert", "samples/part-flange.json", "--machine", "fanuc", "--offset", "5000,0", "-o",
                         (dir / "p.nc").string()});
  const auto s =
      bezcam({"sheet", "samples/part-flange.json", "--machine", "fanuc", "--offset", "5000,0", "-o", out.string()});
  ASSERT_EQ(c.status, 2) << c.err;
  EXPECT_EQ(s.status, 2) << s.err;
  EXPECT_EQ(s.err_first_line(), c.err_first_line());
  EXPECT_EQ(testproc::slurp(out), "old sheet");
  const auto m = bezcam({"sheet", "samples/part-flange.json", "--machine", "no-such-machine", "-o", out.string()});
  EXPECT_EQ(m.status, 2);
  EXPECT_EQ(testproc::slurp(out), "old sheet");
  EXPECT_EQ(dir.files(), std::vector<std::string>{"s.html"});
}

TEST(SheetCommand, ADrawingTakesConvertsSettings) {
  testproc::TempDir dir;
  const auto r = bezcam({"sheet", "samples/part.dxf", "--set", "feed=600", "--set", "cut_z=-1", "--output", "arcs",
                         "-o", (dir / "s.html").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string html = testproc::slurp(dir / "s.html");
  EXPECT_NE(html.find("output arcs"), std::string::npos);
  EXPECT_GT(count(html, "<tr class=\"operation\""), 1u);
  EXPECT_NE(html.find(">600<br>"), std::string::npos);
  // No tool diameter given: the reach is the tool centre's, and says so.
  EXPECT_NE(html.find("(about: the tool centre where no tool diameter is given"), std::string::npos);
}

// Chromium as Debian packages it (.ci/packages), headless.
std::string chromium() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser"})
    if (fs::exists(p)) return p;
  return "";
}

TEST(SheetInBrowser, ChromiumRendersThePictureAndTheToolTable) {
  const std::string browser = chromium();
  if (browser.empty()) GTEST_SKIP() << "chromium is not installed (Debian package chromium, .ci/packages)";
  testproc::TempDir dir;
  const fs::path page = dir / "sheet.html";
  const auto r = bezcam({"sheet", "samples/part-flange-tools.json", "--machine", "fanuc", "-o", page.string(), "-q"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> common{"--headless",        "--disable-gpu",
                                        "--no-sandbox",      "--no-first-run",
                                        "--hide-scrollbars", "--user-data-dir=" + (dir / "profile").string()};
  // The DOM as the browser built it: the tool rows and the picture.
  std::vector<std::string> dump = common;
  dump.insert(dump.end(), {"--dump-dom", "file://" + page.string()});
  const auto d = run(browser, dump, {}, dir.path().string());
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_EQ(count(d.out, "<tr class=\"tool\""), 2u) << d.out.substr(0, 400);
  EXPECT_NE(d.out.find("<svg"), std::string::npos);
  EXPECT_NE(d.out.find("id=\"top-view\""), std::string::npos);
  EXPECT_NE(d.out.find("bull nose end mill"), std::string::npos);
  // A picture of the page: a PNG of the window's size.
  std::vector<std::string> shot = common;
  shot.insert(shot.end(),
              {"--window-size=1100,3600", "--screenshot=" + (dir / "sheet.png").string(), "file://" + page.string()});
  const auto s = run(browser, shot, {}, dir.path().string());
  ASSERT_EQ(s.status, 0) << s.err;
  const std::string png = testproc::slurp(dir / "sheet.png");
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const auto be32 = [&](size_t at) {
    return static_cast<unsigned>(static_cast<unsigned char>(png[at])) << 24 |
           static_cast<unsigned>(static_cast<unsigned char>(png[at + 1])) << 16 |
           static_cast<unsigned>(static_cast<unsigned char>(png[at + 2])) << 8 |
           static_cast<unsigned>(static_cast<unsigned char>(png[at + 3]));
  };
  EXPECT_EQ(be32(16), 1100u);  // IHDR width
  EXPECT_EQ(be32(20), 3600u);  // and height
}

}  // namespace
