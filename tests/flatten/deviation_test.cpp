// measure_deviation() against a plain reference on corpus curves: the
// reading of each direction agrees with a dense search refined around its
// best samples, for the flattener's polylines and for polylines whose
// vertices were moved at random (readings above the tolerance, windows
// that miss). Also: several pieces, rational and high-degree ones.
#include "bezcam/flatten/deviation.hpp"

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <random>

#include "bezcam/flatten/flatten_curve.hpp"

using namespace bezcam;

namespace {

// Nearest distance from x to the whole polyline (every segment).
double to_path(const Vec3& x, const std::vector<Vec3>& poly) {
  if (poly.size() == 1) return dist(x, poly[0]);
  double m = HUGE_VAL;
  for (size_t k = 0; k + 1 < poly.size(); ++k) m = std::min(m, dist_to_segment(x, poly[k], poly[k + 1]));
  return m;
}

// A point of a path of pieces at u in [0, n]: piece floor(u).
Vec3 at(const std::vector<Bezier>& pieces, double u) {
  const size_t i = std::min(pieces.size() - 1, static_cast<size_t>(std::max(0.0, u)));
  return evaluate(pieces[i], std::clamp(u - double(i), 0.0, 1.0));
}

// Golden-section search for an extremum of f on [a, b] to 1e-12 of it.
template <class F>
double golden(double a, double b, F&& f, bool maximize) {
  const double g = 0.3819660112501051;
  double x1 = a + g * (b - a), x2 = b - g * (b - a), f1 = f(x1), f2 = f(x2);
  double best = maximize ? std::max(f1, f2) : std::min(f1, f2);
  for (int i = 0; i < 100 && b - a > 1e-12; ++i) {
    if (maximize ? f1 >= f2 : f1 <= f2)
      b = x2, x2 = x1, f2 = f1, x1 = a + g * (b - a), f1 = f(x1);
    else
      a = x1, x1 = x2, f1 = f2, x2 = b - g * (b - a), f2 = f(x2);
    best = maximize ? std::max({best, f1, f2}) : std::min({best, f1, f2});
  }
  return best;
}

// Nearest distance from x to the curve: the 3 nearest of `m` samples per
// piece, each refined by golden section over its two neighbouring steps.
double to_curve(const Vec3& x, const std::vector<Bezier>& pieces, const std::vector<Vec3>& dense, size_t m) {
  std::vector<std::pair<double, size_t>> near;
  for (size_t j = 0; j < dense.size(); ++j) near.push_back({dist(x, dense[j]), j});
  std::partial_sort(near.begin(), near.begin() + std::min<size_t>(3, near.size()), near.end());
  double best = near[0].first;
  for (size_t r = 0; r < std::min<size_t>(3, near.size()); ++r) {
    const double u = double(near[r].second) / double(m), h = 1.0 / double(m);
    best = std::min(best, golden(
                              std::max(0.0, u - h), std::min(double(pieces.size()), u + h),
                              [&](double v) { return dist(x, at(pieces, v)); }, false));
  }
  return best;
}

// The reference: curve -> path over `m` samples per piece, every local
// largest refined by golden section over its two neighbouring steps; path
// -> curve the same over 64 samples per segment.
Deviation reference(const std::vector<Bezier>& pieces, const std::vector<Vec3>& poly, size_t m = 4000) {
  Deviation d;
  const size_t n = m * pieces.size();
  std::vector<double> c(n + 1);
  std::vector<Vec3> dense(n + 1);
  for (size_t j = 0; j <= n; ++j) dense[j] = at(pieces, double(j) / double(m)), c[j] = to_path(dense[j], poly);
  for (size_t j = 0; j <= n; ++j) {
    d.curve_to_path = std::max(d.curve_to_path, c[j]);
    if ((j == 0 || c[j] >= c[j - 1]) && (j == n || c[j] >= c[j + 1])) {
      const double u = double(j) / double(m), h = 1.0 / double(m);
      d.curve_to_path = std::max(d.curve_to_path, golden(
                                                      std::max(0.0, u - h), std::min(double(pieces.size()), u + h),
                                                      [&](double v) { return to_path(at(pieces, v), poly); }, true));
    }
  }
  // Path -> curve against a coarser chain (each nearest point is refined).
  const size_t m2 = 500, n2 = m2 * pieces.size();
  std::vector<Vec3> chain(n2 + 1);
  for (size_t j = 0; j <= n2; ++j) chain[j] = at(pieces, double(j) / double(m2));
  for (size_t k = 0; k + 1 < poly.size() || k == 0; ++k) {
    const Vec3 a = poly[k], b = poly[std::min(k + 1, poly.size() - 1)];
    constexpr int kSteps = 64;
    std::vector<double> e(kSteps + 1);
    for (int i = 0; i <= kSteps; ++i) e[i] = to_curve(lerp(a, b, double(i) / kSteps), pieces, chain, m2);
    for (int i = 0; i <= kSteps; ++i) {
      d.path_to_curve = std::max(d.path_to_curve, e[i]);
      if ((i == 0 || e[i] >= e[i - 1]) && (i == kSteps || e[i] >= e[i + 1])) {
        const double s = double(i) / kSteps, h = 1.0 / kSteps;
        d.path_to_curve =
            std::max(d.path_to_curve, golden(
                                          std::max(0.0, s - h), std::min(1.0, s + h),
                                          [&](double v) { return to_curve(lerp(a, b, v), pieces, chain, m2); }, true));
      }
    }
    if (poly.size() == 1) break;
  }
  return d;
}

void expect_agrees(const std::vector<Bezier>& pieces, const std::vector<Vec3>& poly, double tol, const char* what) {
  const Deviation fast = measure_deviation(pieces, poly, tol);
  const Deviation ref = reference(pieces, poly);
  // The reference reads at points, refined to 1e-12 of the parameter: the
  // measurement is within kMeasureGap of the tolerance of the truth; the
  // margin here is ten times that.
  EXPECT_NEAR(fast.curve_to_path, ref.curve_to_path, 10 * kMeasureGap * tol) << what;
  EXPECT_NEAR(fast.path_to_curve, ref.path_to_curve, 10 * kMeasureGap * tol) << what;
}

}  // namespace

