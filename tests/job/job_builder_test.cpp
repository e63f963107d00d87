// JobBuilder: a job made in memory converts exactly as the same job read
// from JSON, and bad values are refused naming the place.
#include <gtest/gtest.h>

#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_builder.hpp"
#include "bezcam/job/job_json.hpp"

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
  refused([&] { JobBuilder("j").path("p", {c, Bezier::make({{5, 5, 0}, {6, 6, 0}})}); }, "path.joint",
          "j: entities[0].segments[1]");
}
