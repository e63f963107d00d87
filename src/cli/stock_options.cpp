#include "stock_options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace bezcam::cli {

namespace {

// The default grid: no more columns than this.
constexpr double kDefaultMaxColumns = 4e6;

}  // namespace

StockBox parse_stock_box(const std::string& text) {
  std::vector<double> v;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    const std::string part = text.substr(pos, comma - pos);
    char* end = nullptr;
    const double x = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !std::isfinite(x))
      throw InputError(errc::stock_box, Place::at_option("--stock"),
                       "expected six numbers x0,y0,z0,x1,y1,z1 in millimetres, found \"" + text + "\"");
    v.push_back(x);
    pos = comma + 1;
  }
  if (v.size() != 6)
    throw InputError(errc::stock_box, Place::at_option("--stock"),
                     "expected six numbers x0,y0,z0,x1,y1,z1 in millimetres, found " + std::to_string(v.size()));
  return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

std::size_t parse_memory_limit(const std::string& text) {
  if (text.empty()) return kDefaultStockMemoryLimit;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const std::string unit = end;
  double k = 0;
  if (unit.empty() || unit == "B") k = 1;
  if (unit == "K" || unit == "KiB") k = 1024.0;
  if (unit == "M" || unit == "MiB") k = 1024.0 * 1024;
  if (unit == "G" || unit == "GiB") k = 1024.0 * 1024 * 1024;
  if (unit == "KB") k = 1e3;
  if (unit == "MB") k = 1e6;
  if (unit == "GB") k = 1e9;
  if (end == text.c_str() || k == 0 || !(v > 0) || !std::isfinite(v * k) || v * k > 1e18)
    throw InputError(errc::usage_option, Place::at_option("--memory-limit"),
                     "expected a size such as 512MiB, 2GiB or a number of bytes, found \"" + text + "\"");
  return static_cast<std::size_t>(v * k);
}

double default_stock_cell(const StockBox& b, double tolerance_mm) {
  const double w = b.x1 - b.x0, h = b.y1 - b.y0;
  double c = std::max(tolerance_mm, std::sqrt(w * h / kDefaultMaxColumns));
  while (std::ceil(w / c) * std::ceil(h / c) > kDefaultMaxColumns) c *= 1.001;
  return c;
}

StockTools profile_stock_tools(const MachineProfile& m) {
  StockTools t;
  for (const auto& [d, mm] : m.tool_diameters_mm)
    if (mm > 0) t.emplace(d, ToolShape::flat(mm));
  return t;
}

Error stock_option_error(const Error& e) {
  return e.with_option(e.id() == errc::stock_memory.str() || e.id() == errc::stock_cell.str() ? "--cell" : "--stock");
}

}  // namespace bezcam::cli
