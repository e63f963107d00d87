// Pocketed text (docs/text.md, "Pocketed letters"): each glyph is one
// region, its counters islands, cleared with the pocket's certificate; a
// stroke narrower than the tool is named as unreachable with its place.
#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>

#include "bezcam/cam/pocket_check.hpp"
#include "bezcam/cam/program.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/text/font_text.hpp"

namespace bezcam {
namespace {

struct Built {
  Job job;
  Program program;
};

Built pocket(const std::string& text, const std::string& font, double size, double tool) {
  JobReadOptions o;
  o.text = text::font_outliner();
  const std::string json = R"({"bezcam": 1, "tolerance": 0.01,
    "job": {"feed": 600, "plunge_feed": 100, "safe_z": 5, "top_z": 0, "clearance": 1},
    "entities": [{"type": "text", "id": "t", "text": ")" +
                           text + R"(", "font": ")" + font + R"(", "size": )" + std::to_string(size) +
                           R"(, "operation": "pocket", "cut_z": -1, "tool_diameter": )" + std::to_string(tool) +
                           R"(, "stepover": )" + std::to_string(tool * 0.4) + "}]}";
  Built b{parse_job(json, "text.json", o), {}};
  b.program = build_program(b.job, load_machine_profile("linuxcnc"), ConvertOptions{});
  return b;
}

std::vector<const EntityReport*> pockets(const Program& p) {
  std::vector<const EntityReport*> out;
  for (const EntityReport& e : p.entities)
    if (e.pocket) out.push_back(&e);
  return out;
}

// The tool centre's positions on the cutting moves at depth z (lines and
// arcs by their end points, every move's end).
std::vector<Vec3> ends_at(const Program& p, double z) {
  std::vector<Vec3> out;
  Vec3 cur;
  for (const Move& mv : p.moves) {
    const Motion* m = motion_of(mv);
    if (!m) continue;
    if (m->axes & kAxisX) cur.x = m->to.x;
    if (m->axes & kAxisY) cur.y = m->to.y;
    if (m->axes & kAxisZ) cur.z = m->to.z;
    if (std::abs(cur.z - z) < 1e-9) out.push_back(cur);
  }
  return out;
}

// x0, y0, x1, y1 of an entity's control points.
std::array<double, 4> bounds_of(const Entity& e) {
  std::array<double, 4> b{1e9, 1e9, -1e9, -1e9};
  for (const Bezier& bz : e.curve.pieces)
    for (const Vec3& q : bz.points)
      b = {std::min(b[0], q.x), std::min(b[1], q.y), std::max(b[2], q.x), std::max(b[3], q.y)};
  return b;
}

TEST(TextPocket, EachGlyphIsOneRegionWithItsCountersAsIslands) {
  // "B" has two counters, "A" one: two regions of three and two curves.
  const Built b = pocket("BA", "DejaVu Sans", 20, 1);
  const auto ps = pockets(b.program);
  ASSERT_EQ(ps.size(), 2u);
  EXPECT_EQ(ps[0]->label, "t/0");
  EXPECT_EQ(ps[1]->label, "t/1");
  // B's contours: the outline (the widest) and its counters.
  std::vector<const Entity*> holes;
  for (const Entity& e : b.job.entities)
    if (e.id == "t/0") holes.push_back(&e);
  ASSERT_EQ(holes.size(), 3u);
  const auto width = [](const Entity* e) { return bounds_of(*e)[2] - bounds_of(*e)[0]; };
  holes.erase(std::max_element(holes.begin(), holes.end(),
                               [&](const Entity* a, const Entity* c) { return width(a) < width(c); }));
  for (const EntityReport* r : ps) {
    const PocketCertificate& c = *r->pocket;
    EXPECT_TRUE(c.covered()) << r->label << ": uncut " << c.uncut_area;
    EXPECT_TRUE(c.walls_kept(0.5, 0, 0.01)) << r->label << ": " << c.wall_distance;
    EXPECT_GE(c.wall_distance, 0.5) << r->label;
    EXPECT_EQ(c.rapids_in_material, 0u);
  }
  // The tool keeps out of B's counters: no position at depth within their
  // bounds shrunk by the radius.
  const std::vector<Vec3> at = ends_at(b.program, -1);
  ASSERT_FALSE(at.empty());
  for (const Entity* h : holes) {
    const auto [x0, y0, x1, y1] = bounds_of(*h);
    ASSERT_GT(x1 - x0, 2);
    for (const Vec3& q : at)
      EXPECT_FALSE(q.x > x0 + 0.5 && q.x < x1 - 0.5 && q.y > y0 + 0.5 && q.y < y1 - 0.5)
          << "tool centre in a counter at " << q.x << ", " << q.y;
  }
}

TEST(TextPocket, AStrokeNarrowerThanTheToolIsNamedWithItsPlace) {
  // DejaVu Sans Bold "M" at 11 mm: its slanted strokes meet in a V
  // narrower than a 1.6 mm tool, which clears the rest.
  const Built b = pocket("M", "DejaVu Sans:bold", 11, 1.6);
  const auto ps = pockets(b.program);
  ASSERT_EQ(ps.size(), 1u);
  const PocketCertificate& c = *ps[0]->pocket;
  ASSERT_FALSE(c.unreachable.empty());
  EXPECT_GT(c.unreachable_area, 1);
  EXPECT_TRUE(c.walls_kept(0.8, 0, 0.01));
  double x0 = 1e9, x1 = -1e9;
  for (const Entity& e : b.job.entities)
    for (const Bezier& bz : e.curve.pieces)
      for (const Vec3& q : bz.points) x0 = std::min(x0, q.x), x1 = std::max(x1, q.x);
  for (const PocketPlace& u : c.unreachable) {
    EXPECT_GE(u.at.x, x0);
    EXPECT_LE(u.at.x, x1);
  }
  const auto w = std::find_if(b.program.warnings.begin(), b.program.warnings.end(), [](const std::string& s) {
    return s.find("pocket region \"t/0\"") != std::string::npos && s.find("cannot reach") != std::string::npos;
  });
  ASSERT_NE(w, b.program.warnings.end());
  EXPECT_NE(w->find(" at ("), std::string::npos) << *w;
}

}  // namespace
}  // namespace bezcam
