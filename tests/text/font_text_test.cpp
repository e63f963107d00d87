// Text from fonts, checked against the libraries' own answers: every
// piece of every glyph against FreeType's decomposition of the outline
// (FT_Outline_Decompose), every glyph's place against HarfBuzz's shaping,
// to 1e-9, in a TrueType font (DejaVu Sans: quadratic) and a CFF font
// (Nimbus Sans: cubic); then rotation, alignment and the refusals.
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include <cmath>
#include <gtest/gtest.h>
#include <hb.h>
#include <numbers>

#include "bezcam/error.hpp"
#include "bezcam/text/font_text.hpp"

namespace bezcam::text {
namespace {

// A piece as FreeType decomposes it: its control points in font units.
struct FtPiece {
  std::vector<Vec3> points;
};
struct FtGlyph {
  std::vector<std::vector<FtPiece>> contours;
  double pen_x = 0, pen_y = 0;  // HarfBuzz's origin of the glyph (offsets included), font units
};

// FreeType's decomposition with every coordinate doubled (shift 1), so
// that the implied on-curve points it computes by integer halving are
// exact, then halved back: the outline at full precision.
struct Decomposer {
  std::vector<std::vector<FtPiece>> contours;
  Vec3 cur;
  static Vec3 v(const FT_Vector* p) { return {p->x / 2.0, p->y / 2.0, 0}; }
  static int move_to(const FT_Vector* to, void* u) {
    auto* d = static_cast<Decomposer*>(u);
    d->contours.emplace_back();
    d->cur = v(to);
    return 0;
  }
  static int line_to(const FT_Vector* to, void* u) {
    auto* d = static_cast<Decomposer*>(u);
    if (v(to).x != d->cur.x || v(to).y != d->cur.y) d->contours.back().push_back({{d->cur, v(to)}});
    d->cur = v(to);
    return 0;
  }
  static int conic_to(const FT_Vector* c, const FT_Vector* to, void* u) {
    auto* d = static_cast<Decomposer*>(u);
    d->contours.back().push_back({{d->cur, v(c), v(to)}});
    d->cur = v(to);
    return 0;
  }
  static int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* u) {
    auto* d = static_cast<Decomposer*>(u);
    d->contours.back().push_back({{d->cur, v(c1), v(c2), v(to)}});
    d->cur = v(to);
    return 0;
  }
};

// The glyphs of `text` in `file` as FreeType and HarfBuzz give them, with
// ink only (a space has no contour).
std::vector<FtGlyph> reference(const std::string& file, const std::string& text, double* total_advance) {
  FT_Library lib;
  EXPECT_EQ(FT_Init_FreeType(&lib), 0);
  FT_Face face;
  EXPECT_EQ(FT_New_Face(lib, file.c_str(), 0, &face), 0);
  hb_blob_t* blob = hb_blob_create_from_file(file.c_str());
  hb_face_t* hf = hb_face_create(blob, 0);
  hb_font_t* font = hb_font_create(hf);
  hb_font_set_scale(font, face->units_per_EM, face->units_per_EM);
  hb_buffer_t* buf = hb_buffer_create();
  hb_buffer_add_utf8(buf, text.c_str(), -1, 0, -1);
  hb_buffer_guess_segment_properties(buf);
  hb_shape(font, buf, nullptr, 0);
  unsigned n = 0;
  const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf, &n);
  const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &n);
  std::vector<FtGlyph> out;
  double pen = 0;
  for (unsigned i = 0; i < n; ++i) {
    EXPECT_EQ(FT_Load_Glyph(face, info[i].codepoint, FT_LOAD_NO_SCALE), 0);
    FT_Outline_Funcs f{&Decomposer::move_to, &Decomposer::line_to, &Decomposer::conic_to, &Decomposer::cubic_to, 1, 0};
    Decomposer d;
    EXPECT_EQ(FT_Outline_Decompose(&face->glyph->outline, &f, &d), 0);
    std::erase_if(d.contours, [](const auto& c) { return c.empty(); });
    if (!d.contours.empty()) out.push_back({d.contours, pen + pos[i].x_offset, double(pos[i].y_offset)});
    pen += pos[i].x_advance;
  }
  *total_advance = pen;
  hb_buffer_destroy(buf);
  hb_font_destroy(font);
  hb_face_destroy(hf);
  hb_blob_destroy(blob);
  FT_Done_Face(face);
  FT_Done_FreeType(lib);
  return out;
}

