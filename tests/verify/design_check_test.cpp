#include "bezcam/verify/design_check.hpp"

#include <cmath>
#include <gtest/gtest.h>

#include "bezcam/gcode/timeline.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/verify/machined_program.hpp"

using namespace bezcam;

namespace {

const StockBox kBox{-20, -20, -5, 20, 20, 0};
constexpr double kCell = 0.05;

// A 20 x 20 mm square cut outside with a 4 mm flat end mill, 2 mm deep.
Job square_job(const std::string& side = "outside") {
  const std::string j = R"({"bezcam": 1, "units": "mm", "tolerance": 0.01,
    "job": {"feed": 500, "plunge_feed": 100, "safe_z": 5, "top_z": 0, "cut_z": -2, "spindle_rpm": 10000,
            "tool": 1, "tool_diameter": 4, "side": ")" +
                        side + R"("},
    "entities": [{"id": "square", "type": "path", "closed": true, "segments": [
      {"type": "bezier", "points": [[-10, -10], [10, -10]]}, {"type": "bezier", "points": [[10, -10], [10, 10]]},
      {"type": "bezier", "points": [[10, 10], [-10, 10]]}, {"type": "bezier", "points": [[-10, 10], [-10, -10]]}]}]})";
  return parse_job(j, "square.json");
}

// The tool centre's exact path around the square: sides 2 mm out, corners
// arcs of radius 2 about the square's corners.
const std::string kHead = "G21 G90 G17\nT1 M6\nG0 X-10 Y-12 Z5\nG1 Z-2 F100\n";
const std::string kSouthToNorth = "G1 X10 Y-12 F500\nG3 X12 Y-10 I0 J2\nG1 X12 Y10\nG3 X10 Y12 I-2 J0\n";
const std::string kWestBack = "G3 X-12 Y10 I0 J-2\nG1 X-12 Y-10\nG3 X-10 Y-12 I2 J0\nG0 Z5\n";
const std::string kNorth = "G1 X-10 Y12\n";

DesignCheck check(const std::string& program, const Job& job, const StockTools& tools) {
  StockCutter c(kBox, kCell, tools);
  cut_timeline(c, read_timeline(program));
  return check_design(c.grid(), job, MachineProfile{}, tools);
}

const StockTools kFlat4{{1, ToolShape::flat(4)}};

}  // namespace

TEST(DesignCheck, TheExactOffsetNeitherGougesNorLeavesMaterial) {
  const DesignCheck d = check(kHead + kSouthToNorth + kNorth + kWestBack + "M30\n", square_job(), kFlat4);
  ASSERT_EQ(d.entities.size(), 1u);
  const EntityCheck& e = d.entities[0];
  EXPECT_TRUE(e.compared);
  EXPECT_LE(e.gouge, 1e-9);
  EXPECT_LE(e.excess, d.tolerance);
  EXPECT_EQ(e.gouge_columns, 0u);
  EXPECT_EQ(e.excess_columns, 0u);
  EXPECT_FALSE(d.gouged());
  EXPECT_GE(d.design_bound, 0);  // straight walls flatten exactly
  EXPECT_LE(d.design_bound, d.tolerance / 100);
}

TEST(DesignCheck, APlantedGougeIsFoundWithItsSizeAndPlace) {
  // A second pass 0.3 mm into the east wall, from y = -5 to 5.
  const std::string extra = "G0 X11.7 Y-5\nG1 Z-2 F100\nG1 Y5 F500\nG0 Z5\n";
  const DesignCheck d = check(kHead + kSouthToNorth + kNorth + kWestBack + extra + "M30\n", square_job(), kFlat4);
  const EntityCheck& e = d.entities[0];
  // Measured at the column centres: the deepest within a cell of 0.3.
  EXPECT_LE(e.gouge, 0.3 + 1e-9);
  EXPECT_GE(e.gouge, 0.3 - kCell);
  EXPECT_NEAR(e.gouge_at.x, 10 - e.gouge, 1e-9);
  EXPECT_LE(std::abs(e.gouge_at.y), 5 + std::sqrt(4 - std::pow(11.7 - (10 - e.gouge), 2)) + 1e-9);
  EXPECT_DOUBLE_EQ(e.gouge_at.z, -2);
  EXPECT_TRUE(d.gouged());
  // The tool's disc past x = 10 swept from y = -5 to 5: a 10 x 0.3 strip
  // and the two halves of a circular segment (chord 1.7 from the centre),
  // 2 mm deep; the cells along its outline differ by less than a cell each.
  const double segment = 4 * std::acos(1.7 / 2) - 1.7 * std::sqrt(4 - 1.7 * 1.7);
  EXPECT_NEAR(e.gouge_volume, (10 * 0.3 + segment) * 2, 0.25);
  std::size_t marked = 0;
  for (ColumnClass c : d.classes) marked += c == ColumnClass::gouge;
  EXPECT_EQ(marked, e.gouge_columns);
}

