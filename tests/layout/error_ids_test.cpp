// Error ids are a library contract (docs/errors.md): every id is a named
// constant of include/bezcam/error_ids.hpp, listed once in the docs, used by
// the sources, and no source throws a string-literal id (the constants are
// what tools/error_ids_codemod.py writes; this test keeps it that way).
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "bezcam/error.hpp"
#include "support/files.hpp"

namespace fs = std::filesystem;

namespace {

using bezcam::test::slurp;

// name -> dotted id, as declared in error_ids.hpp.
std::map<std::string, std::string> declared() {
  const std::string text = slurp(fs::path(BEZCAM_SOURCE_DIR) / "include/bezcam/error_ids.hpp");
  static const std::regex decl(R"re(inline constexpr ErrorId (\w+)\{"([^"]+)"\};)re");
  std::map<std::string, std::string> out;
  for (std::sregex_iterator it(text.begin(), text.end(), decl), end; it != end; ++it) out[(*it)[1]] = (*it)[2];
  return out;
}

// Every source file of the library and the program: path -> text.
std::map<std::string, std::string> sources() {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(BEZCAM_SOURCE_DIR) / "src")) {
    const auto ext = e.path().extension();
    if (e.is_regular_file() && (ext == ".cpp" || ext == ".hpp"))
      out[fs::relative(e.path(), BEZCAM_SOURCE_DIR).string()] = slurp(e.path());
  }
  return out;
}

}  // namespace

TEST(ErrorIds, EachConstantIsNamedAfterItsId) {
  const auto ids = declared();
  ASSERT_GT(ids.size(), 100u);
  std::set<std::string> seen;
  for (const auto& [name, dotted] : ids) {
    std::string expect = dotted;
    for (char& c : expect)
      if (c == '.' || c == '-') c = '_';
    EXPECT_EQ(name, expect) << dotted;
    EXPECT_TRUE(seen.insert(dotted).second) << dotted << " is declared twice";
  }
}

TEST(ErrorIds, EachIdIsListedOnceInTheDocs) {
  const std::string doc = slurp(fs::path(BEZCAM_SOURCE_DIR) / "docs/errors.md");
  static const std::regex row(R"re(^\| `([a-z0-9.-]+)` \|)re", std::regex::multiline);
  std::map<std::string, int> listed;
  for (std::sregex_iterator it(doc.begin(), doc.end(), row), end; it != end; ++it) ++listed[(*it)[1]];
  const auto ids = declared();
  std::set<std::string> dotted;
  for (const auto& [name, d] : ids) {
    dotted.insert(d);
    EXPECT_EQ(listed[d], 1) << d << " must be listed exactly once in docs/errors.md";
  }
  for (const auto& [d, n] : listed)
    EXPECT_TRUE(dotted.count(d)) << d << " is listed in docs/errors.md but not declared";
}

TEST(ErrorIds, NoSourceThrowsAStringLiteralId) {
  static const std::regex literal(R"re((InputError|IoError|ControllerError)\(\s*"[a-z0-9]+\.[a-z0-9.-]+")re");
  static const std::regex json_fail(R"re(\bfail\([^;"]*,\s*"[a-z]+\.[a-z0-9.-]+")re");
  static const std::regex gcode_helper(R"re((^|[^\w.>:])(fail|soft|note)\(\s*"[a-z][a-z0-9-]*")re");
  for (const auto& [path, text] : sources()) {
    std::smatch m;
    EXPECT_FALSE(std::regex_search(text, m, literal)) << path << ": " << m.str() << " (use the errc:: constant)";
    EXPECT_FALSE(std::regex_search(text, m, json_fail)) << path << ": " << m.str() << " (use the errc:: constant)";
    if (path.starts_with("src/gcode/"))
      EXPECT_FALSE(std::regex_search(text, m, gcode_helper)) << path << ": " << m.str() << " (use the errc:: constant)";
  }
}

TEST(ErrorIds, EachConstantIsUsed) {
  std::string all;
  for (const auto& [path, text] : sources()) all += text;
  for (const auto& [name, dotted] : declared())
    EXPECT_NE(all.find("errc::" + name), std::string::npos) << "errc::" << name << " is declared but never used";
}

TEST(ErrorIds, IdsCompareByTheirText) {
  using namespace bezcam;
  const std::string held = "job.knots-order";
  EXPECT_TRUE(ErrorId(held) == ErrorId("job.knots-order"));
  EXPECT_FALSE(errc::job_missing == errc::job_range);
  const InputError e(errc::job_missing, Place::at_line(3), "x");
  EXPECT_EQ(e.id(), "job.missing");
  EXPECT_TRUE(e.id() == errc::job_missing);
}

TEST(ErrorPlace, ComposesTodaysText) {
  using bezcam::Place;
  EXPECT_EQ(Place::at_line(12).to_string(), "line 12");
  EXPECT_EQ(Place::in_json("job.json", "entities[3]", "knots[7]").to_string(), "job.json: entities[3].knots[7]");
  EXPECT_EQ(Place::in_json("job.json", "", "tolerance").to_string(), "job.json: tolerance");
  EXPECT_EQ(Place::at_option("--machine").to_string(), "--machine");
  Place p = Place::at_line(4);
  p.file = "prog.nc";
  EXPECT_EQ(p.to_string(), "prog.nc: line 4");
  EXPECT_EQ(Place{}.to_string(), "");
  const bezcam::InputError e(bezcam::errc::job_range, Place::in_json("a.json", "entities[0]", "cut_z"), "bad");
  EXPECT_EQ(e.where(), "a.json: entities[0].cut_z");
  EXPECT_EQ(*e.place().json_path, "entities[0].cut_z");
  EXPECT_STREQ(e.what(), "a.json: entities[0].cut_z: bad");
}
