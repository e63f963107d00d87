// The sides of a part drawn in a drawing: `side: "outside"` is the part's
// outside, so contours nested in others (even-odd) are holes cut on their
// inside, and the tool path of every hole runs at the hole's radius minus
// the tool's (docs/import.md, "Sides of a part"). A job that cuts a hole
// on its outside inside an outline also cut outside is warned about,
// naming both entities.
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <map>
#include <string>
#include <variant>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "bezcam/import/svg_reader.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/drawing_fonts.hpp"

namespace bezcam::import {
namespace {

namespace fs = std::filesystem;
const fs::path kRoot = BEZCAM_SOURCE_DIR;

ImportOptions with(std::vector<std::pair<std::string, std::string>> settings) {
  ImportOptions o = test::with_fonts();
  o.settings = std::move(settings);
  return o;
}

std::map<std::string, CutSide> sides_of(const Job& job) {
  std::map<std::string, CutSide> out;
  for (const Entity& e : job.entities) {
    const JobParams p = e.params.over(job.params);
    out[e.id] = p.side.value_or(CutSide::on);
  }
  return out;
}

// The end points of the entity's cutting moves at depth z (lines and arcs).
std::vector<Vec3> cut_points(const Program& p, const Job& job, const std::string& id, double z) {
  int index = -1;
  for (const Entity& e : job.entities)
    if (e.id == id) index = static_cast<int>(e.index);
  std::vector<Vec3> out;
  for (const Move& m : p.moves) {
    if (m.entity != index) continue;
    if (const auto* l = std::get_if<LineMove>(&m.what); l && std::abs(l->to.z - z) < 1e-9) out.push_back(l->to);
    if (const auto* a = std::get_if<ArcMove>(&m.what); a && std::abs(a->to.z - z) < 1e-9) out.push_back(a->to);
  }
  return out;
}

double xy(const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// samples/part.dxf: an 80 x 50 outline with corners of radius 6, four holes
// of radius 2.5 and a slot 30 x 10. With side "outside" and a 2 mm tool the
// outline is cut 1 mm outside, each hole on a circle of radius 1.5 about
// its centre, the slot 4 mm from its centre line: every hole at its drawn
// size. Measured on the program's moves (arcs: exact circles, the printed
// decimals aside).
TEST(ImportSides, PartDxfHolesComeOutAtTheirDrawnDiameter) {
  const Drawing d = read_drawing(kRoot / "samples/part.dxf");
  ImportOptions opt = with({{"side", "outside"}, {"tool_diameter", "2"}, {"cut_z", "-1"}, {"tolerance", "0.01"}});
  opt.skip = {"NOTES"};  // the note's letters: too small for the tool
  const std::string text = job_json(d, opt);
  EXPECT_NE(text.find("{ \"id\": \"HOLES:37\", \"side\": \"inside\""), std::string::npos) << text.substr(0, 400);
  const Job job = to_job(d, opt);
  ConvertOptions co;
  co.output = OutputMode::arcs;
  const ConvertResult r = convert(job, load_machine_profile("generic"), co);
  const std::map<std::string, Vec3> holes = {
      {"HOLES:37", {10, 10}}, {"HOLES:38", {70, 10}}, {"HOLES:39", {70, 40}}, {"HOLES:3A", {10, 40}}};
  for (const auto& [id, c] : holes) {
    SCOPED_TRACE(id);
    const auto pts = cut_points(r.program, job, id, -1);
    ASSERT_GT(pts.size(), 3u);
    for (const Vec3& q : pts) EXPECT_NEAR(xy(q, c), 2.5 - 1, 0.001);
  }
  {  // the slot: 4 from the segment between its arcs' centres
    const auto pts = cut_points(r.program, job, "HOLES:3B", -1);
    ASSERT_GT(pts.size(), 3u);
    for (const Vec3& q : pts) {
      const double x = std::clamp(q.x, 30.0, 50.0);
      EXPECT_NEAR(std::hypot(q.x - x, q.y - 25), 5 - 1, 0.001) << q.x << " " << q.y;
    }
  }
  {  // the outline: 1 outside the rounded rectangle
    const auto pts = cut_points(r.program, job, "OUTLINE:2F+7", -1);
    ASSERT_GT(pts.size(), 3u);
    for (const Vec3& q : pts) {
      const double qx = std::abs(q.x - 40) - (40 - 6), qy = std::abs(q.y - 25) - (25 - 6);
      const double sd = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0) - 6;
      EXPECT_NEAR(sd, 1, 0.001) << q.x << " " << q.y;
    }
  }
  EXPECT_LE(r.program.max_measured, 0.01);
  for (const std::string& w : r.program.warnings) EXPECT_EQ(w.find("hole"), std::string::npos) << w;
}

// Even-odd depth, touching, duplicates and crossings: a plate (depth 0)
// with a bore (1), a boss left in the bore (2) and a pin hole in the boss
// (3) with its duplicate; a hole touching two edges of the plate from
// inside (1); a part touching the plate from outside (0); a tab crossing
// the plate's edge (inside neither, warned about with the plate).
TEST(ImportSides, EvenOddDepthDecidesEachContoursSide) {
  const Drawing d = read_svg(R"~(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100">
      <rect id="plate" x="0" y="0" width="100" height="60"/>
      <circle id="bore" cx="30" cy="30" r="20"/><circle id="boss" cx="30" cy="30" r="12"/>
      <circle id="pin" cx="30" cy="30" r="4"/><circle id="twin" cx="30" cy="30" r="4"/>
      <circle id="corner" cx="90" cy="50" r="10"/>
      <circle id="neighbour" cx="110" cy="30" r="10"/>
      <rect id="tab" x="60" y="40" width="10" height="30"/>
      <polyline id="mark" points="50,5 55,5"/></svg>)~",
                             "plate.svg");
  const auto side = [](CutSide s) {
    return s == CutSide::inside ? "inside" : s == CutSide::outside ? "outside" : "other";
  };
  std::vector<std::string> warnings;
  const auto out = sides_of(to_job(d, with({{"side", "outside"}, {"tool_diameter", "1"}}), &warnings));
  const std::map<std::string, std::string> want = {{"plate", "outside"},     {"bore", "inside"}, {"boss", "outside"},
                                                   {"pin", "inside"},        {"twin", "inside"}, {"corner", "inside"},
                                                   {"neighbour", "outside"}, {"tab", "outside"}, {"mark", "outside"}};
  for (const auto& [id, s] : want) EXPECT_EQ(side(out.at(id)), s) << id;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("contours \"plate\" and \"tab\" cross each other"), std::string::npos) << warnings[0];
  // `inside`: the drawn regions are openings; every side the other way.
  const auto in = sides_of(to_job(d, with({{"side", "inside"}, {"tool_diameter", "1"}})));
  for (const auto& [id, s] : want)
    if (id != "mark") EXPECT_EQ(side(in.at(id)), s == "outside" ? std::string("inside") : std::string("outside")) << id;
  // Other sides are left as they are.
  const auto left = sides_of(to_job(d, with({{"side", "left"}, {"tool_diameter", "1"}})));
  for (const auto& [id, s] : left) EXPECT_EQ(s, CutSide::left) << id;
}