TEST(Deviation, AgreesWithAReferenceOnCorpusCurves) {
  std::ifstream in(BEZCAM_CORPUS);
  ASSERT_TRUE(in) << "the corpus is missing: " << BEZCAM_CORPUS;
  const auto doc = nlohmann::json::parse(in);
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> off(-2, 2);
  const double tol = 0.01;
  for (size_t i = 0; i < doc["curves"].size(); i += 1000) {
    std::vector<Vec3> p;
    for (const auto& q : doc["curves"][i]) p.push_back({q[0].get<double>(), q[1].get<double>()});
    const std::vector<Bezier> b = {Bezier::make(p)};
    const std::vector<Vec3> poly = flatten(b, {tol, -1}).points;
    expect_agrees(b, poly, tol, "flattened");
    // Vertices moved at random by up to twice the tolerance each way.
    std::vector<Vec3> moved = poly;
    for (Vec3& v : moved) v += Vec3{off(rng) * tol, off(rng) * tol};
    expect_agrees(b, moved, tol, "moved");
    // Every other vertex left out.
    std::vector<Vec3> sparse;
    for (size_t k = 0; k < poly.size(); k += 2) sparse.push_back(poly[k]);
    if (sparse.back() != poly.back()) sparse.push_back(poly.back());
    expect_agrees(b, sparse, tol, "sparse");
  }
}

TEST(Deviation, AgreesWithAReferenceOnPathsOfSeveralKindsOfPieces) {
  const double w = std::sqrt(0.5);
  const std::vector<Bezier> path = {
      Bezier::make({{0, 0}, {20, 10}, {30, 20}, {30, 30}}),
      Bezier::make({{30, 30}, {30, 40}, {20, 40}}, {1, w, 1}),                  // a quarter circle
      Bezier::make({{20, 40}, {10, 40}, {0, 60}, {-10, 30}, {5, 20}, {0, 0}}),  // degree 5
  };
  for (double tol : {0.1, 0.01}) {
    const std::vector<Vec3> poly = flatten(path, {tol, 3}).points;
    expect_agrees(path, poly, tol, "flattened");
    // A polyline that cuts the corner of the arc.
    std::vector<Vec3> cut = poly;
    for (Vec3& v : cut)
      if (v.y > 30 && v.x > 20) v = v + (Vec3{20, 30} - v) * 0.01;
    expect_agrees(path, cut, tol, "cut");
  }
}

