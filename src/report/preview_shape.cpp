// What the preview draws of an entity and measures its cut against: the
// exact curves, control polygons and points (preview_draw.hpp, Shape).
#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/kernel/surface.hpp"
#include "preview_draw.hpp"

namespace bezcam::preview {

// Iso-parameter lines drawn per direction on a surface (borders included).
constexpr int kIsoLines = 10;

Shape entity_shape(const Entity& e) {
  Shape s;
  // A point where one piece or segment starts as the previous one ended is
  // drawn once.
  auto add_points = [&](const std::vector<Vec3>& pts) {
    for (size_t j = 0; j < pts.size(); ++j)
      if (j > 0 || s.control_points.empty() || !(s.control_points.back() == pts[j])) s.control_points.push_back(pts[j]);
  };
  auto add_polygons = [&](const std::vector<Bezier>& pieces) {
    for (const Bezier& pc : pieces) {
      s.polygons.push_back(pc.points);
      add_points(pc.points);
    }
  };
  if (!e.curve.pieces.empty()) {
    s.chains.push_back(e.curve.pieces);
    s.measure = e.curve.pieces;
    s.dim = e.curve.dim;
    s.closed = e.curve.closed;
    // The control polygon the user wrote: a B-spline's de Boor points, a
    // Bézier segment's own points (not the pieces of a decomposition).
    for (const CurveSegment& seg : e.curve.segments) {
      if (seg.nurbs) {
        s.polygons.push_back(seg.nurbs->points);
        add_points(seg.nurbs->points);
      } else {
        add_polygons(
            std::vector<Bezier>(e.curve.pieces.begin() + static_cast<long>(seg.first_piece),
                                e.curve.pieces.begin() + static_cast<long>(seg.first_piece + seg.piece_count)));
      }
    }
  } else if (e.surface && !e.uv_curve.pieces.empty()) {
    // The exact 3D curve S(c(w)): what the tool follows.
    s.measure = map_curve(*e.surface, e.uv_curve, false).points;
    s.chains.push_back(s.measure);
    s.dim = 3;
    s.closed = e.uv_curve.closed;
    add_polygons(s.measure);
  } else if (e.surface) {
    s.surface = true;
    s.dim = 3;
    for (int k = 0; k <= kIsoLines; ++k) {
      const double at = double(k) / kIsoLines;
      s.chains.push_back(iso_curve(*e.surface, 'u', at, false).points);
      s.chains.push_back(iso_curve(*e.surface, 'v', at, false).points);
    }
    // The control net of every cell: its rows and its columns.
    for (const BezierPatch& c : e.surface->grid.cells) {
      for (int i = 0; i <= c.nu; ++i) {
        std::vector<Vec3> row;
        for (int j = 0; j <= c.nv; ++j) row.push_back(c.at(i, j)), s.control_points.push_back(c.at(i, j));
        s.polygons.push_back(std::move(row));
      }
      for (int j = 0; j <= c.nv; ++j) {
        std::vector<Vec3> col;
        for (int i = 0; i <= c.nu; ++i) col.push_back(c.at(i, j));
        s.polygons.push_back(std::move(col));
      }
    }
  }
  return s;
}

bool is_plunge(std::span<const MotionBlock> m, size_t i) {
  const MotionBlock& b = m[i];
  if (!is_feed(b) || b.from.x != b.to.x || b.from.y != b.to.y || !(b.to.z < b.from.z)) return false;
  return i == 0 || m[i - 1].kind == BlockKind::rapid;
}

}  // namespace bezcam::preview
