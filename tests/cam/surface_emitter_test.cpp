// Surface programs measured as the controller sees them: every sample is
// converted, printed, read back through the G-code reader, and the read
// blocks are checked against the true surface, independently of how they
// were made: each cutting point lies within the tolerance of the surface
// (for a ball-end tool: the ball centre is at distance r from it, on the
// upper side), neighbouring passes are never farther apart than the
// stepover, zigzag passes are the raster passes linked, the curve on a
// surface follows the mapped curve, and gouges are refused or skipped.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <tuple>

#include "bezcam/error.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/job/job_json.hpp"

namespace bezcam {
namespace {

const std::string kSamples = BEZCAM_SOURCE_DIR "/samples/";

struct Closest {
  double d = 1e300, u = 0, v = 0;
  Vec3 p;
};

// Nearest point of the surface to x by damped Newton on |S(u,v) - x|^2,
// clamped to the parameter square, from (u, v).
Closest newton(const SurfaceGeometry& s, const Vec3& x, double u, double v) {
  Closest c;
  for (int it = 0; it < 40; ++it) {
    const PatchDerivs d = evaluate_derivs(s, u, v);
    const Vec3 e = d.p - x;
    const double f = dot(e, e);
    c = {std::sqrt(f), u, v, d.p};
    const double gu = dot(d.su, e), gv = dot(d.sv, e);
    const double a = dot(d.su, d.su) + dot(d.suu, e), b = dot(d.su, d.sv) + dot(d.suv, e),
                 cc = dot(d.sv, d.sv) + dot(d.svv, e);
    double det = a * cc - b * b, du, dv;
    if (det > 1e-12 * (a * cc) && a > 0) {
      du = -(cc * gu - b * gv) / det;
      dv = -(a * gv - b * gu) / det;
    } else {  // gradient step
      const double k = 1 / std::max(dot(d.su, d.su) + dot(d.sv, d.sv), 1e-300);
      du = -gu * k, dv = -gv * k;
    }
    double step = 1;
    bool moved = false;
    for (int h = 0; h < 30; ++h, step *= 0.5) {
      const double nu = std::clamp(u + step * du, 0.0, 1.0), nv = std::clamp(v + step * dv, 0.0, 1.0);
      const Vec3 q = evaluate(s, nu, nv);
      if (dot(q - x, q - x) < f) {
        moved = std::abs(nu - u) + std::abs(nv - v) > 1e-15;
        u = nu, v = nv;
        break;
      }
    }
    if (!moved) break;
  }
  return c;
}

Closest closest(const SurfaceGeometry& s, const Vec3& x, double u0 = -1, double v0 = -1) {
  Closest best;
  if (u0 >= 0) best = newton(s, x, u0, v0);
  // A coarse grid search as well when the warm start is not clearly right.
  constexpr int n = 16;
  Closest grid;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double d = dist(evaluate(s, double(i) / n, double(j) / n), x);
      if (d < grid.d) grid = {d, double(i) / n, double(j) / n, {}};
    }
  const Closest g = newton(s, x, grid.u, grid.v);
  return g.d < best.d ? g : best;
}

struct Read {
  Job job;
  MachineProfile m;
  ConvertResult r;
  std::vector<MotionBlock> blocks;
};

Read convert_and_read(Job job, const std::string& machine = "") {
  Read x{std::move(job), {}, {}, {}};
  x.m = load_machine_profile(machine.empty() ? x.job.machine.value_or("generic") : machine);
  x.r = convert(x.job, x.m, ConvertOptions{});
  x.blocks = read_gcode(x.r.gcode, &x.m);
  return x;
}

// Cutting runs of one entity: feed moves between rapids, plunge dropped.
// Each block gives its end point, or with `chord` > 0 its points sampled
// that densely (NURBS blocks as the reader evaluates them).
std::vector<std::vector<Vec3>> runs_of(const Read& x, double feed, double chord = 0) {
  std::vector<std::vector<Vec3>> runs;
  bool in = false;
  for (const auto& b : x.blocks) {
    if (b.kind == BlockKind::rapid) {
      in = false;
      continue;
    }
    if (b.feed != feed) continue;  // plunges, other entities
    if (!in) runs.push_back({b.from});
    in = true;
    if (chord > 0) {
      const auto pts = sample_block(b, chord);
      runs.back().insert(runs.back().end(), pts.begin() + 1, pts.end());
    } else {
      runs.back().push_back(b.to);
    }
  }
  return runs;
}

// Every cutting point (vertices and chord points between them) of a
// surface entity is where it must be: tip on the surface within the
// tolerance (r = 0), or the ball centre tip + r z at distance r within the
// tolerance and above the surface (r > 0). Returns the largest error.
// `vertices_only`: the vertices alone (points sampled on exact-curve blocks).
double check_on_surface(const SurfaceGeometry& s, const std::vector<std::vector<Vec3>>& runs, double r, double tol,
                        bool vertices_only = false) {
  double worst = 0;
  const std::vector<double> at = vertices_only ? std::vector<double>{0.0} : std::vector<double>{0.0, 0.25, 0.5, 0.75};
  for (const auto& run : runs) {
    double u = -1, v = -1;
    for (size_t i = 0; i + 1 < run.size(); ++i)
      for (double f : at) {
        const Vec3 c = lerp(run[i], run[i + 1], f) + Vec3{0, 0, r};
        Closest k = newton(s, c, u < 0 ? 0.5 : u, v < 0 ? 0.5 : v);
        if (u < 0 || std::abs(k.d - r) > tol) k = closest(s, c, u, v);
        u = k.u, v = k.v;
        worst = std::max(worst, std::abs(k.d - r));
        if (r > 0) EXPECT_GT(dot(c - k.p, unit_normal(s, k.u, k.v)), 0) << "ball centre below the surface";
      }
  }
  return worst;
}

double dist_to_poly(const Vec3& x, const std::vector<Vec3>& p) {
  double m = 1e300;
  for (size_t i = 0; i + 1 < p.size(); ++i) m = std::min(m, dist_to_segment(x, p[i], p[i + 1]));
  return p.size() == 1 ? dist(x, p[0]) : m;
}

double brute_gap(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double step) {
  double g = 0;
  for (int side = 0; side < 2; ++side) {
    const auto& x = side ? b : a;
    const auto& y = side ? a : b;
    for (size_t i = 0; i + 1 < x.size(); ++i) {
      const int n = 1 + static_cast<int>(dist(x[i], x[i + 1]) / step);
      for (int k = 0; k <= n; ++k) g = std::max(g, dist_to_poly(lerp(x[i], x[i + 1], double(k) / n), y));
    }
  }
  return g;
}

struct SampleCase {
  const char* file;
  size_t entity;
};
const SampleCase kPatchSamples[] = {{"patch-saddle.json", 0},
                                    {"patch-bonnet-bicubic.json", 0},
                                    {"patch-coons-curved.json", 0},
                                    {"job-curve-on-surface.json", 0}};

TEST(SurfaceProgram, EveryPassLiesWithinTheToleranceOfTheSurface) {
  for (const auto& sc : kPatchSamples) {
    SCOPED_TRACE(sc.file);
    const Read x = convert_and_read(load_job(kSamples + sc.file));
    const Entity& e = x.job.entities[sc.entity];
    const CutParams cp = cut_params(x.job, e, x.m);
    const auto runs = runs_of(x, quantize(cp.feed, x.m.feed_decimals));
    ASSERT_FALSE(runs.empty());
    const double worst = check_on_surface(*e.surface, runs, cp.tool_radius, x.job.tolerance);
    EXPECT_LE(worst, x.job.tolerance);
    // The report agrees: bound within tolerance, measured within bound.
    const EntityReport& rep = x.r.program.entities[sc.entity];
    EXPECT_LE(rep.bound, x.job.tolerance);
    EXPECT_LE(rep.measured, rep.bound + 1e-7);
    size_t cut_blocks = 0;
    for (const auto& run : runs) cut_blocks += run.size() - 1;
    EXPECT_EQ(cut_blocks, rep.blocks);
  }
}

// The sample jobs as raster passes: each pass is one run between a plunge
// and a retract, so neighbours can be compared run by run.
Job as_raster(Job job, size_t entity) {
  job.entities[entity].toolpath.pattern = "raster";
  return job;
}

TEST(SurfaceProgram, NeighbouringPassesAreNeverFartherApartThanTheStepover) {
  for (const auto& sc : kPatchSamples) {
    SCOPED_TRACE(sc.file);
    const Read x = convert_and_read(as_raster(load_job(kSamples + sc.file), sc.entity));
    const Entity& e = x.job.entities[sc.entity];
    const double stepover = *e.toolpath.stepover;
    const auto runs = runs_of(x, quantize(cut_params(x.job, e, x.m).feed, x.m.feed_decimals));
    ASSERT_GE(runs.size(), 10u);
    double worst = 0;
    for (size_t i = 0; i + 1 < runs.size(); ++i)
      worst = std::max(worst, brute_gap(runs[i], runs[i + 1], stepover / 40));
    EXPECT_LE(worst, stepover);
    EXPECT_GE(worst, 0.8 * stepover);  // and the passes are not needlessly dense
    RecordProperty(std::string(sc.file) + ".passes", static_cast<int>(runs.size()));
  }
}

TEST(SurfaceProgram, ZigzagIsTheRasterPassesLinkedAlongTheBorder) {
  const Job job = load_job(kSamples + "patch-saddle.json");
  const Read zig = convert_and_read(job);
  const Read ras = convert_and_read(as_raster(job, 0));
  const double feed = quantize(cut_params(job, job.entities[0], zig.m).feed, zig.m.feed_decimals);
  const auto zr = runs_of(zig, feed), rr = runs_of(ras, feed);
  ASSERT_EQ(zr.size(), 1u);  // one plunge, one continuous cut
  const std::vector<Vec3>& path = zr[0];
  size_t at = 0;
  for (size_t k = 0; k < rr.size(); ++k) {
    std::vector<Vec3> pass = rr[k];
    if (k % 2) std::reverse(pass.begin(), pass.end());
    // The pass appears whole, in order, after the previous one.
    auto it = std::search(path.begin() + static_cast<std::ptrdiff_t>(at), path.end(), pass.begin(), pass.end());
    ASSERT_NE(it, path.end()) << "pass " << k;
    const size_t start = static_cast<size_t>(it - path.begin());
    // Links are short: along the border, about one stepover.
    if (k > 0) {
      double link = 0;
      for (size_t i = at; i < start; ++i) link += dist(path[i], path[i + 1]);
      EXPECT_LE(link, 2.0 * 1.05) << "pass " << k;
    }
    at = start + pass.size() - 1;
  }
  EXPECT_EQ(at, path.size() - 1);
}

TEST(SurfaceProgram, CurveOnASurfaceFollowsTheMappedCurve) {
  const Read x = convert_and_read(load_job(kSamples + "job-curve-on-surface.json"));
  const Entity& e = x.job.entities[1];
  ASSERT_EQ(e.type, "curve_on_surface");
  EXPECT_EQ(e.surface, x.job.entities[0].surface);  // the wing, by id
  const auto runs = runs_of(x, quantize(cut_params(x.job, e, x.m).feed, x.m.feed_decimals));
  ASSERT_EQ(runs.size(), 1u);
  // S(c(w)) sampled densely, straight from the surface and the uv path.
  std::vector<Vec3> dense;
  for (const auto& piece : e.uv_curve.pieces)
    for (int k = 0; k <= 4000; ++k) {
      const Vec3 uv = evaluate(piece, k / 4000.0);
      dense.push_back(evaluate(*e.surface, uv.x, uv.y));
    }
  const double tol = x.job.tolerance;
  double worst = 0;
  for (size_t i = 0; i + 1 < runs[0].size(); ++i)
    for (double f : {0.0, 0.5}) worst = std::max(worst, dist_to_poly(lerp(runs[0][i], runs[0][i + 1], f), dense));
  for (size_t k = 0; k < dense.size(); k += 7) worst = std::max(worst, dist_to_poly(dense[k], runs[0]));
  EXPECT_LE(worst, tol + 1e-4);
  EXPECT_LE(check_on_surface(*e.surface, runs, 0, tol), tol);
  // It starts and ends on the wing's lower border (v = 0) at u = 0.25, 0.75.
  EXPECT_LE(dist(runs[0].front(), evaluate(*e.surface, 0.25, 0)), 0.001);
  EXPECT_LE(dist(runs[0].back(), evaluate(*e.surface, 0.75, 0)), 0.001);
}

// A bowl: the paraboloid z = (x^2 + y^2) / 40 over [-30, 30]^2 (curvature
// radius 20 at the bottom), cut with a ball of radius `r`.
Job bowl(double r, const char* gouge) {
  std::string pts = "[";
  const double x[3] = {-30, 0, 30}, z[3] = {22.5, -22.5, 22.5};
  for (int i = 0; i < 3; ++i) {
    pts += i ? ",[" : "[";
    for (int j = 0; j < 3; ++j)
      pts += (j ? "," : "") + std::string("[") + std::to_string(x[i]) + "," + std::to_string(x[j]) + "," +
             std::to_string(z[i] + z[j] + 20) + "]";
    pts += "]";
  }
  pts += "]";
  const std::string text = R"({"bezcam": 1, "units": "mm", "tolerance": 0.01, "machine": "generic",
    "job": {"feed": 1000, "plunge_feed": 200, "safe_z": 90, "tool_radius": )" +
                           std::to_string(r) + (gouge ? std::string(R"(, "gouge": ")") + gouge + "\"" : "") + R"(},
    "entities": [{"id": "bowl", "type": "bezier_patch", "points": )" +
                           pts + R"(, "toolpath": {"stepover": 3}}]})";
  return parse_job(text, "bowl.json");
}

TEST(SurfaceProgram, GougesAreRefusedNamingEntityUAndV) {
  for (const char* policy : {static_cast<const char*>(nullptr), "refuse"}) {
    try {
      convert(bowl(25, policy), load_machine_profile("generic"), ConvertOptions{});
      FAIL() << "no refusal";
    } catch (const InputError& e) {
      EXPECT_EQ(e.id(), "surface.gouge");
      EXPECT_EQ(e.where(), "bowl.json: entities[0]");
      EXPECT_NE(e.message().find("around u = 0.5, v = "), std::string::npos) << e.message();
      EXPECT_NE(e.message().find("less than the ball-end radius 25"), std::string::npos) << e.message();
      EXPECT_NE(e.message().find("\"gouge\": \"skip\""), std::string::npos) << e.message();
    }
  }
  // A tool smaller than the tightest valley cuts the whole bowl.
  EXPECT_NO_THROW(convert(bowl(19, nullptr), load_machine_profile("generic"), ConvertOptions{}));
}

TEST(SurfaceProgram, SkippedGougeRegionsAreLeftUncutAndTheRestIsSafe) {
  const double r = 25;
  const Read x = convert_and_read(bowl(r, "skip"));
  const Entity& e = x.job.entities[0];
  const auto runs = runs_of(x, 1000);
  ASSERT_GT(runs.size(), 3u);  // the tool lifts over the bottom
  // Nothing cut is a gouge: every ball centre is r away from the bowl.
  EXPECT_LE(check_on_surface(*e.surface, runs, r, x.job.tolerance), x.job.tolerance);
  // The bottom is left: the ball touches the bowl (at its nearest point)
  // only outside the disc where the curvature radius is below 25,
  // |(x, y)| < sqrt(25^2 - 20^2) = 15.
  for (const auto& run : runs)
    for (const auto& p : run) {
      const Closest k = closest(*e.surface, p + Vec3{0, 0, r});
      EXPECT_GT(std::hypot(k.p.x, k.p.y), 15 - 0.05) << p.x << " " << p.y;
    }
  bool warned = false;
  for (const auto& w : x.r.program.warnings) warned = warned || w.find("left uncut") != std::string::npos;
  EXPECT_TRUE(warned);
  size_t skips = 0;
  for (size_t i = x.r.gcode.find("(skipped pass"); i != std::string::npos; i = x.r.gcode.find("(skipped pass", i + 1))
    ++skips;
  EXPECT_GE(skips, 5u);
}

TEST(SurfaceProgram, BoundaryPatternCutsTheFourBordersInOneLoop) {
  Job job = load_job(kSamples + "patch-coons-curved.json");
  job.entities[0].toolpath.pattern = "boundary";
  const Read x = convert_and_read(job);
  const Entity& e = x.job.entities[0];
  const CutParams cp = cut_params(x.job, e, x.m);
  const auto runs = runs_of(x, quantize(cp.feed, x.m.feed_decimals));
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].front(), runs[0].back());  // closed
  EXPECT_LE(check_on_surface(*e.surface, runs, cp.tool_radius, x.job.tolerance), x.job.tolerance);
  // Every border point is near the loop (ball tips: compare tip curves).
  const SurfaceGeometry& s = *e.surface;
  for (int k = 0; k <= 40; ++k) {
    const double t = k / 40.0;
    for (auto [u, v] : {std::pair{t, 0.0}, {1.0, t}, {t, 1.0}, {0.0, t}}) {
      const Vec3 tip = evaluate(s, u, v) + (unit_normal(s, u, v) - Vec3{0, 0, 1}) * cp.tool_radius;
      EXPECT_LE(dist_to_poly(tip, runs[0]), x.job.tolerance + 1e-6);
    }
  }
}