int units_per_em(const std::string& file) {
  FT_Library lib;
  FT_Init_FreeType(&lib);
  FT_Face face;
  FT_New_Face(lib, file.c_str(), 0, &face);
  const int u = face->units_per_EM;
  FT_Done_Face(face);
  FT_Done_FreeType(lib);
  return u;
}

// Compares outline_text() with the reference, point by point, after the
// spec's placement (shift by the alignment, scale, turn about `at`).
// Counts in `halves` the control points on a half unit (implied points).
void expect_same_outlines(const TextSpec& spec, int* halves_out = nullptr) {
  const std::string file = find_font(spec.font, spec.folder).file.string();
  double total = 0;
  const std::vector<FtGlyph> ref = reference(file, spec.text, &total);
  const std::vector<Glyph> got = outline_text(spec);
  const double s = spec.size / units_per_em(file);
  const double shift = spec.align == TextAlign::left ? 0 : spec.align == TextAlign::center ? total / 2 : total;
  const double a = spec.angle * std::numbers::pi / 180;
  int halves = 0;
  EXPECT_EQ(got.size(), ref.size());
  for (size_t g = 0; g < std::min(got.size(), ref.size()); ++g) {
    ASSERT_EQ(got[g].contours.size(), ref[g].contours.size()) << "glyph " << g;
    for (size_t c = 0; c < ref[g].contours.size(); ++c) {
      const auto& rc = ref[g].contours[c];
      const auto& gc = got[g].contours[c].pieces;
      ASSERT_EQ(gc.size(), rc.size()) << "glyph " << g << " contour " << c;
      for (size_t k = 0; k < rc.size(); ++k) {
        ASSERT_EQ(gc[k].points.size(), rc[k].points.size()) << "glyph " << g << " contour " << c << " piece " << k;
        for (size_t j = 0; j < rc[k].points.size(); ++j) {
          const Vec3 f = rc[k].points[j];
          if (f.x != std::floor(f.x) || f.y != std::floor(f.y)) ++halves;
          const double x = (ref[g].pen_x + f.x - shift) * s, y = (ref[g].pen_y + f.y) * s;
          const Vec3 want{spec.at.x + std::cos(a) * x - std::sin(a) * y, spec.at.y + std::sin(a) * x + std::cos(a) * y,
                          0};
          EXPECT_NEAR(gc[k].points[j].x, want.x, 1e-9) << "glyph " << g << " contour " << c << " piece " << k;
          EXPECT_NEAR(gc[k].points[j].y, want.y, 1e-9) << "glyph " << g << " contour " << c << " piece " << k;
        }
      }
    }
  }
  if (halves_out) *halves_out = halves;
}

TextSpec spec(std::string text, std::string font, double size = 10) {
  TextSpec s;
  s.text = std::move(text);
  s.font = std::move(font);
  s.size = size;
  s.at = {3, 4, 0};
  return s;
}

TEST(FontText, TrueTypeOutlinesAreFreeTypesOwnQuadratics) {
  const TextSpec s = spec("No. 42 B8@&gQ", "DejaVu Sans");
  int halves = 0;
  expect_same_outlines(s, &halves);
  // Implied on-curve points between two quadratic controls at odd sums
  // lie on half units: taken exactly, not rounded to the unit.
  EXPECT_GT(halves, 0);
  bool quadratic = false;
  for (const Glyph& g : outline_text(s))
    for (const auto& c : g.contours)
      for (const Bezier& b : c.pieces) quadratic = quadratic || b.degree() == 2;
  EXPECT_TRUE(quadratic);
}

