// Cutting a part (cam/part_cut): passes, leads, tabs, direction and order,
// read from the program's moves; the band from the part is measured from
// the text in gcode/part_roundtrip_test.cpp. The leads are measured here
// against the part by the test's own means (dense samples of the part,
// refined by golden section), never by bezcam's measurement.
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "bezcam/cam/program.hpp"
#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/motion.hpp"
#include "support/cutting_runs.hpp"

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
  const std::string json = R"({"bezcam":1,"tolerance":0.01,)" + top +
                           R"("job":{"feed":600,"plunge_feed":100,"safe_z":5,)" + job_params + R"(},"entities":[)" +
                           entities + "]}";
  return build_program(parse_job(json, "test.json"), load_machine_profile("generic"), ConvertOptions{});
}

struct Cut {
  std::vector<Vec3> plunges;            // where each plunge ends
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
  const Program p =
      build(R"("side":"outside","tool_diameter":6,"top_z":0,"cut_z":-5,"step_down":2)", rect(0, 0, 40, 30));
  const Cut c = cuts(p);
  ASSERT_EQ(c.plunges.size(), 3u);  // ceil(5 / 2) passes of 5/3 each
  EXPECT_NEAR(c.plunges[0].z, -1.667, 1e-9);
  EXPECT_NEAR(c.plunges[1].z, -3.333, 1e-9);
  EXPECT_NEAR(c.plunges[2].z, -5, 1e-12);
  for (const auto& run : c.runs)
    for (const auto& v : run) EXPECT_NEAR(dist_to_rect(v, 0, 0, 40, 30), 3, 0.0101);
}

TEST(PartCut, LeadsStartOnTheWasteSideAndJoinTangentially) {
  const Program p =
      build(R"("side":"outside","tool_diameter":6,"cut_z":-1,"lead":{"radius":4,"length":2})", rect(0, 0, 40, 30));
  const Cut c = cuts(p);
  ASSERT_EQ(c.plunges.size(), 1u);
  // The plunge is off the part: at least r + length from it, never on it.
  EXPECT_GE(dist_to_rect(c.plunges[0], 0, 0, 40, 30), 3 + 2 - 1e-3);
  // Inside: the same on the other side.
  const Program q =
      build(R"("side":"inside","tool_diameter":6,"cut_z":-1,"lead":{"radius":4,"length":2})", rect(0, 0, 40, 30));
  const Cut d = cuts(q);
  const Vec3 s = d.plunges[0];
  EXPECT_TRUE(s.x > 0 && s.x < 40 && s.y > 0 && s.y < 30);
  EXPECT_GE(dist_to_rect(s, 0, 0, 40, 30), 3 + 2 - 1e-3);
}

// The distance from a point to the part, by the test's own means: the
// nearest of dense samples of every piece, refined by golden section
// between that sample's neighbours.
class PartDistance {
 public:
  explicit PartDistance(std::vector<Bezier> part) : part_(std::move(part)) {
    for (size_t k = 0; k < part_.size(); ++k)
      for (int i = 0; i <= kN; ++i)
        at_.push_back({k, static_cast<double>(i) / kN, evaluate(part_[k], static_cast<double>(i) / kN)});
  }
  double operator()(const Vec3& p) const {
    size_t best = 0;
    double d = HUGE_VAL;
    for (size_t i = 0; i < at_.size(); ++i) {
      const double e = std::hypot(at_[i].p.x - p.x, at_[i].p.y - p.y);
      if (e < d) d = e, best = i;
    }
    const Bezier& b = part_[at_[best].piece];
    double lo = std::max(0.0, at_[best].t - 1.0 / kN), hi = std::min(1.0, at_[best].t + 1.0 / kN);
    auto f = [&](double t) {
      const Vec3 q = evaluate(b, t);
      return std::hypot(q.x - p.x, q.y - p.y);
    };
    for (int i = 0; i < 40; ++i) {
      const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
      (f(m1) < f(m2) ? hi : lo) = f(m1) < f(m2) ? m2 : m1;
    }
    return std::min(d, f(0.5 * (lo + hi)));
  }

 private:
  static constexpr int kN = 128;
  struct At {
    size_t piece;
    double t;
    Vec3 p;
  };
  std::vector<Bezier> part_;
  std::vector<At> at_;
};

// Every point of every cutting move at depth (plunges and tab steps are
// straight up and down), every 0.1 along it.
std::vector<Vec3> cut_points(const std::vector<MotionBlock>& run) {
  std::vector<Vec3> out;
  for (const MotionBlock& b : run) {
    if (b.from.x == b.to.x && b.from.y == b.to.y) continue;
    const double len = block_length(b);
    const int n = std::max(2, static_cast<int>(std::ceil(len / 0.1)));
    for (int i = 0; i <= n; ++i) out.push_back(evaluate_block(b, static_cast<double>(i) / n));
  }
  return out;
}