TEST(Deviation, ALoopSkippedByThePolylineReadsItsSize) {
  // The loop of this cubic is about 9 mm across: a polyline that goes
  // straight across its crossing leaves all of it out.
  const Bezier b = Bezier::make({{0, 0}, {30, 20}, {-10, 20}, {20, 0}});
  const std::vector<Vec3> skip = {{0, 0}, {20, 0}};
  const Deviation d = measure_deviation(std::span<const Bezier>(&b, 1), skip, 0.01);
  const Deviation ref = reference({b}, skip);
  EXPECT_GT(d.curve_to_path, 5);
  EXPECT_NEAR(d.curve_to_path, ref.curve_to_path, 1e-8);
  EXPECT_NEAR(d.path_to_curve, ref.path_to_curve, 1e-8);
}

namespace {

// A random piece of degree n across a 10 mm square: control points from
// left to right (within 1 mm), heights at random; weights (when rational)
// between 0.3 and 3. (Not folding back onto itself: the reference's nearest
// points, refined from 500 samples a piece, would read high there.)
Bezier random_piece(std::mt19937_64& rng, int n, bool rational) {
  std::uniform_real_distribution<double> xy(0, 10), dx(-1, 1), w(0.3, 3);
  std::vector<Vec3> p;
  std::vector<double> ws;
  for (int i = 0; i <= n; ++i) p.push_back({10.0 * i / n + dx(rng), xy(rng)}), ws.push_back(w(rng));
  return rational ? Bezier::make(p, ws) : Bezier::make(p);
}

// Flattened, vertices moved at random, every other vertex left out: each
// against the reference.
void expect_agrees_three_ways(const std::vector<Bezier>& path, double tol, std::mt19937_64& rng,
                              const std::string& what) {
  std::uniform_real_distribution<double> off(-2, 2);
  const std::vector<Vec3> poly = flatten(path, {tol, -1}).points;
  expect_agrees(path, poly, tol, (what + ", flattened").c_str());
  std::vector<Vec3> moved = poly;
  for (Vec3& v : moved) v += Vec3{off(rng) * tol, off(rng) * tol};
  expect_agrees(path, moved, tol, (what + ", moved").c_str());
  std::vector<Vec3> sparse;
  for (size_t k = 0; k < poly.size(); k += 2) sparse.push_back(poly[k]);
  if (sparse.back() != poly.back()) sparse.push_back(poly.back());
  expect_agrees(path, sparse, tol, (what + ", sparse").c_str());
}

}  // namespace

TEST(Deviation, AgreesWithAReferenceOnPiecesOfDegreeFourToSeven) {
  // Pieces without a power form: evaluated and split on the stack.
  std::mt19937_64 rng(4);
  for (int n = 4; n <= 7; ++n)
    for (bool rational : {false, true}) {
      const std::vector<Bezier> b = {random_piece(rng, n, rational)};
      expect_agrees_three_ways(b, 0.01, rng, "degree " + std::to_string(n) + (rational ? ", rational" : ""));
    }
}

TEST(Deviation, AgreesWithAReferenceOnRationalPieces) {
  std::mt19937_64 rng(2);
  for (int n = 1; n <= 3; ++n)
    for (int k = 0; k < 2; ++k) {
      const std::vector<Bezier> b = {random_piece(rng, n, true)};
      expect_agrees_three_ways(b, 0.01, rng, "rational degree " + std::to_string(n));
    }
  // Circular arcs of a DXF polyline with bulges (each a rational
  // quadratic: weights 1, cos(sweep / 2), 1), of radii 5, 2 and 2, meeting
  // at corners (a foot passes over a corner to the next arc).
  auto arc = [](Vec3 c, double r, double a0, double sweep) {
    auto on = [&](double a, double rr) { return c + Vec3{std::cos(a), std::sin(a)} * rr; };
    return Bezier::make({on(a0, r), on(a0 + sweep / 2, r / std::cos(sweep / 2)), on(a0 + sweep, r)},
                        {1, std::cos(sweep / 2), 1});
  };
  const double deg = M_PI / 180;
  std::vector<Bezier> path = {arc({0, 5}, 5, -90 * deg, 90 * deg), arc({5, 7}, 2, -90 * deg, -120 * deg)};
  path.push_back(arc(path.back().back() + Vec3{0, 2}, 2, -90 * deg, 120 * deg));
  for (double tol : {0.1, 0.01}) expect_agrees_three_ways(path, tol, rng, "arcs at tolerance " + std::to_string(tol));
}