TEST(FontText, CffOutlinesAreFreeTypesOwnCubics) {
  const TextSpec s = spec("No. 42 B8@&gQ", "Nimbus Sans");
  ASSERT_EQ(find_font(s.font, {}).file.extension(), ".otf");
  expect_same_outlines(s);
  int cubics = 0;
  for (const Glyph& g : outline_text(s))
    for (const auto& c : g.contours)
      for (const Bezier& b : c.pieces) cubics += b.degree() == 3;
  EXPECT_GT(cubics, 10);
}

TEST(FontText, KerningMovesAPairAsHarfBuzzShapesIt) {
  // "AV" is kerned in both fonts: V sits closer to A than A's advance.
  for (const char* font : {"DejaVu Sans", "Nimbus Sans"}) {
    const TextSpec kerned = spec("AV", font);
    expect_same_outlines(kerned);
    const std::vector<Glyph> av = outline_text(kerned), v = outline_text(spec("V", font)),
                             a = outline_text(spec("A", font));
    // V alone at the pen's start, moved by A's nominal advance, would be
    // further right than V after A.
    const std::string file = find_font(font, {}).file.string();
    double advance_a = 0;
    reference(file, "A", &advance_a);
    const double s = 10.0 / units_per_em(file);
    const double dx = av[1].contours[0].pieces[0].points[0].x - v[0].contours[0].pieces[0].points[0].x;
    EXPECT_LT(dx, advance_a * s - 1e-3) << font;
    EXPECT_EQ(av[0].characters, "A");
    EXPECT_EQ(av[1].characters, "V");
  }
}

TEST(FontText, RotatedAndAlignedTextIsTheSameMap) {
  for (const char* font : {"DejaVu Sans", "Nimbus Sans"})
    for (TextAlign al : {TextAlign::left, TextAlign::center, TextAlign::right})
      for (double angle : {0.0, 30.0, 90.0, -135.0}) {
        TextSpec s = spec("Tab AV", font, 7.5);
        s.align = al;
        s.angle = angle;
        s.at = {-12.5, 40, 0};
        expect_same_outlines(s);
      }
}

TEST(FontText, CenteredTextIsCenteredOnTheAdvance) {
  TextSpec s = spec("HH", "DejaVu Sans");
  s.at = {0, 0, 0};
  s.align = TextAlign::center;
  const auto g = outline_text(s);
  // "HH" is symmetric: its ink is centred on the pen's start.
  Box3 b = bounds(g[0].contours[0].pieces[0]);
  for (const Glyph& x : g)
    for (const auto& c : x.contours)
      for (const Bezier& p : c.pieces) {
        const Box3 q = bounds(p);
        b.lo.x = std::min(b.lo.x, q.lo.x);
        b.hi.x = std::max(b.hi.x, q.hi.x);
      }
  EXPECT_NEAR(b.lo.x, -b.hi.x, 1e-9);
}

TEST(FontText, HolesAreTheCountersOfLetters) {
  for (const char* font : {"DejaVu Sans", "Nimbus Sans"}) {
    const auto g = outline_text(spec("B8@l", font));
    ASSERT_EQ(g.size(), 4u) << font;
    for (size_t k : {0, 1}) {  // B and 8: one outline, two counters
      ASSERT_EQ(g[k].contours.size(), 3u) << font << " " << g[k].characters;
      int holes = 0;
      for (const auto& c : g[k].contours) holes += c.hole;
      EXPECT_EQ(holes, 2) << font << " " << g[k].characters;
    }
    EXPECT_EQ(g[3].contours.size(), 1u);
    EXPECT_FALSE(g[3].contours[0].hole);
  }
}

