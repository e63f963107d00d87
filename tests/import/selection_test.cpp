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
      "\"OUTLINE:1\", \"HOLES:2\", \"HOLES:3\", \"HOLES:4\"; its circles' diameters are 4, 20, 100";
  EXPECT_EQ(refusal([&] { (void)to_job(d, o); }), "settings.HOLE:tool: " + what);
  EXPECT_EQ(refusal([&] { (void)job_json(d, o); }), "settings.HOLE:tool: " + what);
  o.scoped.clear();
  o.skip = {"HOLE"};
  EXPECT_EQ(refusal([&] { (void)to_job(d, o); }), "skip: " + what);
}

TEST(Selection, CirclesArePickedByTheirDiameter) {
  const Drawing d = plate();
  EXPECT_TRUE(selects("circle<5", d.contours[1]));
  EXPECT_TRUE(selects("circle<5", d.contours[2]));
  EXPECT_FALSE(selects("circle<5", d.contours[3]));
  EXPECT_TRUE(selects("circle>50", d.contours[0]));
  EXPECT_FALSE(selects("circle>100", d.contours[0]));  // strictly above
  EXPECT_FALSE(selects("circle<4", d.contours[1]));    // strictly below
  // A circle drawn as two arcs is a circle; half of it, or a square, is not.
  Contour halves = d.contours[3];
  halves.pieces = ellipse_arc({0, 0, 0}, {10, 0, 0}, {0, 10, 0}, 0, std::acos(-1.0));
  const auto rest = ellipse_arc({0, 0, 0}, {10, 0, 0}, {0, 10, 0}, std::acos(-1.0), 2 * std::acos(-1.0));
  halves.pieces.insert(halves.pieces.end(), rest.begin(), rest.end());
  EXPECT_TRUE(selects("circle<21", halves));
  Contour open = halves;
  open.pieces.resize(open.pieces.size() / 2);
  open.closed = false;
  EXPECT_FALSE(selects("circle<21", open));
  Contour square = d.contours[3];
  square.pieces.clear();
  const Vec3 p[4] = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
  for (int k = 0; k < 4; ++k) square.pieces.push_back({false, 0, {p[k], p[(k + 1) % 4]}, {}, {}});
  EXPECT_FALSE(selects("circle<100", square));
  // Not a circle selector: a glob that picks nothing here.
  EXPECT_FALSE(selects("circle<", d.contours[1]));
  EXPECT_FALSE(selects("circle<x", d.contours[1]));
  // The small holes get the second tool.
  ImportOptions o = base();
  o.scoped = {{"circle<5", "tool", "2"}, {"circle<5", "tool_diameter", "2"}};
  const Job job = to_job(d, o);
  ASSERT_EQ(job.entities.size(), 4u);
  EXPECT_EQ(job.entities[0].params.tool, std::nullopt);
  EXPECT_EQ(job.entities[1].params.tool, 2);
  EXPECT_EQ(job.entities[2].params.tool, 2);
  EXPECT_EQ(job.entities[3].params.tool, std::nullopt);
  o.scoped = {{"circle>200", "tool", "2"}};
  EXPECT_NE(refusal([&] { (void)to_job(d, o); }).find("its circles' diameters are 4, 20, 100"), std::string::npos);
}

TEST(Selection, TheSidesByNestingArePickedInAngleBrackets) {
  const Drawing d = plate();
  ImportOptions o = base();
  o.scoped = {{"<outside>", "tabs", R"({"count": 4, "width": 5, "height": 0.5})"}, {"<inside>", "feed", "300"}};
  const Job job = to_job(d, o);
  ASSERT_EQ(job.entities.size(), 4u);
  ASSERT_TRUE(job.entities[0].params.tabs);  // the plate
  EXPECT_FALSE(job.entities[0].params.feed);
  for (size_t k = 1; k < 4; ++k) {
    EXPECT_FALSE(job.entities[k].params.tabs) << k;
    EXPECT_EQ(job.entities[k].params.feed, 300) << k;
  }
  const std::string text = job_json(d, o);
  EXPECT_NE(text.find(R"({ "id": "OUTLINE:1", "side": "outside", "tabs": )"), std::string::npos) << text;
  // Without a side there is no nesting to pick by.
  o.settings = {{"feed", "600"}, {"cut_z", "-1"}};
  EXPECT_EQ(refusal([&] { (void)to_job(d, o); }),
            "settings.<outside>:tabs: \"<outside>\" picks the contours the nesting cuts outside, and plate.dxf has no "
            "sides by nesting: give the job a side, side=outside (a part) or side=inside (openings)");
  EXPECT_EQ(refusal([&] { (void)job_json(d, o); }).rfind("settings.<outside>:tabs: ", 0), 0u);
  // --only and --skip choose before the nesting is found.
  o = base();
  o.only = {"<outside>"};
  EXPECT_NE(refusal([&] { (void)to_job(d, o); }).find("it picks the entities a setting goes to"), std::string::npos);
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
