// What a drawing unit is (ReadOptions::units): a unitless DXF or SVG is
// scaled to it, text heights too; a drawing that says its unit keeps it
// when the same is asked and is refused when another is.
#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "support/files.hpp"
#include "support/run_process.hpp"

namespace bezcam::import {
namespace {

namespace fs = std::filesystem;
const fs::path kData = fs::path(BEZCAM_SOURCE_DIR) / "tests/import/data/text";

Vec3 far_corner(const Drawing& d) {
  Vec3 hi{-1e300, -1e300, 0};
  for (const Contour& c : d.contours)
    for (const Piece& p : c.pieces)
      for (const Vec3& q : p.points) hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), 0};
  return hi;
}

TEST(DrawingUnits, AUnitlessDxfIsReadInTheUnitAsked) {
  const Drawing plain = read_drawing(kData / "text-unitless.dxf");
  EXPECT_EQ(plain.declared_units, "");
  EXPECT_EQ(far_corner(plain).x, 4);
  ReadOptions o;
  o.units = "inch";
  const Drawing d = read_drawing(kData / "text-unitless.dxf", o);
  EXPECT_EQ(far_corner(d).x, 4 * 25.4);
  EXPECT_EQ(far_corner(d).y, 2 * 25.4);
  ASSERT_EQ(d.texts.size(), 1u);
  EXPECT_EQ(d.texts[0].height, 0.5 * 25.4);
  EXPECT_EQ(d.texts[0].at.x, 25.4);
  // Then --scale.
  o.scale = 2;
  EXPECT_EQ(far_corner(read_drawing(kData / "text-unitless.dxf", o)).x, 8 * 25.4);
}

TEST(DrawingUnits, ADrawingThatSaysItsUnitIsNotRescaled) {
  const fs::path part = fs::path(BEZCAM_SOURCE_DIR) / "samples/part.dxf";
  ReadOptions o;
  o.units = "mm";
  EXPECT_EQ(far_corner(read_drawing(part, o)).x, 80);
  o.units = "inch";
  try {
    (void)read_drawing(part, o);
    ADD_FAILURE() << "inch accepted for a drawing in mm";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), errc::import_units);
    EXPECT_EQ(e.place().setting, "drawing_units");
    EXPECT_NE(e.message().find("says its unit is mm ($INSUNITS 4), not inch"), std::string::npos) << e.message();
  }
  o.units = "furlong";
  EXPECT_THROW((void)read_drawing(part, o), InputError);
}

TEST(DrawingUnits, AnSvgsLengthsWithoutAUnitAreTheUnitAsked) {
  testproc::TempDir dir;
  const std::string body = R"(<path d="M 0 0 L 10 0"/></svg>)";
  testproc::write_file(
      dir / "px.svg",
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="100" viewBox="0 0 100 50">)" + body);
  testproc::write_file(
      dir / "mm.svg",
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="100mm" viewBox="0 0 100 50">)" + body);
  // Unitless: 2 px per user unit at 96 per inch; with mm, 2 mm per user unit.
  EXPECT_NEAR(far_corner(read_drawing(dir / "px.svg")).x, 20 * 25.4 / 96, 1e-12);
  ReadOptions o;
  o.units = "mm";
  EXPECT_NEAR(far_corner(read_drawing(dir / "px.svg", o)).x, 20, 1e-12);
  EXPECT_NEAR(far_corner(read_drawing(dir / "mm.svg", o)).x, 20, 1e-12);
  o.units = "inch";
  EXPECT_NEAR(far_corner(read_drawing(dir / "px.svg", o)).x, 20 * 25.4, 1e-9);
  EXPECT_THROW((void)read_drawing(dir / "mm.svg", o), InputError);
}

}  // namespace
}  // namespace bezcam::import
