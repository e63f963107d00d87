// DXF TEXT and MTEXT (tests/import/data/text/, written by ezdxf with
// make_text_dxf.py): the string with its codes resolved, the height of the
// capitals, the alignment point, the angle and the style's font read; the
// job's text laid out so that the letters measure and sit as the drawing
// says (DejaVu Sans); the job written by `import` reads as the job built
// in memory; the program read back lies within the tolerance of the
// letters; what a text entity cannot be refused, naming where it is.
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/import/drawing.hpp"
#include "bezcam/import/dxf_reader.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/text/font_text.hpp"
#include "import/dxf_reader_impl.hpp"
#include "support/cutting_runs.hpp"
#include "support/drawing_fonts.hpp"

namespace bezcam::import {
namespace {

namespace fs = std::filesystem;
const fs::path kData = fs::path(BEZCAM_SOURCE_DIR) / "tests/import/data/text";

ImportOptions with_fonts() { return test::with_fonts(); }

const DrawingText& text_of(const Drawing& d, const std::string& id) {
  for (const DrawingText& t : d.texts)
    if (t.id == id) return t;
  throw std::runtime_error("no text " + id);
}

// The bounds of the control points of the entities whose id starts with
// `prefix` (the glyphs of one text, or one glyph), in the frame turned by
// `angle` degrees about `origin`: x along the line, y up from it.
struct Box {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
};
Box local_box(const Job& job, const std::string& prefix, Vec3 origin, double angle) {
  const double a = angle * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
  Box b;
  for (const Entity& e : job.entities)
    if (e.id.rfind(prefix, 0) == 0)
      for (const Bezier& p : e.curve.pieces)
        for (const Vec3& q : p.points) {
          const double dx = q.x - origin.x, dy = q.y - origin.y;
          const double x = c * dx + s * dy, y = -s * dx + c * dy;
          b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x), b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
        }
  return b;
}

TEST(DxfText, ReadsTheStringHeightPlacementAndStyle) {
  const Drawing d = read_drawing(kData / "text.dxf");
  ASSERT_EQ(d.texts.size(), 6u);
  EXPECT_EQ(d.layers.at("NOTES").read.at("TEXT"), 5u);
  EXPECT_EQ(d.layers.at("MARKS").read.at("MTEXT"), 1u);
  const DrawingText& hello = text_of(d, "NOTES:31");
  EXPECT_EQ(hello.text, "HELLO");
  EXPECT_EQ(hello.font, "DejaVuSans.ttf");
  EXPECT_EQ(hello.style, "SANS");
  EXPECT_FALSE(hello.stroke_font);
  EXPECT_EQ(hello.height, 5);
  EXPECT_EQ(hello.at.x, 10);
  EXPECT_EQ(hello.at.y, 10);
  EXPECT_EQ(hello.along, 0);
  EXPECT_EQ(hello.vertical, DrawingText::Vertical::baseline);
  const DrawingText& turned = text_of(d, "NOTES:32");
  EXPECT_EQ(turned.angle, 30);
  EXPECT_EQ(turned.along, 0.5);
  EXPECT_EQ(turned.vertical, DrawingText::Vertical::middle);
  EXPECT_EQ(turned.at.x, 50);
  EXPECT_EQ(turned.at.y, 20);
  EXPECT_EQ(text_of(d, "NOTES:33").along, 1);
  EXPECT_EQ(text_of(d, "NOTES:33").vertical, DrawingText::Vertical::top);
  EXPECT_EQ(text_of(d, "NOTES:34").vertical, DrawingText::Vertical::bottom);
  const DrawingText& aligned = text_of(d, "NOTES:35");
  ASSERT_TRUE(aligned.to);
  EXPECT_EQ(aligned.to->x, 60);
  EXPECT_EQ(aligned.to->y, 50);
  const DrawingText& m = text_of(d, "MARKS:36");
  EXPECT_EQ(m.element, "MTEXT (handle 36)");
  EXPECT_EQ(m.text, "MTEXT \u00B10.1 1/2");
  EXPECT_EQ(m.angle, 90);
  EXPECT_EQ(m.height, 3);
  EXPECT_EQ(m.along, 0.5);
  EXPECT_EQ(m.vertical, DrawingText::Vertical::middle);
}

TEST(DxfText, FormattingCodesAreResolved) {
  using dxf::mtext_plain, dxf::percent_codes;
  EXPECT_EQ(mtext_plain("{\\fArial|b1|i0|c0|p34;A}\\H2.5x;B\\C1;C\\W0.8;D"), "ABCD");
  EXPECT_EQ(mtext_plain("A\\PB"), "A\nB");
  EXPECT_EQ(mtext_plain("A\\~B\\\\C\\{D\\}"), "A B\\C{D}");
  EXPECT_EQ(mtext_plain("\\U+00D8 10"), "\u00D8 10");
  EXPECT_EQ(mtext_plain("\\S3^4;\\S1#8; \\Lunder\\l\\Oover\\o"), "3/41/8 underover");
  EXPECT_EQ(percent_codes("%%c12 %%d %%p0.1 100%%% %%uU%%u %%065"), "\u00D812 \u00B0 \u00B10.1 100% U A");
}

TEST(DxfText, CapitalsAreTheTextsHeightAndSitAtItsAlignmentPoint) {
  const Drawing d = read_drawing(kData / "text.dxf");
  const Job job = to_job(d, with_fonts());
  TextSpec hih;
  hih.text = "HIH";
  hih.font = "DejaVu Sans";
  const text::TextMeasures dejavu = text::measure_text(hih);
  // DejaVu Sans: 2048 units per em, capitals 1493 high: an em of
  // height * 2048 / 1493.
  EXPECT_EQ(dejavu.units_per_em, 2048);
  EXPECT_EQ(dejavu.cap_height, 1493);
  const double eps = 1e-12 * 100;
  // HELLO, left on the baseline at (10, 10), capitals 5 high: the H from
  // y 10 to 15.
  const Box h = local_box(job, "NOTES:31/0", {10, 10, 0}, 0);
  EXPECT_NEAR(h.y0, 0, eps);
  EXPECT_NEAR(h.y1, 5, eps);
  // HIH turned 30 degrees, its middle (half the capitals, half the
  // advance) at (50, 20): capitals 4 high from -2 to 2, the ink (H and I
  // have equal side bearings in DejaVu Sans) centred.
  const Box mid = local_box(job, "NOTES:32/", {50, 20, 0}, 30);
  EXPECT_NEAR(mid.y0, -2, eps);
  EXPECT_NEAR(mid.y1, 2, eps);
  EXPECT_NEAR(mid.x0 + mid.x1, 0, eps);
  // HIT top right at (100, 0): the capitals hang 3 below it.
  const Box top = local_box(job, "NOTES:33/", {100, 0, 0}, 0);
  EXPECT_NEAR(top.y0, -3, eps);
  EXPECT_NEAR(top.y1, 0, eps);
  EXPECT_LT(std::abs(top.x1), 0.1);  // the T's ink ends near the advance's end
  // HIH bottom left at (0, 30), 2 high: the baseline is the descender's
  // depth above the point.
  const Box bottom = local_box(job, "NOTES:34/", {0, 30, 0}, 0);
  EXPECT_NEAR(bottom.y0, -dejavu.descender * 2 / dejavu.cap_height, eps);
  EXPECT_NEAR(bottom.y1 - bottom.y0, 2, eps);
  // HIH aligned from (0, 40) to (60, 50): the advance spans the points,
  // the ink centred between them, standing on the line between them.
  const double angle = std::atan2(10, 60) * 180 / std::numbers::pi, length = std::hypot(60, 10);
  const Box al = local_box(job, "NOTES:35/", {0, 40, 0}, angle);
  EXPECT_NEAR(al.y0, 0, eps);
  EXPECT_NEAR(al.x0 + al.x1, length, eps);
  EXPECT_NEAR(al.y1, length / dejavu.advance * dejavu.cap_height, eps);
  // The MTEXT turned 90 degrees, its middle centre at (120, 30): its M
  // from -1.5 to 1.5 across the line.
  const Box m = local_box(job, "MARKS:36/0", {120, 30, 0}, 90);
  EXPECT_NEAR(m.y0, -1.5, eps);
  EXPECT_NEAR(m.y1, 1.5, eps);
  // Where the glyphs come from, for messages.
  for (const Entity& e : job.entities)
    if (e.id.rfind("MARKS:36/", 0) == 0) EXPECT_EQ(e.origin, "layer \"MARKS\", MTEXT (handle 36), at (120, 30)");
}

TEST(DxfText, TheImportedJobReadsAsTheJobBuiltInMemory) {
  const Drawing d = read_drawing(kData / "text.dxf");
  for (const char* units : {"mm", "inch"}) {
    ImportOptions o = with_fonts();
    o.settings = {{"units", units}, {"side", "outside"}, {"tool_diameter", "0.1"}};
    const Job built = to_job(d, o);
    JobReadOptions ro;
    ro.text = text::font_outliner();
    const Job read = parse_job(job_json(d, o), d.source, ro);
    ASSERT_EQ(built.entities.size(), read.entities.size());
    for (size_t i = 0; i < built.entities.size(); ++i) {
      const Entity &a = built.entities[i], &b = read.entities[i];
      EXPECT_EQ(a.id, b.id);
      EXPECT_EQ(a.type, b.type);
      EXPECT_EQ(a.glyph, b.glyph);
      EXPECT_EQ(a.json_path(), b.json_path());
      EXPECT_EQ(a.params.side, b.params.side) << a.id;
      ASSERT_EQ(a.curve.pieces.size(), b.curve.pieces.size());
      for (size_t k = 0; k < a.curve.pieces.size(); ++k) EXPECT_EQ(a.curve.pieces[k].points, b.curve.pieces[k].points);
    }
  }
}

// Dense points of a read-back block (the reader's own evaluation).
void sample(const MotionBlock& b, std::vector<Vec3>& out) {
  for (int k = 1; k <= 64; ++k) out.push_back(evaluate_block(b, k / 64.0));
}

TEST(DxfText, TheProgramReadBackLiesWithinTheToleranceOfTheLetters) {
  const Drawing d = read_drawing(kData / "text.dxf");
  ImportOptions o = with_fonts();
  o.only = {"NOTES:31", "MARKS"};
  const Job job = to_job(d, o);
  for (const OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
    SCOPED_TRACE(to_string(mode));
    const MachineProfile m = load_machine_profile(mode == OutputMode::nurbs ? "linuxcnc" : "generic");
    ConvertOptions co;
    co.output = mode;
    const ConvertResult r = convert(job, m, co);
    const auto runs = test::cutting_runs(read_gcode(r.gcode, &m));
    ASSERT_EQ(runs.size(), job.entities.size());
    for (size_t i = 0; i < runs.size(); ++i) {
      const Entity& e = job.entities[size_t(r.program.entities[i].entity)];
      std::vector<Vec3> poly{runs[i][0].to};
      for (size_t k = 1; k < runs[i].size(); ++k) {
        if (runs[i][k].kind == BlockKind::linear)
          poly.push_back(runs[i][k].to);
        else
          sample(runs[i][k], poly);
      }
      for (Vec3& p : poly) p.z = 0;
      const Deviation dev = measure_deviation(e.curve.pieces, poly, job.tolerance);
      EXPECT_LE(dev.max(), job.tolerance) << e.id;
    }
  }
}

// A DXF of one entity (the groups after `0\nTEXT\n`), with a STYLE table.
std::string dxf_with(const std::string& type, const std::string& groups) {
  return "0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nSTYLE\n0\nSTYLE\n2\nSANS\n3\nDejaVuSans.ttf\n0\nENDTAB\n0\nENDSEC\n"
         "0\nSECTION\n2\nENTITIES\n0\n" +
         type + "\n5\n2A\n8\nNOTES\n7\nSANS\n10\n3\n20\n4\n" + groups + "0\nENDSEC\n0\nEOF\n";
}

std::string refusal(const std::string& dxf, const ImportOptions& o = with_fonts()) {
  try {
    const Drawing d = read_dxf(dxf, "t.dxf");
    (void)to_job(d, o);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.id()), "import.text") << e.what();
    return e.what();
  }
  return "accepted";
}

