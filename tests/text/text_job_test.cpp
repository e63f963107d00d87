// A job's `text` entity: read with the font outliner, each glyph contour
// an entity with the text's parameters, ids ID/0, ID/1, ..., holes on the
// other side of a part; the refusals named at the entity's keys; and text
// converted in lines, arcs and NURBS within the tolerance.
#include <gtest/gtest.h>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/text/font_text.hpp"

namespace bezcam {
namespace {

JobReadOptions with_text() {
  JobReadOptions o;
  o.text = text::font_outliner();
  return o;
}

std::string job_with(const std::string& text_entity, const std::string& job_keys = "") {
  return R"({"bezcam": 1, "units": "mm", "tolerance": 0.01,
    "job": {"feed": 600, "plunge_feed": 200, "safe_z": 5, "cut_z": -0.5)" +
         job_keys + R"(},
    "entities": [
      {"type": "bezier", "id": "before", "points": [[0, 0], [5, 5]]},
      )" +
         text_entity + R"(,
      {"type": "bezier", "id": "after", "points": [[0, 0], [5, 5]]}]})";
}

TEST(TextJob, GlyphContoursAreEntitiesWithTheTextsParameters) {
  const Job job = parse_job(
      job_with(R"({"type": "text", "id": "plate", "text": "A B", "font": "DejaVu Sans", "size": 8, "at": [10, 20],
                   "cut_z": -0.2, "side": "on"})"),
      "t.json", with_text());
  // before; A (2 contours); B (3 contours); after.
  ASSERT_EQ(job.entities.size(), 7u);
  for (size_t i = 0; i < job.entities.size(); ++i) EXPECT_EQ(job.entities[i].index, i);
  EXPECT_EQ(job.entities[0].json_path(), "entities[0]");
  for (size_t i = 1; i <= 5; ++i) {
    const Entity& e = job.entities[i];
    EXPECT_EQ(e.json_path(), "entities[1]");
    EXPECT_EQ(e.type, "text");
    EXPECT_EQ(e.id, i <= 2 ? "plate/0" : "plate/1");
    EXPECT_EQ(e.glyph, i <= 2 ? "A" : "B");
    EXPECT_TRUE(e.curve.closed);
    EXPECT_EQ(e.params.cut_z, -0.2);
    EXPECT_EQ(e.params.side, CutSide::on);
  }
  EXPECT_EQ(job.entities[6].id, "after");
  EXPECT_EQ(job.entities[6].json_path(), "entities[2]");
}

TEST(TextJob, HolesOfLettersTakeTheOtherSideOfAPart) {
  for (const std::string where : {"entity", "job"}) {
    const std::string side = R"("side": "outside", "tool_diameter": 0.5)";
    const Job job = parse_job(job_with(R"({"type": "text", "id": "t", "text": "B", "font": "Nimbus Sans", "size": 8)" +
                                           (where == "entity" ? ", " + side : "") + "}",
                                       where == "job" ? ", " + side : ""),
                              "t.json", with_text());
    int inside = 0, outside = 0;
    for (const Entity& e : job.entities) {
      if (e.type != "text") continue;
      const auto s = e.params.side ? e.params.side : job.params.side;
      inside += s == CutSide::inside;
      outside += s == CutSide::outside;
    }
    EXPECT_EQ(outside, 1) << where;
    EXPECT_EQ(inside, 2) << where;
  }
}

TEST(TextJob, ATextWithoutIdIsNamedByItsPath) {
  const Job job =
      parse_job(job_with(R"({"type": "text", "text": "l", "font": "DejaVu Sans", "size": 8})"), "t.json", with_text());
  EXPECT_EQ(job.entities[1].id, "entities[1]/0");
}

// The refusal of `entity` (in a job whose entity 1 it is).
InputError refusal(const std::string& entity, const JobReadOptions& o = with_text()) {
  try {
    parse_job(job_with(entity), "t.json", o);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "not refused: " << entity;
  return InputError(errc::text_font, Place{}, "");
}

TEST(TextJob, RefusalsNameTheKeyAndWhatToChange) {
  struct Case {
    std::string entity, id, path, says;
  };
  const std::vector<Case> cases = {
      {R"({"type": "text", "text": "x", "font": "No Such Family", "size": 8})", "text.font", "entities[1].font",
       "is not installed"},
      {R"({"type": "text", "text": "\u00e9\u6f22", "font": "DejaVu Sans", "size": 8})", "text.glyph",
       "entities[1].text", "U+6F22"},
      {R"({"type": "text", "text": "x", "font": "DejaVu Sans", "size": 0})", "job.not-positive", "entities[1].size",
       "> 0"},
      {R"({"type": "text", "text": "", "font": "DejaVu Sans", "size": 8})", "text.empty", "entities[1].text", "empty"},
      {R"({"type": "text", "text": "   ", "font": "DejaVu Sans", "size": 8})", "text.empty", "entities[1].text",
       "only spaces"},
      {R"({"type": "text", "text": "x", "font": "nofont.ttf", "size": 8})", "text.font-file", "entities[1].font",
       "nofont.ttf"},
      {R"({"type": "text", "text": "x", "font": "DejaVu Sans", "size": 8, "align": "middle"})", "job.cut",
       "entities[1].align", "\"center\""},
      {R"({"type": "text", "text": "x", "font": "DejaVu Sans", "size": 8, "at": [1, 2, 3]})", "job.type",
       "entities[1].at", "[x, y]"},
      {R"({"type": "text", "text": "x", "font": "DejaVu Sans", "sise": 8})", "job.key-typo", "entities[1].sise",
       "size"},
  };
  for (const Case& c : cases) {
    const InputError e = refusal(c.entity);
    EXPECT_EQ(e.id(), c.id) << c.entity << ": " << e.what();
    EXPECT_EQ(e.place().json_path, c.path) << c.entity << ": " << e.what();
    EXPECT_NE(e.message().find(c.says), std::string::npos) << e.message();
  }
  // Without an outliner (a library caller's reading), text is refused.
  const InputError none = refusal(R"({"type": "text", "text": "x", "font": "DejaVu Sans", "size": 8})", {});
  EXPECT_EQ(none.id(), errc::text_unavailable.str());
}

TEST(TextJob, TextConvertsWithinTheToleranceInEveryOutput) {
  const MachineProfile m = load_machine_profile("linuxcnc");
  for (const char* font : {"DejaVu Sans", "Nimbus Sans"})
    for (const char* side : {"on", "outside"})
      for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
        const Job job = parse_job(job_with(std::string(R"({"type": "text", "text": "AV8g", "font": ")") + font +
                                           R"(", "size": 12, "angle": 15, "align": "center", "tool_diameter": 0.4,
                                              "side": ")" +
                                           side + "\"}"),
                                  "t.json", with_text());
        ConvertOptions opt;
        opt.output = mode;
        const ConvertResult r = convert(job, m, opt);
        EXPECT_LE(r.program.max_measured, job.tolerance) << font << " " << side << " " << to_string(mode);
        EXPECT_LE(r.program.max_measured, r.program.max_bound);
        EXPECT_EQ(r.program.entities.size(), job.entities.size());
      }
}

}  // namespace
}  // namespace bezcam
