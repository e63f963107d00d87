// Cutting a part (cam/part_cut): passes, leads, tabs, direction and order,
// read from the program's moves; the band from the part is measured from
// the text in gcode/part_roundtrip_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <fstream>
#include <iterator>
#include <set>

#include "bezcam/cam/program.hpp"
#include "bezcam/error.hpp"
#include "bezcam/job/job_json.hpp"

namespace bezcam {
namespace {

// A 40 x 30 rectangle, counter-clockwise, as a closed path.
std::string rect(double x0, double y0, double w, double h, const std::string& extra = "") {
  auto p = [](double x, double y) { return "[" + std::to_string(x) + "," + std::to_string(y) + "]"; };
  const std::string a = p(x0, y0), b = p(x0 + w, y0), c = p(x0 + w, y0 + h), d = p(x0, y0 + h);
  return R"({"type":"path","closed":true)" + extra + R"(,"segments":[{"type":"bezier","points":[)" + a + "," + b +
         R"(]},{"type":"bezier","points":[)" + b + "," + c + R"(]},{"type":"bezier","points":[)" + c + "," + d +
         R"(]},{"type":"bezier","points":[)" + d + "," + a + "]}]}";
}

Program build(const std::string& job_params, const std::string& entities, const std::string& top = "") {
  const std::string json = R"({"bezcam":1,"tolerance":0.01,)" + top + R"("job":{"feed":600,"plunge_feed":100,"safe_z":5,)" +
                           job_params + R"(},"entities":[)" + entities + "]}";
  return build_program(parse_job(json, "test.json"), load_machine_profile("generic"), ConvertOptions{});
}

struct Cut {
  std::vector<Vec3> plunges;          // where each plunge ends
  std::vector<std::vector<Vec3>> runs;  // feed moves between rapids
};
Cut cuts(const Program& p, int entity = -1) {
  Cut c;
  bool in = false;
  for (const Move& mv : p.moves) {
    if (entity >= 0 && mv.entity != entity) continue;
    if (std::holds_alternative<RapidMove>(mv.what)) {
      in = false;
      continue;
    }
    const Motion* m = motion_of(mv);
    if (!m) continue;
    if (!in) {
      c.plunges.push_back(m->to);
      c.runs.emplace_back();
      in = true;
      continue;
    }
    c.runs.back().push_back(m->to);
  }
  return c;
}

double dist_to_rect(const Vec3& p, double x0, double y0, double w, double h) {
  const double dx = std::max({x0 - p.x, 0.0, p.x - (x0 + w)}), dy = std::max({y0 - p.y, 0.0, p.y - (y0 + h)});
  if (dx > 0 || dy > 0) return std::hypot(dx, dy);
  return std::min({p.x - x0, x0 + w - p.x, p.y - y0, y0 + h - p.y});  // inside: to the nearest edge
}

TEST(PartCut, EqualStepsFromTopZDownToCutZ) {
  const Program p = build(R"("side":"outside","tool_diameter":6,"top_z":0,"cut_z":-5,"step_down":2)", rect(0, 0, 40, 30));
  const Cut c = cuts(p);
  ASSERT_EQ(c.plunges.size(), 3u);  // ceil(5 / 2) passes of 5/3 each
  EXPECT_NEAR(c.plunges[0].z, -1.667, 1e-9);
  EXPECT_NEAR(c.plunges[1].z, -3.333, 1e-9);
  EXPECT_NEAR(c.plunges[2].z, -5, 1e-12);
  for (const auto& run : c.runs)
    for (const auto& v : run) EXPECT_NEAR(dist_to_rect(v, 0, 0, 40, 30), 3, 0.0101);
}

TEST(PartCut, LeadsStartOnTheWasteSideAndJoinTangentially) {
  const Program p = build(R"("side":"outside","tool_diameter":6,"cut_z":-1,"lead":{"radius":4,"length":2})",
                          rect(0, 0, 40, 30));
  const Cut c = cuts(p);
  ASSERT_EQ(c.plunges.size(), 1u);
  // The plunge is off the part: at least r + length from it, never on it.
  EXPECT_GE(dist_to_rect(c.plunges[0], 0, 0, 40, 30), 3 + 2 - 1e-3);
  // Inside: the same on the other side.
  const Program q = build(R"("side":"inside","tool_diameter":6,"cut_z":-1,"lead":{"radius":4,"length":2})",
                          rect(0, 0, 40, 30));
  const Cut d = cuts(q);
  const Vec3 s = d.plunges[0];
  EXPECT_TRUE(s.x > 0 && s.x < 40 && s.y > 0 && s.y < 30);
  EXPECT_GE(dist_to_rect(s, 0, 0, 40, 30), 3 + 2 - 1e-3);
}

TEST(PartCut, ALeadTooBigForThePocketIsSaid) {
  const Program p = build(R"("side":"inside","tool_diameter":6,"cut_z":-1,"lead":{"radius":8,"length":5})", rect(0, 0, 20, 15));
  bool said = false;
  for (const auto& w : p.warnings) said = said || w.find("lead-in crosses the curve") != std::string::npos;
  EXPECT_TRUE(said);
  const Program q = build(R"("side":"inside","tool_diameter":6,"cut_z":-1,"lead":{"radius":2,"length":1})", rect(0, 0, 40, 30));
  for (const auto& w : q.warnings) EXPECT_EQ(w.find("lead"), std::string::npos) << w;
}

TEST(PartCut, TabsRaiseOnlyThePassesBelowThem) {
  const Program p = build(R"("side":"outside","tool_diameter":6,"top_z":0,"cut_z":-6,"step_down":2,)"
                          R"("tabs":{"count":3,"width":4,"height":1.5})",
                          rect(0, 0, 40, 30));
  const Cut c = cuts(p);
  ASSERT_EQ(c.plunges.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    std::set<double> zs;
    for (const auto& v : c.runs[k]) zs.insert(v.z);
    if (k < 2) {
      EXPECT_EQ(zs.size(), 1u) << "pass " << k << " is above the tabs' top (-4.5)";
    } else {
      EXPECT_EQ(zs, (std::set<double>{-6, -4.5}));
      // Three rises onto a tab.
      int rises = 0;
      for (size_t i = 1; i < c.runs[k].size(); ++i) rises += c.runs[k][i].z > c.runs[k][i - 1].z;
      EXPECT_EQ(rises, 3);
    }
  }
}

TEST(PartCut, ClimbGoesClockwiseOutsideAndCounterClockwiseInside) {
  auto turning = [](const std::vector<Vec3>& run) {
    double a = 0;
    for (size_t i = 0; i + 1 < run.size(); ++i) a += run[i].x * run[i + 1].y - run[i + 1].x * run[i].y;
    return a;
  };
  const Program out = build(R"("side":"outside","tool_diameter":6,"cut_z":-1,"direction":"climb")", rect(0, 0, 40, 30));
  EXPECT_LT(turning(cuts(out).runs[0]), 0);  // clockwise
  const Program in = build(R"("side":"inside","tool_diameter":6,"cut_z":-1,"direction":"climb")", rect(0, 0, 40, 30));
  EXPECT_GT(turning(cuts(in).runs[0]), 0);
  const Program conv = build(R"("side":"outside","tool_diameter":6,"cut_z":-1,"direction":"conventional")",
                             rect(0, 0, 40, 30));
  EXPECT_GT(turning(cuts(conv).runs[0]), 0);
  // The same whichever way the rectangle is drawn: a clockwise copy.
  const std::string cw = R"({"type":"path","closed":true,"segments":[{"type":"bezier","points":[[0,0],[0,30]]},)"
                         R"({"type":"bezier","points":[[0,30],[40,30]]},{"type":"bezier","points":[[40,30],[40,0]]},)"
                         R"({"type":"bezier","points":[[40,0],[0,0]]}]})";
  const Program out_cw = build(R"("side":"outside","tool_diameter":6,"cut_z":-1,"direction":"climb")", cw);
  const Cut c = cuts(out_cw);
  EXPECT_LT(turning(c.runs[0]), 0);
  for (const auto& v : c.runs[0]) EXPECT_NEAR(dist_to_rect(v, 0, 0, 40, 30), 3, 0.0101);
}

TEST(PartCut, WasteSideNeverComesNearerThanTheRadius) {
  const Program p = build(R"("side":"outside","tool_diameter":6,"cut_z":-1,"tolerance_side":"waste")", rect(0, 0, 40, 30));
  const Cut c = cuts(p);
  for (const auto& run : c.runs)
    for (const auto& v : run) {
      const double d = dist_to_rect(v, 0, 0, 40, 30);
      EXPECT_GE(d, 3 - 1e-12);
      EXPECT_LE(d, 3.01);
    }
}

TEST(PartCut, OrderShortestCutsHolesFirstAndSaysWhatItSaved) {
  // The outline written first, then its two holes, then a far-away part
  // written between them.
  const std::string ents = rect(0, 0, 100, 60, R"(,"id":"plate","side":"outside")") + "," +
                           rect(80, 40, 10, 10, R"(,"id":"hole-b","side":"inside")") + "," +
                           rect(300, 0, 20, 20, R"(,"id":"far","side":"outside")") + "," +
                           rect(10, 10, 10, 10, R"(,"id":"hole-a","side":"inside")");
  const Program p = build(R"("tool_diameter":4,"cut_z":-1)", ents, R"("order":"shortest",)");
  std::vector<std::string> order;
  for (const auto& r : p.entities) order.push_back(r.label);
  auto at = [&](const std::string& id) { return std::find(order.begin(), order.end(), id) - order.begin(); };
  EXPECT_LT(at("hole-a"), at("plate"));
  EXPECT_LT(at("hole-b"), at("plate"));
  EXPECT_NE(p.order_summary.find("saved"), std::string::npos) << p.order_summary;
  // The same file gives the same program.
  const Program again = build(R"("tool_diameter":4,"cut_z":-1)", ents, R"("order":"shortest",)");
  ASSERT_EQ(again.moves.size(), p.moves.size());
  for (size_t i = 0; i < p.moves.size(); ++i)
    if (const Motion* m = motion_of(p.moves[i])) EXPECT_EQ(m->to, motion_of(again.moves[i])->to);
}

TEST(PartCut, StockToLeaveMovesThePathOut) {
  const Program p = build(R"("side":"outside","tool_diameter":6,"stock_to_leave":0.5,"cut_z":-1)", rect(0, 0, 40, 30));
  const Cut c = cuts(p);
  for (const auto& v : c.runs[0]) EXPECT_NEAR(dist_to_rect(v, 0, 0, 40, 30), 3.5, 0.0101);
  EXPECT_DOUBLE_EQ(p.entities[0].offset, 3.5);
}

TEST(PartCut, EntityKeysOverrideTheJobs) {
  const Program p = build(R"("side":"outside","tool_diameter":6,"cut_z":-1)",
                          rect(0, 0, 40, 30, R"(,"tool_diameter":2)"));
  const Cut c = cuts(p);
  for (const auto& v : c.runs[0]) EXPECT_NEAR(dist_to_rect(v, 0, 0, 40, 30), 1, 0.0101);
}

// Letters of real artwork (tests/cam/data): the G's mouth is narrower
// than a 6 mm tool, so outside it the offset falls apart into the outline
// and the G's counter, cut as two stretches; the stretches together reach
// the part wherever the tool fits, and material is said to be left where it
// does not.
TEST(PartCut, AnOffsetThatFallsApartIsCutWhereTheToolFits) {
  const Job job = load_job(BEZCAM_SOURCE_DIR "/tests/cam/data/part-letter-g.json");
  for (OutputMode mode : {OutputMode::lines, OutputMode::arcs}) {
    ConvertOptions opt;
    opt.output = mode;
    Program p;
    ASSERT_NO_THROW(p = build_program(job, load_machine_profile("generic"), opt)) << to_string(mode);
    EXPECT_EQ(cuts(p).runs.size(), 2u);
    bool said = false;
    for (const auto& w : p.warnings) said = said || w.find("material is left at") != std::string::npos;
    EXPECT_TRUE(said);
    EXPECT_LE(p.entities[0].measured, 0.0103);
  }
}

// A channel exactly as wide as the tool (LibreCAD's aw24.dxf): inside it
// the offsets of its two walls coincide, and the tool runs into the
// channel along its middle and back out. The path keeps its band and
// reaches the channel's end wall in every mode.
TEST(PartCut, AChannelExactlyAsWideAsTheToolIsCutAlongItsMiddle) {
  const Job job = load_job(BEZCAM_SOURCE_DIR "/tests/cam/data/part-channel-tool-wide.json");
  for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
    ConvertOptions opt;
    opt.output = mode;
    Program p;
    ASSERT_NO_THROW(p = build_program(job, load_machine_profile("generic"), opt)) << to_string(mode);
    double reach = HUGE_VAL;  // the smallest x the tool centre reaches
    for (const auto& run : cuts(p).runs)
      for (const Vec3& q : run) reach = std::min(reach, q.x);
    EXPECT_NEAR(reach, 3.0, 0.01) << to_string(mode);
    EXPECT_LE(p.entities[0].measured, 0.0101) << to_string(mode);
  }
}

// Tabs on a part whose offset falls apart: they go on the G's outline
// (the stretch that frees the part), and the stretch in its counter, too
// short for them, is cut without them and said; refused only when no
// stretch holds them, naming the longest.
TEST(PartCut, TabsGoOnTheStretchesThatHoldThem) {
  std::ifstream in(BEZCAM_SOURCE_DIR "/tests/cam/data/part-letter-g.json");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string side = R"("side": "outside")";
  ASSERT_NE(text.find(side), std::string::npos);
  auto with = [&](const std::string& tabs) {
    std::string t = text;
    t.replace(t.find(side), side.size(), side + R"(, "step_down": 1, "tabs": )" + tabs);
    return parse_job(t, "part-letter-g.json");
  };
  const Program p = build_program(with(R"({"count": 2, "width": 4, "height": 1})"), load_machine_profile("generic"), ConvertOptions{});
  bool said = false;
  for (const auto& w : p.warnings) said = said || w.find("is cut without tabs") != std::string::npos;
  EXPECT_TRUE(said);
  const Cut c = cuts(p);
  ASSERT_EQ(c.runs.size(), 4u);  // two passes of two stretches
  int rises = 0;
  for (const auto& run : c.runs)
    for (size_t i = 1; i < run.size(); ++i) rises += run[i].z > run[i - 1].z;
  EXPECT_EQ(rises, 2);  // the outline's last pass only
  try {
    (void)build_program(with(R"({"count": 20, "width": 4, "height": 1})"), load_machine_profile("generic"), ConvertOptions{});
    ADD_FAILURE() << "20 tabs of 10 on a path of 164";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "job.cut");
    EXPECT_NE(std::string(e.what()).find("the longest of its 2 stretches"), std::string::npos) << e.what();
  }
}

