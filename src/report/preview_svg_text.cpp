// SVG text for the preview: escaping, pixel numbers, colour scales, path
// data, arrowheads, wrapped lines.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "preview_draw.hpp"

namespace bezcam {
namespace preview {

// ---------------------------------------------------------------------------

std::string esc(std::string_view s) {
  std::string o;
  for (char ch : s) {
    switch (ch) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&apos;"; break;
      default:
        // Control characters are not allowed in XML 1.0.
        if (static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\n')
          o += '?';
        else
          o += ch;
    }
  }
  return o;
}

// Pixel coordinates with 3 decimals (a thousandth of a pixel keeps
// deviations visible when zoomed in), trailing zeros trimmed.
std::string n3(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

std::string rgb(double r, double g, double b) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(std::lround(r)), int(std::lround(g)), int(std::lround(b)));
  return buf;
}

// Deviation colour, on a scale relative to the tolerance: within it a calm
// sequential scale, dark blue at 0 through teal to green at the tolerance
// (a program that uses 97 % of its tolerance keeps its promise and looks
// like it); above it a saturated red that no colour of the scale comes
// near, drawn wider and marked (a broken promise must stand out).
std::string deviation_colour(double d, double tol) {
  if (over_tolerance(d, tol)) return kOverColour;
  const double t = std::clamp(d / tol, 0.0, 1.0);
  struct C {
    double r, g, b;
  };
  const C lo{49, 54, 149}, mid{33, 145, 140}, hi{94, 201, 98};
  const C& a = t < 0.5 ? lo : mid;
  const C& b = t < 0.5 ? mid : hi;
  const double u = t < 0.5 ? t * 2 : (t - 0.5) * 2;
  return rgb(a.r + u * (b.r - a.r), a.g + u * (b.g - a.g), a.b + u * (b.b - a.b));
}

// The largest 1, 2 or 5 times a power of ten not above x.
double nice_below(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= x) return m * p;
  return p;
}

std::string path_d(const View& v, std::span<const Vec3> pts) {
  std::string d;
  d.reserve(pts.size() * 20);
  for (size_t i = 0; i < pts.size(); ++i) {
    const P2 q = v.screen(pts[i]);
    d += (i == 0 ? "M" : " L") + n3(q.x) + " " + n3(q.y);
  }
  return d;
}

// Arrowhead with its tip at `tip`, pointing along `d`.
std::string arrow_d(P2 tip, P2 d, double len, double half_width) {
  const P2 base{tip.x - d.x * len, tip.y - d.y * len};
  const P2 nrm{-d.y, d.x};
  return "M" + n3(tip.x) + " " + n3(tip.y) + " L" + n3(base.x + nrm.x * half_width) + " " +
         n3(base.y + nrm.y * half_width) + " L" + n3(base.x - nrm.x * half_width) + " " +
         n3(base.y - nrm.y * half_width) + " Z";
}

// Tangent of the curve at t, falling back to a nearby chord where the
// derivative vanishes (repeated control points).
Vec3 tangent(const Bezier& b, double t) {
  Vec3 d = derivative(b, t);
  if (norm(d) > 1e-12 * std::max(1.0, max_abs(b.front()))) return d;
  const double t2 = t < 0.5 ? t + 1e-3 : t - 1e-3;
  d = evaluate(b, t2) - evaluate(b, t);
  return t < 0.5 ? d : -d;
}

double text_width(std::string_view s, double font_size, bool bold) {
  // Per character, at least its advance in DejaVu Sans (the widest of the
  // common sans-serif fonts, Debian's default), in ems.
  double em = 0;
  for (unsigned char ch : s) {
    if ((ch & 0xC0) == 0x80) continue;  // UTF-8 continuation byte
    if (ch >= 0x80 || std::string_view("mwMW%@").find(char(ch)) != std::string_view::npos)
      em += 1.0;
    else if (std::string_view("=+<>#&~^*").find(char(ch)) != std::string_view::npos)
      em += 0.85;
    else if (std::string_view(" ijlftrI.,:;'|!()[]{}-/\\\"`").find(char(ch)) != std::string_view::npos)
      em += 0.42;
    else if (ch >= 'A' && ch <= 'Z')
      em += 0.8;
    else
      em += 0.65;
  }
  return em * font_size * (bold ? 1.12 : 1.0);
}

std::vector<std::string> wrap(const std::string& s, double width, double font_size) {
  std::vector<std::string> out;
  std::string line;
  size_t i = 0;
  while (i < s.size()) {
    size_t j = s.find(' ', i);
    if (j == std::string::npos) j = s.size();
    const std::string word = s.substr(i, j - i);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && text_width(longer, font_size) > width) {
      out.push_back(line);
      line = word;
    } else {
      line = longer;
    }
    i = j + 1;
  }
  if (!line.empty()) out.push_back(line);
  return out;
}

}  // namespace preview

std::string preview_deviation_colour(double d, double tol) { return preview::deviation_colour(d, tol); }

std::string preview_feed_colour(double f, double top) {
  // Five stops of a perceptually even scale (viridis' ends and middle).
  static const double stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  const double x = std::clamp(top > 0 ? f / top : 0.0, 0.0, 1.0) * 4;
  const int i = std::min(3, static_cast<int>(x));
  const double t = x - i;
  char b[8];
  int c[3];
  for (int k = 0; k < 3; ++k) c[k] = static_cast<int>(std::lround(stops[i][k] + t * (stops[i + 1][k] - stops[i][k])));
  std::snprintf(b, sizeof b, "#%02x%02x%02x", c[0], c[1], c[2]);
  return b;
}

}  // namespace bezcam
