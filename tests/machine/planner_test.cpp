// The trajectory planner (machine/planner.hpp): the analytic cases hold exactly,
// the caps and the look-ahead starve where they must, corners stay within
// the path tolerance, samples are deterministic and respect the limits.
#include "bezcam/machine/planner.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

#include "bezcam/gcode/timeline.hpp"
#include "bezcam/report/motion_report.hpp"
#include "support/refusal.hpp"

using namespace bezcam;

namespace {

MotionModel model(double v_mm_min = 6000, double a = 1000) {
  MotionModel m;
  m.max_velocity_mm_min = {v_mm_min, v_mm_min, v_mm_min};
  m.max_acceleration_mm_s2 = {a, a, a};
  m.period_s = 0.001;
  m.min_segment_periods = 0;
  m.block_rate_hz = 0;
  m.lookahead_blocks = 1000;
  m.blend_tolerance_mm = 0.01;
  return m;
}

MotionPlan plan(const std::string& gcode, const MotionModel& m) { return plan_motion(read_timeline(gcode), m); }

const char* kHead = "G21 G90 G17\nG0 X0 Y0 Z0\n";

std::string square(double side, const char* mode = "") {
  const std::string s = std::to_string(side);
  return std::string(kHead) + mode + "G1 X" + s + " F3000\nY" + s + "\nX0\nY0\nM30\n";
}

}  // namespace

TEST(Planner, OneLongLineTakesLengthOverSpeedPlusSpeedOverAcceleration) {
  // 100 mm at 50 mm/s with 1000 mm/s^2: accelerate 0.05 s, decelerate 0.05 s.
  const MotionPlan p = plan(std::string(kHead) + "G1 X100 F3000\nM30\n", model());
  EXPECT_NEAR(p.cycle_time_s, 100.0 / 50 + 50.0 / 1000, 1e-9);
  EXPECT_NEAR(p.programmed_feed_time_s, 2.0, 1e-9);
  ASSERT_EQ(p.blocks.size(), 2u);  // the rapid to the start (no move) and the line
  EXPECT_NEAR(p.blocks[1].peak_feed, 3000, 1e-6);
  EXPECT_EQ(p.starved_blocks, 0u);
}

TEST(Planner, AShortLineIsATriangle) {
  // 1 mm cannot reach 50 mm/s at 1000 mm/s^2 (needs 2.5 mm): 2 sqrt(L / a).
  const MotionPlan p = plan(std::string(kHead) + "G1 X1 F3000\nM30\n", model());
  EXPECT_NEAR(p.cycle_time_s, 2 * std::sqrt(1.0 / 1000), 1e-9);
  EXPECT_NEAR(p.blocks[1].peak_feed, 60 * std::sqrt(1000.0 * 1), 1e-6);
  EXPECT_EQ(p.blocks[1].limit, SpeedLimit::acceleration);
}

TEST(Planner, TheAxesLimitsAreProjectedOnTheDirection) {
  MotionModel m = model(60000, 1000);
  m.max_acceleration_mm_s2 = {1000, 250, 1000};
  m.max_velocity_mm_min = {60000, 60000, 600};  // Z at 10 mm/s
  // Along X and Y at 45 degrees: a = min(1000, 250) / cos 45.
  const double L = 100 * std::sqrt(2.0);
  const MotionPlan p = plan(std::string(kHead) + "G1 X100 Y100 F600\nM30\n", m);
  const double a = 250 * std::sqrt(2.0), v = 10;
  EXPECT_NEAR(p.cycle_time_s, L / v + v / a, 1e-9);
  // A feed the Z axis cannot reach is clamped, and said.
  const MotionPlan z = plan(std::string(kHead) + "G1 Z-50 F3000\nM30\n", m);
  EXPECT_EQ(z.clamped_blocks, 1u);
  EXPECT_TRUE(z.blocks[1].clamped);
  EXPECT_NEAR(z.blocks[1].peak_feed, 600, 1e-6);
  EXPECT_NEAR(z.cycle_time_s, 50.0 / 10 + 10.0 / 1000, 1e-9);
}

