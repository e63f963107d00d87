#pragma once
/// SVG drawings (SVG 1.1 geometry) read exactly, through SVG++ over libxml2:
/// path commands M L H V C S Q T A Z (absolute and relative) as given,
/// shapes (rect with rounded corners, circle, ellipse, line, polyline,
/// polygon), `use` of them and of groups, nested transforms (on groups and
/// on each element) applied to the control points, lengths in
/// millimetres from `width`, `height` and `viewBox` (96 user units per
/// inch when unitless), y up (y' = page height - y).
#include <string>
#include <string_view>

#include "bezcam/import/drawing.hpp"

namespace bezcam::import {

/// Reads the SVG text `text`; `source` names the file in messages. Each
/// subpath is a contour (closed where `Z` closes it), with the element's
/// id (`logo`, then `logo.2`, ... for further subpaths; elements without
/// an id are called `path@line 12`; what a `use` draws is prefixed with
/// its id and a slash, `u1/slot`). Elements that are not geometry (text,
/// image, a use of a symbol ...) are counted as skipped. Throws InputError
/// (errc::import_*) naming the file, the element (id and line) and what
/// was expected.
Drawing read_svg(std::string_view text, const std::string& source);

}  // namespace bezcam::import
