// The pocket keys of a job (docs/pocket.md): read, merged entity over job,
// and refused with their JSON path.
#include <gtest/gtest.h>

#include "bezcam/error_ids.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/job/settings.hpp"
#include "support/refusal.hpp"

namespace bezcam {
namespace {

const char* kSquare = R"({"type":"path","closed":true,"segments":[{"type":"bezier","points":[[0,0],[20,0]]},)"
                      R"({"type":"bezier","points":[[20,0],[20,20]]},{"type":"bezier","points":[[20,20],[0,20]]},)"
                      R"({"type":"bezier","points":[[0,20],[0,0]]}])";

Job job(const std::string& job_keys, const std::string& entity_keys) {
  return parse_job(R"({"bezcam":1,"job":{)" + job_keys + "}," + R"("entities":[)" + kSquare + entity_keys + "}]}",
                   "pocket.json");
}

TEST(PocketKeys, EntityKeysWinOverTheJobs) {
  const Job j = job(
      R"("operation":"pocket","stepover":2,"pattern":"zigzag","angle":30)",
      R"(,"id":"a","region":"plate","stepover":1.5,"finish":{"stock":0.2},"entry":{"helix":{"radius":2,"angle":4}})");
  const PocketKeys k = j.entities[0].params.pocket.over(j.params.pocket);
  EXPECT_EQ(k.operation, Operation::pocket);
  EXPECT_EQ(k.region, "plate");
  EXPECT_EQ(k.pattern, PocketPattern::zigzag);
  EXPECT_EQ(k.angle, 30);
  EXPECT_EQ(k.stepover, 1.5);
  EXPECT_EQ(k.finish_stock, 0.2);
  ASSERT_TRUE(k.entry);
  EXPECT_EQ(k.entry->kind, PocketEntry::Kind::helix);
  EXPECT_EQ(k.entry->radius, 2);
  EXPECT_EQ(k.entry->angle, 4);
}

TEST(PocketKeys, EntryForms) {
  EXPECT_EQ(job(R"("entry":"ramp")", "").params.pocket.entry->kind, PocketEntry::Kind::ramp);
  EXPECT_EQ(job(R"("entry":"plunge")", "").params.pocket.entry->kind, PocketEntry::Kind::plunge);
  const auto r = job(R"("entry":{"ramp":{"angle":5}})", "").params.pocket.entry;
  EXPECT_EQ(r->kind, PocketEntry::Kind::ramp);
  EXPECT_EQ(r->angle, 5);
  EXPECT_FALSE(job("", "").params.pocket.operation);
}

TEST(PocketKeys, BadValuesAreRefusedWithTheirPath) {
  struct Case {
    std::string entity_keys;
    std::string id, path;
  } cases[] = {
      {R"(,"stepover":0)", "job.pocket", "entities[0].stepover"},
      {R"(,"stepover":-1)", "job.pocket", "entities[0].stepover"},
      {R"(,"operation":"mill")", "job.operation", "entities[0].operation"},
      {R"(,"pattern":"spiral")", "job.pocket", "entities[0].pattern"},
      {R"(,"load":0)", "job.pocket", "entities[0].load"},
      {R"(,"load":-0.5)", "job.pocket", "entities[0].load"},
      {R"(,"entry":"dive")", "job.pocket", "entities[0].entry"},
      {R"(,"entry":{"helix":{"radius":0}})", "job.not-positive", "entities[0].entry.helix.radius"},
      {R"(,"entry":{"ramp":{"angle":90}})", "job.range", "entities[0].entry.ramp.angle"},
      {R"(,"finish":{"stock":0})", "job.not-positive", "entities[0].finish.stock"},
      {R"(,"finish":{"depth":1})", "job.unknown-key", "entities[0].finish.depth"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.entity_keys);
    const InputError e = test::refusal_of([&] { job("", c.entity_keys); });
    EXPECT_EQ(e.id(), c.id) << e.what();
    EXPECT_EQ(e.place().json_path.value_or(""), c.path) << e.what();
  }
}

TEST(PocketKeys, SetOperationPocketIsASetting) {
  const std::pair<std::string, std::string> s[] = {{"operation", "pocket"}, {"region", "plate"}, {"stepover", "2"}};
  const SettingsJson j = settings_json(s);
  ASSERT_EQ(j.job.size(), 3u);
  EXPECT_EQ(j.job[0].first, "operation");
  EXPECT_EQ(j.job[0].second, "\"pocket\"");
}

}  // namespace
}  // namespace bezcam
