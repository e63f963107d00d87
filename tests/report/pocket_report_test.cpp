// A pocket's certificate in the report: JSON and text.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bezcam/cam/program.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/report/report.hpp"

namespace bezcam {
namespace {

TEST(PocketReport, TheCertificateIsInTheJsonAndTheText) {
  const std::string json =
      R"({"bezcam":1,"tolerance":0.01,"job":{"feed":600,"plunge_feed":100,"safe_z":5,"cut_z":-2,)"
      R"("tool_diameter":6.35,"operation":"pocket","stepover":5},"entities":[{"id":"sq","type":"path","closed":true,)"
      R"("segments":[{"type":"bezier","points":[[0,0],[16,0]]},{"type":"bezier","points":[[16,0],[16,16]]},)"
      R"({"type":"bezier","points":[[16,16],[0,16]]},{"type":"bezier","points":[[0,16],[0,0]]}]}]})";
  const MachineProfile m = load_machine_profile("linuxcnc");
  const Program p = build_program(parse_job(json, "sq.json"), m, ConvertOptions{});
  const ProgramReport r = make_report(p, m);
  const auto j = nlohmann::json::parse(report_json(r));
  const auto& c = j["entities"][0]["pocket"];
  EXPECT_EQ(c["uncut_area"].get<double>(), 0);
  EXPECT_TRUE(c["covered"].get<bool>());
  EXPECT_EQ(c["unreachable"].size(), 4u);
  EXPECT_NEAR(c["wall_distance_asked"].get<double>(), 3.175, 1e-12);
  EXPECT_GE(c["wall_distance"].get<double>(), 3.175 - 0.01);
  EXPECT_EQ(c["rapids_through_material"].get<int>(), 0);
  const std::string text = report_text(r);
  EXPECT_NE(text.find("pocket sq: uncut 0 mm^2"), std::string::npos) << text;
  EXPECT_NE(text.find("no rapid through material"), std::string::npos) << text;
}

}  // namespace
}  // namespace bezcam