TEST(DesignCheck, AMissingSideIsExcess) {
  // The north side is not cut: its kerf stands 2 mm high.
  const std::string lifted = "G0 Z5\nG0 X-10 Y12\nG1 Z-2 F100\n";
  const DesignCheck d = check(kHead + kSouthToNorth + lifted + kWestBack + "M30\n", square_job(), kFlat4);
  const EntityCheck& e = d.entities[0];
  // Measured normal to the kerf the tool would leave: 2 mm at its axis,
  // the nearest column half a cell from it.
  EXPECT_NEAR(e.excess, 2 - kCell / 2, 1e-9);
  EXPECT_GT(e.excess_at.y, 10);
  EXPECT_LE(e.gouge, 1e-9);
  EXPECT_FALSE(d.gouged());
}

TEST(DesignCheck, InsideTheSameProgramGougesTheWholeSquare) {
  // Cut inside, the design's part is outside: the outside path cuts into it.
  const DesignCheck d = check(kHead + kSouthToNorth + kNorth + kWestBack + "M30\n", square_job("inside"), kFlat4);
  EXPECT_NEAR(d.entities[0].gouge, 2, kCell + 1e-9);
  EXPECT_TRUE(d.gouged());
}

TEST(DesignCheck, AGrooveIsTheToolsShapeAlongTheCurve) {
  const std::string j = R"({"bezcam": 1, "units": "mm", "tolerance": 0.01,
    "job": {"feed": 500, "plunge_feed": 100, "safe_z": 5, "top_z": 0, "cut_z": -1, "spindle_rpm": 10000, "tool": 1},
    "entities": [{"id": "line", "type": "bezier", "points": [[-10, 0], [10, 0]]}]})";
  const Job job = parse_job(j, "groove.json");
  const StockTools vee{{1, ToolShape::vee(6, 90)}};
  const std::string exact = "G21 G90\nT1 M6\nG0 X-10 Y0 Z5\nG1 Z-1 F100\nG1 X10 F500\nG0 Z5\nM30\n";
  const DesignCheck ok = check(exact, job, vee);
  EXPECT_LE(ok.entities[0].gouge, 1e-9);
  EXPECT_LE(ok.entities[0].excess, 1e-9);
  const std::string deep = "G21 G90\nT1 M6\nG0 X-10 Y0 Z5\nG1 Z-1.1 F100\nG1 X10 F500\nG0 Z5\nM30\n";
  const DesignCheck d = check(deep, job, vee);
  // 0.1 mm lower: 0.1 normal to the V at its apex, 0.1 sin 45 deg on its
  // slopes; the columns lie between.
  const double slope = 0.1 * std::sin(M_PI / 4);
  EXPECT_GE(d.entities[0].gouge, slope - 1e-9);
  EXPECT_LE(d.entities[0].gouge, 0.1 + 1e-9);
  EXPECT_TRUE(d.gouged());
  const std::string shallow = "G21 G90\nT1 M6\nG0 X-10 Y0 Z5\nG1 Z-0.9 F100\nG1 X10 F500\nG0 Z5\nM30\n";
  const DesignCheck sh = check(shallow, job, vee);
  EXPECT_GE(sh.entities[0].excess, slope - 1e-9);
  EXPECT_LE(sh.entities[0].excess, 0.1 + 1e-9);
  EXPECT_FALSE(sh.gouged());
}

TEST(DesignCheck, SurfacesAreListedAsNotCompared) {
  const std::string j = R"({"bezcam": 1, "units": "mm", "tolerance": 0.01,
    "job": {"feed": 500, "plunge_feed": 100, "safe_z": 5, "top_z": 0, "cut_z": -1, "spindle_rpm": 10000, "tool": 1,
            "tool_diameter": 4},
    "entities": [{"id": "up", "type": "bezier", "points": [[-10, 0, -1], [10, 0, -2]]}]})";
  const DesignCheck d = check("G21 G90\nT1 M6\nG0 X-10 Y0 Z5\nG1 Z-1 F100\nG1 X10 Z-2 F500\nG0 Z5\nM30\n",
                              parse_job(j, "3d.json"), kFlat4);
  EXPECT_FALSE(d.entities[0].compared);
  EXPECT_NE(d.entities[0].not_compared.find("not flat"), std::string::npos);
}
