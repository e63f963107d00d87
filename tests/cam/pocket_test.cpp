// Pockets a new user draws (docs/pocket.md): each program is built, then
// read back by the test's own means (moves replayed, distances sampled)
// besides the certificate bezcam prints.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <sstream>

#include "bezcam/cam/pocket_check.hpp"
#include "bezcam/cam/program.hpp"
#include "bezcam/error_ids.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/pocket_shapes.hpp"
#include "support/refusal.hpp"

namespace bezcam {
namespace {

using namespace test::shapes;

Pts rect(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Program build(const std::string& keys, const std::vector<std::string>& entities, const std::string& top = "") {
  std::string e;
  for (const auto& x : entities) e += (e.empty() ? "" : ",") + x;
  const std::string json = R"({"bezcam":1,"tolerance":0.01,)" + top +
                           R"("job":{"feed":600,"plunge_feed":100,"safe_z":5,)"
                           R"("top_z":0,"clearance":1,"cut_z":-3,"tool_diameter":6,"operation":"pocket",)"
                           R"("region":"p")" +
                           (keys.empty() ? "" : "," + keys) + R"(},"entities":[)" + e + "]}";
  return build_program(parse_job(json, "pocket.json"), load_machine_profile("linuxcnc"), ConvertOptions{});
}

const PocketCertificate& cert(const Program& p) {
  for (const auto& e : p.entities)
    if (e.pocket) return *e.pocket;
  throw std::logic_error("no pocket in the program");
}

// The tool centre's positions at cutting depth z, every 0.05 along the
// moves (arcs by their ends: the test reads lines only there).
std::vector<Vec3> path_at(const Program& p, double z) {
  std::vector<Vec3> out;
  Vec3 cur;
  for (const Move& mv : p.moves) {
    const Motion* m = motion_of(mv);
    if (!m) continue;
    Vec3 to = cur;
    if (m->axes & kAxisX) to.x = m->to.x;
    if (m->axes & kAxisY) to.y = m->to.y;
    if (m->axes & kAxisZ) to.z = m->to.z;
    if (std::holds_alternative<LineMove>(mv.what) && std::abs(cur.z - z) < 1e-9 && std::abs(to.z - z) < 1e-9) {
      const double len = std::hypot(to.x - cur.x, to.y - cur.y);
      const int n = std::max(1, static_cast<int>(len / 0.05));
      for (int k = 0; k <= n; ++k) out.push_back({cur.x + (to.x - cur.x) * k / n, cur.y + (to.y - cur.y) * k / n, z});
    }
    cur = to;
  }
  return out;
}

double nearest(const std::vector<Vec3>& path, double x, double y) {
  double d = 1e300;
  for (const Vec3& p : path) d = std::min(d, std::hypot(p.x - x, p.y - y));
  return d;
}

void expect_certified(const Program& p, double r, double stock = 0) {
  const PocketCertificate& c = cert(p);
  EXPECT_TRUE(c.covered()) << "uncut " << c.uncut_area << " at " << c.uncut_at.x << ", " << c.uncut_at.y;
  EXPECT_EQ(c.uncut_area, 0);
  EXPECT_TRUE(c.walls_kept(r, stock, 0.01)) << c.wall_distance;
  // The passes keep r + stock from the walls as drawn: the margin holds
  // the flattening, the offset's simplification and chords, the rounding.
  EXPECT_GE(c.wall_distance, r + stock) << "at " << c.wall_at.x << ", " << c.wall_at.y;
  EXPECT_LE(c.wall_distance, r + stock + 0.01);  // and not far off: the walls are cut
  EXPECT_EQ(c.rapids_in_material, 0u);
}

TEST(Pocket, SixteenMillimetreSquareWithAQuarterInchToolAtStepoverFiveIsCleared) {
  const Program p = build(R"("tool_diameter":6.35,"stepover":5)", {polygon(rect(0, 0, 16, 16))});
  expect_certified(p, 3.175);
  // The centre, which rings at 5 mm leave, is within r of the path.
  EXPECT_LE(nearest(path_at(p, -3), 8, 8), 3.175);
  // What is left is the four corners, each r^2 (1 - pi/4) within the grid.
  const PocketCertificate& c = cert(p);
  ASSERT_EQ(c.unreachable.size(), 4u);
  for (const auto& u : c.unreachable) EXPECT_NEAR(u.area, 3.175 * 3.175 * (1 - std::numbers::pi / 4), 0.1);
  // The header says so.
  const auto n = std::count_if(p.notes.begin(), p.notes.end(),
                               [](const std::string& s) { return s.starts_with("pocket p: uncut 0 mm^2"); });
  EXPECT_EQ(n, 1);
}

TEST(Pocket, RectangleWithTwoBossesIsClearedAroundThem) {
  for (const char* pattern : {R"("pattern":"offset")", R"("pattern":"zigzag","angle":30)"}) {
    SCOPED_TRACE(pattern);
    const Program p = build(pattern, {polygon(rect(0, 0, 60, 40)), circle(18, 20, 6), circle(42, 20, 6)});
    expect_certified(p, 3);
    const auto path = path_at(p, -3);
    // No tool position within r of a boss (their centres are 6 + 3 off):
    // the offsets' margin holds the walls' flattening, the offset's own
    // simplification and chords, and the rounding.
    EXPECT_GE(nearest(path, 18, 20), 9);
    EXPECT_GE(nearest(path, 42, 20), 9);
    // Between the bosses (a gap of 12) the tool passes.
    EXPECT_LE(nearest(path, 30, 20), 3);
    EXPECT_EQ(cert(p).unreachable.size(), 4u);  // the outline's four corners
  }
}

TEST(Pocket, StarWithTipsHasTheTipAngleAsked) {
  for (double tip : {30.0, 36.0, 50.0}) {
    const Pts p = star_with_tips(5, 30, tip);
    // At each tip, the angle between the edges to the inner corners beside it.
    for (size_t k = 0; k < p.size(); k += 2) {
      const auto& [x, y] = p[k];
      const auto& [ax, ay] = p[(k + 1) % p.size()];
      const auto& [bx, by] = p[(k + p.size() - 1) % p.size()];
      const double ux = ax - x, uy = ay - y, vx = bx - x, vy = by - y;
      const double deg =
          std::acos((ux * vx + uy * vy) / std::hypot(ux, uy) / std::hypot(vx, vy)) * 180 / std::numbers::pi;
      EXPECT_NEAR(deg, tip, 1e-9) << tip << " at tip " << k / 2;
    }
  }
  // The regular pentagram's tips are 36 degrees: inner corners at 11.46.
  EXPECT_NEAR(std::hypot(star_with_tips(5, 30, 36)[1].first, star_with_tips(5, 30, 36)[1].second), 11.4590, 1e-4);
}

TEST(Pocket, StarWithThirtyDegreeTipsIsClearedWhereTheToolFits) {
  const Program p = build(R"("tool_diameter":4)", {polygon(star_with_tips(5, 30, 30))});
  expect_certified(p, 2);
  // Each tip holds what a 4 mm tool cannot reach: five places.
  EXPECT_EQ(cert(p).unreachable.size(), 5u);
  EXPECT_FALSE(p.warnings.empty());
}

TEST(Pocket, LShapeIsClearedAtEveryStepDown) {
  const Program p = build(R"("step_down":1.5)", {polygon(l_shape())});
  expect_certified(p, 3);
  for (double z : {-1.5, -3.0}) {
    const auto path = path_at(p, z);
    ASSERT_FALSE(path.empty()) << z;
    EXPECT_LE(nearest(path, 10, 50), 3) << z;  // up the arm
    EXPECT_LE(nearest(path, 50, 10), 3) << z;  // along the foot
    EXPECT_LE(nearest(path, 13, 13), 3) << z;  // the inner corner's middle
  }
}

TEST(Pocket, NeckNarrowerThanTheToolIsCutWhereItFitsAndNamed) {
  // Two 20 x 20 rooms joined by a neck 4 wide: a 6 mm tool clears both
  // rooms and says what is left in the neck.
  const Program p = build("", {polygon(rooms_with_neck())});
  expect_certified(p, 3);
  const auto path = path_at(p, -3);
  EXPECT_LE(nearest(path, 10, 10), 3);
  EXPECT_LE(nearest(path, 40, 10), 3);
  const PocketCertificate& c = cert(p);
  ASSERT_FALSE(c.unreachable.empty());
  const PocketPlace& neck = c.unreachable.front();  // largest first
  EXPECT_GT(neck.at.x, 19);
  EXPECT_LT(neck.at.x, 31);
  EXPECT_GT(neck.area, 30);
  const bool named = std::any_of(p.warnings.begin(), p.warnings.end(),
                                 [](const std::string& w) { return w.find("cannot reach") != std::string::npos; });
  EXPECT_TRUE(named);
}

TEST(Pocket, StockToLeaveAndTheFinishingRing) {
  const Program p = build(R"("stock_to_leave":0.5,"finish":{"stock":0.3})", {polygon(rect(0, 0, 30, 20))});
  expect_certified(p, 3, 0.5);
  // The last ring runs at r + stock_to_leave, the roughing ones 0.3 off it.
  const auto path = path_at(p, -3);
  EXPECT_NEAR(nearest(path, 0, 10), 3.5, 0.01);
}

TEST(Pocket, ClimbAndConventionalRunTheOuterRingOppositeWays) {
  auto last_ring_area = [](const Program& p) {
    // The signed area of the last run of feed moves at depth: the wall ring.
    std::vector<Vec3> pts, last;
    for (const Move& mv : p.moves)
      if (std::holds_alternative<LineMove>(mv.what) && std::abs(motion_of(mv)->to.z + 3) < 1e-9) {
        pts.push_back(motion_of(mv)->to);
      } else if (std::holds_alternative<RapidMove>(mv.what) || std::holds_alternative<ArcMove>(mv.what)) {
        if (!pts.empty()) last = pts;
        pts.clear();
      }
    pts = last;
    double a = 0;
    for (size_t i = 0; i + 1 < pts.size(); ++i) a += pts[i].x * pts[i + 1].y - pts[i + 1].x * pts[i].y;
    return a;
  };
  const std::string sq = polygon(rect(0, 0, 30, 20));
  EXPECT_GT(last_ring_area(build(R"("direction":"climb")", {sq})), 0);  // counter-clockwise: wall on the right
  EXPECT_LT(last_ring_area(build(R"("direction":"conventional")", {sq})), 0);
}

TEST(Pocket, EntriesStayInTheRegion) {
  const std::string sq = polygon(rect(0, 0, 30, 20));
  auto count = [](const Program& p, auto pred) { return std::count_if(p.moves.begin(), p.moves.end(), pred); };
  const Program helix = build("", {sq});
  EXPECT_GT(count(helix, [](const Move& m) { return std::holds_alternative<ArcMove>(m.what); }), 2);
  expect_certified(helix, 3);
  for (const char* e : {R"("entry":"ramp")", R"("entry":"plunge")"}) {
    const Program p = build(e, {sq});
    EXPECT_EQ(count(p, [](const Move& m) { return std::holds_alternative<ArcMove>(m.what); }), 0) << e;
    expect_certified(p, 3);
  }
}

TEST(Pocket, RefusalsNameTheKey) {
  struct Case {
    std::string keys;
    std::vector<std::string> entities;
    std::string id, path;
  } cases[] = {
      // The tool fits nowhere.
      {"", {polygon(rect(0, 0, 5, 5))}, "job.pocket", "entities[0].tool_diameter"},
      {R"("stepover":7)", {polygon(rect(0, 0, 30, 20))}, "job.pocket", "entities[0].stepover"},
      // A helix of at least a quarter of 10 fits nowhere in a slot 7 wide.
      {R"("entry":{"helix":{"radius":10}})", {polygon(rect(0, 0, 40, 7))}, "job.pocket", "entities[0].entry"},
      // An island crossing the outline.
      {"", {polygon(rect(0, 0, 30, 20)), polygon(rect(25, 5, 35, 15))}, "job.pocket", "entities[1]"},
      // Rest machining after a tool no larger than this one.
      {R"("rest_from":6)", {polygon(rect(0, 0, 30, 20))}, "job.pocket", "entities[0].rest_from"},
      {R"("rest_from":4)", {polygon(rect(0, 0, 30, 20))}, "job.pocket", "entities[0].rest_from"},
      // A load above the radius, and a load without the adaptive pattern.
      {R"("pattern":"adaptive","load":3.5)", {polygon(rect(0, 0, 30, 20))}, "job.pocket", "entities[0].load"},
      {R"("load":1)", {polygon(rect(0, 0, 30, 20))}, "job.pocket", "entities[0].load"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.keys + " " + c.path);
    const InputError e = test::refusal_of([&] { build(c.keys, c.entities); });
    EXPECT_EQ(e.id(), c.id) << e.what();
    EXPECT_EQ(e.place().json_path.value_or(""), c.path) << e.what();
  }
  // The tool table's shape and end.
  const std::string sq = polygon(rect(0, 0, 30, 20));
  for (const char* t : {R"("tools":{"1":{"shape":"vee","diameter":6,"angle":60}},)",
                        R"("tools":{"1":{"shape":"drill","diameter":6,"point_angle":118}},)"}) {
    const InputError e = test::refusal_of([&] { build("", {sq}, t); });
    EXPECT_EQ(e.id(), "job.pocket") << e.what();
    EXPECT_EQ(e.place().json_path.value_or(""), "entities[0].tool") << e.what();
  }
  const InputError plunge =
      test::refusal_of([&] { build(R"("entry":"plunge")", {sq}, R"("tools":{"1":{"shape":"flat","diameter":6}},)"); });
  EXPECT_EQ(plunge.id(), "job.pocket") << plunge.what();
  EXPECT_EQ(plunge.place().json_path.value_or(""), "entities[0].entry") << plunge.what();
  // An open curve.
  const std::string open = R"({"type":"bezier","points":[[0,0],[30,0],[30,20]]})";
  const InputError e = test::refusal_of([&] { build("", {open}); });
  EXPECT_EQ(e.id(), "job.pocket");
  EXPECT_EQ(e.place().json_path.value_or(""), "entities[0].operation");
}

TEST(Pocket, TheToolTablesFluteLengthSplitsTheDepth) {
  // Flutes 1.5 long, a pocket 3 deep, no step_down: two levels, each
  // certified; a center-cutting tool may plunge.
  const Program p = build(R"("entry":"plunge")", {polygon(rect(0, 0, 30, 20))},
                          R"("tools":{"1":{"shape":"flat","diameter":6,"flute_length":1.5,"center_cutting":true}},)");
  expect_certified(p, 3);
  EXPECT_FALSE(path_at(p, -1.5).empty());
  EXPECT_FALSE(path_at(p, -3).empty());
}

TEST(Pocket, RegionsGroupByName) {
  // Without a common region each closed curve is a pocket of its own.
  const std::string json = R"({"bezcam":1,"tolerance":0.01,"job":{"feed":600,"plunge_feed":100,"safe_z":5,)"
                           R"("cut_z":-1,"tool_diameter":4,"operation":"pocket"},"entities":[)" +
                           polygon(rect(0, 0, 30, 20), R"(,"id":"a")") + "," +
                           polygon(rect(40, 0, 60, 20), R"(,"id":"b")") + "]}";
  const Program p = build_program(parse_job(json, "t.json"), load_machine_profile("linuxcnc"), ConvertOptions{});
  ASSERT_EQ(p.entities.size(), 2u);
  EXPECT_EQ(p.entities[0].label, "a");
  EXPECT_EQ(p.entities[1].label, "b");
}

TEST(Pocket, ARegionInsideAnotherIsSaidToBeClearedOver) {
  // A drawing's curves, each its own region by default: the outline's
  // pocket clears over the boss, which a warning names.
  const std::string json = R"({"bezcam":1,"tolerance":0.01,"job":{"feed":600,"plunge_feed":100,"safe_z":5,)"
                           R"("cut_z":-1,"tool_diameter":4,"operation":"pocket"},"entities":[)" +
                           polygon(rect(0, 0, 40, 30), R"(,"id":"outline")") + "," +
                           polygon(rect(15, 10, 25, 20), R"(,"id":"boss")") + "]}";
  const Program p = build_program(parse_job(json, "t.json"), load_machine_profile("linuxcnc"), ConvertOptions{});
  const auto n = std::count_if(p.warnings.begin(), p.warnings.end(), [](const std::string& w) {
    return w.find("\"boss\" (boss) lies inside pocket region \"outline\"") != std::string::npos;
  });
  EXPECT_EQ(n, 1);
  // One region: the boss is an island, no warning.
  const Program q = build(R"("tool_diameter":4)", {polygon(rect(0, 0, 40, 30)), polygon(rect(15, 10, 25, 20))});
  EXPECT_TRUE(std::none_of(q.warnings.begin(), q.warnings.end(),
                           [](const std::string& w) { return w.find("lies inside") != std::string::npos; }));
}

}  // namespace
}  // namespace bezcam
