// The `text` entity of a job file (docs/text.md): its keys read here, its
// glyphs outlined by the TextOutliner of the read options, each glyph
// contour made a closed path entity with the text's cutting parameters.
#include <cmath>

#include "bezcam/job/text.hpp"
#include "job_json_detail.hpp"

namespace bezcam::detail {

namespace {

TextSpec read_spec(const JsonCtx& ctx, const json& obj, const std::string& path) {
  TextSpec s;
  s.text = ctx.string(ctx.require(obj, path, "text"), path + ".text");
  if (s.text.empty())
    ctx.fail(path + ".text", errc::text_empty, "expected the text to cut, found an empty string; write the letters");
  s.font = ctx.string(ctx.require(obj, path, "font"), path + ".font");
  if (s.font.empty())
    ctx.fail(path + ".font", errc::text_font,
             "expected a font family (for example \"DejaVu Sans\") or a font file, found an empty string");
  s.size = ctx.positive(ctx.require(obj, path, "size"), path + ".size");
  if (auto it = obj.find("at"); it != obj.end()) {
    if (!it->is_array() || it->size() != 2) ctx.expected(path + ".at", "a point [x, y]", *it);
    s.at = {ctx.number((*it)[0], path + ".at[0]"), ctx.number((*it)[1], path + ".at[1]"), 0};
  }
  if (auto it = obj.find("align"); it != obj.end()) {
    const std::string a = ctx.string(*it, path + ".align");
    if (a == "left")
      s.align = TextAlign::left;
    else if (a == "center")
      s.align = TextAlign::center;
    else if (a == "right")
      s.align = TextAlign::right;
    else
      ctx.fail(path + ".align", errc::job_cut, "expected \"left\", \"center\" or \"right\", found " + describe(*it));
  }
  if (auto it = obj.find("angle"); it != obj.end()) s.angle = ctx.number(*it, path + ".angle");
  if (ctx.options) s.folder = ctx.options->folder;
  return s;
}

}  // namespace

void parse_text_entity(const JsonCtx& ctx, const json& obj, const std::string& path, const Entity& e,
                       std::vector<Entity>& out) {
  const TextSpec spec = read_spec(ctx, obj, path);
  if (!ctx.options || !ctx.options->text)
    ctx.fail(path + ".type", errc::text_unavailable,
             "this program reads no fonts: text needs the job read with a text outliner (bezcam::text's "
             "font_outliner()); convert the text to paths, or use the bezcam program");
  const std::vector<Glyph> glyphs = ctx.at(path, [&] { return ctx.options->text(spec); });
  if (glyphs.empty())
    ctx.fail(path + ".text", errc::text_empty,
             "expected letters to cut, found only spaces (\"" + spec.text + "\" has no glyph with an outline)");
  // Each glyph's contours carry the text's parameters; a hole takes the
  // other side of a part (the job's side when the text gives none).
  const std::optional<CutSide> side = e.params.side    ? e.params.side
                                      : ctx.job_params ? ctx.job_params->side
                                                       : std::nullopt;
  const std::string base = e.id.empty() ? path : e.id;
  for (size_t g = 0; g < glyphs.size(); ++g) {
    for (const GlyphContour& c : glyphs[g].contours) {
      Entity ge = e;
      ge.id = base + "/" + std::to_string(g);
      ge.glyph = glyphs[g].characters;
      if (c.hole && (side == CutSide::inside || side == CutSide::outside)) ge.params.side = hole_side(side);
      size_t points = 0;
      for (const Bezier& b : c.pieces) points += b.points.size();
      ctx.count_bezier_points(points, path + ".text");
      ge.curve = ctx.at(path, [&] { return make_path(glyph_segments(c), c.pieces, true, 2); });
      out.push_back(std::move(ge));
    }
  }
}

}  // namespace bezcam::detail
