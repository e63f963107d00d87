// In-process A/B of the band flattener (bench/flatten_ab.sh builds it): the library's flatten_pieces()
// against a variant's (the same source file changed, its public functions
// renamed with a _v suffix by bench/flatten_ab.sh), over the same curves
// in interleaved rounds, each side's best round kept. Both sides run in one
// process, on one core, round after round, so a change of the machine's
// speed hits both alike: on a shared machine whose speed swings by half
// from minute to minute, two separate runs cannot tell a 3 % change, this
// can (the same code on both sides reads 1.000 +- 0.005 with 61 rounds).
// Also prints each side's segment count (a variant may change the chords).
// Usage (through bench/flatten_ab.sh): flatten_ab CORPUS.json [EVERY [ROUNDS]]
// with TOLS="0.1 0.01 0.001" (the default) in the environment.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/kernel/bezier.hpp"

namespace bezcam {
double flatten_into_v(std::span<const Bezier> pieces, const FlattenOptions& opt, std::vector<Vec3>& out);
}

int main(int argc, char** argv) {
  using namespace bezcam;
  if (argc < 2) {
    std::fprintf(stderr, "usage: flatten_ab CORPUS.json [EVERY [ROUNDS]]\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::fprintf(stderr, "flatten_ab: cannot read %s\n", argv[1]);
    return 3;
  }
  const nlohmann::json doc = nlohmann::json::parse(in);
  const size_t every = argc > 2 ? std::max(1, std::atoi(argv[2])) : 10;
  const int rounds = argc > 3 ? std::max(1, std::atoi(argv[3])) : 61;
  std::vector<Bezier> curves;
  for (size_t i = 0; i < doc["curves"].size(); i += every) {
    std::vector<Vec3> p;
    for (const auto& q : doc["curves"][i]) p.push_back({q[0].get<double>(), q[1].get<double>()});
    curves.push_back(Bezier::make(p));
  }
  std::vector<double> tols = {0.1, 0.01, 0.001};
  if (const char* e = std::getenv("TOLS")) {
    tols.clear();
    for (const char* p = e; *p;) {
      char* end = nullptr;
      const double t = std::strtod(p, &end);
      if (end == p) break;
      tols.push_back(t);
      p = end;
    }
  }
  std::printf("%zu curves, %d rounds\n", curves.size(), rounds);
  std::vector<Vec3> pts;
  pts.reserve(1 << 16);
  for (const double tol : tols) {
    const FlattenOptions o{.tolerance = tol, .decimals = -1};
    double best[2] = {1e300, 1e300};
    size_t segments[2] = {0, 0};
    for (int r = 0; r < rounds; ++r)
      for (int k = 0; k < 2; ++k) {
        size_t n = 0;
        const auto t0 = std::chrono::steady_clock::now();
        for (const auto& b : curves) {
          pts.clear();
          if (k == 0)
            flatten_into(std::span<const Bezier>(&b, 1), o, pts);
          else
            flatten_into_v(std::span<const Bezier>(&b, 1), o, pts);
          n += pts.size() - 1;
        }
        best[k] =
            std::min(best[k], std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
        segments[k] = n;
      }
    std::printf(
        "tol %g mm: library %.3f us/curve (%zu segments), variant %.3f us/curve (%zu segments), variant / library "
        "%.3f\n",
        tol, best[0] / curves.size(), segments[0], best[1] / curves.size(), segments[1], best[1] / best[0]);
  }
  return 0;
}
