#include "bezcam/stock/stock_image.hpp"

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <zlib.h>

#include "bezcam/error.hpp"

using namespace bezcam;
namespace fs = std::filesystem;

namespace {

std::uint32_t be32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

// A PNG decoded here: chunks checked (CRC), IDAT inflated, rows unfiltered.
struct Png {
  std::uint32_t w = 0, h = 0;
  std::vector<std::uint8_t> rgb;
  const std::uint8_t* at(std::uint32_t x, std::uint32_t y) const { return &rgb[(y * w + x) * 3]; }
};

Png decode(const std::vector<std::uint8_t>& f) {
  Png p;
  const std::uint8_t sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  EXPECT_EQ(std::memcmp(f.data(), sig, 8), 0);
  std::vector<std::uint8_t> z;
  std::size_t pos = 8;
  bool end = false;
  while (pos + 12 <= f.size()) {
    const std::uint32_t len = be32(&f[pos]);
    const std::string type(reinterpret_cast<const char*>(&f[pos + 4]), 4);
    EXPECT_EQ(crc32(0, &f[pos + 4], len + 4), be32(&f[pos + 8 + len])) << type;
    if (type == "IHDR") {
      p.w = be32(&f[pos + 8]);
      p.h = be32(&f[pos + 12]);
      EXPECT_EQ(f[pos + 16], 8);  // bit depth
      EXPECT_EQ(f[pos + 17], 2);  // RGB
    } else if (type == "IDAT") {
      z.insert(z.end(), &f[pos + 8], &f[pos + 8 + len]);
    } else if (type == "IEND") {
      end = true;
    }
    pos += 12 + len;
  }
  EXPECT_TRUE(end);
  EXPECT_EQ(pos, f.size());
  const std::size_t stride = p.w * 3;
  std::vector<std::uint8_t> raw((stride + 1) * p.h);
  uLongf n = raw.size();
  EXPECT_EQ(uncompress(raw.data(), &n, z.data(), z.size()), Z_OK);
  EXPECT_EQ(n, raw.size());
  p.rgb.assign(stride * p.h, 0);
  for (std::uint32_t y = 0; y < p.h; ++y) {
    const int filter = raw[y * (stride + 1)];
    for (std::size_t i = 0; i < stride; ++i) {
      const int x = raw[y * (stride + 1) + 1 + i];
      const int a = i >= 3 ? p.rgb[y * stride + i - 3] : 0, b = y > 0 ? p.rgb[(y - 1) * stride + i] : 0,
                c = (i >= 3 && y > 0) ? p.rgb[(y - 1) * stride + i - 3] : 0;
      int pred = 0;
      if (filter == 1) pred = a;
      if (filter == 2) pred = b;
      if (filter == 3) pred = (a + b) / 2;
      if (filter == 4) {
        const int q = a + b - c, pa = std::abs(q - a), pb = std::abs(q - b), pc = std::abs(q - c);
        pred = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
      }
      p.rgb[y * stride + i] = static_cast<std::uint8_t>(x + pred);
    }
  }
  return p;
}

// 80 x 60 columns: a pocket floor, a slot, and classes on two patches.
DexelGrid sample(std::vector<ColumnClass>& cls) {
  DexelGrid g({0, 0, -6, 40, 30, 0}, 0.5);
  for (double y = 6; y <= 24; y += 2) g.cut(Sweep::line({6, y, -3}, {20, y, -3}), ToolShape::flat(6));
  g.cut(Sweep::line({26, 5, -1}, {34, 25, -5}), ToolShape::ball(6));
  cls.assign(g.nx() * g.ny(), ColumnClass::none);
  for (std::size_t j = 10; j < 20; ++j)
    for (std::size_t i = 10; i < 20; ++i) cls[j * g.nx() + i] = ColumnClass::gouge;  // x 5..10, y 5..10
  for (std::size_t j = 40; j < 50; ++j)
    for (std::size_t i = 60; i < 70; ++i) cls[j * g.nx() + i] = ColumnClass::excess;  // x 30..35, y 20..25
  return g;
}

}  // namespace

