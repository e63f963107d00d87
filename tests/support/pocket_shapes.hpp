#pragma once
// Pocket regions as job entities (JSON text), for the pocket tests and the
// pocket benchmark: polygons of straight Bézier pieces, circles of four
// rational quarters, and the shapes the tests and the benchmark share.
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace bezcam::test::shapes {

using Pts = std::vector<std::pair<double, double>>;

inline std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// A closed path entity through the points; `extra` is more members of it
/// (`,"id":"x"`).
inline std::string polygon(const Pts& p, const std::string& extra = "") {
  std::string s = R"({"type":"path","closed":true)" + extra + R"(,"segments":[)";
  for (size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    s += std::string(i ? "," : "") + R"({"type":"bezier","points":[[)" + num(a.first) + "," + num(a.second) + "],[" +
         num(b.first) + "," + num(b.second) + "]]}";
  }
  return s + "]}";
}

/// A circle as four rational quarters (exact).
inline std::string circle(double cx, double cy, double r) {
  const double w = std::sqrt(0.5);
  std::string s = R"({"type":"path","closed":true,"segments":[)";
  for (int k = 0; k < 4; ++k) {
    const double a0 = k * std::numbers::pi / 2, a1 = a0 + std::numbers::pi / 2;
    const double mx = cx + r * (std::cos(a0) - std::sin(a0)), my = cy + r * (std::sin(a0) + std::cos(a0));
    s += std::string(k ? "," : "") + R"({"type":"bezier","points":[[)" + num(cx + r * std::cos(a0)) + "," +
         num(cy + r * std::sin(a0)) + "],[" + num(mx) + "," + num(my) + "],[" + num(cx + r * std::cos(a1)) + "," +
         num(cy + r * std::sin(a1)) + "]],\"weights\":[1," + num(w) + ",1]}";
  }
  return s + "]}";
}

/// A star of n points, tips at radius ro, inner corners at ri, the first
/// tip up.
inline Pts star(int n, double ro, double ri) {
  Pts p;
  for (int k = 0; k < 2 * n; ++k) {
    const double a = std::numbers::pi * k / n + std::numbers::pi / 2, r = k % 2 ? ri : ro;
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

/// A star of n points, tips at radius ro, whose tips have the interior
/// angle `tip` (degrees). A tip's half angle h and the half angle pi / n
/// between a tip and the next inner corner make the triangle (centre,
/// tip, inner corner) have angles pi / n, h and pi - pi / n - h, so by
/// the sine rule the inner corners lie at ro sin h / sin(pi / n + h).
inline Pts star_with_tips(int n, double ro, double tip) {
  const double h = tip / 2 * std::numbers::pi / 180;
  return star(n, ro, ro * std::sin(h) / std::sin(std::numbers::pi / n + h));
}

/// An L 60 x 60 with arms 20 wide.
inline Pts l_shape() { return {{0, 0}, {60, 0}, {60, 20}, {20, 20}, {20, 60}, {0, 60}}; }

/// Two 20 x 20 rooms joined by a neck 4 wide (narrower than a 6 mm tool).
inline Pts rooms_with_neck() {
  return {{0, 0},   {20, 0},  {20, 8},  {30, 8},  {30, 0},  {50, 0},
          {50, 20}, {30, 20}, {30, 12}, {20, 12}, {20, 20}, {0, 20}};
}

}  // namespace bezcam::test::shapes
