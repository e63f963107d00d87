// The conversion memo (ConvertOptions::memo): a pocket's passes and
// certificate taken from it are those a conversion without it makes, and an
// input that differs is never answered from it.
#include <gtest/gtest.h>
#include <string>

#include "bezcam/cam/program.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "support/pocket_shapes.hpp"

namespace bezcam {
namespace {

Program convert(const Job& job, const MachineProfile& m, OutputMode mode, std::shared_ptr<ConversionMemo> memo,
                double tolerance = 0) {
  ConvertOptions o;
  o.output = mode;
  o.measure = false;
  o.memo = std::move(memo);
  if (tolerance > 0) o.tolerance = tolerance;
  return build_program(job, m, o);
}

// The pockets' certificates of a program, in order.
std::vector<PocketCertificate> certificates(const Program& p) {
  std::vector<PocketCertificate> out;
  for (const EntityReport& r : p.entities)
    if (r.pocket) out.push_back(*r.pocket);
  return out;
}

void expect_same_certificates(const Program& a, const Program& b) {
  const auto ca = certificates(a), cb = certificates(b);
  ASSERT_EQ(ca.size(), cb.size());
  ASSERT_FALSE(ca.empty());
  for (size_t i = 0; i < ca.size(); ++i) {
    EXPECT_EQ(ca[i].uncut_area, cb[i].uncut_area);
    EXPECT_EQ(ca[i].wall_distance, cb[i].wall_distance);
    EXPECT_EQ(ca[i].engagement_deg, cb[i].engagement_deg);
    EXPECT_EQ(ca[i].unreachable_area, cb[i].unreachable_area);
    EXPECT_EQ(ca[i].reachable_area, cb[i].reachable_area);
  }
}

std::string pocket_job(const std::string& pattern, double side) {
  using namespace test::shapes;
  return R"({"bezcam":1,"tolerance":0.02,"job":{"feed":600,"plunge_feed":100,"safe_z":5,"top_z":0,)"
         R"("clearance":1,"cut_z":-2,"tool_diameter":4,"operation":"pocket","region":"p","pattern":")" +
         pattern + R"("},"entities":[)" + polygon({{0, 0}, {side, 0}, {side, 20}, {0, 20}}) + "," + circle(15, 10, 3) +
         "]}";
}

TEST(PocketMemo, WhatItGivesIsWhatAConversionWithoutItMakes) {
  // A 30 x 20 mm pocket round a round island.
  const Job job = parse_job(pocket_job("offset", 30), "memo.json");
  const MachineProfile m = load_machine_profile("linuxcnc");
  const auto memo = make_conversion_memo();
  const Program arcs = convert(job, m, OutputMode::arcs, memo);
  // NURBS cuts a pocket as arcs: its passes and certificate come from the memo.
  const Program nurbs = convert(job, m, OutputMode::nurbs, memo);
  const Program nurbs_alone = convert(job, m, OutputMode::nurbs, nullptr);
  EXPECT_TRUE(nurbs.moves == nurbs_alone.moves);
  expect_same_certificates(nurbs, nurbs_alone);
  // Lines keep the passes further from the walls and print other moves.
  const Program lines = convert(job, m, OutputMode::lines, memo);
  const Program lines_alone = convert(job, m, OutputMode::lines, nullptr);
  EXPECT_TRUE(lines.moves == lines_alone.moves);
  EXPECT_FALSE(lines.moves == arcs.moves);
  expect_same_certificates(lines, lines_alone);
  // Another tolerance: other passes, other certificate.
  const Program coarse = convert(job, m, OutputMode::arcs, memo, 2 * job.tolerance);
  const Program coarse_alone = convert(job, m, OutputMode::arcs, nullptr, 2 * job.tolerance);
  EXPECT_TRUE(coarse.moves == coarse_alone.moves);
  EXPECT_FALSE(coarse.moves == arcs.moves);
  expect_same_certificates(coarse, coarse_alone);
  // Another pattern and another wall: the same again.
  for (const auto& [pattern, side] : {std::pair{"zigzag", 30.0}, std::pair{"offset", 31.0}}) {
    const Job other = parse_job(pocket_job(pattern, side), "memo.json");
    const Program with = convert(other, m, OutputMode::arcs, memo);
    const Program alone = convert(other, m, OutputMode::arcs, nullptr);
    EXPECT_TRUE(with.moves == alone.moves) << pattern << " " << side;
    EXPECT_FALSE(with.moves == arcs.moves) << pattern << " " << side;
    expect_same_certificates(with, alone);
  }
}

}  // namespace
}  // namespace bezcam