Read convert_and_read(Job job, const std::string& machine, OutputMode mode) {
  Read x{std::move(job), {}, {}, {}};
  x.m = load_machine_profile(machine);
  ConvertOptions o;
  o.output = mode;
  x.r = convert(x.job, x.m, o);
  x.blocks = read_gcode(x.r.gcode, &x.m);
  return x;
}

size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
  return n;
}

// Nurbs output on a profile with 3D NURBS blocks (Fanuc G06.2): every
// surface sample takes fewer blocks than as G01 lines, the report's
// independent measurement of the printed blocks and the reader's own
// evaluation of them are within the tolerance, and neighbouring passes as
// printed stay within the stepover.
// The saddle's raster passes as printed blocks on `machine` in `mode`:
// neighbours within the stepover (the sampled polylines stray from the
// blocks by at most `chord` each).
void expect_saddle_raster_within_stepover(const char* machine, OutputMode mode) {
  const Job saddle = as_raster(load_job(kSamples + "patch-saddle.json"), 0);
  const Read x = convert_and_read(saddle, machine, mode);
  const double stepover = *saddle.entities[0].toolpath.stepover, chord = 0.01;
  const auto runs = runs_of(x, quantize(cut_params(saddle, saddle.entities[0], x.m).feed, x.m.feed_decimals), chord);
  ASSERT_GE(runs.size(), 10u);
  double worst = 0;
  for (size_t i = 0; i + 1 < runs.size(); i += 3)
    worst = std::max(worst, brute_gap(runs[i], runs[i + 1], stepover / 20));
  EXPECT_LE(worst, stepover + 2 * chord);
}

