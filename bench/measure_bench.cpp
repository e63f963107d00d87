// The independent deviation measurement alone, one thread, on the
// corpus (bench/corpus/cubics-10k.json): every curve flattened at each
// tolerance (the program's polyline), then measure_deviation() timed over
// all of them. Prints curves/s, segments/s and the largest readings.
// Then pieces without a power form (rational, degree > 3), generated from a
// fixed seed: circular arcs (rational quadratics, as a DXF's), measured
// against their flattening and against a dense one (a printed arc read
// back as chords, as arcs output does), and random pieces of degree 5 and
// 16, polynomial and rational.
//
//   build/measure_bench [--quick] [CORPUS.json]
//
// --quick: the first 1,000 curves. Figures only: nothing is asserted.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"

namespace {

// The pieces measured against their polylines, one thread: a table row.
void time_row(const char* what, const std::vector<bezcam::Bezier>& pieces,
              const std::vector<std::vector<bezcam::Vec3>>& polys, double tol) {
  size_t segs = 0;
  for (const auto& p : polys) segs += p.size() - 1;
  bezcam::Deviation worst;
  const auto t0 = std::chrono::steady_clock::now();
  for (size_t i = 0; i < pieces.size(); ++i) {
    const bezcam::Deviation d =
        bezcam::measure_deviation(std::span<const bezcam::Bezier>(&pieces[i], 1), polys[i], tol);
    worst.curve_to_path = std::max(worst.curve_to_path, d.curve_to_path);
    worst.path_to_curve = std::max(worst.path_to_curve, d.path_to_curve);
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("| %s | %zu | %zu | %.3f | %.0f | %.0f | %.6g | %.6g |\n", what, pieces.size(), segs, s,
              pieces.size() / s, segs / s, worst.curve_to_path, worst.path_to_curve);
}

void other_pieces() {
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> u(0, 1);
  const double tol = 0.01;
  std::printf("\npieces without a power form, tolerance %g mm, one thread\n\n", tol);
  std::printf(
      "| pieces | count | segments | s | pieces/s | segments/s | largest curve->path | largest path->curve |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|\n");
  // Circular arcs: radius 1 to 50 mm, sweep up to 90 degrees either way.
  std::vector<bezcam::Bezier> arcs;
  for (int k = 0; k < 2000; ++k) {
    const bezcam::Vec3 c{100 * u(rng), 100 * u(rng)};
    const double r = 1 + 49 * u(rng), a0 = 6.283185307179586 * u(rng), sw = (u(rng) - 0.5) * 3.141592653589793;
    auto on = [&](double a, double rr) { return c + bezcam::Vec3{std::cos(a), std::sin(a)} * rr; };
    arcs.push_back(bezcam::Bezier::make({on(a0, r), on(a0 + sw / 2, r / std::cos(sw / 2)), on(a0 + sw, r)},
                                        {1, std::cos(sw / 2), 1}));
  }
  std::vector<std::vector<bezcam::Vec3>> polys, dense;
  for (const auto& b : arcs) {
    polys.push_back(bezcam::flatten(b, {tol, -1}).points);
    dense.push_back(bezcam::flatten(b, {1e-4 * tol, -1}).points);
  }
  time_row("circular arcs, flattened", arcs, polys, tol);
  time_row("circular arcs, chords at 1e-4 of it", arcs, dense, tol);
  for (int n : {5, 16})
    for (bool rational : {false, true}) {
      std::vector<bezcam::Bezier> pcs;
      std::vector<std::vector<bezcam::Vec3>> ps;
      for (int k = 0; k < (n == 5 ? 1000 : 200); ++k) {
        std::vector<bezcam::Vec3> p;
        std::vector<double> w;
        for (int i = 0; i <= n; ++i) p.push_back({20 * u(rng), 20 * u(rng)}), w.push_back(0.3 + 2.7 * u(rng));
        pcs.push_back(rational ? bezcam::Bezier::make(p, w) : bezcam::Bezier::make(p));
        ps.push_back(bezcam::flatten(pcs.back(), {tol, -1}).points);
      }
      const std::string what = "degree " + std::to_string(n) + (rational ? ", rational" : "") + ", flattened";
      time_row(what.c_str(), pcs, ps, tol);
    }
}

}  // namespace

int main(int argc, char** argv) {
  std::string corpus = BEZCAM_CORPUS;
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else
      corpus = argv[i];
  }
  std::ifstream in(corpus);
  if (!in) {
    std::fprintf(stderr, "measure_bench: cannot read %s\n", corpus.c_str());
    return 3;
  }
  const nlohmann::json doc = nlohmann::json::parse(in);
  std::vector<bezcam::Bezier> curves;
  for (const auto& c : doc["curves"]) {
    if (quick && curves.size() == 1000) break;
    std::vector<bezcam::Vec3> p;
    for (const auto& q : c) p.push_back({q[0].get<double>(), q[1].get<double>()});
    curves.push_back(bezcam::Bezier::make(p));
  }
  std::printf("corpus: %s, %zu curves, one thread\n\n", corpus.c_str(), curves.size());
  std::printf(
      "| tolerance (mm) | segments | s | curves/s | segments/s | largest curve->path | largest path->curve |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|\n");
  for (double tol : {0.1, 0.01, 0.001}) {
    std::vector<std::vector<bezcam::Vec3>> polys(curves.size());
    size_t segs = 0;
    for (size_t i = 0; i < curves.size(); ++i) {
      polys[i] = bezcam::flatten(curves[i], {tol, -1}).points;
      segs += polys[i].size() - 1;
    }
    bezcam::Deviation worst;
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < curves.size(); ++i) {
      const bezcam::Deviation d =
          bezcam::measure_deviation(std::span<const bezcam::Bezier>(&curves[i], 1), polys[i], tol);
      worst.curve_to_path = std::max(worst.curve_to_path, d.curve_to_path);
      worst.path_to_curve = std::max(worst.path_to_curve, d.path_to_curve);
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("| %g | %zu | %.3f | %.0f | %.0f | %.6g | %.6g |\n", tol, segs, s, curves.size() / s, segs / s,
                worst.curve_to_path, worst.path_to_curve);
  }
  other_pieces();
  return 0;
}
