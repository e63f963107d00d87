// The preview is checked as a document, not as bytes: it must be well-formed
// XML with a viewBox and nothing external, and its elements must say what
// the job and the program say (one group per entity with its curve, control
// polygon and points, start and arrows; feeds and rapids told apart; a scale
// bar whose length is true; deviations that agree with the measured ones).
#include "bezcam/report/preview_svg.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "support/files.hpp"
#include "support/mini_xml.hpp"

namespace bezcam {
namespace {

using bezcam::test::slurp;

using testxml::Element;

struct Built {
  Job job;
  Program program;
  PreviewInput input;
};

Built build(const std::string& json, const std::string& machine = "generic") {
  Built b;
  b.job = parse_job(json, "test.json");
  const MachineProfile m = load_machine_profile(machine);
  b.program = build_program(b.job, m, ConvertOptions{});
  return b;
}

PreviewInput input_for(const Built& b) {
  PreviewInput in;
  in.job = &b.job;
  in.motion = program_motion(b.program);
  in.units = b.program.units;
  in.tolerance = b.program.tolerance;
  in.title = "bezcam preview: test.json";
  return in;
}

// Numbers of an SVG path's d attribute, as (x, y) pairs.
std::vector<std::pair<double, double>> points_of(const std::string& d) {
  std::vector<double> v;
  static const std::regex num(R"(-?[0-9]+(\.[0-9]+)?)");
  for (auto it = std::sregex_iterator(d.begin(), d.end(), num); it != std::sregex_iterator(); ++it)
    v.push_back(std::stod(it->str()));
  std::vector<std::pair<double, double>> pts;
  for (size_t i = 0; i + 1 < v.size(); i += 2) pts.push_back({v[i], v[i + 1]});
  return pts;
}

const std::string kTeardrop = slurp(BEZCAM_SOURCE_DIR "/samples/path-closed-teardrop.json");

TEST(PreviewSvg, IsWellFormedSelfContainedAndSized) {
  const Built b = build(kTeardrop);
  const std::string svg = preview_svg(input_for(b), PreviewOptions{});
  const Element root = testxml::parse(svg);
  EXPECT_EQ(root.name, "svg");
  EXPECT_EQ(root.attr("xmlns"), "http://www.w3.org/2000/svg");
  // The viewBox matches the width and height, so it scales in any viewer.
  std::istringstream vb(root.attr("viewBox"));
  double x0, y0, w, h;
  vb >> x0 >> y0 >> w >> h;
  EXPECT_EQ(x0, 0);
  EXPECT_EQ(y0, 0);
  EXPECT_EQ(w, 1200);
  EXPECT_EQ(std::stod(root.attr("width")), w);
  EXPECT_EQ(std::stod(root.attr("height")), h);
  // Nothing external: no links, images, scripts, styles from elsewhere.
  EXPECT_TRUE(root.by_name("image").empty());
  EXPECT_TRUE(root.by_name("script").empty());
  EXPECT_TRUE(root.by_name("use").empty());
  for (const auto* e : root.find_all([](const Element&) { return true; }))
    for (const auto& [k, v] : e->attrs) {
      EXPECT_EQ(k.find("href"), std::string::npos) << e->name;
      if (v.find("url(") != std::string::npos) EXPECT_EQ(v.rfind("url(#", 0), 0u) << v;
    }
  // Title and units are stated.
  ASSERT_EQ(root.by_name("title").empty(), false);
  EXPECT_EQ(root.by_class("title").at(0)->text, "bezcam preview: test.json");
  EXPECT_EQ(root.by_class("units").at(0)->text, "units: mm");
}

TEST(PreviewSvg, EntityGroupHoldsCurveControlPolygonPointsStartAndArrows) {
  const Built b = build(kTeardrop);
  const Element root = testxml::parse(preview_svg(input_for(b), PreviewOptions{}));
  // A 2D job: the top view only.
  ASSERT_NE(root.by_id("top-view"), nullptr);
  EXPECT_EQ(root.by_id("iso-view"), nullptr);
  const auto ents = root.by_class("entity");
  ASSERT_EQ(ents.size(), 1u);
  const Element& e = *ents[0];
  EXPECT_EQ(e.attr("data-entity"), "0");
  EXPECT_EQ(e.attr("data-id"), "teardrop");
  EXPECT_EQ(e.by_class("curve").size(), 1u);
  EXPECT_EQ(e.by_class("control-polygon").size(), 1u);
  // Three cubic pieces end to end: 4 + 3 + 3 control points (the closing
  // point coincides with the first but is its own control point).
  EXPECT_EQ(e.by_class("control-point").size(), 10u);
  EXPECT_EQ(e.by_class("start-point").size(), 1u);
  EXPECT_EQ(e.by_class("direction-arrow").size(), 2u);
  ASSERT_EQ(e.by_class("entity-label").size(), 1u);
  EXPECT_EQ(e.by_class("entity-label")[0]->text, "teardrop");

  // The curve starts at the start point, and so does the cut.
  const auto curve = points_of(e.by_class("curve")[0]->attr("d"));
  const Element& sp = *e.by_class("start-point")[0];
  EXPECT_NEAR(curve.front().first, std::stod(sp.attr("cx")), 1e-3);
  EXPECT_NEAR(curve.front().second, std::stod(sp.attr("cy")), 1e-3);
  // The closed path ends where it starts.
  EXPECT_NEAR(curve.back().first, curve.front().first, 1e-3);
  EXPECT_NEAR(curve.back().second, curve.front().second, 1e-3);

  // Without control polygons: none drawn, the rest still there.
  PreviewOptions no;
  no.control = false;
  const Element r2 = testxml::parse(preview_svg(input_for(b), no));
  EXPECT_TRUE(r2.by_class("control-polygon").empty());
  EXPECT_TRUE(r2.by_class("control-point").empty());
  EXPECT_EQ(r2.by_class("curve").size(), 1u);
}

TEST(PreviewSvg, BsplineControlPolygonIsTheOneInTheFile) {
  // The drawn control points are the de Boor points as written, not the
  // control points of the Bézier decomposition.
  const std::string text = slurp(BEZCAM_SOURCE_DIR "/samples/curve-bspline-wave.json");
  const Built b = build(text);
  ASSERT_EQ(b.job.entities.size(), 1u);
  const auto& seg = b.job.entities[0].curve.segments.at(0);
  ASSERT_TRUE(seg.nurbs);
  const Element root = testxml::parse(preview_svg(input_for(b), PreviewOptions{}));
  const auto cps = root.by_class("control-point");
  ASSERT_EQ(cps.size(), seg.nurbs->points.size());
  EXPECT_GT(b.job.entities[0].curve.pieces.size() * 3 + 1, cps.size());  // fewer than the pieces' points
  EXPECT_EQ(points_of(root.by_class("control-polygon").at(0)->attr("d")).size(), seg.nurbs->points.size());
}

TEST(PreviewSvg, ScaleBarIsTrueToTheDrawing) {
  // Control points (0,0) and (30,30) of the teardrop are 30*sqrt(2) apart.
  const Built b = build(kTeardrop);
  const Element root = testxml::parse(preview_svg(input_for(b), PreviewOptions{}));
  const auto bars = root.by_class("scale-bar");
  ASSERT_EQ(bars.size(), 1u);
  const double len = std::stod(bars[0]->attr("data-length"));
  const auto bar = points_of(bars[0]->by_name("path").at(0)->attr("d"));
  ASSERT_EQ(bar.size(), 4u);
  const double px_per_unit = (bar[2].first - bar[1].first) / len;
  EXPECT_GT(px_per_unit, 0);
  EXPECT_EQ(bars[0]->by_name("text").at(0)->text, std::to_string(int(len)) + " mm");
  const auto cps = root.by_class("control-point");
  const Element& p0 = *cps[0];  // (0, 0)
  const Element& p3 = *cps[3];  // (30, 30)
  const double dx = std::stod(p3.attr("cx")) - std::stod(p0.attr("cx"));
  const double dy = std::stod(p3.attr("cy")) - std::stod(p0.attr("cy"));
  EXPECT_NEAR(dx, 30 * px_per_unit, 2e-3);
  EXPECT_NEAR(dy, -30 * px_per_unit, 2e-3);  // y grows downwards on screen
}

TEST(PreviewSvg, FeedsAndRapidsAreDrawnDifferently) {
  const Built b = build(slurp(BEZCAM_SOURCE_DIR "/samples/job-exercises-all.json"));
  const Element root = testxml::parse(preview_svg(input_for(b), PreviewOptions{}));
  const auto rapids = root.by_class("rapid");
  ASSERT_EQ(rapids.size(), 1u);  // all rapids in one dashed path
  EXPECT_FALSE(rapids[0]->attr("stroke-dasharray").empty());
  const auto feeds = root.by_class("feed");
  ASSERT_EQ(feeds.size(), b.job.entities.size());  // one run per entity (plunges are invisible from above)
  for (size_t i = 0; i < feeds.size(); ++i) {
    EXPECT_TRUE(feeds[i]->attr("stroke-dasharray").empty());
    EXPECT_EQ(feeds[i]->attr("data-entity"), std::to_string(b.program.entities[i].entity));  // in the cut order
    EXPECT_NE(feeds[i]->attr("stroke"), rapids[0]->attr("stroke"));
    // One vertex per cutting block plus the start.
    EXPECT_EQ(points_of(feeds[i]->attr("d")).size(), b.program.entities[i].blocks + 1);
  }
  // Rapids between the 9 entities: each over-move is a visible subpath.
  const std::string rd = rapids[0]->attr("d");
  EXPECT_EQ(std::count(rd.begin(), rd.end(), 'M'), 8);
  EXPECT_EQ(root.by_class("entity").size(), 9u);
  EXPECT_EQ(root.by_class("legend").size(), 1u);
}

TEST(PreviewSvg, ThreeDimensionalWorkGetsAnIsometricView) {
  const Built b = build(slurp(BEZCAM_SOURCE_DIR "/samples/curve-cube-3d.json"));
  const Element root = testxml::parse(preview_svg(input_for(b), PreviewOptions{}));
  const Element* iso = root.by_id("iso-view");
  ASSERT_NE(iso, nullptr);
  EXPECT_EQ(iso->by_class("entity").size(), 1u);
  EXPECT_EQ(iso->by_class("scale-bar").size(), 1u);
  EXPECT_EQ(iso->by_class("axes").size(), 1u);
  // The plunge is visible from the side: the iso view has more feed paths
  // (the plunge joins the cut in one run) with a vertical stretch.
  const auto feeds = iso->by_class("feed");
  ASSERT_FALSE(feeds.empty());
  // The isometric projection keeps the entity's start: cube start (0,0,0),
  // the first control point; the control point (1,1,1) sits straight above
  // (1,1,0) on the page (z is vertical).
  const auto cps = iso->by_class("control-point");
  ASSERT_EQ(cps.size(), 4u);
  EXPECT_NEAR(std::stod(cps[2]->attr("cx")), std::stod(cps[3]->attr("cx")), 1e-3);
  EXPECT_GT(std::stod(cps[2]->attr("cy")), std::stod(cps[3]->attr("cy")));
}

TEST(PreviewSvg, DeviationColoursAgreeWithTheMeasuredDeviation) {
  for (const char* sample : {"path-closed-teardrop.json", "job-exercises-all.json", "curve-cube-3d.json"}) {
    SCOPED_TRACE(sample);
    const Built b = build(slurp(std::string(BEZCAM_SOURCE_DIR "/samples/") + sample));
    PreviewOptions o;
    o.deviation = true;
    const Element root = testxml::parse(preview_svg(input_for(b), o));
    const auto top = root.by_id("top-view")->by_class("feed");
    size_t blocks = 0;
    for (const auto& e : b.program.entities) blocks += e.blocks;
    std::vector<const Element*> coloured;
    for (const auto* f : top)
      if (f->has("data-deviation")) coloured.push_back(f);
    // In 2D every cutting block is drawn (plunges are not cutting blocks).
    if (std::string(sample) != "curve-cube-3d.json") EXPECT_EQ(coloured.size(), blocks);
    double mx = 0;
    for (const auto* f : coloured) {
      const double d = std::stod(f->attr("data-deviation"));
      EXPECT_GE(d, 0);
      EXPECT_LE(d, b.program.tolerance);
      mx = std::max(mx, d);
      EXPECT_NE(f->attr("stroke"), "#ff0000");  // within the tolerance: not the alarm colour
    }
    // The largest block deviation is the program's measured deviation, to
    // the accuracy both claim (a fraction of a per cent of the tolerance).
    EXPECT_NEAR(mx, b.program.max_measured, 3e-3 * b.program.tolerance);
    EXPECT_EQ(root.by_class("deviation-scale").size(), 1u);
  }
}

TEST(PreviewSvg, DeviationOfAForeignProgramIsMeasuredAgainstTheNearestCurve) {
  const Built b = build(slurp(BEZCAM_SOURCE_DIR "/samples/job-exercises-all.json"));
  auto motion = program_motion(b.program);
  const auto tagged = block_deviations(b.job, motion, b.program.tolerance);
  for (auto& m : motion) m.entity = -1;  // as if read back from G-code
  const auto untagged = block_deviations(b.job, motion, b.program.tolerance);
  ASSERT_EQ(tagged.size(), untagged.size());
  for (size_t i = 0; i < tagged.size(); ++i) {
    EXPECT_EQ(tagged[i].block, untagged[i].block);
    EXPECT_EQ(tagged[i].entity, untagged[i].entity);
    EXPECT_NEAR(tagged[i].deviation, untagged[i].deviation, 1e-12);
  }
  // A path moved 0.05 mm along X: no block can deviate by more than its
  // old deviation plus the shift, and where the curve runs across X (the
  // seeds' curves have vertical tangents) the cut is about 0.05 off. It is
  // drawn in the alarm colour.
  for (auto& m : motion) m.from.x += 0.05, m.to.x += 0.05;
  const auto moved = block_deviations(b.job, motion, b.program.tolerance);
  ASSERT_EQ(moved.size(), tagged.size());
  double mx = 0;
  for (size_t i = 0; i < moved.size(); ++i) {
    EXPECT_LE(moved[i].deviation, tagged[i].deviation + 0.05 + 1e-4);
    mx = std::max(mx, moved[i].deviation);
  }
  EXPECT_GT(mx, 0.05 - b.program.tolerance);
  PreviewInput in = input_for(b);
  in.motion = motion;
  PreviewOptions o;
  o.deviation = true;
  const std::string svg = preview_svg(in, o);
  EXPECT_NE(svg.find("class=\"feed over-tolerance\""), std::string::npos);
  // Unmistakable: the alarm red, wider, ringed, and counted in the legend.
  const Element root = testxml::parse(svg);
  const auto over = root.by_class("over-tolerance");
  ASSERT_FALSE(over.empty());
  EXPECT_EQ(over[0]->attr("stroke"), "#ff0000");
  EXPECT_EQ(over[0]->attr("stroke-width"), "6");
  EXPECT_EQ(root.by_class("over-tolerance-mark").size(), over.size());
  ASSERT_EQ(root.by_class("over-tolerance-count").size(), 1u);
  EXPECT_NE(root.by_class("over-tolerance-count")[0]->text.find(std::to_string(over.size()) + " block"),
            std::string::npos);
}

TEST(PreviewSvg, ColoursAreRelativeToTheTolerance) {
  // A program that uses 97 % of its tolerance keeps its promise: its
  // colour is far from the alarm red (the scale runs blue to green).
  for (double f : {0.0, 0.5, 0.97, 1.0}) {
    const std::string c = preview_deviation_colour(f * 0.01, 0.01);
    const int r = std::stoi(c.substr(1, 2), nullptr, 16), g = std::stoi(c.substr(3, 2), nullptr, 16);
    EXPECT_LT(r, 128) << f << " " << c;
    EXPECT_GT(g, 40) << f << " " << c;
  }
  EXPECT_EQ(preview_deviation_colour(0.0101, 0.01), "#ff0000");
}

TEST(PreviewSvg, TextIsEscaped) {
  const std::string job = R"({"bezcam": 1, "entities": [
    {"id": "a<b & \"c\" 'd'", "type": "bezier", "points": [[0, 0], [1, 2], [3, 0]]}]})";
  const Built b = build(job);
  PreviewInput in = input_for(b);
  in.warnings = {"refused: x < y & z"};
  const Element root = testxml::parse(preview_svg(in, PreviewOptions{}));
  EXPECT_EQ(root.by_class("entity-label").at(0)->text, "a<b & \"c\" 'd'");
  EXPECT_EQ(root.by_class("entity").at(0)->attr("data-id"), "a<b & \"c\" 'd'");
  EXPECT_EQ(root.by_class("warning").at(0)->text, "refused: x < y & z");
}