TEST(SurfaceProgram, NurbsBlocksOnFanucTakeFewerBlocksThanLinesWithinTolerance) {
  for (const auto& sc : kPatchSamples) {
    SCOPED_TRACE(sc.file);
    const Job job = load_job(kSamples + sc.file);
    const Read lines = convert_and_read(job, "fanuc", OutputMode::lines);
    const Read nurbs = convert_and_read(job, "fanuc", OutputMode::nurbs);
    const Entity& e = job.entities[sc.entity];
    const EntityReport& ln = lines.r.program.entities[sc.entity];
    const EntityReport& nb = nurbs.r.program.entities[sc.entity];
    EXPECT_LT(nb.blocks, ln.blocks);
    RecordProperty(std::string(sc.file) + ".lines", static_cast<int>(ln.blocks));
    RecordProperty(std::string(sc.file) + ".nurbs", static_cast<int>(nb.blocks));
    EXPECT_GT(count_of(nurbs.r.gcode, "G06.2"), 0u);
    EXPECT_LE(nb.bound, job.tolerance);
    EXPECT_GT(nb.measured, 0);
    EXPECT_LE(nb.measured, job.tolerance * 1.001);
    for (const auto& w : nurbs.r.program.warnings) EXPECT_EQ(w.find("G01 lines"), std::string::npos) << w;
    const CutParams cp = cut_params(job, e, nurbs.m);
    // Points of the blocks as the reader evaluates them, a few per tolerance of sag.
    const auto runs = runs_of(nurbs, quantize(cp.feed, nurbs.m.feed_decimals), job.tolerance / 2);
    ASSERT_FALSE(runs.empty());
    EXPECT_LE(check_on_surface(*e.surface, runs, cp.tool_radius, job.tolerance, true), job.tolerance);
  }
  // Raster passes as printed blocks: neighbours within the stepover.
  expect_saddle_raster_within_stepover("fanuc", OutputMode::nurbs);
  // The boundary pattern: four borders, each its blocks, still one loop.
  Job coons = load_job(kSamples + "patch-coons-curved.json");
  coons.entities[0].toolpath.pattern = "boundary";
  const Read b = convert_and_read(coons, "fanuc", OutputMode::nurbs);
  const Read bl = convert_and_read(coons, "fanuc", OutputMode::lines);
  EXPECT_LT(b.r.program.entities[0].blocks, bl.r.program.entities[0].blocks);
  const CutParams bcp = cut_params(coons, coons.entities[0], b.m);
  const auto loop = runs_of(b, quantize(bcp.feed, b.m.feed_decimals), coons.tolerance / 2);
  ASSERT_EQ(loop.size(), 1u);
  EXPECT_LE(dist(loop[0].front(), loop[0].back()), 0.0011);
  EXPECT_LE(check_on_surface(*coons.entities[0].surface, loop, bcp.tool_radius, coons.tolerance, true),
            coons.tolerance);
}

