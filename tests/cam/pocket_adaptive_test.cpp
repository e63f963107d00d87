// Adaptive clearing and rest machining (docs/pocket.md): the certificate
// bezcam prints, measured by its independent check, holds on pockets a new
// user draws; the check itself catches a path that breaks the bound.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>

#include "bezcam/cam/pocket_check.hpp"
#include "bezcam/cam/program.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/pocket_shapes.hpp"

namespace bezcam {
namespace {

using namespace test::shapes;

Program build(const std::string& keys, const std::vector<std::string>& entities) {
  std::string e;
  for (const auto& x : entities) e += (e.empty() ? "" : ",") + x;
  const std::string json = R"({"bezcam":1,"tolerance":0.01,"job":{"feed":600,"plunge_feed":100,"safe_z":5,)"
                           R"("top_z":0,"clearance":1,"cut_z":-3,"tool_diameter":6,"operation":"pocket",)"
                           R"("region":"p",)" +
                           keys + R"(},"entities":[)" + e + "]}";
  return build_program(parse_job(json, "adaptive.json"), load_machine_profile("linuxcnc"), ConvertOptions{});
}

const PocketCertificate& cert(const Program& p) {
  for (const auto& e : p.entities)
    if (e.pocket) return *e.pocket;
  throw std::logic_error("no pocket in the program");
}

// The length of the feed moves in XY.
double fed(const Program& p) {
  double len = 0;
  Vec3 cur;
  for (const Move& mv : p.moves) {
    const Motion* m = motion_of(mv);
    if (!m) continue;
    Vec3 to = cur;
    if (m->axes & kAxisX) to.x = m->to.x;
    if (m->axes & kAxisY) to.y = m->to.y;
    if (m->axes & kAxisZ) to.z = m->to.z;
    if (!is_rapid(mv)) len += std::hypot(to.x - cur.x, to.y - cur.y);
    cur = to;
  }
  return len;
}

// Adaptive: everything reachable cut, the walls kept, no rapid through
// material, and the engagement within arccos(1 - load / r) + 2 degrees.
void expect_adaptive(const Program& p, double r, double load) {
  const PocketCertificate& c = cert(p);
  EXPECT_EQ(c.uncut_area, 0) << "at " << c.uncut_at.x << ", " << c.uncut_at.y;
  EXPECT_TRUE(c.walls_kept(r, 0, 0.01)) << c.wall_distance;
  EXPECT_GE(c.wall_distance, r) << "at " << c.wall_at.x << ", " << c.wall_at.y;
  EXPECT_EQ(c.rapids_in_material, 0u);
  const double bound = std::acos(1 - load / r) * 180 / std::numbers::pi + 2;
  EXPECT_NEAR(c.engagement_bound, bound, 1e-9);
  EXPECT_TRUE(c.engagement_kept());
  EXPECT_LE(c.engagement_deg, bound) << "at " << c.engagement_at.x << ", " << c.engagement_at.y;
  EXPECT_GT(c.engagement_deg, 0);
  const auto line = std::find_if(p.notes.begin(), p.notes.end(), [](const std::string& s) {
    return s.find("largest engagement") != std::string::npos &&
           s.find("bound arccos(1 - load/r) + 2") != std::string::npos;
  });
  EXPECT_NE(line, p.notes.end());
}

TEST(PocketAdaptive, SixteenMillimetreSquareWithAQuarterInchTool) {
  const Program p =
      build(R"("pattern":"adaptive","tool_diameter":6.35)", {polygon({{0, 0}, {16, 0}, {16, 16}, {0, 16}})});
  expect_adaptive(p, 3.175, 0.15 * 6.35);
  EXPECT_EQ(cert(p).unreachable.size(), 4u);  // the corners' last sliver
}

TEST(PocketAdaptive, LShapeKeepsTheBoundInBothArms) {
  const Program p =
      build(R"("pattern":"adaptive","load":1.2)", {polygon({{0, 0}, {36, 0}, {36, 16}, {16, 16}, {16, 36}, {0, 36}})});
  expect_adaptive(p, 3, 1.2);
}

TEST(PocketAdaptive, NeckNarrowerThanTheToolIsCutWhereItFitsAndNamed) {
  const Program p = build(R"("pattern":"adaptive")", {polygon(rooms_with_neck())});
  expect_adaptive(p, 3, 0.9);
  const PocketCertificate& c = cert(p);
  ASSERT_FALSE(c.unreachable.empty());
  EXPECT_GT(c.unreachable.front().at.x, 19);  // the neck, largest first
  EXPECT_LT(c.unreachable.front().at.x, 31);
  EXPECT_TRUE(std::any_of(p.warnings.begin(), p.warnings.end(),
                          [](const std::string& w) { return w.find("cannot reach") != std::string::npos; }));
}

TEST(PocketAdaptive, StarTipsNarrowerThanTheToolAreNamedWhereTheyWrapIt) {
  // Five tips of 36 (a regular pentagram) or 30 degrees, a 4 mm tool: the
  // tool's last positions in a tip touch both walls, and what lies ahead
  // wraps it. Every place where the check reads more than the bound there
  // is named, with the tip; elsewhere the bound holds.
  const double r = 2, load = 0.6;
  for (double tip : {36.0, 30.0}) {
    const Pts star = star_with_tips(5, 30, tip);
    const Program p = build(R"("pattern":"adaptive","tool_diameter":4)", {polygon(star)});
    const PocketCertificate& c = cert(p);
    EXPECT_EQ(c.uncut_area, 0) << tip << " at " << c.uncut_at.x << ", " << c.uncut_at.y;
    EXPECT_TRUE(c.walls_kept(r, 0, 0.01)) << tip << ": " << c.wall_distance;
    EXPECT_GE(c.unreachable.size(), 5u) << tip;  // the tips beyond the tool's reach
    ASSERT_FALSE(c.engagement_kept()) << tip;
    ASSERT_FALSE(c.engagement_corners.empty()) << tip;
    EXPECT_LE(c.engagement_corners.size(), 5u) << tip;
    // Each named place lies in a tip: no farther from its apex than the
    // tool's last position there (r / sin(tip / 2)) and a diameter.
    const double reach = r / std::sin(tip / 2 * std::numbers::pi / 180) + 2 * r;
    for (const auto& h : c.engagement_corners) {
      double nearest = 1e300;
      for (const auto& [x, y] : star)
        if (std::hypot(x, y) > 29) nearest = std::min(nearest, std::hypot(h.at.x - x, h.at.y - y));
      EXPECT_LE(nearest, reach) << tip << ": " << h.at.x << ", " << h.at.y;
      EXPECT_GT(h.deg, c.engagement_bound) << tip;
    }
    EXPECT_EQ(c.engagement_corners.front().deg, c.engagement_deg) << tip;
    EXPECT_LT(c.engagement_away_deg, c.engagement_deg) << tip;
    // Away from the 30-degree tips the bound holds; beside the regular
    // pentagram's wider tips the check reads one 2-degree step above it.
    EXPECT_LE(c.engagement_away_deg, c.engagement_bound + (tip > 30 ? 2 : 0)) << tip;
    EXPECT_GE(c.engagement_away_deg, std::acos(1 - load / r) * 180 / std::numbers::pi - 10) << tip;
    const auto w = std::find_if(p.warnings.begin(), p.warnings.end(), [](const std::string& s) {
      return s.find("in places that wrap the tool (corners sharper than it") != std::string::npos;
    });
    ASSERT_NE(w, p.warnings.end()) << tip;
    EXPECT_NE(w->find("elsewhere at most"), std::string::npos) << *w;
  }
}

TEST(PocketAdaptive, AGapNarrowerThanTheToolAndALoadEachSideIsNamedAsOne) {
  // A 40 x 25 plate round a boss of radius 5.9, a 6 mm tool, load 1.2:
  // the gaps above and below the boss are 6.6 wide, narrower than the
  // tool and a load each side (8.4), and every tool position reaches all
  // of their material. The places the engagement passes the bound there
  // are named as places that wrap the tool, and the warning gives both
  // reasons (it gave only the corners', material out of reach, of which
  // there is none in a gap).
  const Program p = build(R"("pattern":"adaptive","load":1.2,"cut_z":-1)",
                          {polygon({{0, 0}, {40, 0}, {40, 25}, {0, 25}}), circle(20, 12.5, 5.9)});
  const PocketCertificate& c = cert(p);
  EXPECT_TRUE(c.covered());
  ASSERT_FALSE(c.engagement_corners.empty());
  size_t in_gap = 0;
  for (const auto& h : c.engagement_corners) in_gap += h.at.x > 14 && h.at.x < 26;  // (beside the boss)
  EXPECT_GT(in_gap, 0u);
  const auto w = std::find_if(p.warnings.begin(), p.warnings.end(),
                              [](const std::string& s) { return s.find("engagement of") != std::string::npos; });
  ASSERT_NE(w, p.warnings.end());
  EXPECT_NE(w->find("gaps where walls either side lie nearer together than the tool and a load each side"),
            std::string::npos)
      << *w;
  EXPECT_TRUE(std::any_of(p.notes.begin(), p.notes.end(), [](const std::string& n) {
    return n.find("places that wrap the tool at most") != std::string::npos ||
           n.find("place that wraps the tool at most") != std::string::npos;
  }));
}

TEST(PocketAdaptive, EachPieceIsEnteredByAHelixInsideIt) {
  // The two rooms of the neck each get a helix (G02/G03 descending), and
  // no move at depth joins them (the neck holds no tool position).
  const Program p = build(R"("pattern":"adaptive")", {polygon(rooms_with_neck())});
  Vec3 cur;
  int crossings = 0;
  for (const Move& mv : p.moves) {
    const Motion* m = motion_of(mv);
    if (!m) continue;
    Vec3 to = cur;
    if (m->axes & kAxisX) to.x = m->to.x;
    if (m->axes & kAxisY) to.y = m->to.y;
    if (m->axes & kAxisZ) to.z = m->to.z;
    if (!is_rapid(mv) && to.z < -2.9 && cur.z < -2.9 && (cur.x < 25) != (to.x < 25)) ++crossings;
    cur = to;
  }
  EXPECT_EQ(crossings, 0);
}

TEST(PocketAdaptive, MaterialPastAGapTheRingsCannotPassGetsAHelixOfItsOwn) {
  // A boss 7.5 mm from the long walls: the rings grown from the helix on
  // the left stop at the gaps beside it (a ring through one would take
  // more than the load), and the right half, out of their reach, was left
  // to the ring along the walls: 47.5 mm^2 uncut, a full slot (180
  // degrees). It now gets a helix and rings of its own.
  const Program p =
      build(R"("pattern":"adaptive","load":1)", {polygon({{0, 0}, {40, 0}, {40, 25}, {0, 25}}), circle(20, 12.5, 5)});
  expect_adaptive(p, 3, 1);
  // Helices: arcs going down, each about its own centre.
  std::vector<Vec3> centres;
  Vec3 cur;
  for (const Move& mv : p.moves) {
    const Motion* m = motion_of(mv);
    if (!m) continue;
    if (const auto* a = std::get_if<ArcMove>(&mv.what);
        a && a->to.z < cur.z - 1e-9 &&
        std::none_of(centres.begin(), centres.end(), [&](const Vec3& c) { return dist_xy(c, a->center) < 1e-6; }))
      centres.push_back(a->center);
    if (m->axes & kAxisX) cur.x = m->to.x;
    if (m->axes & kAxisY) cur.y = m->to.y;
    if (m->axes & kAxisZ) cur.z = m->to.z;
  }
  ASSERT_GE(centres.size(), 2u);
  EXPECT_TRUE(std::any_of(centres.begin(), centres.end(), [](const Vec3& c) { return c.x > 25; }));
}

TEST(PocketRest, OnlyWhatTheLargerToolLeftIsCut) {
  const std::string rect = polygon({{0, 0}, {40, 0}, {40, 30}, {0, 30}});
  const Program full = build(R"("pattern":"offset")", {rect});
  const Program rest = build(R"("pattern":"offset","rest_from":16)", {rect});
  const PocketCertificate& c = cert(rest);
  EXPECT_TRUE(c.rest);
  EXPECT_EQ(c.uncut_area, 0) << "at " << c.uncut_at.x << ", " << c.uncut_at.y;
  // The 16 mm tool left the four corners: r^2 (1 - pi/4) less this tool's,
  // each (8^2 - 3^2)(1 - pi/4) = 11.8.
  EXPECT_NEAR(c.reachable_area, 4 * (64 - 9) * (1 - std::numbers::pi / 4), 2);
  EXPECT_LT(fed(rest), fed(full) / 3);
  const auto line = std::find_if(rest.notes.begin(), rest.notes.end(), [](const std::string& s) {
    return s.find("the tool before left") != std::string::npos;
  });
  EXPECT_NE(line, rest.notes.end());
  // Every move at depth is near a corner: within 8 + 3 of one, on both axes.
  Vec3 cur;
  for (const Move& mv : rest.moves) {
    const Motion* m = motion_of(mv);
    if (!m) continue;
    Vec3 to = cur;
    if (m->axes & kAxisX) to.x = m->to.x;
    if (m->axes & kAxisY) to.y = m->to.y;
    if (m->axes & kAxisZ) to.z = m->to.z;
    if (!is_rapid(mv) && std::abs(to.z + 3) < 1e-9 && std::abs(cur.z + 3) < 1e-9) {
      const bool corner_x = to.x < 11 || to.x > 29, corner_y = to.y < 11 || to.y > 19;
      EXPECT_TRUE(corner_x && corner_y) << to.x << ", " << to.y;
    }
    cur = to;
  }
}

TEST(PocketRest, AdaptiveRestCutsTheCornersWithinTheBound) {
  const Program p = build(R"("pattern":"adaptive","rest_from":16)", {polygon({{0, 0}, {40, 0}, {40, 30}, {0, 30}})});
  expect_adaptive(p, 3, 0.9);
  EXPECT_TRUE(cert(p).rest);
}

TEST(PocketCheck, TheEngagementBoundCatchesASlot) {
  // A straight pass through fresh material is a slot: 180 degrees, far
  // above what a load of a tenth of the radius allows.
  PocketCheckInput in;
  in.walls = {{{0, 0, 0}, {40, 0, 0}, {40, 20, 0}, {0, 20, 0}}};
  in.radius = 3;
  in.tolerance = 0.01;
  in.levels = {-3};
  in.load = 0.3;
  std::vector<Move> moves;
  LineMove down;
  down.to = {5, 10, -3};
  down.feed = 100;
  moves.push_back({down});
  LineMove across = down;
  across.to = {35, 10, -3};
  moves.push_back({across});
  in.moves = &moves;
  in.to = moves.size();
  in.start = {5, 10, 5};
  const PocketCertificate c = check_pocket(in);
  EXPECT_GE(c.engagement_deg, 170);
  EXPECT_FALSE(c.engagement_kept());
  EXPECT_NEAR(c.engagement_bound, std::acos(0.9) * 180 / std::numbers::pi + 2, 1e-9);
}

}  // namespace
}  // namespace bezcam
