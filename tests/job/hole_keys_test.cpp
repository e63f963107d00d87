// Holes in a job (docs/holes.md): `point` entities and the drilling keys,
// read, merged entity over job, accepted as settings, refused with their
// JSON path.
#include <gtest/gtest.h>

#include "bezcam/error_ids.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/job/settings.hpp"
#include "support/refusal.hpp"

namespace bezcam {
namespace {

Job job(const std::string& job_keys, const std::string& entity) {
  return parse_job(R"({"bezcam":1,"job":{)" + job_keys + "}," + R"("entities":[)" + entity + "]}", "holes.json");
}

TEST(HoleKeys, PointsAndDrillKeysAreRead) {
  const Job j = job(R"("operation":"drill","peck":2,"retract_z":1.5,"to":"tip")",
                    R"({"type":"point","at":[3,4],"id":"h","peck":1.5,"chip_break":true,"dwell":0.25})");
  ASSERT_EQ(j.entities.size(), 1u);
  const Entity& e = j.entities[0];
  ASSERT_TRUE(e.point);
  EXPECT_EQ(e.point->x, 3);
  EXPECT_EQ(e.point->y, 4);
  EXPECT_TRUE(e.curve.pieces.empty());
  const JobParams p = e.params.over(j.params);
  EXPECT_EQ(p.pocket.operation, Operation::drill);
  EXPECT_EQ(p.drill.peck, 1.5);
  EXPECT_EQ(p.drill.chip_break, true);
  EXPECT_EQ(p.drill.dwell, 0.25);
  EXPECT_EQ(p.drill.retract_z, 1.5);
  EXPECT_EQ(p.drill.to_tip, true);
  EXPECT_EQ(job(R"("operation":"bore")", R"({"type":"point","at":[0,0]})").params.pocket.operation, Operation::bore);
  EXPECT_EQ(job(R"("to":"diameter")", R"({"type":"point","at":[0,0]})").params.drill.to_tip, false);
}

TEST(HoleKeys, BadValuesAreRefusedWithTheirPath) {
  struct Case {
    std::string entity;
    std::string id, path;
  } cases[] = {
      {R"({"type":"point"})", "job.missing", "entities[0].at"},
      {R"({"type":"point","at":[1,2,3]})", "job.type", "entities[0].at"},
      {R"({"type":"point","at":"here"})", "job.type", "entities[0].at"},
      {R"({"type":"point","at":[1,2],"points":[[0,0]]})", "job.unknown-key", "entities[0].points"},
      {R"({"type":"point","at":[1,2],"peck":-1})", "job.hole", "entities[0].peck"},
      {R"({"type":"point","at":[1,2],"dwell":-0.5})", "job.hole", "entities[0].dwell"},
      {R"({"type":"point","at":[1,2],"to":"bottom"})", "job.hole", "entities[0].to"},
      {R"({"type":"point","at":[1,2],"chip_break":1})", "job.type", "entities[0].chip_break"},
      {R"({"type":"point","at":[1,2],"retract_z":"up"})", "job.type", "entities[0].retract_z"},
      {R"({"type":"point","at":[1,2],"pek":1})", "job.key-typo", "entities[0].pek"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.entity);
    const InputError e = test::refusal_of([&] { job("", c.entity); });
    EXPECT_EQ(e.id(), c.id) << e.what();
    EXPECT_EQ(e.place().json_path.value_or(""), c.path) << e.what();
  }
}

TEST(HoleKeys, DrillKeysAreSettings) {
  // `--set operation=drill --set peck=2 ...` for a drawing.
  const std::pair<std::string, std::string> s[] = {{"operation", "drill"}, {"peck", "2"},      {"chip_break", "true"},
                                                   {"dwell", "0.5"},       {"retract_z", "1"}, {"to", "tip"}};
  const SettingsJson j = settings_json(s);
  ASSERT_EQ(j.job.size(), 6u);
  EXPECT_EQ(j.job[0].second, "\"drill\"");
  const JobParams p = entity_params(j.job, "part.dxf", "settings");
  EXPECT_EQ(p.pocket.operation, Operation::drill);
  EXPECT_EQ(p.drill.peck, 2);
  EXPECT_EQ(p.drill.chip_break, true);
  EXPECT_EQ(p.drill.dwell, 0.5);
  EXPECT_EQ(p.drill.retract_z, 1);
  EXPECT_EQ(p.drill.to_tip, true);
}

}  // namespace
}  // namespace bezcam