TEST(DxfText, WhatATextEntityCannotBeIsRefusedWhereItIs) {
  const std::string at = "t.dxf: layer \"NOTES\", TEXT (handle 2A) at (3, 4): ";
  EXPECT_EQ(refusal(dxf_with("TEXT", "40\n2\n1\nAB\n")), "accepted");
  EXPECT_EQ(refusal(dxf_with("TEXT", "40\n2\n41\n0.8\n1\nAB\n")).rfind(at + "a width factor of 0.8", 0), 0u);
  EXPECT_EQ(refusal(dxf_with("TEXT", "40\n2\n51\n15\n1\nAB\n")).rfind(at + "an oblique angle of 15", 0), 0u);
  EXPECT_EQ(refusal(dxf_with("TEXT", "40\n2\n71\n2\n1\nAB\n")).rfind(at + "mirrored text", 0), 0u);
  EXPECT_EQ(refusal(dxf_with("TEXT", "40\n2\n72\n5\n11\n9\n21\n4\n1\nAB\n")).rfind(at + "text fitted", 0), 0u);
  EXPECT_EQ(refusal(dxf_with("TEXT", "40\n0\n1\nAB\n")).rfind(at + "expected a text height > 0", 0), 0u);
  EXPECT_EQ(refusal(dxf_with("TEXT", "40\n2\n210\n0\n220\n0\n230\n-1\n1\nAB\n"))
                .rfind(at + "expected text in the drawing's XY plane", 0),
            0u);
  EXPECT_EQ(
      refusal(dxf_with("MTEXT", "40\n2\n1\nA\\PB\n"))
          .rfind("t.dxf: layer \"NOTES\", MTEXT (handle 2A) at (3, 4): expected one line of text, found several", 0),
      0u);
}