TEST(Planner, WithJerkTheRampsAreSCurves) {
  MotionModel m = model();
  m.max_jerk_mm_s3 = std::array<double, 3>{20000, 20000, 20000};
  // 50 mm/s >= a^2 / j = 50: each ramp takes v/a + a/j.
  const MotionPlan p = plan(std::string(kHead) + "G1 X100 F3000\nM30\n", m);
  EXPECT_NEAR(p.cycle_time_s, 100.0 / 50 + 50.0 / 1000 + 1000.0 / 20000, 1e-9);
}

TEST(Planner, ShortChordsAboveTheBlockRateAreStarved) {
  // 0.05 mm chords at F6000 (100 mm/s) on a controller starting 1000
  // blocks per second: 60 x 0.05 x 1000 = 3000 < 6000, so they are starved
  // and take at least length / (0.05 x 1000).
  MotionModel m = model(20000, 5000);
  m.block_rate_hz = 1000;
  std::string g = kHead;
  g += "G1 F6000\n";
  const int n = 2000;
  for (int i = 1; i <= n; ++i) {
    const double a = 0.05 * i / 20;  // on a circle of radius 20
    char b[80];
    std::snprintf(b, sizeof b, "X%.6f Y%.6f\n", 20 * std::sin(a), 20 - 20 * std::cos(a));
    g += b;
  }
  g += "M30\n";
  const MotionPlan p = plan(g, m);
  double length = 0;
  for (const auto& b : p.blocks) length += b.length;
  EXPECT_GE(p.cycle_time_s, length / (0.05 * 1000));
  EXPECT_GT(p.starved_blocks, n * 9 / 10);
  EXPECT_LT(p.mean_feed_ratio, 0.51);
  size_t block_rate = 0;
  for (const auto& b : p.blocks) block_rate += b.limit == SpeedLimit::block_rate;
  EXPECT_GT(block_rate, size_t(n * 9 / 10));
  // The same chords under the block rate's limit are not starved.
  m.block_rate_hz = 4000;
  const MotionPlan q = plan(g, m);
  EXPECT_EQ(q.starved_blocks, 0u);
  EXPECT_LT(q.cycle_time_s, p.cycle_time_s * 0.6);
}

TEST(Planner, TheMinimumSegmentTimeCapsShortBlocks) {
  MotionModel m = model(20000, 5000);
  m.min_segment_periods = 1.02;
  std::string g = std::string(kHead) + "G1 F6000\n";
  for (int i = 1; i <= 400; ++i) g += "X" + std::to_string(0.05 * i) + "\n";  // collinear: no corners
  g += "M30\n";
  const MotionPlan p = plan(g, m);
  // 0.05 mm per 1.02 ms at most: 49 mm/s < 100 mm/s.
  for (size_t i = 2; i + 2 < p.blocks.size(); ++i) {
    EXPECT_LE(p.blocks[i].peak_feed, 60 * 0.05 / 0.00102 + 1e-6);
    EXPECT_TRUE(p.blocks[i].starved);
    EXPECT_EQ(p.blocks[i].limit, SpeedLimit::segment_time);
  }
}

TEST(Planner, AShortLookAheadStarvesAndSlows) {
  MotionModel m = model(20000, 500);
  std::string g = std::string(kHead) + "G1 F12000\n";
  for (int i = 1; i <= 300; ++i) g += "X" + std::to_string(0.5 * i) + "\n";
  g += "M30\n";
  const MotionPlan wide = plan(g, m);
  m.lookahead_blocks = 4;  // 2 mm ahead: stopping from 200 mm/s needs 40 mm
  const MotionPlan narrow = plan(g, m);
  EXPECT_GT(narrow.cycle_time_s, wide.cycle_time_s * 1.5);
  EXPECT_GT(narrow.starved_blocks, 100u);
  size_t look = 0;
  for (const auto& b : narrow.blocks) look += b.limit == SpeedLimit::lookahead;
  EXPECT_GT(look, 100u);
  // Seeing 4 blocks of 0.5 mm, the block it executes included, the
  // machine must be able to stop within 2 mm.
  for (const auto& b : narrow.blocks) EXPECT_LE(b.peak_feed, 60 * std::sqrt(2 * 500 * 2.0) + 1e-6);
}

