// JobBuilder: a job made in memory converts exactly as the same job read
// from JSON, and bad values are refused naming the place.
#include "bezcam/job/job_builder.hpp"

#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/machine_profile.hpp"

using namespace bezcam;

namespace {

const char* kJson = R"({"bezcam": 1, "units": "mm", "tolerance": 0.005,
  "job": {"feed": 800, "plunge_feed": 200, "safe_z": 5, "cut_z": -0.5, "spindle_rpm": 12000},
  "entities": [
    {"id": "lens", "type": "path", "closed": true, "segments": [
      {"type": "bezier", "points": [[0, 0], [10, 15], [40, 15], [50, 0]]},
      {"type": "bezier", "points": [[50, 0], [40, -15], [10, -15], [0, 0]]}]},
    {"id": "arch", "type": "bezier", "points": [[60, 0], [70, 20], [80, 0]], "weights": [1, 0.5, 1], "feed": 400}
  ]})";

Job built() {
  JobParams slow;
  slow.feed = 400;
  return JobBuilder("lens.json")
      .tolerance(0.005)
      .feed(800)
      .plunge_feed(200)
      .safe_z(5)
      .cut_z(-0.5)
      .spindle_rpm(12000)
      .path("lens",
            {Bezier::make({{0, 0, 0}, {10, 15, 0}, {40, 15, 0}, {50, 0, 0}}),
             Bezier::make({{50, 0, 0}, {40, -15, 0}, {10, -15, 0}, {0, 0, 0}})},
            true)
      .bezier("arch", Bezier::make({{60, 0, 0}, {70, 20, 0}, {80, 0, 0}}, {1, 0.5, 1}), slow)
      .build();
}

}  // namespace

TEST(JobBuilder, ConvertsExactlyAsTheSameJobReadFromJson) {
  const Job from_json = parse_job(kJson, "lens.json");
  const Job in_memory = built();
  ASSERT_EQ(in_memory.entities.size(), from_json.entities.size());
  for (const char* machine : {"generic", "fanuc", "linuxcnc"}) {
    const MachineProfile m = load_machine_profile(machine);
    for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
      ConvertOptions opt;
      opt.output = mode;
      const std::string a = convert(from_json, m, opt).gcode;
      const std::string b = convert(in_memory, m, opt).gcode;
      EXPECT_EQ(a, b) << machine << " " << to_string(mode);
      EXPECT_NE(a.find("M30"), std::string::npos);
    }
  }
}

TEST(JobBuilder, RefusesBadValuesNamingThePlace) {
  auto refused = [](auto&& make, const std::string& id, const std::string& where) {
    try {
      make();
      ADD_FAILURE() << "not refused: " << id;
    } catch (const InputError& e) {
      EXPECT_EQ(e.id(), id);
      EXPECT_EQ(e.where(), where);
    }
  };
  const Bezier c = Bezier::make({{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  refused([] { JobBuilder("j").tolerance(-1); }, "job.not-positive", "j: tolerance");
  refused([] { JobBuilder("j").build(); }, "job.missing", "j: entities");
  refused([&] { JobBuilder("j").feed(0).bezier("a", c).build(); }, "job.not-positive", "j: job.feed");
  JobParams p;
  p.plunge_feed = -5;
  refused([&] { JobBuilder("j").bezier("a", c).bezier("b", c, p).build(); }, "job.not-positive",
          "j: entities[1].plunge_feed");
  // A path whose second segment does not start where the first ends.
  refused(
      [&] {
        JobBuilder("j").path("p", {c, Bezier::make({{5, 5, 0}, {6, 6, 0}})});
      },
      "path.joint", "j: entities[0].segments[1]");
}

namespace {

// A path of a Bézier and a B-spline (its weights all equal: polynomial),
// and curves through points, open and closed, as a file has them.
const char* kSplineJson = R"({"bezcam": 1, "units": "mm", "job": {"feed": 600, "safe_z": 5, "cut_z": -1},
  "entities": [
    {"id": "hook", "type": "path", "segments": [
      {"type": "bezier", "points": [[0, 0], [5, 10], [10, 0]]},
      {"type": "bspline", "degree": 2, "points": [[10, 0], [15, -10], [20, 0], [25, 5]],
       "knots": [0, 0, 0, 0.4, 1, 1, 1], "weights": [2, 2, 2, 2]}]},
    {"id": "wave", "type": "interpolate", "through": [[0, 20], [10, 25], [20, 18], [30, 24]]},
    {"id": "loop", "type": "interpolate", "closed": true, "through": [[40, 0], [50, 10], [40, 20], [30, 10]]}
  ]})";

Job spline_built() {
  return JobBuilder("splines.json")
      .feed(600)
      .safe_z(5)
      .cut_z(-1)
      .path_segments("hook", {Bezier::make({{0, 0, 0}, {5, 10, 0}, {10, 0, 0}}),
                              NurbsCurve::make(2, {{10, 0, 0}, {15, -10, 0}, {20, 0, 0}, {25, 5, 0}},
                                               {0, 0, 0, 0.4, 1, 1, 1}, {2, 2, 2, 2})})
      .interpolate("wave", {{0, 20, 0}, {10, 25, 0}, {20, 18, 0}, {30, 24, 0}})
      .interpolate("loop", {{40, 0, 0}, {50, 10, 0}, {40, 20, 0}, {30, 10, 0}}, true)
      .build();
}

}  // namespace

TEST(JobBuilder, PathSegmentsAndInterpolationsAreTheFilesCurves) {
  const Job from_json = parse_job(kSplineJson, "splines.json");
  const Job in_memory = spline_built();
  ASSERT_EQ(in_memory.entities.size(), from_json.entities.size());
  for (size_t k = 0; k < from_json.entities.size(); ++k) {
    const CurveGeometry &a = from_json.entities[k].curve, &b = in_memory.entities[k].curve;
    EXPECT_EQ(in_memory.entities[k].type, from_json.entities[k].type);
    EXPECT_EQ(b.closed, a.closed);
    ASSERT_EQ(b.segments.size(), a.segments.size());
    for (size_t s = 0; s < a.segments.size(); ++s) {
      EXPECT_EQ(b.segments[s].kind, a.segments[s].kind);
      EXPECT_EQ(b.segments[s].rational, a.segments[s].rational);
      EXPECT_EQ(b.segments[s].nurbs != nullptr, a.segments[s].nurbs != nullptr);
    }
  }
  for (const char* machine : {"generic", "linuxcnc"}) {
    const MachineProfile m = load_machine_profile(machine);
    for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
      ConvertOptions opt;
      opt.output = mode;
      EXPECT_EQ(convert(in_memory, m, opt).gcode, convert(from_json, m, opt).gcode)
          << machine << " " << to_string(mode);
    }
  }
}