TEST(PreviewSvg, SurfacesAreDrawnAsIsoLinesWithTheirControlNet) {
  const std::string job = R"({"bezcam": 1, "entities": [
    {"id": "dome", "type": "bezier_patch",
     "points": [[[0,0,0],[0,20,5],[0,40,0]], [[20,0,5],[20,20,20],[20,40,5]], [[40,0,0],[40,20,5],[40,40,0]]]}]})";
  const Job j = parse_job(job, "patch.json");
  PreviewInput in;
  in.job = &j;
  const Element root = testxml::parse(preview_svg(in, PreviewOptions{}));
  ASSERT_NE(root.by_id("iso-view"), nullptr);
  const Element* e = root.by_id("iso-view")->by_class("entity").at(0);
  // Eleven lines each way, borders included; a 3 x 3 net: 3 rows and 3
  // columns in one polygon path, 9 points.
  EXPECT_EQ(e->by_class("iso-line").size(), 22u);
  EXPECT_EQ(e->by_class("control-point").size(), 9u);
  const std::string net = e->by_class("control-polygon").at(0)->attr("d");
  EXPECT_EQ(std::count(net.begin(), net.end(), 'M'), 6);
}

TEST(PreviewSvg, RefusesWhatItCannotDraw) {
  PreviewInput empty;
  try {
    preview_svg(empty, PreviewOptions{});
    FAIL() << "expected a refusal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.id(), "preview.empty");
  }
  const Built b = build(kTeardrop);
  PreviewInput no_job = input_for(b);
  no_job.job = nullptr;
  PreviewOptions dev;
  dev.deviation = true;
  EXPECT_THROW(preview_svg(no_job, dev), InputError);
  // A program alone (no job) is drawn.
  const Element root = testxml::parse(preview_svg(no_job, PreviewOptions{}));
  EXPECT_TRUE(root.by_class("entity").empty());
  EXPECT_FALSE(root.by_class("feed").empty());
}

