// Flattening benchmark on the corpus (bench/corpus/cubics-10k.json):
// for tolerances 0.1, 0.01 and 0.001 mm, prints for bezcam's flattener (the
// band, its default, and with every vertex on the curve) and for cairo's
// (same process, same machine, so the speed is a ratio): curves per second,
// segments against the greedy maximal on-curve chord minimum (computed here
// by bisection on the exact chord deviation), curves over tolerance and the
// largest deviation as a fraction of the tolerance, both measured
// independently (flatten/deviation.hpp).
//
// Usage: flatten_bench [CORPUS.json] [--quick]   (--quick: every 10th curve)
//        flatten_bench [--quick] --only bezcam|cairo --tol T
//          runs one method once over the corpus inside run_only(), for
//          bench/flatten_instructions.sh (instruction counts under callgrind,
//          which machine load does not change); with --repeat N, N times
//          (for a sampling profiler: perf record).
//        flatten_bench [--quick] --only hash|hash-all
//          prints a fingerprint of the band flattener's vertices (hash-all:
//          also over space, rational and degree-4 pieces), for checking that
//          a change meant to be faster flattens exactly alike.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <vector>

#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"

#ifdef BEZCAM_HAVE_CAIRO
#include <cairo.h>
#endif

using namespace bezcam;
using Clock = std::chrono::steady_clock;

namespace {

struct Curve {
  Bezier b;
  std::string kind;
};

std::vector<Curve> load(const std::string& path, bool quick) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "flatten_bench: cannot read %s\n", path.c_str());
    std::exit(3);
  }
  nlohmann::json doc = nlohmann::json::parse(in);
  std::vector<Curve> out;
  const auto& cs = doc["curves"];
  for (size_t i = 0; i < cs.size(); ++i) {
    if (quick && i % 10) continue;
    std::vector<Vec3> pts;
    for (const auto& p : cs[i]) pts.push_back({p[0].get<double>(), p[1].get<double>()});
    out.push_back({Bezier::make(pts), doc["kinds"][i].get<std::string>()});
  }
  return out;
}

// Greedy maximal chords: from each on-curve vertex, the longest chord whose
// exact deviation is within tol (bisection to 1e-12 in t).
size_t greedy_count(const Bezier& b, double tol) {
  size_t n = 0;
  double t0 = 0;
  while (t0 < 1) {
    ++n;
    if (chord_deviation(b, t0, 1) <= tol) break;
    double lo = t0, hi = 1;
    while (hi - lo > 1e-12) {
      const double m = 0.5 * (lo + hi);
      (chord_deviation(b, t0, m) <= tol ? lo : hi) = m;
    }
    if (lo <= t0) lo = std::nextafter(t0, 2.0);
    t0 = lo;
  }
  return n;
}

#ifdef BEZCAM_HAVE_CAIRO
struct Cairo {
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  cairo_t* cr = cairo_create(s);
  ~Cairo() {
    cairo_destroy(cr);
    cairo_surface_destroy(s);
  }
  // CTM scaled by 1/tol so that cairo's device tolerance of 1 is tol in
  // user space and its 24.8 fixed point is tol/256.
  void flatten(const Bezier& b, double tol, std::vector<Vec3>& out) {
    cairo_identity_matrix(cr);
    cairo_scale(cr, 1 / tol, 1 / tol);
    cairo_set_tolerance(cr, 1.0);
    cairo_new_path(cr);
    const auto& p = b.points;
    cairo_move_to(cr, p[0].x, p[0].y);
    cairo_curve_to(cr, p[1].x, p[1].y, p[2].x, p[2].y, p[3].x, p[3].y);
    cairo_path_t* path = cairo_copy_path_flat(cr);
    out.clear();
    for (int i = 0; i < path->num_data; i += path->data[i].header.length)
      if (path->data[i].header.type == CAIRO_PATH_MOVE_TO || path->data[i].header.type == CAIRO_PATH_LINE_TO)
        out.push_back({path->data[i + 1].point.x, path->data[i + 1].point.y});
    cairo_path_destroy(path);
  }
};
#endif

struct Row {
  std::string method;
  double tol = 0;
  size_t segments = 0, over = 0;
  double worst = 0, us_per_curve = 0;
};

// Times several methods in interleaved rounds (so that a change of load on
// the machine hits all of them alike) and keeps each one's best round.
std::vector<double> time_us_per_curve(const std::vector<Curve>& cs,
                                      const std::vector<std::function<void(const Bezier&)>>& fs) {
  std::vector<double> best(fs.size(), 1e300);
  for (int rep = 0; rep < 7; ++rep)
    for (size_t k = 0; k < fs.size(); ++k) {
      const auto t0 = Clock::now();
      for (const auto& c : cs) fs[k](c.b);
      best[k] = std::min(best[k], std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
    }
  for (auto& b : best) b /= cs.size();
  return best;
}

}  // namespace

