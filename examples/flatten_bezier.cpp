// Example 1: flatten a cubic Bézier curve within a tolerance, and print the
// polyline with its proven bound.
//
//   build/examples/flatten_bezier [TOLERANCE]
#if defined(BEZCAM_EXAMPLE_PARTS_ONLY)
// A program that links only bezcam::flatten includes only what it uses.
#include <bezcam/error.hpp>
#include <bezcam/flatten/flatten_curve.hpp>
#include <bezcam/kernel/bezier.hpp>
#else
#include <bezcam/bezcam.hpp>
#endif

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  const double tol = argc > 1 ? std::atof(argv[1]) : 0.01;
  try {
    // The seeds' classic: a cubic from (0,0) to (100,0), bulging up.
    const bezcam::Bezier curve = bezcam::Bezier::make({{0, 0, 0}, {25, 60, 0}, {75, 60, 0}, {100, 0, 0}});
    bezcam::FlattenOptions opt;
    opt.tolerance = tol;  // mm: the largest distance between curve and polyline
    opt.decimals = 3;     // the vertices will be printed with 3 decimals: rounding counts too
    const bezcam::FlattenResult r = bezcam::flatten(curve, opt);
    std::printf("%zu vertices, proven bound %.6g mm (tolerance %.6g mm)\n", r.points.size(), r.bound, tol);
    for (const bezcam::Vec3& p : r.points) std::printf("%.3f %.3f\n", p.x, p.y);
    return r.bound <= tol ? 0 : 1;
  } catch (const bezcam::Error& e) {
    std::fprintf(stderr, "error %s: %s\n", e.id().c_str(), e.what());
    return 2;
  }
}