TEST(Deviation, AgreesWithAReferenceOnPiecesOfDegreeSixteenAndMore) {
  // Degree >= 16: the cascade's work space on the heap.
  std::mt19937_64 rng(16);
  for (int n : {16, 20})
    for (bool rational : {false, true}) {
      const std::vector<Bezier> b = {random_piece(rng, n, rational)};
      expect_agrees_three_ways(b, 0.05, rng, "degree " + std::to_string(n) + (rational ? ", rational" : ""));
    }
}

TEST(Deviation, CatchesAWrongPolylineOnRationalAndHighDegreePieces) {
  // Every interior vertex in turn moved across by three times the
  // tolerance: the reading is over the tolerance each time, and never
  // below the reference.
  std::mt19937_64 rng(3);
  const double tol = 0.01;
  for (int n : {2, 5, 17}) {
    const Bezier b = random_piece(rng, n, true);
    const std::vector<Vec3> poly = flatten(std::vector<Bezier>{b}, {tol, -1}).points;
    for (size_t k = 1; k + 1 < poly.size(); k += std::max<size_t>(1, poly.size() / 7)) {
      std::vector<Vec3> moved = poly;
      const Vec3 along = moved[k + 1] - moved[k - 1];
      moved[k] += Vec3{-along.y, along.x} * (3 * tol / norm(along));
      const double d = measure_deviation(std::span<const Bezier>(&b, 1), moved, tol).max();
      EXPECT_GT(d, 1.5 * tol) << "degree " << n << ", vertex " << k << " of " << poly.size();
    }
  }
}

TEST(Deviation, AgreesWithTheTrueDistanceOnHardCurves) {
  // The flattener's polylines of the hard curves of flatten_curve_test.cpp
  // (a cusp, inflections, a long one; not the curve doubling back along
  // its chord, where the reference's three nearest samples may all lie on
  // the wrong strand): both readings within ten times kMeasureGap of the reference's
  // true distances (nearest points refined on the curve). A brute force
  // against a chain of 20,000 chords of the curve instead reads path ->
  // curve up to the chain's own sag high (5e-6 of the tolerance on the
  // cusp): points outside a convex stretch are farther from its chords
  // than from it.
  const double tol = 0.01;
  for (const Bezier& b :
       {Bezier::make({{0, 0}, {60, 40}, {0, 40}, {60, 0}}), Bezier::make({{0, 0}, {30, 60}, {60, -60}, {90, 0}}),
        Bezier::make({{0, 0}, {300, 700}, {700, -300}, {1000, 0}})}) {
    const std::vector<Bezier> path = {b};
    expect_agrees(path, flatten(path, {tol, 3}).points, tol, "hard curve");
  }
}

TEST(Deviation, SettlesAFoldOfTheCurve) {
  // A cubic on a line that runs out, back and out again (turning at t =
  // (220 -+ sqrt(13200)) / 440, at x = 12.83 and -2.83), against the
  // polyline through its turning points, moved across the line by `across`
  // and stopping `short_by` before each turn. Where a point of the
  // polyline is near a fold its foot on the curve moves like the square
  // root of its distance; the readings are still the true distances: the
  // polyline's offset one way, and the offset and the stretch beyond each
  // turn together the other.
  const Bezier b = Bezier::make({{0, 0}, {40, 0}, {-30, 0}, {10, 0}}, {}, 2);
  const double r = std::sqrt(13200.0), t1 = (220 - r) / 440, t2 = (220 + r) / 440;
  for (double across : {0.0, 0.005})
    for (double short_by : {0.0, 0.003}) {
      const Vec3 up{0, across, 0}, dx{short_by, 0, 0};
      const std::vector<Vec3> poly = {b.front(), evaluate(b, t1) + up - dx, evaluate(b, t2) + up + dx, b.back()};
      const Deviation d = measure_deviation(std::span<const Bezier>(&b, 1), poly, 0.01);
      // (the ends of the polyline are on the curve: from them the
      // polyline's distance grows to `across` at the turns)
      EXPECT_NEAR(d.path_to_curve, across, kMeasureGap * 0.01 + 1e-12) << across << " " << short_by;
      EXPECT_NEAR(d.curve_to_path, std::hypot(across, short_by), kMeasureGap * 0.01 + 1e-12)
          << across << " " << short_by;
    }
}