// A LibreCAD drawing (librecad-data): a flange of radius 10 with three
// holes on its centre line, the middle one (radius 4) touching both
// others (radius 3), the outer ones touching the flange from inside.
// Every hole is found inside the flange, none inside another, and cut at
// its drawn size.
TEST(ImportSides, LibreCadFlangeWithTouchingHoles) {
  const fs::path file = "/usr/share/librecad/library/kinetics/kin124.dxf";
  if (!fs::exists(file)) GTEST_SKIP() << "librecad-data is not installed";
  const Drawing d = read_drawing(file);
  Job job = to_job(d, with({{"side", "outside"}, {"tool_diameter", "1"}, {"cut_z", "-1"}}));
  const auto s = sides_of(job);
  EXPECT_EQ(s.at("0:49"), CutSide::outside);  // the flange
  for (const char* h : {"0:46", "0:47", "0:48"}) EXPECT_EQ(s.at(h), CutSide::inside) << h;
  // Its centre lines and the arrow are open curves, which no side fits:
  // the closed contours are cut.
  std::vector<Entity> closed;
  for (Entity& e : job.entities)
    if (e.curve.closed) closed.push_back(std::move(e));
  for (size_t i = 0; i < closed.size(); ++i) closed[i].index = i;
  job.entities = std::move(closed);
  ConvertOptions co;
  co.output = OutputMode::arcs;
  const ConvertResult r = convert(job, load_machine_profile("generic"), co);
  const std::map<std::string, std::pair<Vec3, double>> circles = {{"0:46", {{12, 7}, 3 - 0.5}},
                                                                  {"0:47", {{12, 0}, 4 - 0.5}},
                                                                  {"0:48", {{12, -7}, 3 - 0.5}},
                                                                  {"0:49", {{12, 0}, 10 + 0.5}}};
  for (const auto& [id, cr] : circles) {
    SCOPED_TRACE(id);
    const auto pts = cut_points(r.program, job, id, -1);
    ASSERT_GT(pts.size(), 3u);
    for (const Vec3& q : pts) EXPECT_NEAR(xy(q, cr.first), cr.second, 0.001);
  }
}

// A job file (not a drawing) says what each entity's side is; a hole cut
// "outside" inside an outline cut "outside" is warned about, naming both.
TEST(ImportSides, JobWithAHoleCutOutsideIsWarned) {
  const Drawing d = read_drawing(kRoot / "samples/part.dxf");
  ImportOptions opt = with({{"side", "outside"}, {"tool_diameter", "2"}});
  opt.skip = {"NOTES"};  // the note's letters: too small for the tool
  std::string text = job_json(d, opt);
  const auto program_warnings = [](const std::string& t) {
    JobReadOptions ro;
    ro.text = text::font_outliner();
    const Job job = parse_job(t, "part.json", ro);
    return convert(job, load_machine_profile("generic"), ConvertOptions{}).program.warnings;
  };
  for (const std::string& w : program_warnings(text)) EXPECT_EQ(w.find("is cut \"outside\""), std::string::npos) << w;
  const std::string hole = "{ \"id\": \"HOLES:38\", \"side\": \"inside\"";
  ASSERT_NE(text.find(hole), std::string::npos);
  text.replace(text.find(hole), hole.size(), "{ \"id\": \"HOLES:38\", \"side\": \"outside\"");
  const auto w = program_warnings(text);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_TRUE(
      w[0].starts_with("entities[2] (id \"HOLES:38\") is cut \"outside\" but lies inside entities[0] (id "
                       "\"OUTLINE:2F+7\"), also cut \"outside\": it is a hole in that part"))
      << w[0];
}

}  // namespace
}  // namespace bezcam::import