// A deliberately wrong block is caught by the reader-side check: one
// control point of a printed G06.2 block moved by 0.2 mm.
TEST(SurfaceProgram, AWrongNurbsBlockIsCaught) {
  const Job job = load_job(kSamples + "patch-saddle.json");
  Read x = convert_and_read(job, "fanuc", OutputMode::nurbs);
  const Entity& e = job.entities[0];
  const CutParams cp = cut_params(job, e, x.m);
  const double feed = quantize(cp.feed, x.m.feed_decimals);
  // The second control point line of the first block: "N.. X.. Y.. Z.. R.. K.."
  std::string text = x.r.gcode;
  size_t at = text.find("G06.2");
  ASSERT_NE(at, std::string::npos);
  at = text.find('\n', at) + 1;
  const size_t z = text.find(" Z", at);
  ASSERT_LT(z, text.find('\n', at));
  const size_t end = text.find(' ', z + 1);
  const double v = std::stod(text.substr(z + 2, end - z - 2));
  text.replace(z + 2, end - z - 2, fmt_num(v + 0.2));
  x.blocks = read_gcode(text, &x.m);
  // The moved block (in the first run) leaves the surface by far more than
  // the tolerance; the same check passes every sample's true blocks (above).
  const auto runs = runs_of(x, feed, 0.005);
  ASSERT_FALSE(runs.empty());
  EXPECT_GT(check_on_surface(*e.surface, {runs.front()}, cp.tool_radius, job.tolerance, true), 0.02);
}