// An x cut inside with a 1 mm tool and the tolerance on the waste side: the
// path's inner corners, half the tolerance away from the part, lie off the
// true offset's corners along their bisectors by more than the tolerance
// where the corners are sharp, while the material they leave is the
// band's. The program is written: the independent measurement build_program
// runs holds its path within [r, r + tolerance] of the part and the material
// it leaves within the tolerance.
TEST(PartCut, SharpInnerCornersOnTheWasteSideKeepTheBand) {
  const Job job = load_job(BEZCAM_SOURCE_DIR "/tests/cam/data/part-letter-x.json");
  Program p;
  ASSERT_NO_THROW(p = build_program(job, load_machine_profile("generic"), ConvertOptions{}));
  EXPECT_GT(p.entities[0].measured, 0.0);
  EXPECT_LE(p.entities[0].measured, 0.0103);
}

// Wasted blocks: cutting moves that go less than the rounding unit, and
// moves that turn back the way the previous one came (by more than 150
// degrees where they meet). An offset part's path has neither: at a small
// kink of its arc spline the two offsets overshoot their crossing by a
// hair, and a path that ran past the crossing, back and on again would
// print three moves of a micrometre or two doubling back on each other.
struct Wasted {
  size_t moves = 0, short_moves = 0, reversing = 0;
};
Wasted wasted_blocks(const Program& p, double unit) {
  Wasted w;
  Vec3 at, last_dir;  // where the tool is, the direction the last XY move ended in
  bool known = false, cutting = false;
  auto unit_dir = [](const Vec3& v) {
    const double l = std::hypot(v.x, v.y);
    return l > 0 ? Vec3{v.x / l, v.y / l, 0} : Vec3{};
  };
  for (const Move& mv : p.moves) {
    const Motion* m = motion_of(mv);
    if (!m) continue;
    const bool rapid = std::holds_alternative<RapidMove>(mv.what);
    const Vec3 d{m->to.x - at.x, m->to.y - at.y, 0};
    if (rapid || !known || (d.x == 0 && d.y == 0)) {  // a rapid, a plunge, a tab's rise
      cutting = cutting && !rapid && known && m->to.z == at.z;
      if (!rapid && known && d.x == 0 && d.y == 0 && m->to.z == at.z) ++w.short_moves;  // goes nowhere
      at = m->to;
      known = true;
      continue;
    }
    Vec3 d0 = unit_dir(d), d1 = d0;
    if (const auto* a = std::get_if<ArcMove>(&mv.what)) {
      const double s = a->ccw ? 1 : -1;
      d0 = unit_dir(Vec3{-(at.y - a->center.y) * s, (at.x - a->center.x) * s, 0});
      d1 = unit_dir(Vec3{-(a->to.y - a->center.y) * s, (a->to.x - a->center.x) * s, 0});
    }
    ++w.moves;
    if (std::hypot(d.x, d.y) < unit * (1 - 1e-6)) ++w.short_moves;  // the unit itself, less the doubles' error
    if (cutting && d0.x * last_dir.x + d0.y * last_dir.y < std::cos(150 * std::numbers::pi / 180)) ++w.reversing;
    last_dir = d1;
    cutting = true;
    at = m->to;
  }
  return w;
}

TEST(PartCut, AnOffsetPathHasNoWastedBlocks) {
  MachineProfile m = load_machine_profile("linuxcnc");  // 4 decimals: a unit of 0.1 micrometre
  ASSERT_EQ(m.decimals_mm, 4);
  for (const char* sample : {"part-cam-notch", "part-lettering", "part-flange"}) {
    const Job job = load_job(std::string(BEZCAM_SOURCE_DIR "/samples/") + sample + ".json");
    for (OutputMode mode : {OutputMode::lines, OutputMode::arcs}) {
      ConvertOptions opt;
      opt.output = mode;
      opt.measure = false;
      const Wasted w = wasted_blocks(build_program(job, m, opt), 1e-4);
      EXPECT_GT(w.moves, 20u) << sample;
      EXPECT_EQ(w.short_moves, 0u) << sample << " " << to_string(mode);
      EXPECT_EQ(w.reversing, 0u) << sample << " " << to_string(mode);
    }
  }
}

}  // namespace
}  // namespace bezcam
