// Picking a drawing's contours by layer or id (globs) for --set
// SELECTOR:KEY=VALUE, --only and --skip: what each entity gets, in the
// job file and in the job built in memory, and the refusals, named at the
// option's setting.
#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/import/conic.hpp"
#include "bezcam/import/drawing.hpp"
#include "bezcam/job/job_json.hpp"

namespace bezcam::import {
namespace {

Contour circle(std::string id, std::string layer, double x, double r) {
  Contour c;
  c.id = std::move(id);
  c.layer = std::move(layer);
  c.element = "test";
  c.pieces = ellipse_arc({x, 0, 0}, {r, 0, 0}, {0, r, 0}, 0, 2 * std::acos(-1.0));
  c.closed = true;
  return c;
}

// A plate (layer OUTLINE) holding two small holes and a large one (layer
// HOLES).
Drawing plate() {
  Drawing d;
  d.source = "plate.dxf";
  d.format = "dxf";
  d.contours = {circle("OUTLINE:1", "OUTLINE", 0, 50), circle("HOLES:2", "HOLES", -20, 2),
                circle("HOLES:3", "HOLES", 20, 2), circle("HOLES:4", "HOLES", 0, 10)};
  d.layers["OUTLINE"].read["CIRCLE"] = 1;
  d.layers["HOLES"].read["CIRCLE"] = 3;
  return d;
}

ImportOptions base() {
  ImportOptions o;
  o.settings = {{"feed", "600"}, {"cut_z", "-1"}, {"side", "outside"}, {"tool", "1"}, {"tool_diameter", "6"}};
  return o;
}

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return (e.place().setting ? *e.place().setting + ": " : std::string()) + e.message();
  }
  return "accepted";
}

TEST(Selection, GlobsMatchTheLayerOrTheId) {
  const Drawing d = plate();
  EXPECT_TRUE(selects("HOLES", d.contours[1]));
  EXPECT_TRUE(selects("HOL*", d.contours[1]));
  EXPECT_TRUE(selects("HOLES:[23]", d.contours[2]));
  EXPECT_FALSE(selects("HOLES:[23]", d.contours[3]));
  EXPECT_FALSE(selects("HOLE", d.contours[1]));
  EXPECT_TRUE(selects("*", d.contours[0]));
  Contour svg = d.contours[0];
  svg.layer.clear();
  svg.id = "logo.2";
  EXPECT_TRUE(selects("logo*", svg));
  EXPECT_FALSE(selects("", svg));
}

TEST(Selection, ScopedSettingsGoOnTheEntitiesTheyPickInTheOrderGiven) {
  const Drawing d = plate();
  ImportOptions o = base();
  o.scoped = {{"HOLES", "feed", "400"},
              {"HOLES:[23]", "tool", "2"},
              {"HOLES:[23]", "tool_diameter", "2"},
              {"HOLES:3", "feed", "300"},
              {"OUTLINE", "tabs", R"({"count": 4, "width": 5, "height": 0.5})"},
              {"HOLES:4", "side", "outside"}};
  const Job job = to_job(d, o);
  ASSERT_EQ(job.entities.size(), 4u);
  EXPECT_FALSE(job.entities[0].params.feed);
  ASSERT_TRUE(job.entities[0].params.tabs);
  EXPECT_EQ(job.entities[0].params.tabs->count, 4);
  EXPECT_EQ(job.entities[0].params.side, CutSide::outside);  // by nesting
  EXPECT_EQ(job.entities[1].params.feed, 400);
  EXPECT_EQ(job.entities[1].params.tool, 2);
  EXPECT_EQ(job.entities[1].params.side, CutSide::inside);  // by nesting
  EXPECT_EQ(job.entities[2].params.feed, 300);              // the later setting wins
  EXPECT_EQ(job.entities[3].params.tool, std::nullopt);
  EXPECT_EQ(job.entities[3].params.side, CutSide::outside);  // given wins over nesting
  const std::string text = job_json(d, o);
  EXPECT_NE(text.find(R"({ "id": "HOLES:3", "side": "inside", "feed": 300, "tool": 2, "tool_diameter": 2, "type")"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(R"({ "id": "HOLES:4", "feed": 400, "side": "outside", "type")"), std::string::npos) << text;
}

TEST(Selection, OnlyAndSkipPickTheContoursToCut) {
  const Drawing d = plate();
  ImportOptions o = base();
  o.only = {"HOLES"};
  o.skip = {"HOLES:4"};
  const Job job = to_job(d, o);
  ASSERT_EQ(job.entities.size(), 2u);
  EXPECT_EQ(job.entities[0].id, "HOLES:2");
  EXPECT_EQ(job.entities[1].id, "HOLES:3");
  // Without the outline, the holes are parts of their own: cut outside.
  EXPECT_EQ(job.entities[0].params.side, CutSide::outside);
  o.skip = {"HOLES*"};
  EXPECT_EQ(refusal([&] { (void)to_job(d, o); }),
            "expected geometry to cut among the layers and entities asked for, found none");
}

TEST(Selection, RefusesASelectorThatMatchesNothingNamingWhatTheDrawingHas) {
  const Drawing d = plate();
  ImportOptions o = base();
  o.scoped = {{"HOLE", "tool", "2"}};
  const std::string what =
      "plate.dxf has no layer and no entity matching \"HOLE\"; its layers are \"HOLES\", \"OUTLINE\", its entities "
      "\"OUTLINE:1\", \"HOLES:2\", \"HOLES:3\", \"HOLES:4\"";
  EXPECT_EQ(refusal([&] { (void)to_job(d, o); }), "settings.HOLE:tool: " + what);
  EXPECT_EQ(refusal([&] { (void)job_json(d, o); }), "settings.HOLE:tool: " + what);
  o.scoped.clear();
  o.skip = {"HOLE"};
  EXPECT_EQ(refusal([&] { (void)to_job(d, o); }), "skip: " + what);
}

TEST(Selection, RefusesWhatAnEntityDoesNotTakeAtTheOptionThatGaveIt) {
  const Drawing d = plate();
  ImportOptions o = base();
  o.scoped = {{"HOLES", "tolerance", "0.1"}};
  EXPECT_EQ(refusal([&] { check_options(o); }),
            "settings.HOLES:tolerance: \"tolerance\" is a setting of the whole job, not of an entity; give it "
            "without a selector (tolerance=0.1)");
  o.scoped = {{"HOLES", "fed", "1"}};
  EXPECT_NE(refusal([&] { check_options(o); }).find("settings.HOLES:fed: unknown key \"fed\": did you mean \"feed\"?"),
            std::string::npos);
  o.scoped = {{"HOLES", "feed", "400"}, {"HOLES:3", "feed", "fast"}};
  EXPECT_EQ(refusal([&] { (void)to_job(d, o); }),
            "settings.HOLES:3:feed: expected a number, found the string \"fast\"");
  o.scoped = {{"HOLES:3", "tabs.count", "0"}};
  EXPECT_EQ(refusal([&] { (void)to_job(d, o); }), "settings.HOLES:3:tabs.count: expected at least 1 tab, found 0");
}

}  // namespace
}  // namespace bezcam::import
