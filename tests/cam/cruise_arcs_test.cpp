// Arcs and NURBS output on LinuxCNC, whose planner gives an arc less
// acceleration than a line (docs/motion.md, "Arcs where the tool
// cruises"): lines where the tool changes speed, arcs or exact blocks
// where it cruises, joined tangentially; at F6000 no slower than lines.
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <span>
#include <sstream>
#include <string>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/motion.hpp"

namespace bezcam {
namespace {

const char* const kCurves[] = {
    "curve-bspline-wave",        "curve-bspline-unclamped",    "curve-interpolate-closed-cam",
    "curve-interpolate-hermite", "curve-interpolate-lagrange", "curve-interpolate-airfoil",
    "path-mixed-bezier-bspline", "path-closed-teardrop",       "path-mixed-closed-keyhole",
    "job-finish-pass",           "curve-nurbs-circle",         "curve-rational-quarter-circle",
    "curve-semicircle"};

// A curve sample with every feed set to `feed` mm/min (and the job's keys
// in `job` set too).
Job sample_at(const std::string& name, double feed, const nlohmann::json& job = nlohmann::json::object()) {
  std::ifstream in(std::string(BEZCAM_SOURCE_DIR) + "/samples/" + name + ".json");
  nlohmann::json j = nlohmann::json::parse(in);
  for (const auto& [k, v] : job.items()) j["job"][k] = v;
  auto walk = [&](auto& self, nlohmann::json& n) -> void {
    if (n.is_object()) {
      for (auto& [k, v] : n.items()) {
        if (k == "feed" && v.is_number())
          v = feed;
        else
          self(self, v);
      }
    } else if (n.is_array()) {
      for (auto& v : n) self(self, v);
    }
  };
  walk(walk, j);
  return parse_job(j.dump(), name + ".json");
}

ConvertResult convert_as(const Job& job, const MachineProfile& m, OutputMode mode) {
  ConvertOptions o;
  o.output = mode;
  return convert(job, m, o);
}

// Direction (unit, in the plane) a block starts or ends in; zero for a
// block along Z.
Vec3 direction(const MotionBlock& b, bool at_end) {
  Vec3 d;
  if (b.kind == BlockKind::rapid) return d;
  if (is_arc(b)) {
    const Vec3 r = (at_end ? b.to : b.from) - b.center;
    d = b.kind == BlockKind::arc_ccw ? Vec3{-r.y, r.x, 0} : Vec3{r.y, -r.x, 0};
  } else if (b.kind == BlockKind::linear) {
    d = b.to - b.from;
    d.z = 0;
  } else if (b.ctrl.size() >= 2) {
    const auto& c = b.ctrl;
    d = at_end ? c.back() - c[c.size() - 2] : c[1] - c[0];
    d.z = 0;
  }
  const double l = std::hypot(d.x, d.y);
  return l > 1e-12 ? d / l : Vec3{};
}

// The curve's own corners turn by more than this (radians).
constexpr double kCorner = 0.1;

struct Joints {
  size_t line_arc = 0, line_arc_kinked = 0;  // a line and an arc meet
  size_t arc_arc = 0, arc_arc_kinked = 0;    // two arcs meet
};

// The joints between cutting blocks where one of the two is an arc (not at
// the curve's own corners), and how many of them turn by more than `angle`.
Joints arc_joints(const Program& p, double angle) {
  Joints j;
  const std::vector<MotionBlock> mb = program_motion(p);
  for (size_t i = 0; i + 1 < mb.size(); ++i) {
    const MotionBlock &a = mb[i], &b = mb[i + 1];
    if (!is_arc(a) && !is_arc(b)) continue;
    const Vec3 u = direction(a, true), v = direction(b, false);
    if ((u.x == 0 && u.y == 0) || (v.x == 0 && v.y == 0)) continue;  // a plunge or a retract
    const double turn = std::atan2(std::abs(u.x * v.y - u.y * v.x), u.x * v.x + u.y * v.y);
    if (turn > kCorner) continue;
    const bool both = is_arc(a) && is_arc(b);
    ++(both ? j.arc_arc : j.line_arc);
    if (turn > angle) ++(both ? j.arc_arc_kinked : j.line_arc_kinked);
  }
  return j;
}

// Each sample at F6000 on linuxcnc and fanuc: arcs and NURBS programs take
// at most 1 % longer than lines, within their proven bound.
void expect_no_slower_than_lines(std::span<const char* const> samples) {
  for (const char* machine : {"linuxcnc", "fanuc"}) {
    const MachineProfile m = load_machine_profile(machine);
    for (const char* name : samples) {
      SCOPED_TRACE(std::string(machine) + " " + name);
      const Job job = sample_at(name, 6000);
      const double lines = convert_as(job, m, OutputMode::lines).plan->cycle_time_s;
      for (const OutputMode mode : {OutputMode::arcs, OutputMode::nurbs}) {
        const ConvertResult r = convert_as(job, m, mode);
        EXPECT_LE(r.plan->cycle_time_s, lines * 1.01) << to_string(mode);
        EXPECT_LE(r.program.max_measured, r.program.max_bound);
        EXPECT_LE(r.program.max_bound, r.program.tolerance);
      }
    }
  }
}

TEST(CruiseArcs, ArcsAndNurbsAreNoSlowerThanLinesAtF6000) { expect_no_slower_than_lines(kCurves); }

TEST(CruiseArcs, EveryArcJointIsTangentAsLinuxCncJudgesIt) {
  // LinuxCNC takes a joint as tangent when turning by it within one servo
  // period at the feed, as a share of the axes' acceleration (doubled at
  // arcs), stays below 0.1: at F6000, 1000 mm/s^2 and 1 ms, below
  // 0.1 x 1000 / (2 x (100 / 0.001 + 1000)) = 4.95e-4 rad.
  const double kink = 0.1 * 1000 / (2 * (100 / 0.001 + 1000));
  const MachineProfile m = load_machine_profile("linuxcnc");
  Joints all;
  for (const char* name : kCurves) {
    SCOPED_TRACE(name);
    const ConvertResult r = convert_as(sample_at(name, 6000), m, OutputMode::arcs);
    const Joints j = arc_joints(r.program, kink);
    all.line_arc += j.line_arc;
    all.line_arc_kinked += j.line_arc_kinked;
    all.arc_arc += j.arc_arc;
    all.arc_arc_kinked += j.arc_arc_kinked;
  }
  // Every joint between a line and an arc is tangent: the lines where the
  // tool changes speed meet the arcs along their tangents. Between arcs
  // too: each arc of a chain ends along the curve, so the chain never has
  // to start again at a kink on these samples.
  std::cout << "[ joints   ] arcs output at F6000 on linuxcnc: " << all.line_arc << " line-arc joints, "
            << all.line_arc_kinked << " kinked; " << all.arc_arc << " arc-arc joints, " << all.arc_arc_kinked
            << " kinked\n";
  EXPECT_GT(all.line_arc, 20u);
  EXPECT_EQ(all.line_arc_kinked, 0u) << "of " << all.line_arc;
  EXPECT_GT(all.arc_arc, 100u);
  EXPECT_EQ(all.arc_arc_kinked, 0u) << "of " << all.arc_arc;
}

TEST(CruiseArcs, PocketPassesAreTangentChainsWhereTheirPolylineRounds) {
  // A pocket pass's polyline is an offset of the walls' chords: its
  // straight runs end a little before or after the round that follows, so
  // an arc from a vertex turned there by up to 0.04 rad (the offset plate:
  // 14 joints, 2 of them where a ring starts on a straight run just before
  // a round). The joints are made where the moves' supports touch, and a
  // ring starting so starts with a line to its round.
  const double kink = 0.1 * 1000 / (2 * (100 / 0.001 + 1000));
  const MachineProfile m = load_machine_profile("linuxcnc");
  for (const auto& [name, most] : {std::pair{"part-plate", 0u}, std::pair{"part-plate-drilled", 0u}}) {
    SCOPED_TRACE(name);
    const ConvertResult r = convert_as(sample_at(name, 6000), m, OutputMode::arcs);
    const Joints j = arc_joints(r.program, kink);
    std::cout << "[ joints   ] " << name << " in arcs at F6000: " << j.line_arc + j.arc_arc << " joints, "
              << j.line_arc_kinked + j.arc_arc_kinked << " kinked\n";
    EXPECT_GT(j.line_arc + j.arc_arc, 100u);
    EXPECT_LE(j.line_arc_kinked + j.arc_arc_kinked, most);
    EXPECT_LE(r.program.max_measured, r.program.max_bound);
    EXPECT_LE(r.program.max_bound, r.program.tolerance);
  }
}

TEST(CruiseArcs, LinesWhereTheToolSpeedsUpAndSlowsDownArcsBetween) {
  // The circle of radius 40 at F6000: the tool needs 5 mm to reach the
  // feed at 1000 mm/s^2, where LinuxCNC gives an arc of this radius 72 %
  // of it; the arcs program starts and ends with lines, and joins them to
  // its arcs by lines along the arcs' tangents.
  const MachineProfile m = load_machine_profile("linuxcnc");
  const ConvertResult r = convert_as(sample_at("curve-nurbs-circle", 6000), m, OutputMode::arcs);
  const std::vector<MotionBlock> mb = program_motion(r.program);
  std::vector<BlockKind> cut;
  for (const MotionBlock& b : mb)
    if (b.kind != BlockKind::rapid && b.from.z == b.to.z) cut.push_back(b.kind);
  ASSERT_GT(cut.size(), 6u);
  EXPECT_EQ(cut.front(), BlockKind::linear);
  EXPECT_EQ(cut.back(), BlockKind::linear);
  EXPECT_NE(r.gcode.find("(G01 where the tool speeds up or slows down, where that is faster: machine linuxcnc gives "
                         "arcs less acceleration than lines)\n"),
            std::string::npos);
  size_t arcs = 0;
  for (const BlockKind k : cut) arcs += k == BlockKind::arc_ccw || k == BlockKind::arc_cw;
  EXPECT_GE(arcs, 4u);
  const Joints j = arc_joints(r.program, 4.95e-4);
  EXPECT_EQ(j.line_arc, 2u);
  EXPECT_EQ(j.line_arc_kinked + j.arc_arc_kinked, 0u);
  // Faster than the arcs all along, which the profile's generic planner
  // (arcs with a line's acceleration) writes.
  MachineProfile generic_planner = m;
  generic_planner.motion->planner = MotionModel::Planner::generic;
  const ConvertResult plain = convert_as(sample_at("curve-nurbs-circle", 6000), generic_planner, OutputMode::arcs);
  EXPECT_EQ(plain.program.entities[0].blocks, 4u);
  Program replanned = plain.program;
  EXPECT_LT(r.plan->cycle_time_s,
            plan_motion(program_timeline(replanned), *m.motion, PlanDetail::summary).cycle_time_s);
}

TEST(CruiseArcs, PartCutsInArcsAndNurbsAreNoSlowerThanLines) {
  // Cut as parts, the curves' offsets follow tangent arc chains: the
  // offsets of their arcs meet with no small joint arc between them (a
  // tiny NURBS piece whose rounded control points kink the path).
  // Without that the cam's NURBS program took 17 % longer than its lines
  // on fanuc at F6000, the lettering's arcs program 5 % on linuxcnc.
  const char* const parts[] = {"part-cam-notch", "part-lettering"};
  expect_no_slower_than_lines(parts);
}

TEST(CruiseArcs, PartLeadsRunIntoAndOutOfThePathTangentially) {
  // The cam's lead-in runs on into its path and the path into its
  // lead-out at the feed: the tool stops only at the plunge and the
  // retract, so the lead-in ends and the lead-out starts with arcs (not
  // the lines of a tool slowing down or speeding up), each joint tangent
  // as LinuxCNC judges it at F6000, none of them a corner. Cut as if each
  // stopped there, lines met the path's arcs turning by up to 0.39 rad.
  const double kink = 0.1 * 1000 / (2 * (100 / 0.001 + 1000));
  const MachineProfile m = load_machine_profile("linuxcnc");
  const ConvertResult r = convert_as(sample_at("part-cam-notch", 6000), m, OutputMode::arcs);
  const std::vector<MotionBlock> mb = program_motion(r.program);
  size_t joints = 0, leads = 0;
  for (size_t i = 0; i + 1 < mb.size(); ++i) {
    const MotionBlock &a = mb[i], &b = mb[i + 1];
    if (a.entity != 0 || b.entity != 0 || (!is_arc(a) && !is_arc(b))) continue;
    const Vec3 u = direction(a, true), v = direction(b, false);
    if ((u.x == 0 && u.y == 0) || (v.x == 0 && v.y == 0)) continue;  // a plunge or a retract
    ++joints;
    // (the leads' arcs: the radius 5 the job asks)
    leads += (is_arc(a) && std::abs(dist(a.to, a.center) - 5) < 0.01) ||
             (is_arc(b) && std::abs(dist(b.from, b.center) - 5) < 0.01);
    const double turn = std::atan2(std::abs(u.x * v.y - u.y * v.x), u.x * v.x + u.y * v.y);
    EXPECT_LE(turn, kink) << "joint at X" << a.to.x << " Y" << a.to.y;
  }
  EXPECT_GT(joints, 50u);
  EXPECT_GE(leads, 4u);  // per pass: the lead-in's arc into the path, the path into the lead-out's arc
}

TEST(CruiseArcs, PartOffsetsAreTangentWhereTheirArcChainsStartAgain) {
  // The flange with the tolerance on both sides of its outline: the arc
  // spline its offset is made from could not go on from its concave
  // flanks into its lobes and started a chain again at a small angle, and
  // the offsets crossed there at a corner of 7e-3 rad in every pass. The
  // move before such a joint is now a biarc into the next: no joint
  // between two arcs turns by more than LinuxCNC's limit at F6000.
  const MachineProfile m = load_machine_profile("linuxcnc");
  const ConvertResult r = convert_as(sample_at("part-flange", 800, {{"tolerance_side", "both"}}), m, OutputMode::arcs);
  const Joints j = arc_joints(r.program, 0.1 * 1000 / (2 * (100 / 0.001 + 1000)));
  EXPECT_GT(j.arc_arc, 100u);
  EXPECT_EQ(j.arc_arc_kinked, 0u) << "of " << j.arc_arc;
  EXPECT_LE(r.program.max_measured, r.program.max_bound);
  EXPECT_LE(r.program.max_bound, r.program.tolerance);
}

TEST(CruiseArcs, PartOffsetsCarryNoStubsBetweenTheirPieces) {
  // A part's offset is made from an unrounded arc fit of its curve: a stub
  // that fit left at a piece's end, or a kink there, became a printed move
  // of micrometres (its direction off by its rounding) in every pass. The
  // flange's outline (lobes and concave flanks, tangent at every joint)
  // keeps none (four per pass without the fit's rules at the pieces' ends,
  // one where its closed fit closed on itself before it closed with a
  // biarc).
  const MachineProfile m = load_machine_profile("linuxcnc");
  const ConvertResult r = convert_as(sample_at("part-flange", 6000), m, OutputMode::arcs);
  std::map<int, std::pair<size_t, size_t>> per_entity;  // passes (plunges), moves under 0.01 mm
  for (const MotionBlock& b : program_motion(r.program)) {
    if (b.kind == BlockKind::rapid) continue;
    const Vec3 d = b.to - b.from;
    auto& [passes, tiny] = per_entity[b.entity];
    if (d.z < 0) ++passes;
    if (d.z == 0 && std::hypot(d.x, d.y) < 0.01) ++tiny;
  }
  EXPECT_EQ(per_entity.size(), 6u);
  for (const auto& [entity, counts] : per_entity) {
    SCOPED_TRACE("entity " + std::to_string(entity));
    EXPECT_GT(counts.first, 0u);
    EXPECT_EQ(counts.second, 0u);
  }
}

}  // namespace
}  // namespace bezcam
