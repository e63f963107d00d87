// The independent deviation measurement alone, one thread, on the shared
// corpus (shared/bench/cubics-10k.json): every curve flattened at each
// tolerance (the program's polyline), then measure_deviation() timed over
// all of them. Prints curves/s, segments/s and the largest readings.
//
//   build/measure_bench [--quick] [CORPUS.json]
//
// --quick: the first 1,000 curves. Figures only: nothing is asserted.
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"

int main(int argc, char** argv) {
  std::string corpus = std::string(BEZCAM_SHARED_DIR) + "/bench/cubics-10k.json";
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--quick")) quick = true;
    else corpus = argv[i];
  }
  std::ifstream in(corpus);
  if (!in) {
    std::printf("measure_bench: corpus %s not found: benchmark skipped\n", corpus.c_str());
    return 0;
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
  std::printf("| tolerance (mm) | segments | s | curves/s | segments/s | largest curve->path | largest path->curve |\n");
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
  return 0;
}
