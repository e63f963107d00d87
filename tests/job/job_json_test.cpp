// Reading jobs: every rule of docs/job-format.md, errors that name the JSON path,
// expected and found, and the refusal of unknown keys.
#include "bezcam/job/job_json.hpp"

#include <gtest/gtest.h>
#include <tuple>

#include "bezcam/error.hpp"
#include "bezcam/job/job.hpp"
#include "bezcam/job/keys.hpp"

using namespace bezcam;

namespace {

// Parses and returns the error's full text ("where: message"), or "" if none.
std::string error_of(const std::string& text) {
  try {
    parse_job(text, "job.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string wrap(const std::string& entity) { return R"({"bezcam": 1, "entities": [)" + entity + "]}"; }

}  // namespace

TEST(JobJson, ReadsTheSpecExample) {
  const Job j = parse_job(R"({
    "bezcam": 1, "units": "mm", "tolerance": 0.01, "machine": "generic-fanuc",
    "job": { "feed": 1200, "plunge_feed": 300, "safe_z": 5, "cut_z": -0.5, "spindle_rpm": 12000, "tool": 1 },
    "entities": [ { "id": "seed-ex-4", "type": "bezier", "points": [[0,0],[1,0],[2,1],[0,1]] } ] })",
                          "x.json");
  EXPECT_EQ(j.units, Units::mm);
  EXPECT_EQ(j.tolerance, 0.01);
  EXPECT_EQ(*j.machine, "generic-fanuc");
  EXPECT_EQ(*j.params.feed, 1200);
  EXPECT_EQ(*j.params.tool, 1);
  ASSERT_EQ(j.entities.size(), 1u);
  const Entity& e = j.entities[0];
  EXPECT_EQ(e.id, "seed-ex-4");
  EXPECT_EQ(e.curve.dim, 2);
  EXPECT_EQ(e.curve.max_degree(), 3);
  EXPECT_TRUE(j.warnings.empty());
}

TEST(JobJson, DefaultsAndInchJobs) {
  const Job j =
      parse_job(R"({"bezcam": 1, "units": "inch", "entities": [{"type": "bezier", "points": [[0,0],[1,1]]}]})", "x");
  EXPECT_EQ(j.units, Units::inch);
  EXPECT_NEAR(j.tolerance, 0.01 / 25.4, 1e-15);  // 0.01 mm expressed in inches
  EXPECT_EQ(j.entities[0].label(), "entities[0]");
}

TEST(JobJson, ErrorsNameThePathExpectedAndFound) {
  EXPECT_EQ(error_of(wrap(R"({"type": "bezier", "points": [[0,0],[1,"a"]]})")),
            "job.json: entities[0].points[1][1]: expected a number, found the string \"a\"");
  EXPECT_EQ(error_of(wrap(R"({"type": "bezier", "points": [[0,0]]})")),
            "job.json: entities[0].points: expected an array of at least 2 elements, found an array of 1 element");
  EXPECT_EQ(error_of(wrap(R"({"type": "bezier", "points": [[0,0],[1,1,1]]})")),
            "job.json: entities[0].points[1]: expected a 2D point like the entity's first point, found a 3D point");
  EXPECT_EQ(error_of(wrap(R"({"type": "bezier", "points": [[0,0],[1,1]], "weights": [1, 0]})")),
            "job.json: entities[0].weights[1]: expected a finite weight > 0, found 0");
  EXPECT_EQ(error_of(wrap(R"({"type": "spiral"})")).substr(0, 40), "job.json: entities[0].type: expected one");
  EXPECT_NE(error_of(R"({"bezcam": 2, "entities": []})").find("bezcam: expected format version 1, found 2"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"entities": []})").find("bezcam"), std::string::npos);
  EXPECT_NE(
      error_of(R"({"bezcam": 1, "tolerance": 0, "entities": []})").find("tolerance: expected a number > 0, found 0"),
      std::string::npos);
  EXPECT_NE(error_of(R"({"bezcam": 1, "units": "cm", "entities": []})").find("units: expected \"mm\" or \"inch\""),
            std::string::npos);
  EXPECT_NE(
      error_of(
          R"({"bezcam": 1, "job": {"safe_z": 1, "cut_z": 2}, "entities": [{"type": "bezier", "points": [[0,0],[1,1]]}]})")
          .find("job.cut_z: expected cut_z below safe_z"),
      std::string::npos);
  EXPECT_NE(error_of("[1, 2]").find("expected a JSON object"), std::string::npos);
  // Syntax errors give line and column.
  const std::string syn = error_of("{\n  \"bezcam\": 1,\n  \"entities\": [,]\n}");
  EXPECT_NE(syn.find("line 3"), std::string::npos) << syn;
}

TEST(JobJson, UnknownKeysAreRefusedWithTheirPath) {
  // An unknown key would be ignored: a `stock` the reader does not know
  // would cut the part to size. Each is refused, in the file's order.
  try {
    parse_job(R"({"bezcam": 1, "colour": "red", "job": {"stock": 0.2},
                  "entities": [{"type": "bezier", "points": [[0,0],[1,1]], "author": 3}]})",
              "w.json");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "job.unknown-key");
    EXPECT_EQ(std::string(e.what()),
              "w.json: colour: unknown key \"colour\" (a key bezcam does not know is refused: it "
              "would otherwise be ignored; keys of your own start with \"x-\")");
    ASSERT_EQ(e.more().size(), 2u) << e.what();
    EXPECT_EQ(e.more()[0].where(), "w.json: job.stock");
    EXPECT_NE(std::string(e.more()[0].what()).find("did you mean \"stock_to_leave\"?"), std::string::npos)
        << e.more()[0].what();
    EXPECT_EQ(e.more()[1].where(), "w.json: entities[0].author");
  }
}