// One method, once over the corpus (callgrind collects inside this only).
// `pts` comes reserved, so that the heap's one-off work (the allocator
// consolidating what the corpus's parsing freed) is not counted.
__attribute__((noinline)) size_t run_only(const std::vector<Curve>& curves, const std::string& method, double tol,
                                          std::vector<Vec3>& pts) {
  size_t segments = 0;
  if (method == "bezcam") {
    for (const auto& c : curves) {
      pts.clear();
      flatten_into(std::span<const Bezier>(&c.b, 1), {tol, -1}, pts);
      segments += pts.size() - 1;
    }
  }
#ifdef BEZCAM_HAVE_CAIRO
  if (method == "cairo") {
    Cairo cairo;
    for (const auto& c : curves) {
      cairo.flatten(c.b, tol, pts);
      segments += pts.size() - 1;
    }
  }
#endif
  return segments;
}

// The corpus as one job:
// read from its JSON text, converted for the generic profile in lines at
// 0.01 mm with the independent measurement on (as `bezcam convert` does),
// written; wall-clock time of each step and the peak memory.
void whole_job(const std::vector<Curve>& curves) {
  std::string text = "{\"bezcam\": 1, \"units\": \"mm\", \"tolerance\": 0.01, \"entities\": [";
  char buf[96];
  for (size_t i = 0; i < curves.size(); ++i) {
    text += i ? ",\n" : "\n";
    text += "{\"type\": \"bezier\", \"points\": [";
    for (size_t k = 0; k < curves[i].b.points.size(); ++k) {
      std::snprintf(buf, sizeof buf, "%s[%.17g, %.17g]", k ? ", " : "", curves[i].b.points[k].x,
                    curves[i].b.points[k].y);
      text += buf;
    }
    text += "]}";
  }
  text += "]}\n";
  using clk = std::chrono::steady_clock;
  const auto t0 = clk::now();
  const bezcam::Job job = bezcam::parse_job(text, "corpus.json");
  const auto t1 = clk::now();
  const bezcam::MachineProfile m =
      bezcam::load_machine_profile(std::string(BEZCAM_SOURCE_DIR) + "/machines/generic.json", {});
  bezcam::ConvertOptions o;
  const bezcam::ConvertResult r = bezcam::convert(job, m, o);
  const auto t2 = clk::now();
  const double parse_s = std::chrono::duration<double>(t1 - t0).count();
  const double convert_s = std::chrono::duration<double>(t2 - t1).count();
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf(
      "\nwhole job: %zu curves as one job, generic, lines, 0.01 mm, measured: read %.3f s, build + measure + "
      "write %.3f s, total %.3f s (%.0f curves/s, target < 1 s for 10,000); %zu program bytes, largest "
      "deviation %.6f mm; peak memory %ld MB\n",
      curves.size(), parse_s, convert_s, parse_s + convert_s, curves.size() / (parse_s + convert_s), r.gcode.size(),
      r.program.max_measured, ru.ru_maxrss / 1024);
}