TEST(DxfText, AStrokeFontIsRefusedUnlessASettingNamesAFont) {
  const Drawing d = read_drawing(kData / "text-shx.dxf");
  ASSERT_EQ(d.texts.size(), 1u);
  EXPECT_TRUE(d.texts[0].stroke_font);
  try {
    (void)to_job(d, with_fonts());
    ADD_FAILURE() << "an SHX font was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), errc::import_text);
    EXPECT_NE(std::string(e.what()).find("layer \"NOTES\", TEXT (handle 32) at (20, 25): its style \"ROMANS\" names "
                                         "the stroke font \"romans.shx\" (SHX)"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("set 'NOTES:font=DejaVu Sans'"), std::string::npos) << e.what();
  }
  ImportOptions o = with_fonts();
  o.scoped = {{"NOTES", "font", "DejaVu Serif"}};
  const Job job = to_job(d, o);
  size_t glyphs = 0;
  for (const Entity& e : job.entities) glyphs += e.type == "text";
  EXPECT_GT(glyphs, 5u);  // PART 7: five glyphs, A and R with a counter
  EXPECT_NE(job_json(d, o).find("\"font\": \"DejaVu Serif\""), std::string::npos);
  // A font the setting names must be installed: refused at the setting.
  o.scoped = {{"NOTES", "font", "No Such Family Bezcam"}};
  try {
    (void)to_job(d, o);
    ADD_FAILURE() << "an unknown family was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), errc::text_font);
    EXPECT_EQ(e.place().setting, "settings.NOTES:font");
  }
  // A text key whose selector picks no text.
  o.scoped = {{"OUTLINE", "font", "DejaVu Sans"}};
  EXPECT_THROW((void)to_job(d, o), InputError);
}

TEST(DxfText, AFontThatIsNotInstalledIsReplacedWithAWarning) {
  const Drawing d = read_drawing(kData / "text-missing-font.dxf");
  std::vector<std::string> warnings;
  const Job job = to_job(d, with_fonts(), &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("names the font \"no-such-font-bezcam.ttf\", which is not installed; it is cut in \"" +
                             text::default_font().family + "\" instead"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("[font-substituted]"), std::string::npos);
  // The capitals still measure the drawing's height.
  const Box h = local_box(job, "NOTES:32/0", {20, 25, 0}, 0);
  EXPECT_NEAR(h.y1 - h.y0, 5, 1e-9);
}

TEST(DxfText, WithoutFontsATextIsRefusedNotDropped) {
  const Drawing d = read_drawing(kData / "text.dxf");
  try {
    (void)to_job(d);
    ADD_FAILURE() << "text without fonts was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), errc::text_unavailable);
  }
  ImportOptions o;
  o.skip = {"NOTES", "MARKS"};
  EXPECT_EQ(to_job(d, o).entities.size(), 1u);
}

}  // namespace
}  // namespace bezcam::import