TEST(Planner, CornersAreBlendedWithinTheToleranceOrStoppedExactly) {
  const MotionModel m = model();
  const MotionPlan exact = plan(square(50, "G61\n"), m);
  // Four lines, each from rest to rest.
  EXPECT_NEAR(exact.cycle_time_s, 4 * (50.0 / 50 + 50.0 / 1000), 1e-9);
  EXPECT_EQ(exact.max_path_deviation, 0);
  const MotionPlan blended = plan(square(50, "G64 P0.05\n"), m);
  EXPECT_LT(blended.cycle_time_s, exact.cycle_time_s);
  EXPECT_GT(blended.max_path_deviation, 0.01);
  EXPECT_LE(blended.max_path_deviation, 0.05 + 1e-12);
  // Without a path mode in the program, the profile's tolerance applies.
  const MotionPlan dflt = plan(square(50), m);
  EXPECT_LE(dflt.max_path_deviation, m.blend_tolerance_mm + 1e-12);
  EXPECT_GT(dflt.max_path_deviation, 0.5 * m.blend_tolerance_mm);
  EXPECT_GT(dflt.cycle_time_s, blended.cycle_time_s);
  // A looser tolerance is never slower.
  MotionModel stop = m;
  stop.blend_tolerance_mm = 0;
  EXPECT_NEAR(plan(square(50), stop).cycle_time_s, exact.cycle_time_s, 1e-9);
}

TEST(Planner, TheExecutedPathStaysWithinTheToleranceOfTheProgram) {
  // Every sample of a blended square lies within P of the programmed square.
  const MotionPlan p = plan(square(20, "G64 P0.02\n"), model());
  double worst = 0;
  size_t n = 0;
  sample_plan(p, [&](double, const Vec3& q, double) {
    const double dx = std::min(std::abs(q.x), std::abs(q.x - 20)), dy = std::min(std::abs(q.y), std::abs(q.y - 20));
    const bool inside = q.x > -1e-9 && q.x < 20 + 1e-9 && q.y > -1e-9 && q.y < 20 + 1e-9;
    EXPECT_TRUE(inside) << q.x << " " << q.y;
    worst = std::max(worst, std::min(dx, dy));
    ++n;
  });
  EXPECT_LE(worst, 0.02 + 1e-9);
  EXPECT_GT(worst, 0.005);  // the corners are really rounded
  EXPECT_EQ(n, static_cast<size_t>(std::ceil(p.cycle_time_s / 0.001 - 1e-9)) + 1);
}

TEST(Planner, ArcsCountTheirCentripetalAcceleration) {
  // A full circle of radius 2 at F6000 (100 mm/s): v^2 / R = 5000 mm/s^2 is
  // far above sqrt(3)/2 x 1000, so the arc runs at sqrt(0.866 a R).
  const MotionPlan p = plan(std::string(kHead) + "G0 X2\nG2 X2 Y0 I-2 J0 F6000\nM30\n", model(20000, 1000));
  const PlannedBlock& arc = p.blocks.back();
  const double vmax = std::sqrt(std::sqrt(3.0) / 2 * 1000 * 2);
  EXPECT_NEAR(arc.peak_feed, 60 * vmax, 1e-6);
  EXPECT_EQ(arc.limit, SpeedLimit::curvature);
  EXPECT_GT(arc.time_s, 2 * M_PI * 2 / vmax);
  // On a large radius the programmed feed is reached.
  const MotionPlan big = plan(std::string(kHead) + "G0 X100\nG2 X100 Y0 I-100 J0 F3000\nM30\n", model(20000, 1000));
  EXPECT_NEAR(big.blocks.back().peak_feed, 3000, 1e-6);
}