int main(int argc, char** argv) {
  std::string corpus = BEZCAM_CORPUS;
  bool quick = false;
  std::string only;
  double only_tol = 0.01;
  int repeat = 1;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[i], "--only") && i + 1 < argc)
      only = argv[++i];
    else if (!std::strcmp(argv[i], "--tol") && i + 1 < argc)
      only_tol = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else
      corpus = argv[i];
  }
  const auto curves = load(corpus, quick);
  if (only == "hash" || only == "hash-all") {
    // A fingerprint of every vertex the band flattener emits over the
    // corpus, for tolerances and decimals: two builds that print the same
    // hash flatten alike. "hash-all" adds, for every 10th curve, the same
    // curve lifted into space (z from x and y), made rational (inner
    // weights 2 and 1/2) and raised to degree 4: the pieces the general
    // search takes.
    std::vector<Bezier> extra;
    if (only == "hash-all")
      for (size_t i = 0; i < curves.size(); i += 10) {
        const Bezier& b = curves[i].b;
        std::vector<Vec3> p3 = b.points;
        for (auto& p : p3) p.z = 0.3 * p.x - 0.2 * p.y;
        extra.push_back(Bezier::make(p3, {}, 3));
        extra.push_back(Bezier::make(b.points, {1, 2, 0.5, 1}));
        extra.push_back(elevate(b));
      }
    unsigned long long h = 1469598103934665603ull;
    for (int dec : {-1, 3, 4})
      for (double tol : {0.1, 0.01, 0.001, 0.03}) {
        if (dec == 3 && tol < 0.005) continue;
        auto run = [&](const Bezier& b) {
          const double bound = flatten_pieces(std::span<const Bezier>(&b, 1), {tol, dec}, [&](const FlatVertex& v) {
            for (double d : {v.point.x, v.point.y, v.point.z, v.t}) {
              unsigned long long u;
              std::memcpy(&u, &d, 8);
              h = (h ^ u) * 1099511628211ull;
            }
          });
          unsigned long long u;
          std::memcpy(&u, &bound, 8);
          h = (h ^ u) * 1099511628211ull;
        };
        for (const auto& c : curves) run(c.b);
        for (const auto& b : extra) run(b);
      }
    std::printf("hash %llx\n", h);
    return 0;
  }
  if (!only.empty()) {
    std::vector<Vec3> pts;
    pts.reserve(1 << 16);
    size_t segments = 0;
    for (int r = 0; r < repeat; ++r) segments = run_only(curves, only, only_tol, pts);
    std::printf("%s tol %g: %zu segments\n", only.c_str(), only_tol, segments);
    return 0;
  }
  std::printf("corpus: %s, %zu curves%s\n\n", corpus.c_str(), curves.size(), quick ? " (quick: every 10th)" : "");
  std::printf(
      "| tol mm | method | segments | ratio to greedy | curves over tol | max dev / tol | us per curve | curves/s | "
      "speed vs cairo |\n");
  std::printf("|---:|---|---:|---:|---:|---:|---:|---:|---:|\n");
  std::vector<std::string> band_lines;
  auto fmt = [](double v, const char* f = "%g") {
    char buf[32];
    std::snprintf(buf, sizeof buf, f, v);
    return std::string(buf);
  };
  for (double tol : {0.1, 0.01, 0.001}) {
    size_t greedy = 0;
    for (const auto& c : curves) greedy += greedy_count(c.b, tol);
    std::vector<Row> rows;
    std::vector<Vec3> pts_b, pts_c;
    std::vector<std::function<void(const Bezier&)>> fs;
    const FlattenOptions band{.tolerance = tol, .decimals = -1};
    const FlattenOptions on_curve{.tolerance = tol, .decimals = -1, .on_curve = true};
    for (const FlattenOptions* o : {&band, &on_curve})
      fs.push_back([&, o](const Bezier& b) {
        pts_b.clear();
        flatten_into(std::span<const Bezier>(&b, 1), *o, pts_b);
      });
    // The documented call: a new result per curve, as a program using the
    // library writes it.
    size_t kept = 0;
    fs.push_back([&](const Bezier& b) { kept += flatten(b, band).points.size(); });
#ifdef BEZCAM_HAVE_CAIRO
    Cairo cairo;
    fs.push_back([&](const Bezier& b) { cairo.flatten(b, tol, pts_c); });
#endif
    const std::vector<double> us = time_us_per_curve(curves, fs);
    // bezcam: the band (default), then vertices on the curve
    for (int k = 0; k < 2; ++k) {
      Row r{k == 0 ? "bezcam band (default: vertices off the curve, proven band chords)"
                   : "bezcam on-curve (exact chord bound, greedy search)",
            tol};
      r.us_per_curve = us[k];
      for (const auto& c : curves) {
        const auto f = flatten(c.b, k == 0 ? band : on_curve);
        r.segments += f.points.size() - 1;
        const double d = measure_deviation(std::span<const Bezier>(&c.b, 1), f.points, tol).max();
        r.over += d > tol;
        r.worst = std::max(r.worst, d / tol);
      }
      rows.push_back(r);
    }
    {
      Row r = rows[0];
      r.method = "bezcam flatten() (the documented call: a new result per curve)";
      r.us_per_curve = us[2];
      rows.push_back(r);
    }
#ifdef BEZCAM_HAVE_CAIRO
    {
      Row r{"cairo copy_path_flat, CTM scaled by 1/tol", tol};
      std::vector<Vec3> pts;
      r.us_per_curve = us[3];
      for (const auto& c : curves) {
        cairo.flatten(c.b, tol, pts);
        r.segments += pts.size() - 1;
        const double d = measure_deviation(std::span<const Bezier>(&c.b, 1), pts, tol).max();
        r.over += d > tol;
        r.worst = std::max(r.worst, d / tol);
      }
      rows.push_back(r);
    }
#endif
    const double cairo_us = rows.size() > 3 ? rows[3].us_per_curve : 0;
    std::printf("| %g | greedy maximal on-curve chords (on-curve minimum) | %zu | 1.000 | 0 | - | - | - | - |\n", tol,
                greedy);
    for (const auto& r : rows)
      std::printf("| %g | %s | %zu | %.3f | %zu | %.4f | %.2f | %.0f | %s |\n", tol, r.method.c_str(), r.segments,
                  double(r.segments) / greedy, r.over, r.worst, r.us_per_curve, 1e6 / r.us_per_curve,
                  cairo_us > 0 ? (std::to_string(cairo_us / r.us_per_curve).substr(0, 4) + "x").c_str() : "-");
    band_lines.push_back("| " + fmt(tol) + " | " + std::to_string(rows[0].segments) + " | " + std::to_string(greedy) +
                         " | " + fmt(double(rows[0].segments) / greedy, "%.3f") + " | " + std::to_string(rows[0].over) +
                         " |");
    std::fflush(stdout);
  }
  std::printf("\nband against the on-curve greedy minimum (target <= 0.85 at 0.01 mm):\n\n");
  std::printf(
      "| tol mm | band segments | on-curve greedy | band / greedy | curves over tol |\n|---:|---:|---:|---:|---:|\n");
  for (const auto& l : band_lines) std::printf("%s\n", l.c_str());
  whole_job(curves);
  return 0;
}