std::vector<Bezier> pieces_of(const std::string& entity) {
  return parse_job(R"({"bezcam":1,"entities":[)" + entity + "]}", "part.json").entities.at(0).curve.pieces;
}

// A circle of radius R about (cx, cy) as four rational quarters, and a
// regular hexagon, in either winding; the teardrop sample's cubics.
std::string circle(double cx, double cy, double R, bool ccw) {
  std::string segs;
  const double w = std::sqrt(0.5);
  for (int k = 0; k < 4; ++k) {
    const int a = ccw ? k : 4 - k, b = ccw ? k + 1 : 3 - k;
    auto pt = [&](double ang, double rr) {
      return "[" + std::to_string(cx + rr * std::cos(ang)) + "," + std::to_string(cy + rr * std::sin(ang)) + "]";
    };
    const double a0 = a * std::numbers::pi / 2, a1 = b * std::numbers::pi / 2;
    segs += std::string(k ? "," : "") + R"({"type":"bezier","weights":[1,)" + std::to_string(w) + R"(,1],"points":[)" +
            pt(a0, R) + "," + pt(0.5 * (a0 + a1), R / w) + "," + pt(a1, R) + "]}";
  }
  return R"({"type":"path","closed":true,"segments":[)" + segs + "]}";
}
std::string polygon(const std::vector<std::pair<double, double>>& pts, bool ccw) {
  std::vector<std::pair<double, double>> v = pts;
  if (!ccw) std::reverse(v.begin(), v.end());
  std::string segs;
  for (size_t i = 0; i < v.size(); ++i) {
    const auto& a = v[i];
    const auto& b = v[(i + 1) % v.size()];
    segs += std::string(i ? "," : "") + R"({"type":"bezier","points":[[)" + std::to_string(a.first) + "," +
            std::to_string(a.second) + "],[" + std::to_string(b.first) + "," + std::to_string(b.second) + "]]}";
  }
  return R"({"type":"path","closed":true,"segments":[)" + segs + "]}";
}
std::string teardrop(bool ccw) {
  const std::string a = R"({"type":"bezier","points":[[0,0],[20,10],[30,20],[30,30]]},)"
                        R"({"type":"bezier","points":[[30,30],[30,40],[20,45],[10,40]]},)"
                        R"({"type":"bezier","points":[[10,40],[0,35],[-10,20],[0,0]]})";
  const std::string b = R"({"type":"bezier","points":[[0,0],[-10,20],[0,35],[10,40]]},)"
                        R"({"type":"bezier","points":[[10,40],[20,45],[30,40],[30,30]]},)"
                        R"({"type":"bezier","points":[[30,30],[30,20],[20,10],[0,0]]})";
  return R"({"type":"path","closed":true,"segments":[)" + (ccw ? a : b) + "]}";
}