TEST(Planner, CurveBlocksAreSlowedByTheirCurvature) {
  // A G5 cubic with a tight turn in the middle at a high feed: the tight
  // part runs slower than the feed, by the curvature there.
  const std::string g = std::string(kHead) + "G5 X10 Y0 I10 J10 P-10 Q10 F6000\nM30\n";
  const MotionPlan p = plan(g, model(20000, 1000));
  const PlannedBlock& c = p.blocks.back();
  EXPECT_EQ(c.kind, BlockKind::bezier);
  EXPECT_LT(c.peak_feed, 6000);
  double slowest = 1e9;
  for (const PlanSegment& sg : p.segments)
    if (sg.block == static_cast<int>(p.blocks.size()) - 1 && sg.limit == SpeedLimit::curvature)
      slowest = std::min(slowest, sg.vmax);
  EXPECT_LT(slowest, 50);  // the tight turn, well under the feed's 100 mm/s
  // At a low feed it is reached.
  const MotionPlan slow = plan(std::string(kHead) + "G5 X10 Y0 I10 J10 P-10 Q10 F300\nM30\n", model(20000, 1000));
  EXPECT_NEAR(slow.blocks.back().peak_feed, 300, 1e-6);
  // The executed path is the curve: every sample lies on it (within the
  // chord of the arc-length table).
  sample_plan(p, [&](double, const Vec3& q, double) { EXPECT_LE(std::abs(q.z), 1e-12); });
}

TEST(Planner, PausesTakeTheirTimeAndStopTheMachine) {
  MotionModel m = model();
  m.tool_change_s = 7;
  m.spindle_start_s = 2;
  const MotionPlan p = plan(std::string(kHead) + "T2 M6\nS1000 M3\nG1 X100 F3000\nG4 P1.5\nX200\nM30\n", m);
  EXPECT_NEAR(p.pause_time_s, 7 + 2 + 1.5, 1e-12);
  // Two separate lines (stopped by the dwell) plus the pauses.
  EXPECT_NEAR(p.cycle_time_s, 10.5 + 2 * (2 + 0.05), 1e-9);
}

// Canned cycles (gcode/reader.hpp) are planned as the moves they expand
// into: every peck's feed and rapids take their time, and G82's dwell at
// the bottom is a pause like G04's.
TEST(Planner, CannedCyclesCountEveryPeckAndDwell) {
  const MotionModel m = model();
  const auto g83 = [](const char* q) {
    return std::string(kHead) + "G0 Z10\nF600\nG98 G83 X5 Y5 Z-10 R2 Q" + q + "\nX15\nG80\nM30\n";
  };
  double before = 0;
  size_t blocks_before = 0;
  for (const char* q : {"20", "5", "3", "2", "1", "0.5"}) {
    SCOPED_TRACE(std::string("Q") + q);
    const Timeline tl = read_timeline(g83(q));
    const MotionPlan p = plan_motion(tl, m);
    EXPECT_EQ(p.blocks.size(), tl.blocks.size());
    EXPECT_GT(tl.blocks.size(), blocks_before);
    EXPECT_GT(p.cycle_time_s, before + 0.1);
    before = p.cycle_time_s;
    blocks_before = tl.blocks.size();
  }
  // Two holes: G82's dwell of 0.75 s at each bottom adds exactly 1.5 s
  // (the drill stops there anyway, turning back up).
  const std::string holes = std::string(kHead) + "G0 Z10\nF600\nG98 G8_ X5 Y5 Z-3 R2_\nX15\nG80\nM30\n";
  std::string g81 = holes, g82 = holes;
  g81.replace(g81.find("G8_"), 3, "G81").replace(g81.find("R2_"), 3, "R2");
  g82.replace(g82.find("G8_"), 3, "G82").replace(g82.find("R2_"), 3, "R2 P0.75");
  const MotionPlan a = plan(g81, m), b = plan(g82, m);
  EXPECT_NEAR(b.pause_time_s, 1.5, 1e-12);
  EXPECT_NEAR(b.cycle_time_s, a.cycle_time_s + 1.5, 1e-9);
}

TEST(Planner, SamplesAreDeterministicAndWithinTheLimits) {
  const std::string g = square(30, "G64 P0.01\n");
  const MotionModel m = model();
  const MotionPlan p = plan(g, m);
  const std::string a = motion_samples_tsv(p), b = motion_samples_tsv(plan(g, m));
  EXPECT_EQ(a, b);
  Vec3 prev{0, 0, 0};
  double prev_v = 0;
  bool first = true;
  sample_plan(p, [&](double, const Vec3& q, double feed) {
    const double v = feed / 60;
    if (!first) {
      EXPECT_LE(dist(prev, q), 50 * 0.001 * (1 + 1e-9));           // never above the feed
      EXPECT_LE(std::abs(v - prev_v), 1000 * 0.001 * (1 + 1e-6));  // nor the acceleration
    }
    first = false;
    prev = q;
    prev_v = v;
  });
  EXPECT_NEAR(prev.x, 0, 1e-9);
  EXPECT_NEAR(prev.y, 0, 1e-9);
}

