// Values given on the command line for a job file's entities (--set
// SELECTOR:KEY=VALUE, JobReadOptions::entity_settings): a text's letters,
// font and size replaced, other keys set by glob, and the refusals named
// at the setting.
#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/text/font_text.hpp"

namespace bezcam {
namespace {

const std::string kJob = R"({"bezcam": 1, "units": "mm", "tolerance": 0.01,
  "job": {"feed": 600, "plunge_feed": 200, "safe_z": 5, "cut_z": -0.5},
  "entities": [
    {"type": "text", "id": "serial", "text": "No. 42", "font": "DejaVu Sans", "size": 5, "side": "on"},
    {"type": "text", "id": "name", "text": "AB", "font": "DejaVu Sans", "size": 8, "at": [0, 10], "side": "on"},
    {"type": "bezier", "id": "edge", "points": [[0, 0], [50, 0]]}]})";

Job read(std::vector<EntitySetting> settings) {
  JobReadOptions o;
  o.text = text::font_outliner();
  o.entity_settings = std::move(settings);
  return parse_job(kJob, "plate.json", o);
}

std::string glyphs_of(const Job& job, const std::string& prefix) {
  std::string out;
  std::string last;
  for (const Entity& e : job.entities)
    if (e.id.starts_with(prefix + "/") && e.id != last) out += e.glyph, last = e.id;
  return out;
}

TEST(TextSettings, TheTextOfAJobIsReplacedByItsId) {
  EXPECT_EQ(glyphs_of(read({}), "serial"), "No.42");
  const Job job = read({{"serial", "text", "No. 43"}});
  EXPECT_EQ(glyphs_of(job, "serial"), "No.43");
  EXPECT_EQ(glyphs_of(job, "name"), "AB");
  // Digits alone stay text, and a quoted JSON string is that string.
  EXPECT_EQ(glyphs_of(read({{"serial", "text", "0043"}}), "serial"), "0043");
  EXPECT_EQ(glyphs_of(read({{"serial", "text", "\"7 \\u00b7 8\""}}), "serial"), "7·8");
}

TEST(TextSettings, SizeAtAlignAndFontMoveTheLetters) {
  const auto bounds_x = [](const Job& job, const std::string& id) {
    double lo = 1e9, hi = -1e9;
    for (const Entity& e : job.entities)
      if (e.id == id)
        for (const Bezier& b : e.curve.pieces)
          for (const Vec3& p : b.points) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
    return std::pair{lo, hi};
  };
  const auto [lo, hi] = bounds_x(read({}), "name/0");
  const auto [lo2, hi2] = bounds_x(read({{"name", "size", "16"}}), "name/0");
  EXPECT_NEAR(hi2 - lo2, 2 * (hi - lo), 1e-9);
  const auto [lo3, hi3] = bounds_x(read({{"name", "at", "[100, 10]"}}), "name/0");
  EXPECT_NEAR(lo3, lo + 100, 1e-9);
  EXPECT_NEAR(hi3, hi + 100, 1e-9);
  const auto [lo4, hi4] = bounds_x(read({{"name", "align", "right"}}), "name/1");
  EXPECT_LT(hi4, 0);
  const auto [lo5, hi5] = bounds_x(read({{"name", "font", "Nimbus Sans"}}), "name/0");
  EXPECT_NE(hi5 - lo5, hi - lo);
}

TEST(TextSettings, AGlobSetsACuttingParameterOfEveryEntityItMatches) {
  const Job job = read({{"*", "cut_z", "-1"},
                        {"n*", "cut_z", "-0.3"},
                        {"edge", "tabs.count", "3"},
                        {"edge", "tabs.width", "4"},
                        {"edge", "tabs", R"({"height": 1})"}});
  for (const Entity& e : job.entities) {
    ASSERT_TRUE(e.params.cut_z) << e.id;
    EXPECT_EQ(*e.params.cut_z, e.id.starts_with("name/") ? -0.3 : -1) << e.id;
    EXPECT_EQ(e.params.tabs.has_value(), e.id == "edge") << e.id;
  }
  // Dotted keys and objects merge into one `tabs`.
  const Tabs& t = *job.entities.back().params.tabs;
  EXPECT_EQ(t.count, 3);
  EXPECT_EQ(t.width, 4);
  EXPECT_EQ(t.height, 1);
}

// The refusal's place is the setting, and its message says what to change.
void refused(std::vector<EntitySetting> settings, const std::string& id, const std::string& place,
             const std::string& words) {
  try {
    (void)read(std::move(settings));
    ADD_FAILURE() << "not refused: " << place;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.id()), id) << e.what();
    EXPECT_EQ(e.place().setting.value_or(""), place) << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(TextSettings, RefusalsAreNamedAtTheSetting) {
  refused({{"seria", "text", "1"}}, "usage.setting", "settings.seria:text", "\"serial\", \"name\", \"edge\"");
  refused({{"edge", "text", "1"}}, "usage.setting", "settings.edge:text", "not a text");
  refused({{"serial", "cutz", "1"}}, "usage.setting", "settings.serial:cutz", "cut_z");
  refused({{"serial", "tolerance", "1"}}, "usage.setting", "settings.serial:tolerance", "whole job");
  refused({{"serial", "id", "x"}}, "usage.setting", "settings.serial:id", "selects it");
  refused({{"serial", "size", "-1"}}, "job.not-positive", "settings.serial:size", "> 0");
  refused({{"name", "font", "Nope Sans"}}, "text.font", "settings.name:font", "Nope Sans");
  refused({{"serial", "text", ""}}, "text.empty", "settings.serial:text", "empty");
  refused({{"edge", "tabs.count", "3"}}, "job.missing", "settings.edge:tabs.count", "width");
}

}  // namespace
}  // namespace bezcam