std::string glyph() {
  std::ifstream in(BEZCAM_SOURCE_DIR "/tests/cam/data/script-glyph.json");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Leads on the waste side for every side, direction and winding, on curved
// and polygonal contours, in lines and arcs output: every point the tool
// cuts at depth (leads included) is at least r less the tolerance from the
// part, the plunge is well away from it, and the lead-out mirrors the
// lead-in about the part's normal through the path's start.
TEST(PartCut, LeadsStayOnTheWasteSideForEverySideDirectionAndWinding) {
  const double r = 3, tol = 0.01;
  std::vector<std::pair<double, double>> hex;
  for (int k = 0; k < 6; ++k)
    hex.push_back({20 * std::cos(k * std::numbers::pi / 3), 20 * std::sin(k * std::numbers::pi / 3)});
  for (const bool ccw : {true, false}) {
    const std::map<std::string, std::string> contours{{"circle", circle(0, 0, 20, ccw)},
                                                      {"teardrop", teardrop(ccw)},
                                                      {"rectangle", polygon({{0, 0}, {40, 0}, {40, 30}, {0, 30}}, ccw)},
                                                      {"hexagon", polygon(hex, ccw)}};
    for (const auto& [name, entity] : contours) {
      const PartDistance to_part(pieces_of(entity));
      for (const char* side : {"outside", "inside", "left", "right"})
        for (const char* direction : {"climb", "conventional", "as-drawn"})
          for (const char* output : {"lines", "arcs"}) {
            SCOPED_TRACE(name + (ccw ? " ccw " : " cw ") + side + " " + direction + " " + output);
            const std::string json =
                R"({"bezcam":1,"tolerance":0.01,"job":{"feed":600,"plunge_feed":100,"safe_z":5,"cut_z":-1,)"
                R"("tool_diameter":6,"lead":{"radius":3,"length":2},"side":")" +
                std::string(side) + R"(","direction":")" + direction + R"("},"entities":[)" + entity + "]}";
            ConvertOptions opt;
            opt.output = std::string(output) == "arcs" ? OutputMode::arcs : OutputMode::lines;
            const Program p = build_program(parse_job(json, "leads.json"), load_machine_profile("generic"), opt);
            for (const auto& w : p.warnings) EXPECT_EQ(w.find("lead"), std::string::npos) << w;
            const auto runs = test::cutting_runs(program_motion(p));
            ASSERT_EQ(runs.size(), 1u);
            const auto& run = runs[0];
            ASSERT_GE(run.size(), 4u);
            double nearest = HUGE_VAL;
            for (const Vec3& q : cut_points(run)) nearest = std::min(nearest, to_part(q));
            EXPECT_GE(nearest, r - tol);
            const Vec3 a = run.front().to;  // the plunge: where the lead-in starts
            EXPECT_GE(to_part(a), r + 1);
            if (opt.output == OutputMode::arcs) {
              // A line, then the lead-in's arc to the path's start; the
              // lead-out's arc then its line end the run.
              const Vec3 s = run[2].to, b = run.back().to;
              EXPECT_EQ(run[2].kind == BlockKind::arc_cw || run[2].kind == BlockKind::arc_ccw, true);
              const double ds = to_part(s);
              EXPECT_NEAR(ds, r, tol);
              // The part's normal through s: from its nearest point (found
              // here by stepping against the gradient of the distance).
              const double h = 1e-4;
              Vec3 n{to_part({s.x + h, s.y, 0}) - to_part({s.x - h, s.y, 0}),
                     to_part({s.x, s.y + h, 0}) - to_part({s.x, s.y - h, 0}), 0};
              n = n * (1 / std::hypot(n.x, n.y));
              const Vec3 u = a - s, v = b - s;
              EXPECT_NEAR(std::hypot(u.x, u.y), std::hypot(v.x, v.y), 2e-3);
              EXPECT_NEAR(dot(u, n), dot(v, n), 2e-3);                             // as far out
              EXPECT_NEAR(u.x * n.y - u.y * n.x, -(v.x * n.y - v.y * n.x), 2e-3);  // on either side of the normal
            }
          }
    }
  }
}

// A closed contour whose clipped offset ends in a short stretch running
// back (a glyph of a script's logo): the lead-out leaves where the part's
// normal says, away from the part, as the lead-in comes in; it does not
// follow the last stretch's direction into the part.
TEST(PartCut, ALeadOutOnAClippedOffsetTurnsAwayFromThePart) {
  const std::string entity = glyph();
  const PartDistance to_part(pieces_of(entity));
  for (OutputMode mode : {OutputMode::lines, OutputMode::arcs}) {
    SCOPED_TRACE(to_string(mode));
    ConvertOptions opt;
    opt.output = mode;
    const Program p = build_program(
        parse_job(R"({"bezcam":1,"tolerance":0.01,"job":{"feed":600,"plunge_feed":100,"safe_z":5,"cut_z":-1,)"
                  R"("side":"outside","tool_diameter":6,"lead":{"radius":3,"length":2}},"entities":[)" +
                      entity + "]}",
                  "glyph.json"),
        load_machine_profile("generic"), opt);
    for (const auto& w : p.warnings) EXPECT_EQ(w.find("lead"), std::string::npos) << w;
    const auto runs = test::cutting_runs(program_motion(p));
    ASSERT_EQ(runs.size(), 1u);
    double nearest = HUGE_VAL;
    for (const Vec3& q : cut_points(runs[0])) nearest = std::min(nearest, to_part(q));
    EXPECT_GE(nearest, 3 - 0.01);
    EXPECT_GE(to_part(runs[0].back().to), 3 + 1);  // the lead-out ends away from the part
  }
}

