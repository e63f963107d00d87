// Arcs in the three planes (G17 XY, G18 ZX, G19 YZ), helical in each: the
// kernel's plane coordinates, the direction rule per plane, the writer's
// plane and centre words and the reader reading them back as the same
// arcs; bad centre words named with their line.
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/gcode/writer.hpp"
#include "bezcam/kernel/arc.hpp"

namespace bezcam {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(PlaneArc, PlanesAreCyclicPermutationsOfTheAxes) {
  const Vec3 p{1, 2, 3};
  EXPECT_EQ(to_plane(p, Plane::xy), (Vec3{1, 2, 3}));
  EXPECT_EQ(to_plane(p, Plane::zx), (Vec3{3, 1, 2}));  // G18: (z, x), axis y
  EXPECT_EQ(to_plane(p, Plane::yz), (Vec3{2, 3, 1}));  // G19: (y, z), axis x
  for (Plane pl : {Plane::xy, Plane::zx, Plane::yz}) EXPECT_EQ(from_plane(to_plane(p, pl), pl), p);
  EXPECT_EQ(g_number(Plane::zx), 18);
  EXPECT_EQ(world_axis(Plane::zx, 2), 1);
  EXPECT_EQ(world_axis(Plane::yz, 2), 0);
}

// G03 turns from the plane's first axis to its second (RS274/NGC: counter-
// clockwise seen from the positive third axis): in G18 from Z to X, in G19
// from Y to Z. The third axis runs linearly with the angle.
TEST(PlaneArc, DirectionSweepAndHelixPerPlane) {
  // G18: from (x 0, z 5) to (x 5, z 0) around the origin, y climbing 0 -> 2.
  Arc g18{{0, 0, 5}, {5, 2, 0}, {0, 0, 0}, true, Plane::zx};
  EXPECT_NEAR(g18.sweep(), kPi / 2, 1e-15);  // from the Z axis to the X axis: G03's way
  Vec3 m = g18.point(0.5);
  EXPECT_NEAR(m.x, 5 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(m.z, 5 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(m.y, 1, 1e-15);
  g18.ccw = false;
  EXPECT_NEAR(g18.sweep(), 3 * kPi / 2, 1e-15);
  m = g18.point(1.0 / 3);  // a quarter turn back: the -X axis
  EXPECT_NEAR(m.x, -5, 1e-12);
  EXPECT_NEAR(m.z, 0, 1e-12);
  // G19: from (y 5, z 0) to (y 0, z 5), x falling 1 -> 0: a quarter, G03.
  const Arc g19{{1, 5, 0}, {0, 0, 5}, {7, 0, 0}, true, Plane::yz};
  EXPECT_NEAR(g19.sweep(), kPi / 2, 1e-15);
  EXPECT_NEAR(g19.r_start(), 5, 1e-15);  // the centre's x (the axis) is ignored
  EXPECT_NEAR(g19.point(0.5).x, 0.5, 1e-15);
  // Extent in the plane: a G19 half turn reaches z = -5 and leaves x alone.
  const Arc half{{0, 5, 0}, {0, -5, 0}, {0, 0, 0}, false, Plane::yz};
  const Box3 b = arc_extent(half);
  EXPECT_NEAR(b.lo.z, -5, 1e-12);
  EXPECT_NEAR(b.hi.z, 0, 1e-12);
  EXPECT_EQ(b.lo.x, 0);
  EXPECT_EQ(b.hi.x, 0);
  // Exact pieces of a planar G18 arc lie on its circle, in the plane y = 0.
  const Arc flat{{0, 0, 5}, {5, 0, 0}, {0, 0, 0}, true, Plane::zx};
  for (const Bezier& piece : bezier_pieces(flat))
    for (double t : {0.0, 0.3, 0.7, 1.0}) {
      const Vec3 q = evaluate(piece, t);
      EXPECT_NEAR(std::hypot(q.x, q.z), 5, 1e-12);
      EXPECT_EQ(q.y, 0);
    }
}

Program helix_program() {
  Program p;
  p.units = Units::mm;
  p.decimals = 3;
  p.safe_z = 5;
  auto feed_arc = [](Vec3 to, Vec3 c, bool ccw, Plane pl) {
    ArcMove a;
    a.to = to;
    a.center = c;
    a.ccw = ccw;
    a.plane = pl;
    a.feed = 300;
    return Move{a, 0};
  };
  RapidMove r;
  r.to = {10, 0, 5};
  p.moves.push_back({r});
  LineMove l;
  l.to = {10, 0, 0};
  l.feed = 100;
  p.moves.push_back({l});
  // G18 helix: a quarter around (x 0, z 0) from x 10 to z -10, y 0 -> 3
  // (from the X axis towards -Z: G03's way, from Z towards X, seen in (z, x)).
  p.moves.push_back(feed_arc({0, 3, -10}, {0, 0, 0}, true, Plane::zx));
  // G19 helix: a quarter around (y 3, z 0) from z -10 to y 13, x 0 -> -2.
  p.moves.push_back(feed_arc({-2, 13, 0}, {0, 3, 0}, true, Plane::yz));
  // G17 again: a half turn around (x -2, y 8).
  p.moves.push_back(feed_arc({-2, 3, 0}, {-2, 8, 0}, true, Plane::xy));
  return p;
}

TEST(PlaneArc, WriterPrintsPlaneAndCentreWordsAndReaderReadsThemBack) {
  const MachineProfile m = load_machine_profile("linuxcnc");
  const Program p = helix_program();
  const std::string text = write_gcode(p, m);
  EXPECT_NE(text.find("G18\n"), std::string::npos) << text;
  EXPECT_NE(text.find("G19\n"), std::string::npos) << text;
  EXPECT_NE(text.find("G3 X0. Y3. Z-10. I-10. K0."), std::string::npos) << text;
  EXPECT_NE(text.find("G3 X-2. Y13. Z0. J0. K10."), std::string::npos) << text;
  EXPECT_NE(text.find("G17\n"), std::string::npos) << text;
  const auto blocks = read_gcode(text, &m);
  std::vector<MotionBlock> arcs;
  for (const auto& b : blocks)
    if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) arcs.push_back(b);
  ASSERT_EQ(arcs.size(), 3u);
  EXPECT_EQ(arcs[0].plane, Plane::zx);
  EXPECT_EQ(arcs[0].kind, BlockKind::arc_ccw);
  EXPECT_EQ(arcs[1].plane, Plane::yz);
  EXPECT_EQ(arcs[2].plane, Plane::xy);
  const auto motion = program_motion(p);
  size_t k = 0;
  for (const auto& b : motion) {
    if (b.kind != BlockKind::arc_cw && b.kind != BlockKind::arc_ccw) continue;
    const MotionBlock& r = arcs[k++];
    EXPECT_EQ(r.to, b.to);
    // The centre as read: in-plane words, the start's value on the axis.
    for (int i = 0; i < 2; ++i) {
      const int a = world_axis(b.plane, i);
      EXPECT_NEAR(r.center[a], b.center[a], 1e-12);
    }
    // The same path, point for point (helix included).
    for (double t : {0.25, 0.5, 0.75}) EXPECT_NEAR(dist(evaluate_block(r, t), evaluate_block(b, t)), 0, 1e-12);
    EXPECT_NEAR(block_length(r), block_length(b), 1e-9);
  }
  // Helix length: a quarter of radius 10 climbing 3.
  EXPECT_NEAR(block_length(arcs[0]), std::hypot(10 * kPi / 2, 3), 1e-9);
  // The program ends in G17.
  EXPECT_LT(text.rfind("G17"), text.find("M30") == std::string::npos ? text.size() : text.find("M30"));
}

TEST(PlaneArc, RArcsAndCompensationPerPlane) {
  const std::string head = "G21 G90 G17 F100\nG00 X10 Y0 Z0\n";
  // R in G18: the centre on the chord's left for a minor G03 in (z, x):
  // from (z 0, x 10) to (z 10, x 0) around (z 10, x 10).
  auto b = read_gcode(head + "G18 G03 Z10 X0 R10\n");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[1].plane, Plane::zx);
  EXPECT_NEAR(b[1].center.x, 10, 1e-12);
  EXPECT_NEAR(b[1].center.z, 10, 1e-12);
  EXPECT_NEAR(arc_sweep(b[1]), kPi / 2, 1e-12);
  // Cutter compensation is G17's only, both ways round.
  try {
    read_gcode(head + "G19\nG41 D0\n");
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "gcode.cutter-comp");
    EXPECT_EQ(e.where(), "line 4");
  }
  try {
    read_gcode(head + "G41 D0\nG18\n");
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "gcode.plane");
    EXPECT_EQ(e.where(), "line 4");
  }
}

}  // namespace
}  // namespace bezcam
