// Settings given as KEY=VALUE (the CLI's --set): JSON values, dotted keys
// nested and merged, and unknown keys refused naming the key meant.
#include "bezcam/job/settings.hpp"

#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/refusal.hpp"

using namespace bezcam;
using bezcam::test::refusal_of;

namespace {

using Settings = std::vector<std::pair<std::string, std::string>>;
using Members = std::vector<std::pair<std::string, std::string>>;

InputError refused(const Settings& s) {
  return refusal_of([&] { settings_json(s); });
}

}  // namespace

TEST(Settings, DottedKeysMakeOneObject) {
  const SettingsJson j = settings_json(Settings{
      {"tabs.count", "4"}, {"feed", "600"}, {"tabs.width", "5"}, {"tabs.height", "1.5"}, {"tolerance", "0.005"}});
  EXPECT_EQ(j.top, (Members{{"tolerance", "0.005"}}));
  EXPECT_EQ(j.job, (Members{{"tabs", R"({"count":4,"width":5,"height":1.5})"}, {"feed", "600"}}));
}

TEST(Settings, ValuesAreJsonWhereTheyReadAsJson) {
  const SettingsJson j = settings_json(Settings{{"lead", R"({"radius":4,"length":2})"},
                                                {"before", R"(["M08", "G04 P1"])"},
                                                {"side", "outside"},
                                                {"machine", R"("fanuc")"},
                                                {"units", "inch"},
                                                {"cut_z", "-6"},
                                                {"step_down", ".5"},
                                                {"safe_z", "5."},
                                                {"x-note", "a note, with spaces"}});
  EXPECT_EQ(j.top, (Members{{"machine", R"("fanuc")"}, {"units", R"("inch")"}}));
  EXPECT_EQ(j.job, (Members{{"lead", R"({"radius":4,"length":2})"},
                            {"before", R"(["M08","G04 P1"])"},
                            {"side", R"("outside")"},
                            {"cut_z", "-6"},
                            {"step_down", "0.5"},
                            {"safe_z", "5.0"},
                            {"x-note", R"("a note, with spaces")"}}));
}

TEST(Settings, AnObjectMergesIntoTheKeysGivenBefore) {
  const SettingsJson j =
      settings_json(Settings{{"lead.radius", "4"}, {"lead", R"({"length": 2})"}, {"feed", "500"}, {"feed", "600"}});
  EXPECT_EQ(j.job, (Members{{"lead", R"({"radius":4,"length":2})"}, {"feed", "600"}}));
}

TEST(Settings, AnUnknownKeyIsAUsageErrorNamingTheKeyMeant) {
  InputError e = refused({{"depth", "-6"}});
  EXPECT_EQ(e.id(), "usage.setting");
  EXPECT_EQ(e.where(), "settings.depth");
  EXPECT_EQ(e.message(),
            "unknown key \"depth\": did you mean \"cut_z\"? (a key bezcam does not know is refused: it "
            "would otherwise be ignored)");
  e = refused({{"cutz", "-1"}});
  EXPECT_NE(e.message().find("did you mean \"cut_z\"? (a misspelt key"), std::string::npos) << e.message();
  e = refused({{"tabs.cont", "4"}});
  EXPECT_EQ(e.where(), "settings.tabs.cont");
  EXPECT_NE(e.message().find("unknown key \"tabs.cont\": did you mean \"tabs.count\"?"), std::string::npos)
      << e.message();
  e = refused({{"colour", "red"}});
  EXPECT_NE(e.message().find("keys of your own start with \"x-\""), std::string::npos) << e.message();
  e = refused({{"entities", "[]"}});
  EXPECT_EQ(e.id(), "usage.setting");
  e = refused({{"feed.max", "4"}});
  EXPECT_EQ(e.message(), "\"feed\" takes a value, not keys; give it as feed=VALUE");
  e = refused({{"tabs..count", "4"}});
  EXPECT_NE(e.message().find("names joined by dots"), std::string::npos) << e.message();
}

TEST(Settings, AValueThatStartsAsJsonMustBeJson) {
  // A missing brace must not turn the lead into a string.
  InputError e = refused({{"lead", R"({"radius":4)"}});
  EXPECT_EQ(e.where(), "settings.lead");
  EXPECT_NE(e.message().find("is not valid JSON"), std::string::npos) << e.message();
  e = refused({{"feed", "1e999"}});
  EXPECT_NE(e.message().find("too large for a double"), std::string::npos) << e.message();
}

TEST(Settings, TheJobReaderTakesWhatTheyMake) {
  const SettingsJson s = settings_json(Settings{{"tabs.count", "4"},
                                                {"tabs.width", "5"},
                                                {"tabs.height", "1.5"},
                                                {"lead", R"({"radius":4,"length":2})"},
                                                {"side", "outside"},
                                                {"tool_diameter", "6"},
                                                {"units", "inch"}});
  std::string text = R"({"bezcam": 1, )";
  for (const auto& [k, v] : s.top) text += "\"" + k + "\": " + v + ", ";
  text += R"("job": {)";
  for (size_t i = 0; i < s.job.size(); ++i) text += (i ? ", \"" : "\"") + s.job[i].first + "\": " + s.job[i].second;
  text += R"(}, "entities": [{"type": "bezier", "points": [[0,0],[1,1]]}]})";
  const Job j = parse_job(text, "t.json");
  ASSERT_TRUE(j.params.tabs);
  EXPECT_EQ(j.params.tabs->count, 4);
  EXPECT_EQ(j.params.tabs->width, 5);
  EXPECT_EQ(j.params.tabs->height, 1.5);
  ASSERT_TRUE(j.params.lead);
  EXPECT_EQ(j.params.lead->radius, 4);
  EXPECT_EQ(j.params.lead->length, 2);
  EXPECT_EQ(j.params.side, CutSide::outside);
  EXPECT_EQ(j.units, Units::inch);
}