TEST(JobJson, AWordForAKeyNamesTheKey) {
  // `depth` is not a key: the depth of a cut is cut_z.
  for (const auto& [text, where, meant] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {R"({"bezcam": 1, "job": {"depth": -6}, "entities": [{"type": "bezier", "points": [[0,0],[1,1]]}]})",
            "job.depth", "cut_z"},
           {R"({"bezcam": 1, "entities": [{"type": "bezier", "points": [[0,0],[1,1]], "diameter": 6}]})",
            "entities[0].diameter", "tool_diameter"},
           {R"({"bezcam": 1, "job": {"rpm": 9000}, "entities": [{"type": "bezier", "points": [[0,0],[1,1]]}]})",
            "job.rpm", "spindle_rpm"}}) {
    try {
      parse_job(text, "t.json");
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.id(), "job.unknown-key") << e.what();
      EXPECT_EQ(e.where(), "t.json: " + where) << e.what();
      EXPECT_NE(std::string(e.what()).find("did you mean \"" + meant + "\"?"), std::string::npos) << e.what();
    }
  }
}

TEST(JobJson, KeysOfTheUsersOwnStartWithX) {
  const Job j = parse_job(R"({"bezcam": 1, "x-author": "me", "job": {"x-order-no": 4711, "feed": 600},
      "entities": [{"type": "bezier", "points": [[0,0],[1,1]], "x-note": {"any": ["thing"]},
                    "lead": {"radius": 1, "x-why": "clamps"}}]})",
                          "t.json");
  EXPECT_TRUE(j.warnings.empty());
  EXPECT_EQ(*j.params.feed, 600);
}

TEST(JobJson, OrderIsTheJobsNotAnEntitys) {
  EXPECT_NE(error_of(wrap(R"({"type": "bezier", "points": [[0,0],[1,1]], "order": "shortest"})"))
                .find("job.json: entities[0].order: unknown key \"order\""),
            std::string::npos);
}

TEST(JobJson, LikelyTyposAreRefusedNamingTheKeyTheyResemble) {
  // A misspelt key must never cut at the default (spec "Errors").
  for (
      const auto& [text, where, like] : std::vector<std::tuple<std::string, std::string, std::string>>{
          {R"({"bezcam": 1, "tolerence": 0.001, "entities": [{"type": "bezier", "points": [[0,0],[1,1]]}]})",
           "tolerence", "tolerance"},
          {R"({"bezcam": 1, "Tolerance": 0.001, "entities": [{"type": "bezier", "points": [[0,0],[1,1]]}]})",
           "Tolerance", "tolerance"},
          {R"({"bezcam": 1, "job": {"cutz": -1}, "entities": [{"type": "bezier", "points": [[0,0],[1,1]]}]})",
           "job.cutz", "cut_z"},
          {R"({"bezcam": 1, "entities": [{"type": "bezier", "points": [[0,0],[1,1]], "plunge_fed": 3}]})",
           "entities[0].plunge_fed", "plunge_feed"},
          {R"({"bezcam": 1, "entities": [{"type": "bspline", "degree": 1, "points": [[0,0],[1,1]], "knot": [0,0,1,1]}]})",
           "entities[0].knot", "knots"}}) {
    try {
      parse_job(text, "t.json");
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& e) {
      EXPECT_EQ(e.id(), "job.key-typo") << e.what();
      EXPECT_EQ(e.where(), "t.json: " + where) << e.what();
      EXPECT_NE(std::string(e.what()).find("did you mean \"" + like + "\""), std::string::npos) << e.what();
    }
  }
}

TEST(JobJson, IndependentErrorsAreEachReported) {
  // Two bad entities and two unknown keys: four refusals, in the file's
  // order.
  try {
    parse_job(R"({"bezcam": 1, "colour": "red", "tolerence": 0.1, "entities": [
        {"type": "bezier", "points": [[0,0]]},
        {"type": "bezier", "points": [[0,0],[1,1]]},
        {"type": "bspline", "degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [0,0,0,1,1]}]})",
              "t.json");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "t.json: colour") << e.what();
    ASSERT_EQ(e.more().size(), 3u) << e.what();
    EXPECT_EQ(e.more()[0].where(), "t.json: tolerence") << e.more()[0].what();
    EXPECT_EQ(e.more()[0].id(), "job.key-typo");
    EXPECT_EQ(e.more()[1].where().rfind("t.json: entities[0]", 0), 0u) << e.more()[1].what();
    EXPECT_EQ(e.more()[2].where().rfind("t.json: entities[2]", 0), 0u) << e.more()[2].what();
  }
}