// Arcs output: every surface sample takes fewer blocks than as G01 lines,
// as G02/G03 arcs in G17, G18 or G19 (helical where the run climbs); the
// program read back by the reader lies on the surface within the tolerance
// (the arcs sampled as the reader evaluates them), the report's bound and
// independent measurement are within it, and raster passes as printed
// stay within the stepover.
TEST(SurfaceProgram, ArcsInThreePlanesTakeFewerBlocksThanLinesWithinTolerance) {
  for (const auto& sc : kPatchSamples) {
    SCOPED_TRACE(sc.file);
    const Job job = load_job(kSamples + sc.file);
    const std::string machine = job.machine.value_or("generic");
    const Read lines = convert_and_read(job, machine, OutputMode::lines);
    const Read arcs = convert_and_read(job, machine, OutputMode::arcs);
    const Entity& e = job.entities[sc.entity];
    const EntityReport& ln = lines.r.program.entities[sc.entity];
    const EntityReport& ar = arcs.r.program.entities[sc.entity];
    EXPECT_LT(ar.blocks, ln.blocks);
    RecordProperty(std::string(sc.file) + ".arcs", static_cast<int>(ar.blocks));
    size_t read_arcs = 0, helical = 0, other_planes = 0;
    for (const auto& b : arcs.blocks) {
      if (b.kind != BlockKind::arc_cw && b.kind != BlockKind::arc_ccw) continue;
      ++read_arcs;
      const int h = world_axis(b.plane, 2);
      helical += b.from[h] != b.to[h];
      other_planes += b.plane != Plane::xy;
    }
    EXPECT_GT(read_arcs, 0u);
    if (sc.file == std::string("patch-saddle.json")) EXPECT_GT(other_planes, 0u);  // passes along Y: G19
    RecordProperty(std::string(sc.file) + ".helical", static_cast<int>(helical));
    EXPECT_LE(ar.bound, job.tolerance);
    EXPECT_GT(ar.measured, 0);
    EXPECT_LE(ar.measured, job.tolerance * 1.001);
    for (const auto& w : arcs.r.program.warnings) EXPECT_EQ(w.find("G01 lines"), std::string::npos) << w;
    const CutParams cp = cut_params(job, e, arcs.m);
    const auto runs = runs_of(arcs, quantize(cp.feed, arcs.m.feed_decimals), job.tolerance / 2);
    ASSERT_FALSE(runs.empty());
    EXPECT_LE(check_on_surface(*e.surface, runs, cp.tool_radius, job.tolerance, true), job.tolerance);
  }
  expect_saddle_raster_within_stepover("generic", OutputMode::arcs);
}

