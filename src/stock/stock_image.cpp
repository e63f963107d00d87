#include "bezcam/stock/stock_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <zlib.h>

#include "bezcam/error.hpp"
#include "bezcam/format.hpp"

namespace bezcam {

namespace {

struct Rgb {
  double r, g, b;
};

constexpr Rgb kDeep{70, 80, 96}, kTop{228, 216, 192};
constexpr Rgb kGouge{228, 0, 0}, kExcess{0, 110, 255};

Rgb mix(Rgb a, Rgb b, double t) { return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t}; }

// ---- a small raster ----------------------------------------------------------

struct Raster {
  int w = 0, h = 0;
  std::vector<std::uint8_t> px;  // RGB, rows from the top
  Raster(int w_, int h_, Rgb fill) : w(w_), h(h_), px(static_cast<std::size_t>(w_) * h_ * 3) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) set(x, y, fill);
  }
  void set(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    std::uint8_t* p = &px[(static_cast<std::size_t>(y) * w + x) * 3];
    p[0] = static_cast<std::uint8_t>(std::clamp(std::lround(c.r), 0L, 255L));
    p[1] = static_cast<std::uint8_t>(std::clamp(std::lround(c.g), 0L, 255L));
    p[2] = static_cast<std::uint8_t>(std::clamp(std::lround(c.b), 0L, 255L));
  }
  void rect(int x, int y, int rw, int rh, Rgb c) {
    for (int j = y; j < y + rh; ++j)
      for (int i = x; i < x + rw; ++i) set(i, j, c);
  }
};

