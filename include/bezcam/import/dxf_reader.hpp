#pragma once
/// DXF drawings (ASCII) read exactly through libdime: LINE, ARC, CIRCLE,
/// ELLIPSE, LWPOLYLINE and POLYLINE (bulges as arcs), SPLINE (control
/// points, knots and weights as a NURBS; fit points only as an
/// interpolation), INSERT of blocks (scale, rotation, mirror), the
/// arbitrary axis algorithm for extrusion directions, `$INSUNITS`; TEXT
/// and MTEXT as the drawing's texts with their styles' fonts.
#include <string>
#include <string_view>

#include "bezcam/import/drawing.hpp"

namespace bezcam::import {

/// Reads the DXF text `text`; `source` names the file in messages. Each
/// entity is a contour of its layer (joined later, join_contours()), with
/// the id `LAYER:HANDLE`; each TEXT and MTEXT a DrawingText of the same id
/// (refused with errc::import_text, naming its layer, handle and point,
/// when a text entity cannot be what it asks for). HATCH, DIMENSION,
/// images and other entities that are not curves are counted as skipped,
/// per layer. Throws
/// InputError (errc::import_*) naming the file, the entity (handle) or the
/// line and group code, and what was expected.
Drawing read_dxf(std::string_view text, const std::string& source);

}  // namespace bezcam::import