TEST(JobBuilder, InterpolationThatCannotBeMadeIsRefusedAtItsEntity) {
  try {
    JobBuilder("j").interpolate("a", {{0, 0, 0}, {1, 1, 0}}).interpolate("b", {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}});
    ADD_FAILURE() << "two equal points in a row were accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().rfind("j: entities[1]", 0), 0u) << e.what();
  }
}

TEST(JobBuilder, SettingsAreReadAsTheFilesKeys) {
  const std::vector<std::pair<std::string, std::string>> sets = {
      {"units", "inch"},          {"feed", "20"},      {"cut_z", "-0.1"},     {"side", "outside"},
      {"tool_diameter", "0.125"}, {"tabs.count", "2"}, {"tabs.width", "0.2"}, {"tabs.height", "0.05"},
      {"order", "shortest"}};
  const Job built = JobBuilder("s").safe_z(1).settings(sets).bezier("a", Bezier::make({{0, 0, 0}, {1, 1, 0}})).build();
  const Job read = parse_job(R"({"bezcam": 1, "units": "inch", "job": {"feed": 20, "cut_z": -0.1, "safe_z": 1,
      "side": "outside", "tool_diameter": 0.125, "tabs": {"count": 2, "width": 0.2, "height": 0.05},
      "order": "shortest"}, "entities": [{"id": "a", "type": "bezier", "points": [[0, 0], [1, 1]]}]})",
                             "s");
  EXPECT_EQ(built.units, read.units);
  EXPECT_EQ(built.tolerance, read.tolerance);  // the default follows the units
  EXPECT_EQ(built.order_shortest, read.order_shortest);
  EXPECT_EQ(built.params.feed, read.params.feed);
  EXPECT_EQ(built.params.cut_z, read.params.cut_z);
  EXPECT_EQ(built.params.safe_z, read.params.safe_z);  // given before, kept
  EXPECT_EQ(built.params.side, read.params.side);
  EXPECT_EQ(built.params.tool_diameter, read.params.tool_diameter);
  ASSERT_TRUE(built.params.tabs && read.params.tabs);
  EXPECT_EQ(built.params.tabs->count, read.params.tabs->count);
  EXPECT_EQ(built.params.tabs->width, read.params.tabs->width);
  // A tolerance given before the settings stays when they give none.
  EXPECT_EQ(JobBuilder("t")
                .tolerance(0.002)
                .settings(sets)
                .bezier("a", Bezier::make({{0, 0, 0}, {1, 1, 0}}))
                .build()
                .tolerance,
            0.002);
  // A value the job refuses is named at its JSON path, in the builder's name.
  try {
    JobBuilder("drawing.svg").settings(std::vector<std::pair<std::string, std::string>>{{"feed", "-5"}});
    ADD_FAILURE() << "feed -5 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "drawing.svg: job.feed");
  }
}
