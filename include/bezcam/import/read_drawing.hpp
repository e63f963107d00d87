#pragma once
/// Reading a drawing file by its kind: `.svg` (svg_reader.hpp) or `.dxf`
/// (dxf_reader.hpp), at most kMaxJobBytes (refused before it is read).
#include <filesystem>
#include <string>

#include "bezcam/import/drawing.hpp"

namespace bezcam::import {

/// How a drawing is read: its coordinates multiplied by `scale` (> 0), a
/// DXF's contours joined within `join_tolerance` (0: the default,
/// join_contours()).
struct ReadOptions {
  double scale = 1;
  double join_tolerance = 0;
};

/// True when the file name ends in .svg or .dxf (any case).
bool is_drawing(const std::filesystem::path& file);

/// Reads the drawing; a DXF's contours that meet end to end are then
/// joined (join_contours()); an SVG keeps each subpath as it is. Throws IoError when the file cannot be read,
/// InputError (limit.file-size, errc::import_*) when it is too large or is
/// not a drawing bezcam reads.
Drawing read_drawing(const std::filesystem::path& file, const ReadOptions& opt = {});

}  // namespace bezcam::import
