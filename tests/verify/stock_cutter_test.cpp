#include "bezcam/verify/stock_cutter.hpp"

#include <cmath>
#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/verify/machined_program.hpp"

using namespace bezcam;

namespace {

const StockBox kBox{-20, -20, -5, 20, 20, 0};

StockTools flat6() { return {{1, ToolShape::flat(6)}}; }

// The grid a program leaves, read with no machine profile.
std::string machined_hash(const std::string& program, const StockTools& tools, double cell = 0.1) {
  StockCutter c(kBox, cell, tools);
  cut_timeline(c, read_timeline(program));
  return c.grid().hash_hex();
}

}  // namespace

TEST(StockCutter, AFlatSlotRemovesItsVolume) {
  // A 20 mm slot 1 mm deep with a 6 mm flat end mill: a 20 x 6 rectangle
  // and two half discs of radius 3.
  StockCutter c(kBox, 0.05, flat6());
  cut_timeline(c, read_timeline("G21 G90\nT1 M6\nG0 X-10 Y0 Z5\nG1 Z-1 F100\nG1 X10\nG0 Z5\nM30\n"));
  const DexelGrid& g = c.grid();
  const double exact = 20 * 6 * 1 + M_PI * 9 * 1;
  // The cells along the outline: at most its length times a cell.
  EXPECT_NEAR(g.removed_volume(), exact, (40 + 2 * M_PI * 3) * 0.05 * 1);
  EXPECT_DOUBLE_EQ(g.deepest().z, -1);
  EXPECT_EQ(c.blocks(), 4u);
  EXPECT_EQ(c.rapid_cuts(), 0u);
}

TEST(StockCutter, AnInchProgramCutsWhatItsMillimetreTwinCuts) {
  const std::string mm =
      "G21 G90\nT1 M6\nG0 X-12.7 Y2.54 Z5.08\nG1 Z-1.27 F100\nG1 X12.7\nG2 X12.7 Y-2.54 I0 J-2.54\nM30\n";
  const std::string in = "G20 G90\nT1 M6\nG0 X-0.5 Y0.1 Z0.2\nG1 Z-0.05 F4\nG1 X0.5\nG2 X0.5 Y-0.1 I0 J-0.1\nM30\n";
  EXPECT_EQ(machined_hash(mm, flat6()), machined_hash(in, flat6()));
  EXPECT_NE(machined_hash(mm, flat6()), DexelGrid(kBox, 0.1).hash_hex());
}

TEST(StockCutter, AProgramAboveTheStockLeavesItUntouched) {
  const std::string above = "G21 G90\nT1 M6\nG0 X-10 Y0 Z5\nG1 Z0.5 F100\nG1 X10\nG2 X10 Y-4 I0 J-2\nM30\n";
  EXPECT_EQ(machined_hash(above, flat6()), DexelGrid(kBox, 0.1).hash_hex());
}

TEST(StockCutter, ARapidThroughMaterialIsCountedWithItsLine) {
  StockCutter c(kBox, 0.1, flat6());
  cut_timeline(c, read_timeline("G21 G90\nT1 M6\nG0 X-10 Y0 Z5\nG0 Z-1\nG0 X10\nG1 Z-2 F100\nM30\n"));
  (void)c.grid();
  EXPECT_EQ(c.rapid_cuts(), 2u);  // the plunge and the traverse
  EXPECT_EQ(c.first_rapid_cut_line(), 4);
}

TEST(StockCutter, AToolTheTableLacksIsRefusedAtItsLine) {
  StockCutter c(kBox, 0.1, flat6());
  try {
    cut_timeline(c, read_timeline("G21 G90\nT2 M6\nG0 X0 Y0 Z5\nG1 Z-1 F100\nM30\n"));
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "verify.tool");
    EXPECT_EQ(e.where(), "line 4");  // the first move from a known place
    EXPECT_NE(std::string(e.what()).find("T1 (flat D6)"), std::string::npos) << e.what();
  }
}

TEST(StockCutter, NoToolLoadedTakesTheOnlyToolOfTheTable) {
  // Grbl programs change no tool: the table's one tool cuts.
  const std::string p = "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nM30\n";
  EXPECT_NE(machined_hash(p, flat6()), DexelGrid(kBox, 0.1).hash_hex());
  StockTools two = flat6();
  two.emplace(2, ToolShape::ball(3));
  EXPECT_THROW(machined_hash(p, two), InputError);
}

TEST(StockCutter, CurveBlocksAreSweptWithinTheirBound) {
  // A G5.2 NURBS block: its flattening's bound is the grid's added error.
  StockCutter c(kBox, 0.1, flat6());
  cut_timeline(c, read_timeline("G21 G90\nT1 M6\nG0 X-10 Y0 Z5\nG1 Z-1 F100\n"
                                "G5.2 X-10 Y0 P1 L3\nX0 Y10 P1\nX10 Y0 P1\nG5.3\nM30\n"));
  EXPECT_GT(c.grid().added_error(), 0);
  EXPECT_LE(c.grid().added_error(), StockCutterOptions{}.curve_tolerance_mm);
}

TEST(MachinedProgram, TheProgramsStockHoldsItsCutsAndTheTool) {
  const Timeline tl = read_timeline("G21 G90\nT1 M6\nG0 X-10 Y0 Z5\nG1 Z-1 F100\nG1 X10 Y2\nG0 Z5\nM30\n");
  const StockBox b = program_stock_box(tl, flat6());
  EXPECT_DOUBLE_EQ(b.x0, -13);
  EXPECT_DOUBLE_EQ(b.x1, 13);
  EXPECT_DOUBLE_EQ(b.y0, -3);
  EXPECT_DOUBLE_EQ(b.y1, 5);
  EXPECT_DOUBLE_EQ(b.z0, -2);
  EXPECT_DOUBLE_EQ(b.z1, 5);  // the plunge starts at Z5
  EXPECT_NO_THROW(check_stock_holds_program(b, tl, flat6()));
  try {
    check_stock_holds_program({20, 20, -5, 40, 40, 0}, tl, flat6());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "verify.stock-outside");
  }
  try {
    program_stock_box(read_timeline("G21 G90\nG0 X1 Y1 Z5\nM30\n"), flat6());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "verify.empty");
  }
}

TEST(StockCutter, CannedCyclesDrillTheirHolesWithTheDrillsPoint) {
  // G83 pecks and G81 holes in G99: each hole is the drill's cone at the
  // bottom, whatever the pecks did on the way.
  const StockTools drill{{3, ToolShape::drill(5, 118)}};
  StockCutter c(kBox, 0.1, drill);
  cut_timeline(c, read_timeline("G21 G90 G17\nT3 M6\nG0 X0 Y0 Z5\nG99 G83 X-5.05 Y-5.05 Z-3 R1 Q1.1 F100\n"
                                "G81 X5.05 Y5.05 Z-3 R1\nG80\nG0 Z5\nM30\n"));
  const DexelGrid& g = c.grid();
  const double k = 1 / std::tan(59 * M_PI / 180);
  for (const double cx : {-5.05, 5.05})
    for (std::size_t j = 0; j < g.ny(); ++j)
      for (std::size_t i = 0; i < g.nx(); ++i) {
        const double rho = std::hypot(g.x_center(i) - cx, g.y_center(j) - cx);
        if (rho < 2.5 - 1e-9) EXPECT_NEAR(g.floor(i, j), -3 + rho * k, 1e-9) << g.x_center(i) << " " << g.y_center(j);
      }
  EXPECT_NEAR(g.deepest().z, -3, 1e-9);  // the holes' axes pass through column centres
}