// A lead that would cut into the part is never written: its line is made
// shorter where that is enough (said in a warning), and a lead whose arc
// does not fit is refused, naming the key and the radius that fits.
TEST(PartCut, ALeadTooBigForThePocketIsShortenedOrRefused) {
  // A 20 x 15 pocket: the tool's centre keeps to a 14 x 9 rectangle, from
  // (3, 3) to (17, 12); the lead joins the path in the middle of a long
  // side, at (10, 3) or (10, 12), and turns into the pocket.
  try {
    (void)build(R"("side":"inside","tool_diameter":6,"cut_z":-1,"lead":{"radius":8,"length":1})", rect(0, 0, 20, 15));
    ADD_FAILURE() << "a lead arc of radius 8 from the middle of a long side reaches x = 2";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "job.cut");
    EXPECT_EQ(e.where(), "test.json: job.lead");
    EXPECT_NE(std::string(e.what()).find("the lead-in at (10, "), std::string::npos)
        << e.what();  // a long side's middle
    EXPECT_NE(std::string(e.what()).find("would cut into the part"), std::string::npos) << e.what();
    // Its arc reaches x = 10 - R: a radius up to 7 fits, and a little more
    // (what the band leaves beside the lead's own chord error).
    const std::string what = e.what();
    const size_t at = what.find("a lead of radius ");
    ASSERT_NE(at, std::string::npos) << what;
    const double fits = std::stod(what.substr(at + 17));
    EXPECT_GE(fits, 7);
    EXPECT_LE(fits, 7.0075);
    EXPECT_NE(what.find(" and no line fits there: make it smaller"), std::string::npos) << what;
  }
  // In a 20 x 20 pocket (the tool's centre in a 14 x 14 square) a lead of
  // radius 2 fits at the middle of any side; a line of 14 after it would
  // reach 2 beyond the opposite side: it is made 12 long.
  const Program p =
      build(R"("side":"inside","tool_diameter":6,"cut_z":-1,"lead":{"radius":2,"length":14})", rect(0, 0, 20, 20));
  bool said = false;
  for (const auto& w : p.warnings) {
    const size_t at = w.find("the lead's line is made ");
    if (at == std::string::npos) continue;
    const double made = std::stod(w.substr(at + 24));
    EXPECT_GE(made, 12) << w;
    EXPECT_LE(made, 12.0075) << w;
    said = w.find(" long, not 14, at (") != std::string::npos &&
           w.find("): a longer one would cut into the part") != std::string::npos;
  }
  EXPECT_TRUE(said);
  const Cut c = cuts(p);
  ASSERT_EQ(c.plunges.size(), 1u);
  EXPECT_GE(dist_to_rect(c.plunges[0], 0, 0, 20, 20), 3 - 0.01);
  EXPECT_LE(dist_to_rect(c.plunges[0], 0, 0, 20, 20), 3);
  for (const auto& run : c.runs)
    for (const auto& v : run) EXPECT_GE(dist_to_rect(v, 0, 0, 20, 20), 3 - 0.0101);
  // Room enough: no word about the lead.
  const Program q =
      build(R"("side":"inside","tool_diameter":6,"cut_z":-1,"lead":{"radius":2,"length":1})", rect(0, 0, 40, 30));
  for (const auto& w : q.warnings) EXPECT_EQ(w.find("lead"), std::string::npos) << w;
}

// The entity's proven bound covers what is measured of it, its leads
// included (their arcs and lines are read against their own geometry) and
// the true offset where the path is clipped at inner corners (a point of it
// is one no nearer than r to the whole part: nearer, it is folded away).
TEST(PartCut, TheBoundCoversTheLeadsAndTheClippedCorners) {
  for (const char* machine : {"generic", "fanuc", "linuxcnc"})
    for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
      SCOPED_TRACE(std::string(machine) + " " + to_string(mode));
      ConvertOptions opt;
      opt.output = mode;
      const Program p = build_program(
          parse_job(R"({"bezcam":1,"tolerance":0.01,"job":{"feed":600,"plunge_feed":100,"safe_z":5,"cut_z":-1,)"
                    R"("side":"outside","tool_diameter":6,"lead":{"radius":3,"length":2}},"entities":[)" +
                        rect(0, 0, 40, 30) + "," + glyph() + "]}",
                    "bound.json"),
          load_machine_profile(machine), opt);
      ASSERT_EQ(p.entities.size(), 2u);
      for (const auto& e : p.entities) {
        EXPECT_GT(e.measured, 0) << e.label;
        EXPECT_LE(e.measured, e.bound) << e.label;
      }
    }
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
  const Program conv =
      build(R"("side":"outside","tool_diameter":6,"cut_z":-1,"direction":"conventional")", rect(0, 0, 40, 30));
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
  const Program p =
      build(R"("side":"outside","tool_diameter":6,"cut_z":-1,"tolerance_side":"waste")", rect(0, 0, 40, 30));
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
  const Program p =
      build(R"("side":"outside","tool_diameter":6,"cut_z":-1)", rect(0, 0, 40, 30, R"(,"tool_diameter":2)"));
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
  const Program p = build_program(with(R"({"count": 2, "width": 4, "height": 1})"), load_machine_profile("generic"),
                                  ConvertOptions{});
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
    (void)build_program(with(R"({"count": 20, "width": 4, "height": 1})"), load_machine_profile("generic"),
                        ConvertOptions{});
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