// A pass that turns half a helix round Y spreads least along Z (the arch
// rises 27 along Z, its control points run 40 along X and 58 along Y), so
// the least-spread plane is G17, where it fits no arc; the other planes are
// tried then, and its passes are cut as helical G18 arcs, fewer blocks than
// lines, within the tolerance measured independently and on the surface.
TEST(SurfaceProgram, APassTurningRoundYTakesG18ArcsThoughItSpreadsLeastAlongZ) {
  const std::string text = R"({"bezcam": 1, "units": "mm", "tolerance": 0.01,
    "job": {"feed": 1000, "plunge_feed": 300, "safe_z": 40, "tool_radius": 0},
    "entities": [{"id": "twisted-arch", "type": "bezier_patch", "points": [
      [[20, 0, 0], [20, 8, 0]],
      [[20, 16.6667, 26.6667], [20, 24.6667, 26.6667]],
      [[-20, 33.3333, 26.6667], [-20, 41.3333, 26.6667]],
      [[-20, 50, 0], [-20, 58, 0]]],
      "toolpath": {"pattern": "zigzag", "direction": "u", "stepover": 4}}]})";
  const Job job = parse_job(text, "twisted-arch.json");
  ASSERT_EQ(least_climb_plane(std::vector<Bezier>{
                Bezier::make({{20, 0, 0}, {20, 16.6667, 26.6667}, {-20, 33.3333, 26.6667}, {-20, 50, 0}}, {}, 3)}),
            Plane::xy);
  const Read lines = convert_and_read(job, "generic", OutputMode::lines);
  const Read arcs = convert_and_read(job, "generic", OutputMode::arcs);
  const EntityReport& ln = lines.r.program.entities[0];
  const EntityReport& ar = arcs.r.program.entities[0];
  size_t g18 = 0, others = 0;
  for (const auto& b : arcs.blocks) {
    if (b.kind != BlockKind::arc_cw && b.kind != BlockKind::arc_ccw) continue;
    (b.plane == Plane::zx ? g18 : others) += 1;
  }
  EXPECT_GT(g18, 0u);
  EXPECT_EQ(others, 0u);
  EXPECT_LT(2 * ar.blocks, ln.blocks);
  EXPECT_LE(ar.bound, job.tolerance);
  EXPECT_GT(ar.measured, 0);
  EXPECT_LE(ar.measured, job.tolerance * 1.001);
  const CutParams cp = cut_params(job, job.entities[0], arcs.m);
  const auto runs = runs_of(arcs, quantize(cp.feed, arcs.m.feed_decimals), job.tolerance / 2);
  ASSERT_FALSE(runs.empty());
  EXPECT_LE(check_on_surface(*job.entities[0].surface, runs, cp.tool_radius, job.tolerance, true), job.tolerance);
}

