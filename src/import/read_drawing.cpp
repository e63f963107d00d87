#include "bezcam/import/read_drawing.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "bezcam/error.hpp"
#include "bezcam/import/dxf_reader.hpp"
#include "bezcam/import/svg_reader.hpp"
#include "bezcam/limits.hpp"

namespace bezcam::import {
namespace {
// The units a drawing is read in: a unitless drawing's unit is scaled to
// the one asked for; a drawing that says another is refused.
void apply_units(Drawing& d, const std::string& units) {
  if (units.empty()) return;
  const double mm = mm_per_named_unit(units);
  if (!d.declared_units.empty()) {
    if (std::abs(d.declared_mm - mm) <= 1e-12 * mm) return;
    throw InputError(errc::import_units, Place::at_setting("drawing_units"),
                     d.source + " says its unit is " + d.declared_units + ", not " + units +
                         "; leave the units out to read it in its own, or scale it");
  }
  scale_drawing(d, mm / d.mm_per_unit);
  d.mm_per_unit = mm;
}

std::string lower_ext(const std::filesystem::path& f) {
  std::string e = f.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}
}  // namespace

double mm_per_named_unit(const std::string& units) {
  static const std::pair<const char*, double> known[] = {{"um", 1e-3}, {"mm", 1},      {"cm", 10},
                                                         {"m", 1000},  {"inch", 25.4}, {"foot", 304.8}};
  for (const auto& [name, mm] : known)
    if (units == name) return mm;
  throw InputError(errc::usage_option, Place::at_setting("drawing_units"),
                   "expected um, mm, cm, m, inch or foot, found \"" + units + "\"");
}

bool is_drawing(const std::filesystem::path& file) {
  const std::string e = lower_ext(file);
  return e == ".svg" || e == ".dxf";
}

Drawing read_drawing(const std::filesystem::path& file, const ReadOptions& opt) {
  const std::string text = read_bounded(file, kMaxJobBytes, "drawing");
  const std::string source = file.string();
  if (lower_ext(file) != ".dxf") {
    Drawing d = read_svg(text, source);  // each subpath its own entity
    apply_units(d, opt.units);
    if (opt.scale != 1) scale_drawing(d, opt.scale);
    return d;
  }
  Drawing d = read_dxf(text, source);
  apply_units(d, opt.units);
  if (opt.scale != 1) scale_drawing(d, opt.scale);
  join_contours(d, opt.join_tolerance);
  return d;
}

}  // namespace bezcam::import
