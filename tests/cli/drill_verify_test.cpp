// `bezcam verify --design` on drilled and bored holes (docs/holes.md,
// docs/verify.md): each hole is compared as a pocket of its circle (a
// point's: the drill's), no false gouge at a drill's point, and a hole
// drilled elsewhere is a gouge.
#include <fstream>
#include <gtest/gtest.h>
#include <regex>

#include "in_process.hpp"
#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;

testproc::Result bezcam(const std::vector<std::string>& args) {
  return testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, BEZCAM_SOURCE_DIR);
}

const char* kJob = R"({"bezcam":1,"tolerance":0.01,
 "tools":{"1":{"shape":"flat","diameter":4},"2":{"shape":"drill","diameter":3,"point_angle":118}},
 "job":{"feed":600,"plunge_feed":150,"safe_z":5,"top_z":0,"clearance":1,"cut_z":-3},
 "entities":[
  {"id":"spot","type":"point","at":[5,5],"operation":"drill","tool":2,"peck":1},
  {"id":"bore","type":"path","closed":true,"operation":"bore","tool":1,"segments":[
   {"type":"bezier","points":[[19,5],[19,9],[15,9]],"weights":[1,0.7071067811865476,1]},
   {"type":"bezier","points":[[15,9],[11,9],[11,5]],"weights":[1,0.7071067811865476,1]},
   {"type":"bezier","points":[[11,5],[11,1],[15,1]],"weights":[1,0.7071067811865476,1]},
   {"type":"bezier","points":[[15,1],[19,1],[19,5]],"weights":[1,0.7071067811865476,1]}]}]})";

TEST(DrillVerify, HolesAreComparedWithTheirCircles) {
  testproc::TempDir dir;
  const fs::path job = dir / "holes.json", nc = dir / "holes.nc", bad = dir / "moved.nc";
  std::ofstream(job) << kJob;
  ASSERT_EQ(
      bezcam({"convert", job.string(), "--machine", "linuxcnc", "--output", "arcs", "-o", nc.string(), "-q"}).status,
      0);
  const auto ok = bezcam({"verify", nc.string(), "--machine", "linuxcnc", "--design", job.string(), "--cell", "0.02"});
  EXPECT_EQ(ok.status, 0) << ok.out << ok.err;
  EXPECT_NE(ok.out.find("spot: largest gouge 0 mm"), std::string::npos) << ok.out;
  // The bore's wall within the tolerance (its arcs against the design's
  // flattened circle).
  EXPECT_TRUE(std::regex_search(ok.out, std::regex(R"(bore: largest gouge (0|[0-9.]+e-0[5-9]) mm)"))) << ok.out;
  // The drilled hole 0.5 mm off: a gouge into its wall.
  std::string g = testproc::slurp(nc);
  const size_t at = g.find("X5. Y5.");
  ASSERT_NE(at, std::string::npos) << g;
  g.replace(at, 7, "X5.5 Y5.");
  std::ofstream(bad) << g;
  const auto moved =
      bezcam({"verify", bad.string(), "--machine", "linuxcnc", "--design", job.string(), "--cell", "0.02"});
  EXPECT_EQ(moved.status, 5) << moved.out << moved.err;
  EXPECT_TRUE(std::regex_search(moved.out, std::regex(R"(spot: largest gouge 0\.(4[89]|5)\d* mm)"))) << moved.out;
}

// The plate sample: a recess round two bosses, four holes drilled with a
// second tool, the outline with a third; no gouge anywhere.
TEST(DrillVerify, TheDrilledPlateSampleHasNoGouge) {
  testproc::TempDir dir;
  const fs::path nc = dir / "plate.nc";
  ASSERT_EQ(
      bezcam({"convert", "samples/part-plate-drilled.json", "--machine", "linuxcnc", "-o", nc.string(), "-q"}).status,
      0);
  const auto r = bezcam(
      {"verify", nc.string(), "--machine", "linuxcnc", "--design", "samples/part-plate-drilled.json", "--cell", "0.1"});
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  for (const char* hole : {"hole-1: largest gouge 0 mm", "hole-2: largest gouge 0 mm", "hole-3: largest gouge 0 mm",
                           "hole-4: largest gouge 0 mm"})
    EXPECT_NE(r.out.find(hole), std::string::npos) << r.out;
}

}  // namespace
