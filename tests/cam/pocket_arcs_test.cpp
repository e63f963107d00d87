// A pocket's passes as arcs (cam/pocket_arcs.cpp, docs/pocket.md): every
// block's bound is checked here by sampling both ways (the drawn arc, a
// spiral when its printed radii differ, against the polyline), and a pocket
// cut in arcs output is read back from its moves.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <numbers>
#include <random>

#include "bezcam/cam/pocket_check.hpp"
#include "bezcam/cam/program.hpp"
#include "bezcam/cam/program_motion.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/job/job_json.hpp"
#include "cam/pocket_plan.hpp"
#include "support/pocket_shapes.hpp"

namespace bezcam {
namespace {

double seg_dist(const Vec3& p, const Vec3& a, const Vec3& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// Points of the block drawn from `from` (a controller's spiral: the radius
// moving linearly with the angle from the start's to the end's).
std::vector<Vec3> drawn(const Vec3& from, const FitMove& m, int n) {
  std::vector<Vec3> out;
  if (m.kind == FitKind::line) {
    for (int k = 0; k <= n; ++k)
      out.push_back({from.x + (m.to.x - from.x) * k / n, from.y + (m.to.y - from.y) * k / n, 0});
    return out;
  }
  const Vec3 c = m.center;
  const double rs = std::hypot(from.x - c.x, from.y - c.y), re = std::hypot(m.to.x - c.x, m.to.y - c.y);
  const double a0 = std::atan2(from.y - c.y, from.x - c.x);
  double sweep = std::atan2(m.to.y - c.y, m.to.x - c.x) - a0;
  if (m.kind == FitKind::arc_ccw && sweep <= 0) sweep += 2 * std::numbers::pi;
  if (m.kind == FitKind::arc_cw && sweep >= 0) sweep -= 2 * std::numbers::pi;
  for (int k = 0; k <= n; ++k) {
    const double t = static_cast<double>(k) / n, r = rs + (re - rs) * t;
    out.push_back({c.x + r * std::cos(a0 + sweep * t), c.y + r * std::sin(a0 + sweep * t), 0});
  }
  return out;
}

// Each block against the stretch of polyline it replaces, both ways, by
// sampling; returns the largest reading and checks it against each bound.
// A block ends at a vertex or, where the fitter made a joint a vertex of
// its own, within half the bound and a rounding (`decimals`) of a segment,
// beside it: the stretch then ends at the segment's nearest point, and the
// next starts there.
double check_blocks(const std::vector<Vec3>& poly, const std::vector<FitMove>& moves, double tol, int decimals) {
  double worst = 0;
  size_t at = 0;
  Vec3 from = poly.front(), head = poly.front();  // the block's start, and the stretch's
  auto inside = [](const Vec3& p, const Vec3& a, const Vec3& b) {
    const double dx = b.x - a.x, dy = b.y - a.y, t = (p.x - a.x) * dx + (p.y - a.y) * dy;
    return t > 0 && t < dx * dx + dy * dy;
  };
  auto nearest = [](const Vec3& p, const Vec3& a, const Vec3& b) {
    const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
    return Vec3{a.x + t * dx, a.y + t * dy, 0};
  };
  for (const FitMove& m : moves) {
    EXPECT_LE(m.bound, tol);
    // The block ends at a vertex after `at`, or on a segment from there.
    std::vector<Vec3> stretch{head};
    size_t end = at;
    Vec3 tail;
    bool found = false;
    for (size_t k = at; k + 1 < poly.size() && !found; ++k) {
      if (poly[k + 1].x == m.to.x && poly[k + 1].y == m.to.y) {
        end = k + 1, tail = poly[k + 1], found = true;
      } else if (seg_dist(m.to, poly[k], poly[k + 1]) <= tol / 2 + 0.75 * std::pow(10.0, -decimals) &&
                 inside(m.to, poly[k], poly[k + 1]) && (k > at || std::hypot(m.to.x - head.x, m.to.y - head.y) > 0)) {
        end = k, tail = nearest(m.to, poly[k], poly[k + 1]), found = true;
      } else {
        stretch.push_back(poly[k + 1]);
      }
    }
    EXPECT_TRUE(found) << "block ends off the polyline";
    if (!found) return 1e300;
    stretch.push_back(tail);
    const int n = 2000;
    const auto pts = drawn(from, m, n);
    // The samples of the drawn block are chords of it: their sagitta is
    // allowed on top of the bound.
    double sag = 0;
    if (m.kind != FitKind::line) {
      const double r = std::max(std::hypot(from.x - m.center.x, from.y - m.center.y),
                                std::hypot(m.to.x - m.center.x, m.to.y - m.center.y));
      sag = r * (1 - std::cos(std::numbers::pi / n));
    }
    double d = 0;
    for (const Vec3& p : pts) {
      double best = 1e300;
      for (size_t k = 0; k + 1 < stretch.size(); ++k) best = std::min(best, seg_dist(p, stretch[k], stretch[k + 1]));
      d = std::max(d, best);
    }
    for (size_t k = 0; k + 1 < stretch.size(); ++k)
      for (int s = 0; s <= 10; ++s) {
        const Vec3 q{stretch[k].x + (stretch[k + 1].x - stretch[k].x) * s / 10,
                     stretch[k].y + (stretch[k + 1].y - stretch[k].y) * s / 10, 0};
        double best = 1e300;
        for (size_t i = 1; i < pts.size(); ++i) best = std::min(best, seg_dist(q, pts[i - 1], pts[i]));
        d = std::max(d, best);
      }
    EXPECT_LE(d, m.bound + sag + 1e-9) << "block ending at " << m.to.x << ", " << m.to.y;
    worst = std::max(worst, d - sag);
    from = m.to;
    at = end;
    head = tail;
  }
  EXPECT_EQ(at, poly.size() - 1);
  return worst;
}

TEST(PocketArcs, ARingRoundACircleWithItsChordErrorBecomesFourArcs) {
  // The offset of a circle flattened with its vertices on the curve within
  // 0.00125, 4 decimals: the vertices on the offset, the chords dipping.
  std::vector<Vec3> poly;
  const double a = 0.00125, R = 15;
  const int n = static_cast<int>(std::ceil(std::numbers::pi / std::acos((R - a) / R)));
  for (int i = 0; i <= n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    poly.push_back(quantize(Vec3{40 + R * std::cos(t), 30 + R * std::sin(t), 0}, 4));
  }
  poly.back() = poly.front();
  const auto moves = detail::polyline_arcs(poly, 0.0025, 4, 0.002);
  EXPECT_LE(moves.size(), 4u);
  Vec3 from = poly.front();
  for (const FitMove& m : moves) {
    EXPECT_EQ(m.kind, FitKind::arc_ccw);
    // Every arc longer than a tenth of the turn is the circle itself.
    if (std::hypot(m.to.x - from.x, m.to.y - from.y) > 2 * 15 * std::sin(std::numbers::pi / 10))
      EXPECT_NEAR(std::hypot(m.center.x - 40, m.center.y - 30), 0, 0.01);
    from = m.to;
  }
  check_blocks(poly, moves, 0.0025, 4);
}

TEST(PocketArcs, EveryBlockOfRandomPassesKeepsItsBound) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int run = 0; run < 12; ++run) {
    SCOPED_TRACE(run);
    // Arcs of random radii and turns, straight runs and corners, with noise.
    std::vector<Vec3> poly{{0, 0, 0}};
    double heading = u(rng) * std::numbers::pi;
    for (int piece = 0; piece < 8; ++piece) {
      const double radius = 2 + 20 * (u(rng) + 1), turn = u(rng) * 2, step = 0.2 + 0.3 * (u(rng) + 1);
      const bool straight = u(rng) > 0.5;
      for (int k = 0; k < 30; ++k) {
        if (!straight) heading += turn * step / radius;
        const Vec3& p = poly.back();
        poly.push_back(quantize(
            Vec3{p.x + step * std::cos(heading) + 0.002 * u(rng), p.y + step * std::sin(heading) + 0.002 * u(rng), 0},
            3));
      }
      heading += u(rng) * 1.5;  // a corner
    }
    for (double tol : {0.002, 0.005, 0.02}) {
      const auto moves = detail::polyline_arcs(poly, tol, 3, 0.002);
      EXPECT_LT(moves.size(), poly.size() - 1);
      EXPECT_LE(check_blocks(poly, moves, tol, 3), tol + 1e-6);
    }
  }
}

// The joints between consecutive blocks that turn by more than `angle`
// (radians), of `joints` in all.
size_t kinked_joints(const Vec3& start, const std::vector<FitMove>& moves, double angle, size_t& joints) {
  auto dir = [](const Vec3& from, const FitMove& m, bool at_end) {
    if (m.kind == FitKind::line) return Vec3{m.to.x - from.x, m.to.y - from.y, 0};
    const Vec3 r =
        at_end ? Vec3{m.to.x - m.center.x, m.to.y - m.center.y, 0} : Vec3{from.x - m.center.x, from.y - m.center.y, 0};
    return m.kind == FitKind::arc_ccw ? Vec3{-r.y, r.x, 0} : Vec3{r.y, -r.x, 0};
  };
  size_t kinked = 0;
  joints = 0;
  Vec3 from = start;
  for (size_t i = 0; i + 1 < moves.size(); ++i) {
    const Vec3 u = dir(from, moves[i], true), v = dir(moves[i].to, moves[i + 1], false);
    ++joints;
    kinked += std::atan2(std::abs(u.x * v.y - u.y * v.x), u.x * v.x + u.y * v.y) > angle;
    from = moves[i].to;
  }
  return kinked;
}

TEST(PocketArcs, ASmoothPassIsATangentChain) {
  // A ring along a wall of lines and round corners, as the pocket's
  // offsets give it: vertices on the offset to 4 decimals, the corners'
  // chords within 0.00125 and a little of the simplification's error.
  // The blocks leave in the direction the one before ends in: only the
  // joint after the first block, which starts free, may turn by more than
  // LinuxCNC's limit at F6000 (free arcs: all 7, by 1.3e-3 to 1.7e-3 rad).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> poly;
  const double w = 50, h = 30, rc = 1.5;
  const Vec3 centres[] = {{w, 0, 0}, {w, h, 0}, {0, h, 0}, {0, 0, 0}};
  for (int c = 0; c < 4; ++c) {
    const double a0 = (c - 1) * std::numbers::pi / 2;
    const int n = 20;
    for (int k = 0; k <= n; ++k) {
      const double t = a0 + std::numbers::pi / 2 * k / n, e = k == 0 || k == n ? 0 : 0.0004 * u(rng);
      poly.push_back(
          quantize(Vec3{centres[c].x + (rc + e) * std::cos(t), centres[c].y + (rc + e) * std::sin(t), 0}, 4));
    }
  }
  poly.push_back(poly.front());
  const auto moves = detail::polyline_arcs(poly, 0.0025, 4, 0.002);
  check_blocks(poly, moves, 0.0025, 4);
  size_t joints = 0;
  const size_t kinked = kinked_joints(poly.front(), moves, 4.95e-4, joints);
  std::cout << "[ pocket   ] " << moves.size() << " blocks, " << kinked << " of " << joints << " joints kinked\n";
  EXPECT_GE(joints, 7u);
  EXPECT_LE(kinked, 1u);
}

TEST(PocketArcs, ALoopAFewDigitsAcrossStaysLines) {
  // A pass's last, vanishing ring: LinuxCNC refuses an arc of radius 0.0009
  // ("zero-radius arc"), and its words would hold a few digits.
  const std::vector<Vec3> loop{{29.8753, 17.1806, 0},
                               {29.8747, 17.1814, 0},
                               {29.8753, 17.1822, 0},
                               {29.8759, 17.1814, 0},
                               {29.8753, 17.1806, 0}};
  std::vector<Vec3> poly = loop;
  for (const FitMove& m : detail::polyline_arcs(poly, 0.0005, 4, 0.002)) EXPECT_EQ(m.kind, FitKind::line);
  // A loop of radius 0.5 is arcs.
  poly.clear();
  for (int i = 0; i <= 60; ++i) {
    const double t = 2 * std::numbers::pi * i / 60;
    poly.push_back(quantize(Vec3{29.875 + 0.5 * std::cos(t), 17.1814 + 0.5 * std::sin(t), 0}, 4));
  }
  poly.back() = poly.front();
  const auto moves = detail::polyline_arcs(poly, 0.002, 4, 0.002);
  EXPECT_TRUE(std::any_of(moves.begin(), moves.end(), [](const FitMove& m) { return m.kind != FitKind::line; }));
}

Program plate(const std::string& output, const std::string& machine) {
  using namespace test::shapes;
  const std::string json =
      R"({"bezcam":1,"tolerance":0.01,"job":{"feed":600,"plunge_feed":100,"safe_z":5,"top_z":0,"clearance":1,)"
      R"("cut_z":-3,"tool_diameter":6,"operation":"pocket","region":"p","stepover":2.4},"entities":[)" +
      polygon({{0, 0}, {60, 0}, {60, 40}, {0, 40}}) + "," + circle(18, 20, 6) + "," + circle(42, 20, 6) + "]}";
  ConvertOptions o;
  o.output = parse_output_mode(output);
  return build_program(parse_job(json, "pocket.json"), load_machine_profile(machine), o);
}

TEST(PocketArcs, ArcsOutputCutsThePocketInArcsWithTheSameCertificate) {
  for (const char* machine : {"linuxcnc", "fanuc", "grbl"}) {
    SCOPED_TRACE(machine);
    const Program lines = plate("lines", machine), arcs = plate("arcs", machine);
    size_t arc_moves = 0;
    for (const Move& m : arcs.moves)
      if (const auto* a = std::get_if<ArcMove>(&m.what); a && std::abs(a->to.z + 3) < 1e-9) ++arc_moves;
    // The rings round the bosses are arcs at depth (the helix's full turn is 2).
    EXPECT_GT(arc_moves, 20u);
    EXPECT_LT(arcs.moves.size() * 3, lines.moves.size());
    for (const Program* p : {&lines, &arcs}) {
      const PocketCertificate* c = nullptr;
      for (const auto& e : p->entities)
        if (e.pocket) c = &*e.pocket;
      ASSERT_NE(c, nullptr);
      EXPECT_EQ(c->uncut_area, 0);
      EXPECT_GE(c->wall_distance, 3);
      EXPECT_LE(c->wall_distance, 3.01);
      EXPECT_EQ(c->rapids_in_material, 0u);
    }
  }
}

// A plate cleared by adaptive passes at `feed` (the plunges at a sixth):
// 60 x 40 round two bosses, or 40 x 25 round one.
Program adaptive_plate(const std::string& output, double feed, bool small = false) {
  using namespace test::shapes;
  const std::string walls =
      small ? polygon({{0, 0}, {40, 0}, {40, 25}, {0, 25}}) + "," + circle(20, 12.5, 5)
            : polygon({{0, 0}, {60, 0}, {60, 40}, {0, 40}}) + "," + circle(18, 20, 6) + "," + circle(42, 20, 6);
  const std::string json =
      R"({"bezcam":1,"tolerance":0.01,"job":{"feed":)" + num(feed) + R"(,"plunge_feed":)" + num(feed / 6) +
      R"(,"safe_z":5,"top_z":0,"clearance":1,"cut_z":-)" + (small ? "1" : "3") +
      R"(,"tool_diameter":6,"operation":"pocket","region":"p","pattern":"adaptive","load":1},"entities":[)" + walls +
      "]}";
  ConvertOptions o;
  o.output = parse_output_mode(output);
  return build_program(parse_job(json, "adaptive.json"), load_machine_profile("linuxcnc"), o);
}

bool has_note(const Program& p, const std::string& part) {
  return std::any_of(p.notes.begin(), p.notes.end(), [&](const std::string& n) { return n.find(part) != n.npos; });
}

TEST(PocketArcs, AdaptivePassesInArcsAreNoSlowerThanLinesOnLinuxCnc) {
  // LinuxCNC gives an arc half the tangential acceleration of a line: at
  // F6000 the adaptive passes' tight turns, where the tool slows down and
  // speeds up, took 10 % longer in arcs than in lines on the large plate:
  // the passes faster in lines are cut in lines. On the small one (9.7 %
  // longer in arcs) the passes so chosen still took 1.2 % longer: the
  // arcs output's plan keeps its passes a little farther from the walls,
  // and its adaptive passes differ. The pocket is cut as lines output
  // cuts it there.
  const auto model = *load_machine_profile("linuxcnc").motion;
  for (bool small : {false, true}) {
    SCOPED_TRACE(small ? "40 x 25" : "60 x 40");
    const Program lines = adaptive_plate("lines", 6000, small), arcs = adaptive_plate("arcs", 6000, small);
    const double tl = plan_motion(program_timeline(lines), model, PlanDetail::summary).cycle_time_s;
    const double ta = plan_motion(program_timeline(arcs), model, PlanDetail::summary).cycle_time_s;
    std::cout << "F6000: lines " << tl << " s (" << lines.moves.size() << " moves), arcs " << ta << " s ("
              << arcs.moves.size() << " moves)\n";
    EXPECT_LE(ta, 1.01 * tl);
    EXPECT_LE(arcs.moves.size(), lines.moves.size());
    EXPECT_TRUE(has_note(arcs, "G01 for the pocket passes that are faster in lines"));
    const PocketCertificate* c = nullptr;
    for (const auto& e : arcs.entities)
      if (e.pocket) c = &*e.pocket;
    ASSERT_NE(c, nullptr);
    EXPECT_TRUE(c->covered());
    EXPECT_TRUE(c->walls_kept(3, 0, 0.01));
    EXPECT_EQ(c->rapids_in_material, 0u);
  }
  // The offset rings at F600 stay arcs: lines would save nothing.
  EXPECT_FALSE(has_note(plate("arcs", "linuxcnc"), "G01 for the pocket passes"));
}

}  // namespace
}  // namespace bezcam
