// Joining a DXF's entities with a join tolerance: gaps up to it closed
// exactly and reported, nearly closed contours found with their gap, a
// drawing scaled.
#include <gtest/gtest.h>

#include "bezcam/import/drawing.hpp"
#include "bezcam/import/dxf_reader.hpp"
#include "bezcam/job/job.hpp"

namespace bezcam::import {
namespace {

// A 10 mm square of four lines whose last corner is 0.01 mm open: the
// fourth line starts at (0.01, 10), not where the third ends, (0, 10).
Drawing open_square() {
  const std::string dxf =
      "0\nSECTION\n2\nENTITIES\n"
      "0\nLINE\n5\nA1\n8\nOUT\n10\n0\n20\n0\n11\n10\n21\n0\n"
      "0\nLINE\n5\nA2\n8\nOUT\n10\n10\n20\n0\n11\n10\n21\n10\n"
      "0\nLINE\n5\nA3\n8\nOUT\n10\n10\n20\n10\n11\n0\n21\n10\n"
      "0\nLINE\n5\nA4\n8\nOUT\n10\n0.01\n20\n10\n11\n0\n21\n0\n"
      "0\nENDSEC\n0\nEOF\n";
  return read_dxf(dxf, "gap.dxf");
}

TEST(JoinTolerance, TheDefaultLeavesAGapOpenAndFindsItNearlyClosed) {
  Drawing d = open_square();
  join_contours(d);
  ASSERT_EQ(d.contours.size(), 1u);
  EXPECT_FALSE(d.contours[0].closed);
  EXPECT_TRUE(d.closed_gaps.empty());
  const std::vector<Gap> near = nearly_closed(d, 0.1);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(near[0].id, d.contours[0].id);
  EXPECT_NEAR(near[0].size, 0.01, 1e-12);
  EXPECT_NEAR(near[0].at.x, 0.005, 1e-12);
  EXPECT_NEAR(near[0].at.y, 10, 1e-12);
  EXPECT_TRUE(nearly_closed(d, 0.009).empty());
}

TEST(JoinTolerance, AGapUpToItIsClosedExactlyAndReported) {
  Drawing d = open_square();
  join_contours(d, 0.009);  // smaller than the gap: stays open
  ASSERT_EQ(d.contours.size(), 1u);
  EXPECT_FALSE(d.contours[0].closed);
  d = open_square();
  join_contours(d, 0.02);
  ASSERT_EQ(d.contours.size(), 1u);
  const Contour& c = d.contours[0];
  EXPECT_TRUE(c.closed);
  EXPECT_EQ(c.pieces.back().end().x, c.pieces.front().start().x);  // exactly
  EXPECT_EQ(c.pieces.back().end().y, c.pieces.front().start().y);
  ASSERT_EQ(d.closed_gaps.size(), 1u);
  EXPECT_EQ(d.closed_gaps[0].id, c.id);
  EXPECT_NEAR(d.closed_gaps[0].size, 0.01, 1e-12);
  EXPECT_NEAR(d.closed_gaps[0].at.x, 0.005, 1e-12);
  std::vector<std::string> warnings;
  const Job job = to_job(d, {}, &warnings);
  EXPECT_TRUE(job.entities.at(0).curve.closed);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0],
            "contour \"" + c.id +
                "\": a gap of 0.01 mm at (0.005, 10) closed by the join tolerance (the ends moved to meet) "
                "[gap-closed]");
  // Where the entity is in the drawing, for messages.
  EXPECT_EQ(job.entities.at(0).origin.rfind("layer \"OUT\", ", 0), 0u) << job.entities.at(0).origin;
  EXPECT_NE(job.entities.at(0).origin.find(", from ("), std::string::npos) << job.entities.at(0).origin;
}

TEST(JoinTolerance, ScalingMultipliesEveryCoordinate) {
  Drawing d = open_square();
  scale_drawing(d, 2.5);
  EXPECT_DOUBLE_EQ(d.size(), 25);
  join_contours(d);
  const std::vector<Gap> near = nearly_closed(d, 1);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_NEAR(near[0].size, 0.025, 1e-12);
}

}  // namespace
}  // namespace bezcam::import
