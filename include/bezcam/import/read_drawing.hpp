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
  /// What a drawing unit is when the file does not say (Drawing's
  /// declared_units empty): "um", "mm", "cm", "m", "inch" or "foot"; empty:
  /// as read. A drawing that says another unit is refused.
  std::string units;
};

/// Millimetres per unit named `units` (ReadOptions::units). Throws
/// InputError (errc::usage_option, at the setting `drawing_units`) for
/// another name.
double mm_per_named_unit(const std::string& units);

/// True when the file name ends in .svg or .dxf (any case).
bool is_drawing(const std::filesystem::path& file);

/// Reads the drawing; a unitless one is scaled to `units`, then by `scale`;
/// a DXF's contours that meet end to end are then joined
/// (join_contours()); an SVG keeps each subpath as it is. Throws IoError
/// when the file cannot be read, InputError (limit.file-size,
/// errc::import_*) when it is too large or is not a drawing bezcam reads,
/// errc::import_units (at the setting `drawing_units`) when the drawing
/// says a unit other than `units`.
Drawing read_drawing(const std::filesystem::path& file, const ReadOptions& opt = {});

}  // namespace bezcam::import