// 5 x 7 glyphs of the characters the legend prints.
const char* const* glyph(char c) {
  static const char* const g0[] = {".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."};
  static const char* const g1[] = {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."};
  static const char* const g2[] = {".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"};
  static const char* const g3[] = {"#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."};
  static const char* const g4[] = {"...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."};
  static const char* const g5[] = {"#####", "#....", "####.", "....#", "....#", "#...#", ".###."};
  static const char* const g6[] = {"..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."};
  static const char* const g7[] = {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."};
  static const char* const g8[] = {".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."};
  static const char* const g9[] = {".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."};
  static const char* const dot[] = {".....", ".....", ".....", ".....", ".....", ".##..", ".##.."};
  static const char* const minus[] = {".....", ".....", ".....", "#####", ".....", ".....", "....."};
  static const char* const C[] = {".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."};
  static const char* const E[] = {"#####", "#....", "#....", "####.", "#....", "#....", "#####"};
  static const char* const G[] = {".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"};
  static const char* const M[] = {"#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"};
  static const char* const O[] = {".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."};
  static const char* const S[] = {".####", "#....", "#....", ".###.", "....#", "....#", "####."};
  static const char* const U[] = {"#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."};
  static const char* const X[] = {"#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"};
  static const char* const Z[] = {"#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"};
  switch (c) {
    case '0': return g0;
    case '1': return g1;
    case '2': return g2;
    case '3': return g3;
    case '4': return g4;
    case '5': return g5;
    case '6': return g6;
    case '7': return g7;
    case '8': return g8;
    case '9': return g9;
    case '.': return dot;
    case '-': return minus;
    case 'C': return C;
    case 'E': return E;
    case 'G': return G;
    case 'M': return M;
    case 'O': return O;
    case 'S': return S;
    case 'U': return U;
    case 'X': return X;
    case 'Z': return Z;
    default: return nullptr;
  }
}

constexpr int kFont = 2;             // pixels per glyph dot
constexpr int kAdvance = 6 * kFont;  // glyph width and its gap
constexpr int kTextHeight = 7 * kFont;

int text(Raster& r, int x, int y, const std::string& s, Rgb c) {
  for (char ch : s) {
    if (const char* const* g = glyph(ch))
      for (int row = 0; row < 7; ++row)
        for (int col = 0; col < 5; ++col)
          if (g[row][col] == '#') r.rect(x + col * kFont, y + row * kFont, kFont, kFont, c);
    x += kAdvance;
  }
  return x;
}

// ---- PNG ------------------------------------------------------------------------

void put32(std::vector<std::uint8_t>& o, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) o.push_back(static_cast<std::uint8_t>((v >> s) & 0xff));
}

void chunk(std::vector<std::uint8_t>& o, const char* type, const std::vector<std::uint8_t>& data) {
  put32(o, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = o.size();
  o.insert(o.end(), type, type + 4);
  o.insert(o.end(), data.begin(), data.end());
  const uLong crc = crc32(0L, o.data() + start, static_cast<uInt>(o.size() - start));
  put32(o, static_cast<std::uint32_t>(crc));
}

int paeth(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  return (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
}

std::vector<std::uint8_t> encode_png(const Raster& r) {
  // Each row with the filter (none, sub, up, average, Paeth) whose bytes sum
  // smallest as signed values (the usual heuristic), then zlib.
  const std::size_t stride = static_cast<std::size_t>(r.w) * 3;
  std::vector<std::uint8_t> raw;
  raw.reserve((stride + 1) * r.h);
  std::vector<std::uint8_t> zero(stride, 0), cand(stride), best(stride);
  for (int y = 0; y < r.h; ++y) {
    const std::uint8_t* cur = &r.px[y * stride];
    const std::uint8_t* up = y > 0 ? &r.px[(y - 1) * stride] : zero.data();
    long best_cost = -1;
    int best_f = 0;
    for (int f = 0; f < 5; ++f) {
      long cost = 0;
      for (std::size_t i = 0; i < stride; ++i) {
        const int a = i >= 3 ? cur[i - 3] : 0, b = up[i], c = i >= 3 ? up[i - 3] : 0;
        int pred = 0;
        if (f == 1)
          pred = a;
        else if (f == 2)
          pred = b;
        else if (f == 3)
          pred = (a + b) / 2;
        else if (f == 4)
          pred = paeth(a, b, c);
        const auto v = static_cast<std::uint8_t>(cur[i] - pred);
        cand[i] = v;
        cost += v < 128 ? v : 256 - v;
      }
      if (best_cost < 0 || cost < best_cost) {
        best_cost = cost;
        best_f = f;
        best.swap(cand);
      }
    }
    raw.push_back(static_cast<std::uint8_t>(best_f));
    raw.insert(raw.end(), best.begin(), best.end());
  }
  uLongf zlen = compressBound(static_cast<uLong>(raw.size()));
  std::vector<std::uint8_t> z(zlen);
  if (compress2(z.data(), &zlen, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK)
    throw std::runtime_error("zlib could not compress the picture");
  z.resize(zlen);
  std::vector<std::uint8_t> o = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> ihdr;
  put32(ihdr, static_cast<std::uint32_t>(r.w));
  put32(ihdr, static_cast<std::uint32_t>(r.h));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, no interlace
  chunk(o, "IHDR", ihdr);
  chunk(o, "IDAT", z);
  chunk(o, "IEND", {});
  return o;
}

// ---- the map --------------------------------------------------------------------

struct Map {
  int mw = 0, mh = 0;  // blocks of columns
  int block = 1;       // columns per block side
  int zoom = 1;        // pixels per block side
  double zlo = 0, zhi = 0;
  Raster image{0, 0, {0, 0, 0}};
};

Map render_map(const DexelGrid& g, const StockImageOptions& opt) {
  const std::size_t n = g.nx() * g.ny();
  if (!opt.classes.empty() && opt.classes.size() != n)
    throw std::invalid_argument("stock image: " + std::to_string(opt.classes.size()) + " classes for " +
                                std::to_string(n) + " columns");
  Map m;
  const int side = std::max(16, opt.max_side);
  const std::size_t big = std::max(g.nx(), g.ny());
  m.block = static_cast<int>((big + side - 1) / side);
  m.mw = static_cast<int>((g.nx() + m.block - 1) / m.block);
  m.mh = static_cast<int>((g.ny() + m.block - 1) / m.block);
  m.zoom = std::clamp(600 / std::max(m.mw, m.mh), 1, 8);
  // The block's lowest floor; its class: a gouge before an excess.
  std::vector<double> h(static_cast<std::size_t>(m.mw) * m.mh, g.box().z1);
  std::vector<std::uint8_t> cls(h.size(), 0);
  for (std::size_t j = 0; j < g.ny(); ++j)
    for (std::size_t i = 0; i < g.nx(); ++i) {
      const std::size_t b = (j / m.block) * m.mw + i / m.block;
      h[b] = std::min(h[b], g.floor(i, j));
      if (!opt.classes.empty()) {
        const auto c = static_cast<std::uint8_t>(opt.classes[j * g.nx() + i]);
        if (c == 1 || (c == 2 && cls[b] == 0)) cls[b] = c;
      }
    }
  m.zhi = g.box().z1;
  m.zlo = std::min(*std::min_element(h.begin(), h.end()), m.zhi);
  const double span = m.zhi - m.zlo, step = g.cell() * m.block;
  auto H = [&](int i, int j) {
    return h[static_cast<std::size_t>(std::clamp(j, 0, m.mh - 1)) * m.mw + std::clamp(i, 0, m.mw - 1)];
  };
  // Light from the north-west, 45 degrees up; a level floor keeps its colour.
  const double alt = std::numbers::pi / 4, lx = -std::cos(alt) / std::sqrt(2.0), ly = std::cos(alt) / std::sqrt(2.0),
               lz = std::sin(alt);
  m.image = Raster(m.mw * m.zoom, m.mh * m.zoom, {0, 0, 0});
  for (int j = 0; j < m.mh; ++j)
    for (int i = 0; i < m.mw; ++i) {
      const double dzdx = (H(i + 1, j) - H(i - 1, j)) / (((i + 1 < m.mw) + (i > 0)) * step + (m.mw == 1));
      const double dzdy = (H(i, j + 1) - H(i, j - 1)) / (((j + 1 < m.mh) + (j > 0)) * step + (m.mh == 1));
      const double len = std::sqrt(dzdx * dzdx + dzdy * dzdy + 1);
      const double lambert = std::max(0.0, (-dzdx * lx - dzdy * ly + lz) / len) / lz;
      const double t = span > 0 ? (H(i, j) - m.zlo) / span : 1.0;
      Rgb c = mix(kDeep, kTop, t);
      const double f = std::clamp(0.3 + 0.7 * lambert, 0.0, 1.35);
      c = {c.r * f, c.g * f, c.b * f};
      const std::uint8_t k = cls[static_cast<std::size_t>(j) * m.mw + i];
      if (k == 1) c = mix(c, kGouge, 0.75);
      if (k == 2) c = mix(c, kExcess, 0.65);
      const int py = (m.mh - 1 - j) * m.zoom;  // +y up
      m.image.rect(i * m.zoom, py, m.zoom, m.zoom, c);
    }
  return m;
}

// A round length (1, 2 or 5 times a power of ten, in mm) near `target` mm.
double nice_length(double target) {
  const double p = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= target) return m * p;
  return p;
}

struct Legend {
  int width = 0, height = 0, map_h = 0;
  double bar_mm = 0;
  int bar_px = 0;
};

Legend legend_layout(const Map& m, double cell) {
  Legend L;
  L.map_h = m.image.h;
  L.width = std::max(m.image.w, 460);
  L.height = m.image.h + 3 * 26 + 16;
  const double mm_per_px = cell * m.block / m.zoom;
  L.bar_mm = nice_length(std::max(m.image.w / 4.0, 40.0) * mm_per_px);
  L.bar_px = static_cast<int>(std::lround(L.bar_mm / mm_per_px));
  return L;
}

std::string base64(const std::vector<std::uint8_t>& d) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string o;
  o.reserve((d.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < d.size(); i += 3) {
    const std::uint32_t v = (d[i] << 16) | (i + 1 < d.size() ? d[i + 1] << 8 : 0) | (i + 2 < d.size() ? d[i + 2] : 0);
    o.push_back(t[(v >> 18) & 63]);
    o.push_back(t[(v >> 12) & 63]);
    o.push_back(i + 1 < d.size() ? t[(v >> 6) & 63] : '=');
    o.push_back(i + 2 < d.size() ? t[v & 63] : '=');
  }
  return o;
}

void write_file(const std::string& path, const char* data, std::size_t size, const char* what) {
  bool opened = false;
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    opened = static_cast<bool>(f);
    if (f) f.write(data, static_cast<std::streamsize>(size));
    if (f && f.flush()) return;
  }
  std::error_code ec;
  if (opened) std::filesystem::remove(path, ec);
  throw IoError(errc::io_write, Place::at_file(path), std::string("cannot write the ") + what);
}

}  // namespace

std::vector<std::uint8_t> stock_png(const DexelGrid& grid, const StockImageOptions& opt) {
  const Map m = render_map(grid, opt);
  const Legend L = legend_layout(m, grid.cell());
  Raster r(L.width, L.height, {255, 255, 255});
  for (int y = 0; y < m.image.h; ++y)
    std::copy_n(&m.image.px[static_cast<std::size_t>(y) * m.image.w * 3], m.image.w * 3,
                &r.px[static_cast<std::size_t>(y) * r.w * 3]);
  const Rgb ink{20, 20, 20};
  int y = L.map_h + 10;
  // the height ramp, deepest to top
  int x = text(r, 10, y, "Z", ink) + 6;
  for (int i = 0; i < 160; ++i) r.rect(x + i, y, 1, kTextHeight, mix(kDeep, kTop, i / 159.0));
  text(r, x + 172, y, format_fixed(m.zlo, 3) + " .. " + format_fixed(m.zhi, 3) + " MM", ink);
  // the classes
  y += 26;
  r.rect(10, y, kTextHeight, kTextHeight, kGouge);
  x = text(r, 10 + kTextHeight + 8, y, "GOUGE", ink) + 24;
  r.rect(x, y, kTextHeight, kTextHeight, kExcess);
  text(r, x + kTextHeight + 8, y, "EXCESS", ink);
  // the scale bar
  y += 26;
  r.rect(10, y + 4, L.bar_px, 6, ink);
  r.rect(10, y, 2, kTextHeight, ink);
  r.rect(10 + L.bar_px - 2, y, 2, kTextHeight, ink);
  text(r, 10 + L.bar_px + 12, y, format_significant(L.bar_mm, 6) + " MM", ink);
  return encode_png(r);
}

std::string stock_svg(const DexelGrid& grid, const StockImageOptions& opt) {
  const Map m = render_map(grid, opt);
  const Legend L = legend_layout(m, grid.cell());
  auto rgb = [](Rgb c) {
    char b[32];
    std::snprintf(b, sizeof b, "rgb(%ld,%ld,%ld)", std::lround(c.r), std::lround(c.g), std::lround(c.b));
    return std::string(b);
  };
  std::string s;
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" +
       std::to_string(L.width) + "\" height=\"" + std::to_string(L.height) + "\" viewBox=\"0 0 " +
       std::to_string(L.width) + " " + std::to_string(L.height) + "\">\n";
  s += "<title>machined stock: " + std::to_string(grid.nx()) + " x " + std::to_string(grid.ny()) + " columns, cell " +
       format_significant(grid.cell(), 6) + " mm</title>\n";
  s += "<defs><linearGradient id=\"ramp\"><stop offset=\"0\" stop-color=\"" + rgb(kDeep) +
       "\"/><stop offset=\"1\" stop-color=\"" + rgb(kTop) + "\"/></linearGradient></defs>\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s += "<image x=\"0\" y=\"0\" width=\"" + std::to_string(m.image.w) + "\" height=\"" + std::to_string(m.image.h) +
       "\" style=\"image-rendering:pixelated\" xlink:href=\"data:image/png;base64," + base64(encode_png(m.image)) +
       "\"/>\n";
  const std::string font = "font-family=\"sans-serif\" font-size=\"14\" fill=\"rgb(20,20,20)\"";
  int y = L.map_h + 10;
  s += "<text x=\"10\" y=\"" + std::to_string(y + 12) + "\" " + font + ">z</text>\n";
  s += "<rect x=\"24\" y=\"" + std::to_string(y) + "\" width=\"160\" height=\"14\" fill=\"url(#ramp)\"/>\n";
  s += "<text x=\"196\" y=\"" + std::to_string(y + 12) + "\" " + font + ">" + format_fixed(m.zlo, 3) + " .. " +
       format_fixed(m.zhi, 3) + " mm</text>\n";
  y += 26;
  s += "<rect x=\"10\" y=\"" + std::to_string(y) + "\" width=\"14\" height=\"14\" fill=\"" + rgb(kGouge) + "\"/>\n";
  s += "<text x=\"32\" y=\"" + std::to_string(y + 12) + "\" " + font + ">gouge</text>\n";
  s += "<rect x=\"100\" y=\"" + std::to_string(y) + "\" width=\"14\" height=\"14\" fill=\"" + rgb(kExcess) + "\"/>\n";
  s += "<text x=\"122\" y=\"" + std::to_string(y + 12) + "\" " + font + ">excess</text>\n";
  y += 26;
  s += "<rect x=\"10\" y=\"" + std::to_string(y + 4) + "\" width=\"" + std::to_string(L.bar_px) +
       "\" height=\"6\" fill=\"rgb(20,20,20)\"/>\n";
  s += "<text x=\"" + std::to_string(L.bar_px + 22) + "\" y=\"" + std::to_string(y + 12) + "\" " + font + ">" +
       format_significant(L.bar_mm, 6) + " mm</text>\n";
  s += "</svg>\n";
  return s;
}

void write_stock_png(const DexelGrid& grid, const std::string& path, const StockImageOptions& opt) {
  const std::vector<std::uint8_t> b = stock_png(grid, opt);
  write_file(path, reinterpret_cast<const char*>(b.data()), b.size(), "picture");
}

void write_stock_svg(const DexelGrid& grid, const std::string& path, const StockImageOptions& opt) {
  const std::string s = stock_svg(grid, opt);
  write_file(path, s.data(), s.size(), "picture");
}

}  // namespace bezcam