TEST(StockImage, PngShowsMapClassesAndLegend) {
  std::vector<ColumnClass> cls;
  const DexelGrid g = sample(cls);
  StockImageOptions opt;
  opt.classes = cls;
  const Png p = decode(stock_png(g, opt));
  // 80 x 60 columns drawn at 7 pixels each (600 / 80), the legend below
  const std::uint32_t zoom = 600 / 80;
  EXPECT_EQ(p.w, std::max<std::uint32_t>(80 * zoom, 460));
  EXPECT_EQ(p.h, 60 * zoom + 94);
  auto pixel = [&](double x, double y) {  // the pixel at the centre of the column holding (x, y)
    const auto i = static_cast<std::uint32_t>(x / 0.5), j = static_cast<std::uint32_t>(y / 0.5);
    return p.at(i * zoom + zoom / 2, (59 - j) * zoom + zoom / 2);
  };
  const std::uint8_t* top = pixel(38, 2);      // untouched stock: light
  const std::uint8_t* pocket = pixel(12, 15);  // the pocket floor, level: darker than the top
  const std::uint8_t* gouge = pixel(7, 7);
  const std::uint8_t* excess = pixel(32, 22);
  EXPECT_GT(top[0], 200);
  EXPECT_LT(pocket[0], top[0]);
  EXPECT_EQ(pocket[0], pixel(14, 17)[0]);  // a level floor shades evenly
  EXPECT_GT(gouge[0], 180);
  EXPECT_LT(gouge[1], 80);
  EXPECT_LT(gouge[2], 80);
  EXPECT_GT(excess[2], 180);
  EXPECT_LT(excess[0], 80);
  // the legend: the gouge swatch in the second line, dark text, white paper
  const std::uint32_t y2 = 60 * zoom + 10 + 26 + 5;
  EXPECT_EQ(p.at(14, y2)[0], 228);
  EXPECT_EQ(p.at(14, y2)[1], 0);
  EXPECT_EQ(p.at(p.w - 2, p.h - 2)[0], 255);
  int dark = 0;
  for (std::uint32_t y = 60 * zoom; y < p.h; ++y)
    for (std::uint32_t x = 0; x < p.w; ++x) dark += p.at(x, y)[0] < 60 && p.at(x, y)[1] < 60;
  EXPECT_GT(dark, 300);  // text and the scale bar
}

TEST(StockImage, LargeGridsAreDrawnInBlocks) {
  DexelGrid g({0, 0, -2, 100, 50, 0}, 0.05);  // 2000 x 1000 columns
  g.cut(Sweep::line({10, 10, -1}, {90, 40, -1}), ToolShape::vee(6, 90));
  StockImageOptions opt;
  opt.max_side = 500;
  const Png p = decode(stock_png(g, opt));
  EXPECT_EQ(p.w, 500u);  // blocks of 4 x 4 columns
  EXPECT_EQ(p.h, 250u + 94);
}

TEST(StockImage, SvgIsWellFormedAndEmbedsThePng) {
  std::vector<ColumnClass> cls;
  const DexelGrid g = sample(cls);
  StockImageOptions opt;
  opt.classes = cls;
  const std::string s = stock_svg(g, opt);
  EXPECT_EQ(s.rfind("<?xml", 0), 0u);
  EXPECT_NE(s.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_NE(s.find("data:image/png;base64,iVBORw0KGgo"), std::string::npos);  // the PNG signature in base64
  EXPECT_NE(s.find(">gouge</text>"), std::string::npos);
  EXPECT_NE(s.find(">excess</text>"), std::string::npos);
  EXPECT_NE(s.find(" mm</text>"), std::string::npos);
  EXPECT_EQ(s.substr(s.size() - 7), "</svg>\n");
  const fs::path dir = fs::temp_directory_path() / ("bezcam_img_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  write_stock_svg(g, (dir / "m.svg").string(), opt);
  write_stock_png(g, (dir / "m.png").string(), opt);
  EXPECT_GT(fs::file_size(dir / "m.png"), 1000u);
  if (std::system("/usr/bin/python3 -c 'import xml.dom.minidom' >/dev/null 2>&1") == 0)
    EXPECT_EQ(std::system(("/usr/bin/python3 -c 'import xml.dom.minidom, sys; d = xml.dom.minidom.parse(sys.argv[1]); "
                           "assert d.documentElement.tagName == \"svg\"' " +
                           (dir / "m.svg").string())
                              .c_str()),
              0);
  if (const char* keep = std::getenv("BEZCAM_KEEP_IMAGES")) {
    fs::copy_file(dir / "m.png", fs::path(keep) / "stock_sample.png", fs::copy_options::overwrite_existing);
    fs::copy_file(dir / "m.svg", fs::path(keep) / "stock_sample.svg", fs::copy_options::overwrite_existing);
  }
  fs::remove_all(dir);
}

TEST(StockImage, RefusesClassesOfAnotherSize) {
  DexelGrid g({0, 0, -1, 4, 4, 0}, 1);
  std::vector<ColumnClass> cls(15);
  StockImageOptions opt;
  opt.classes = cls;
  EXPECT_THROW(stock_png(g, opt), std::invalid_argument);
}