TEST(Keys, EditDistanceAndResemblance) {
  EXPECT_EQ(edit_distance("tolerence", "tolerance"), 1);
  EXPECT_EQ(edit_distance("cutz", "cut_z"), 1);
  EXPECT_EQ(edit_distance("ponits", "points"), 1);  // a swap of neighbours is one edit
  EXPECT_EQ(edit_distance("", "abc"), 3);
  const std::vector<std::string_view> known{"id", "type", "points", "feed"};
  EXPECT_EQ(resembled_key("ponts", known), "points");
  EXPECT_FALSE(resembled_key("xy", known));  // short keys: one edit at most
  EXPECT_FALSE(resembled_key("colour", known));
}

TEST(Keys, AnUnknownKeyNamesTheKeyItIsTakenFor) {
  const std::vector<std::string_view> known{"feed", "spindle_rpm", "cut_z"};
  // `speed` is two edits from `feed`, but it is the spindle's.
  UnknownKey u = unknown_key("speed", known);
  EXPECT_EQ(u.meant, "spindle_rpm");
  EXPECT_FALSE(u.typo);
  u = unknown_key("fed", known);
  EXPECT_EQ(u.meant, "feed");
  EXPECT_TRUE(u.typo);
  // A word names its key only where that key is known.
  EXPECT_FALSE(unknown_key("stock", known).meant);
  EXPECT_EQ(
      unknown_key("cont", std::vector<std::string_view>{"count"}, "tabs.").message,
      "unknown key \"tabs.cont\": did you mean \"tabs.count\"? (a misspelt key is refused: it would otherwise take "
      "the default)");
  EXPECT_TRUE(user_key("x-anything"));
  EXPECT_FALSE(user_key("xfeed"));
}

TEST(JobJson, PathJointsAndContinuity) {
  const Job j = parse_job(wrap(R"({"type": "path", "closed": true, "segments": [
      {"type": "bezier", "points": [[0,0],[1,0],[2,0]]},
      {"type": "bezier", "points": [[2,0],[3,0],[4,1],[4,2]]},
      {"type": "bezier", "points": [[4,2],[4,3],[0,0]]}]})"),
                          "p.json");
  const auto& g = j.entities[0].curve;
  EXPECT_TRUE(g.closed);
  ASSERT_EQ(g.joints.size(), 3u);
  // Quadratic (0,0)(1,0)(2,0) ends with derivative 2*(1,0); the cubic starts
  // with 3*(1,0): same direction, different length -> G1.
  EXPECT_EQ(g.joints[0], Continuity::G1);
  // (4,1)->(4,2) then (4,2)->(4,3): tangents 3*(0,1) and 2*(0,1): G1.
  EXPECT_EQ(g.joints[1], Continuity::G1);
  EXPECT_EQ(g.joints[2], Continuity::C0);  // closing corner
  EXPECT_NE(
      error_of(wrap(R"({"type": "path", "segments": [
      {"type": "bezier", "points": [[0,0],[1,1]]}, {"type": "bezier", "points": [[1,1.001],[2,2]]}]})"))
          .find(
              "entities[0].segments[1]: expected to start where segments[0] ends (1, 1), found a start at (1, 1.001)"),
      std::string::npos);
  EXPECT_NE(
      error_of(wrap(R"({"type": "path", "closed": true, "segments": [{"type": "bezier", "points": [[0,0],[1,1]]}]})"))
          .find("marked closed"),
      std::string::npos);
}

TEST(JobJson, ContinuityLevels) {
  // Two halves of one cubic meet C2 (same polynomial on both sides, scaled).
  const Bezier b = Bezier::make({{0, 0}, {1, 2}, {3, 2}, {4, 0}});
  auto [l, r] = split(b, 0.5);
  EXPECT_EQ(joint_continuity(l, r, 1e-12), Continuity::C2);
  // C1 but not C2: equal first derivatives, different second.
  const Bezier a = Bezier::make({{0, 0}, {1, 0}, {2, 0}});
  const Bezier c = Bezier::make({{2, 0}, {3, 0}, {4, 1}});
  EXPECT_EQ(joint_continuity(a, c, 1e-12), Continuity::C1);
  EXPECT_EQ(joint_continuity(a, Bezier::make({{2, 0}, {2, 1}}), 1e-12), Continuity::C0);
  EXPECT_EQ(joint_continuity(a, Bezier::make({{2.1, 0}, {2, 1}}), 1e-12), Continuity::none);
}

TEST(JobJson, NonFiniteNumbersAreRefused) {
  // 1e999 overflows to infinity in the parser: named, not crashed on.
  const std::string e = error_of(wrap(R"({"type": "bezier", "points": [[0,0],[1e999,1]]})"));
  EXPECT_NE(e.find("line 1, column"), std::string::npos) << e;
  EXPECT_NE(e.find("expected a finite number, found 1e999"), std::string::npos) << e;
}