TEST(Planner, TheCycleTimeIsContinuousInTheLengths) {
  // A ramp that runs over several collinear segments builds its jerk up
  // once. Whether a segment's ramp continues into the next must not hang on
  // a cruise or a deceleration of a few ulps left by rounding: moving the
  // joints by 1e-10 mm changes the time by about that much, not by the
  // jerk's share of a ramp (a / 2j = 25 ms here).
  MotionModel m = model(60000, 1000);
  m.max_jerk_mm_s3 = std::array<double, 3>{20000, 20000, 20000};
  auto program = [](double shift) {
    std::string g = std::string(kHead) + "G1 F60000\n";
    double x = 0;
    for (int i = 0; i < 12; ++i) {
      x += 0.37 + 0.011 * i + (i == 5 ? shift : 0);
      char b[64];
      std::snprintf(b, sizeof b, "X%.12f\n", x);
      g += b;
    }
    return g + "M30\n";
  };
  double lo = 1e300, hi = -1e300;
  for (int k = 0; k <= 40; ++k) {
    const double t = plan(program(1e-11 * k), m).cycle_time_s;
    lo = std::min(lo, t);
    hi = std::max(hi, t);
  }
  EXPECT_LT(hi - lo, 1e-6) << "cycle times from " << lo << " to " << hi << " s";
}

TEST(Planner, InchProgramsUseTheLimitsInInches) {
  const MotionPlan p = plan("G20 G90 G17\nG0 X0 Y0 Z0\nG1 X4 F120\nM30\n", model(6000, 1000));
  // 4 in at 2 in/s, a = 1000 / 25.4 in/s^2.
  EXPECT_NEAR(p.cycle_time_s, 4.0 / 2 + 2.0 / (1000 / 25.4), 1e-9);
}

TEST(MotionProfile, MissingOrOutOfRangeSettingsAreRefusedNamingTheKey) {
  const std::string base = R"({"name": "m", "motion": {"max_velocity_mm_min": {"x": 1000, "y": 1000, "z": 1000},
    "max_acceleration_mm_s2": {"x": 100, "y": 100, "z": 100}, "period_s": 0.001, "min_segment_periods": 1,
    "block_rate_hz": 500, "lookahead_blocks": 16, "blend_tolerance_mm": 0.01}})";
  const MachineProfile ok = parse_machine_profile(base, "m.json");
  ASSERT_TRUE(ok.motion);
  EXPECT_EQ(ok.motion->lookahead_blocks, 16);
  EXPECT_FALSE(ok.motion->max_jerk_mm_s3);
  auto refused = [&](const std::string& from, const std::string& to, const std::string& where) {
    std::string t = base;
    const auto at = t.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    t.replace(at, from.size(), to);
    try {
      parse_machine_profile(t, "m.json");
      ADD_FAILURE() << "accepted: " << to;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
    }
  };
  refused(R"("period_s": 0.001, )", "", "motion.period_s");
  refused(R"("period_s": 0.001)", R"("period_s": 0)", "motion.period_s");
  refused(R"("y": 100, "z": 100})", R"("y": -100, "z": 100})", "motion.max_acceleration_mm_s2.y");
  refused(R"("x": 1000, "y": 1000, "z": 1000})", R"("x": 1000, "y": 1000})", "motion.max_velocity_mm_min.z");
  refused(R"("lookahead_blocks": 16)", R"("lookahead_blocks": 2.5)", "motion.lookahead_blocks");
  refused(R"("blend_tolerance_mm": 0.01)", R"("blend_tolerance_mm": -1)", "motion.blend_tolerance_mm");
  refused(R"("block_rate_hz": 500)", R"("block_rate_hz": "fast")", "motion.block_rate_hz");
}

TEST(MotionProfile, EveryShippedProfileHasAMotionModel) {
  for (const auto& name : machine_profile_names()) {
    const MachineProfile m = load_machine_profile(name);
    EXPECT_TRUE(m.motion) << name;
  }
}