// Where the dialect cannot carry a 3D block (LinuxCNC's G5.x move in X and
// Y), or the machine takes no arcs, passes stay G01 lines and a warning says
// why, once per entity.
TEST(SurfaceProgram, LinesWhereNoBlockCanCarryAPassAndSaidSo) {
  const Job job = load_job(kSamples + "patch-saddle.json");
  for (auto [machine, mode, why] : {std::tuple{"linuxcnc", OutputMode::nurbs, "move in X and Y only"},
                                    std::tuple{"generic", OutputMode::nurbs, "has no NURBS words"}}) {
    SCOPED_TRACE(machine);
    const Read x = convert_and_read(job, machine, mode);
    size_t said = 0;
    for (const auto& w : x.r.program.warnings) said += w.find(why) != std::string::npos;
    EXPECT_EQ(said, 1u);
    for (const auto& mv : x.r.program.moves) EXPECT_FALSE(std::holds_alternative<CurveMove>(mv.what));
    const Read l = convert_and_read(job, machine, OutputMode::lines);
    EXPECT_EQ(x.r.program.entities[0].blocks, l.r.program.entities[0].blocks);
  }
}

TEST(SurfaceProgram, TravelLimitsAndSafeZAreEnforced) {
  // The bonnet fits UNISURF's 1500 x 1200 mm; moved 400 mm it does not.
  Job job = load_job(kSamples + "patch-bonnet-bicubic.json");
  EXPECT_NO_THROW(convert(job, load_machine_profile("unisurf"), ConvertOptions{}));
  std::string text = R"({"bezcam": 1, "tolerance": 0.05, "job": {"feed": 2000, "plunge_feed": 500,
    "safe_z": 50, "tool_radius": 10}, "entities": [{"type": "bezier_patch", "points":
    [[[400, -100, 0], [400, 100, 0]], [[800, -100, 10], [800, 100, 10]]], "toolpath": {"stepover": 8}}]})";
  try {
    convert(parse_job(text, "far.json"), load_machine_profile("unisurf"), ConvertOptions{});
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "program.travel");
  }
  text.replace(text.find("\"safe_z\": 50"), 12, "\"safe_z\": 5");
  try {
    convert(parse_job(text, "low.json"), load_machine_profile("generic"), ConvertOptions{});
    FAIL() << "no refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "job.above-safe-z");
    EXPECT_NE(e.message().find("the surface rises to z = 10"), std::string::npos) << e.message();
  }
}

}  // namespace
}  // namespace bezcam
