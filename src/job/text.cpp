#include "bezcam/job/text.hpp"

namespace bezcam {

std::optional<CutSide> hole_side(std::optional<CutSide> side) {
  if (side == CutSide::outside) return CutSide::inside;
  if (side == CutSide::inside) return CutSide::outside;
  return side;
}

std::vector<CurveSegment> glyph_segments(const GlyphContour& c) {
  std::vector<CurveSegment> segs;
  segs.reserve(c.pieces.size());
  for (size_t k = 0; k < c.pieces.size(); ++k) {
    CurveSegment s;
    s.kind = "bezier";
    s.degree = c.pieces[k].degree();
    s.first_piece = k;
    s.piece_count = 1;
    segs.push_back(std::move(s));
  }
  return segs;
}

}  // namespace bezcam
