// Warnings by kind: tagged, read back, grouped per entity.
#include "bezcam/warnings.hpp"

#include <gtest/gtest.h>

#include "bezcam/cam/program.hpp"
#include "bezcam/error.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/machine_profile.hpp"

namespace bezcam {
namespace {

TEST(Warnings, KindIsReadFromTheTag) {
  EXPECT_EQ(warning_kind(tagged_warning("a: material is left", "material-left")), "material-left");
  EXPECT_EQ(warning_kind("a: no tag"), "");
  EXPECT_EQ(warning_kind("a: brackets [not a kind]"), "");
  EXPECT_TRUE(is_warning_kind("tabs-skipped"));
  EXPECT_FALSE(is_warning_kind("tabs"));
}

TEST(Warnings, OneKindOnOneEntityIsOneLineWithACount) {
  const std::vector<std::string> in = {tagged_warning("a: stretch 1 too short", "tabs-skipped"),
                                       "machine m has no tool changer",
                                       tagged_warning("b: stretch 1 too short", "tabs-skipped"),
                                       tagged_warning("a: stretch 2 too short", "tabs-skipped"),
                                       tagged_warning("a: material left", "material-left"),
                                       tagged_warning("a: stretch 3 too short", "tabs-skipped")};
  const std::vector<std::string> out = grouped_warnings(in);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0], "a: stretch 1 too short (3 warnings of this kind on a; the first shown) [tabs-skipped]");
  EXPECT_EQ(out[1], in[1]);
  EXPECT_EQ(out[2], in[2]);
  EXPECT_EQ(out[3], in[4]);
  EXPECT_EQ(grouped_warnings(out), out);  // grouping twice changes nothing
}

TEST(Refusals, EveryEntityRefusedIsReportedOnce) {
  // Two open curves cut "inside" and one closed curve that is fine: two
  // refusals, each naming its entity.
  const std::string open = R"({"type":"bezier","points":[[0,0],[10,0],[10,10]],"side":"inside"})";
  const Job job = parse_job(R"({"bezcam":1,"job":{"feed":600,"plunge_feed":100,"safe_z":5,"cut_z":-1,
      "tool_diameter":2,"order":"as-written"},"entities":[)" +
                                open + "," + open + "]}",
                            "t.json");
  try {
    build_program(job, load_machine_profile("generic"), ConvertOptions{});
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("entities[0]"), std::string::npos) << e.what();
    ASSERT_EQ(e.more().size(), 1u) << e.what();
    EXPECT_NE(std::string(e.more()[0].what()).find("entities[1]"), std::string::npos) << e.more()[0].what();
  }
}

}  // namespace
}  // namespace bezcam
