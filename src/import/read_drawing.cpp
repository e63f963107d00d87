#include "bezcam/import/read_drawing.hpp"

#include <algorithm>
#include <cctype>

#include "bezcam/error.hpp"
#include "bezcam/import/dxf_reader.hpp"
#include "bezcam/import/svg_reader.hpp"
#include "bezcam/limits.hpp"

namespace bezcam::import {
namespace {
std::string lower_ext(const std::filesystem::path& f) {
  std::string e = f.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return e;
}
}  // namespace

bool is_drawing(const std::filesystem::path& file) {
  const std::string e = lower_ext(file);
  return e == ".svg" || e == ".dxf";
}

Drawing read_drawing(const std::filesystem::path& file, const ReadOptions& opt) {
  const std::string text = read_bounded(file, kMaxJobBytes, "drawing");
  const std::string source = file.string();
  if (lower_ext(file) != ".dxf") {
    Drawing d = read_svg(text, source);  // each subpath its own entity
    if (opt.scale != 1) scale_drawing(d, opt.scale);
    return d;
  }
  Drawing d = read_dxf(text, source);
  if (opt.scale != 1) scale_drawing(d, opt.scale);
  join_contours(d, opt.join_tolerance);
  return d;
}

}  // namespace bezcam::import