TEST(PreviewSvg, PartCuttingShowsTheToolsWidthTabsAndMaterialLeft) {
  // The flange: tabs on its outline; the cam sample: a notch the tool cannot enter.
  const Built f = build(slurp(BEZCAM_SOURCE_DIR "/samples/part-flange.json"));
  PreviewInput in = input_for(f);
  add_part_cutting(in, f.program, f.job.entities.size());
  const std::string svg = preview_svg(in, PreviewOptions{});
  size_t swept = 0, tabs = 0;
  for (size_t at = svg.find("class=\"swept\""); at != std::string::npos; at = svg.find("class=\"swept\"", at + 1))
    ++swept;
  for (size_t at = svg.find("class=\"tab\""); at != std::string::npos; at = svg.find("class=\"tab\"", at + 1)) ++tabs;
  EXPECT_EQ(swept, f.job.entities.size());  // every entity is cut with a tool of known width
  EXPECT_EQ(tabs, 4u);                      // the outline's four tabs, on its deepest pass
  EXPECT_EQ(svg.find("material-left"), std::string::npos);

  const Built c = build(slurp(BEZCAM_SOURCE_DIR "/samples/part-cam-notch.json"));
  PreviewInput ic = input_for(c);
  add_part_cutting(ic, c.program, c.job.entities.size());
  const std::string cs = preview_svg(ic, PreviewOptions{});
  const size_t left = cs.find("class=\"material-left\"");
  ASSERT_NE(left, std::string::npos);
  EXPECT_NE(cs.find("data-entity=\"1\"", left), std::string::npos);  // on the notched disc
  EXPECT_NO_THROW(testxml::parse(cs));
}

}  // namespace
}  // namespace bezcam