TEST(FontText, EveryContourIsClosedEndToEnd) {
  for (const Glyph& g : outline_text(spec("Quartz & jig 0123456789", "Nimbus Sans")))
    for (const auto& c : g.contours) {
      ASSERT_FALSE(c.pieces.empty());
      EXPECT_EQ(c.pieces.back().back().x, c.pieces.front().front().x);
      EXPECT_EQ(c.pieces.back().back().y, c.pieces.front().front().y);
      for (size_t k = 1; k < c.pieces.size(); ++k) {
        EXPECT_EQ(c.pieces[k].front().x, c.pieces[k - 1].back().x);
        EXPECT_EQ(c.pieces[k].front().y, c.pieces[k - 1].back().y);
      }
    }
}

// ---- Refusals ------------------------------------------------------------

InputError refusal(const TextSpec& s) {
  try {
    outline_text(s);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "not refused: " << s.text << " in " << s.font;
  return InputError(errc::text_font, Place{}, "");
}

TEST(FontText, AFamilyNotInstalledIsRefusedNamingTheNearest) {
  const InputError e = refusal(spec("x", "DejaVu Sanz"));
  EXPECT_EQ(e.id(), errc::text_font.str());
  EXPECT_EQ(e.place().json_path, "font");
  EXPECT_NE(e.message().find("\"DejaVu Sanz\" is not installed"), std::string::npos) << e.message();
  EXPECT_NE(e.message().find("\"DejaVu Sans\""), std::string::npos) << e.message();
  // fontconfig substitutes silently; the substitute is named, not taken.
  EXPECT_NE(e.message().find("would substitute"), std::string::npos) << e.message();
  EXPECT_EQ(refusal(spec("x", "Helvetica")).id(), errc::text_font.str());
  EXPECT_EQ(refusal(spec("x", ":bold")).id(), errc::text_font.str());
}

TEST(FontText, ACharacterTheFontLacksIsNamedWithItsCodePoint) {
  const InputError e = refusal(spec("No \u6F22 here", "DejaVu Sans"));
  EXPECT_EQ(e.id(), errc::text_glyph.str());
  EXPECT_EQ(e.place().json_path, "text");
  EXPECT_NE(e.message().find("\"\u6F22\" (U+6F22)"), std::string::npos) << e.message();
  EXPECT_NE(e.message().find("DejaVu Sans"), std::string::npos) << e.message();
  const InputError line = refusal(spec("two\nlines", "DejaVu Sans"));
  EXPECT_EQ(line.id(), errc::text_glyph.str());
  EXPECT_NE(line.message().find("U+000A"), std::string::npos) << line.message();
}

TEST(FontText, AFileThatIsNotAFontIsRefused) {
  const auto dir = std::filesystem::temp_directory_path() / "bezcam_text_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "junk.ttf") << "this is not a font";
  TextSpec s = spec("x", "junk.ttf");
  s.folder = dir;
  const InputError e = refusal(s);
  EXPECT_EQ(e.id(), errc::text_font_file.str());
  EXPECT_EQ(e.place().json_path, "font");
  EXPECT_NE(e.message().find("junk.ttf is not a font"), std::string::npos) << e.message();
  s.font = "missing.otf";
  EXPECT_EQ(refusal(s).id(), errc::text_font_file.str());
  // A relative file is found in the folder given, the job file's.
  s.font = "DejaVuSans.ttf";
  s.folder = "/usr/share/fonts/truetype/dejavu";
  EXPECT_EQ(outline_text(s).size(), 1u);
  std::filesystem::remove_all(dir);
}

TEST(FontText, ASizeNotPositiveIsRefused) {
  for (double size : {0.0, -2.0, std::nan("")}) {
    const InputError e = refusal(spec("x", "DejaVu Sans", size));
    EXPECT_EQ(e.id(), errc::job_not_positive.str());
    EXPECT_EQ(e.place().json_path, "size");
  }
}

}  // namespace
}  // namespace bezcam::text
