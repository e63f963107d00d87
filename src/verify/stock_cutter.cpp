#include "bezcam/verify/stock_cutter.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "bezcam/error.hpp"

namespace bezcam {

namespace {

// Moves gathered before a batch is swept: enough for the threads to share
// rows, few enough that a tool change does not wait long.
constexpr std::size_t kBatch = 4096;

// A floor lowered by less than this is not a cut (a rapid grazing the
// surface it left a micrometre above).
constexpr double kCutMm = 1e-6;

Vec3 scaled(const Vec3& p, double k) { return {p.x * k, p.y * k, p.z * k}; }

Sweep to_sweep(const MotionBlock& b, double curve_tolerance) {
  switch (b.kind) {
    case BlockKind::rapid:
    case BlockKind::linear: return Sweep::line(b.from, b.to);
    case BlockKind::arc_cw:
    case BlockKind::arc_ccw: return Sweep::arc(block_arc(b));
    case BlockKind::nurbs:
    case BlockKind::bezier: {
      const std::vector<Bezier> pieces = block_to_bezier(b);
      return Sweep::curve(pieces, curve_tolerance);
    }
  }
  return Sweep::line(b.from, b.to);
}

std::string tool_list(const StockTools& tools) {
  if (tools.empty()) return "the tools table is empty";
  std::string s = "the tools table has ";
  bool first = true;
  for (const auto& [n, t] : tools) {
    s += (first ? "T" : ", T") + std::to_string(n) + " (" + t.describe() + ")";
    first = false;
  }
  return s;
}

}  // namespace

ToolShape stock_tool_shape(const ToolEntry& t) {
  switch (t.shape) {
    case ToolType::flat: return ToolShape::flat(t.diameter);
    case ToolType::ball: return ToolShape::ball(t.diameter);
    case ToolType::bull: return ToolShape::bull(t.diameter, t.corner_radius.value_or(0));
    case ToolType::vee: return ToolShape::vee(t.diameter, t.angle.value_or(0));
    case ToolType::drill: return ToolShape::drill(t.diameter, t.point_angle.value_or(0));
  }
  return ToolShape::flat(t.diameter);
}

StockTools stock_tools(const ToolTable& mm) {
  StockTools out;
  for (const ToolEntry& e : mm.entries) out.emplace(e.number, stock_tool_shape(e));
  return out;
}

MotionBlock block_in_mm(const MotionBlock& b, Units units) {
  const double k = mm_per_unit(units);
  if (k == 1.0) return b;
  MotionBlock m = b;
  m.from = scaled(b.from, k);
  m.to = scaled(b.to, k);
  m.center = scaled(b.center, k);
  m.feed = b.feed * k;
  for (Vec3& c : m.ctrl) c = scaled(c, k);
  return m;
}

const ToolShape& stock_tool(const StockTools& tools, int tool, int line) {
  if (auto it = tools.find(tool); it != tools.end()) return it->second;
  if (tool == 0 && tools.size() == 1) return tools.begin()->second;
  const std::string which =
      tool == 0 ? "with no tool loaded (no T- M06 before it)" : "with tool T" + std::to_string(tool);
  throw InputError(errc::verify_tool, Place::at_line(line),
                   "the program cuts " + which + ", and " + tool_list(tools) +
                       ": give every tool the program uses in the tools table");
}

const ToolShape* swept_tool(const StockTools& tools, const MotionBlock& b, int tool) {
  // A rapid with no tool in the spindle cuts nothing (the start of a
  // program, before its first tool change); nor is one swept from where
  // the tool is not known (the controller moves from wherever it stands).
  if (b.kind == BlockKind::rapid && tool == 0 && tools.size() != 1 && !tools.count(0)) return nullptr;
  if (b.kind == BlockKind::rapid && b.from_known != 7) return nullptr;
  return &stock_tool(tools, tool, b.line);
}

StockCutter::StockCutter(const StockBox& box_mm, double cell_mm, StockTools tools, const StockCutterOptions& opt)
    : grid_(box_mm, cell_mm, opt.memory_limit), tools_(std::move(tools)), curve_tolerance_(opt.curve_tolerance_mm) {
  grid_.set_threads(opt.threads);
}

void StockCutter::cut(const MotionBlock& b, int tool, Units units) {
  ++blocks_;
  const ToolShape* swept = swept_tool(tools_, b, tool);
  if (!swept) return;
  const ToolShape& t = *swept;
  const MotionBlock m = block_in_mm(b, units);
  Sweep s = to_sweep(m, curve_tolerance_);
  if (b.kind == BlockKind::rapid) {
    // A rapid below the top of the stock may be a crash: swept on its own,
    // with the floors it passes over compared before and after.
    if (std::min(m.from.z, m.to.z) < grid_.box().z1 && rapid_cuts_material(s, t)) {
      if (rapid_cuts_++ == 0) first_rapid_cut_line_ = b.line;
    }
    return;
  }
  if (pending_tool_ != &t) flush();
  pending_tool_ = &t;
  pending_.push_back(std::move(s));
  if (pending_.size() >= kBatch) flush();
}

bool StockCutter::rapid_cuts_material(const Sweep& s, const ToolShape& t) {
  flush();
  const Box3 e = s.extent();
  const double c = grid_.cell(), r = t.radius();
  const StockBox& box = grid_.box();
  auto index = [&](double v, double v0, std::size_t n) {
    const double k = std::floor((v - v0) / c);
    return static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(n - 1)));
  };
  const std::size_t i0 = index(e.lo.x - r, box.x0, grid_.nx()), i1 = index(e.hi.x + r, box.x0, grid_.nx());
  const std::size_t j0 = index(e.lo.y - r, box.y0, grid_.ny()), j1 = index(e.hi.y + r, box.y0, grid_.ny());
  std::vector<double> before;
  before.reserve((i1 - i0 + 1) * (j1 - j0 + 1));
  for (std::size_t j = j0; j <= j1; ++j)
    for (std::size_t i = i0; i <= i1; ++i) before.push_back(grid_.floor(i, j));
  grid_.cut(s, t);
  std::size_t k = 0;
  bool cut = false;
  for (std::size_t j = j0; j <= j1; ++j)
    for (std::size_t i = i0; i <= i1; ++i) cut = cut || grid_.floor(i, j) < before[k++] - kCutMm;
  return cut;
}

void StockCutter::flush() {
  if (!pending_.empty()) grid_.cut(pending_, *pending_tool_);
  pending_.clear();
}

const DexelGrid& StockCutter::grid() {
  flush();
  return grid_;
}

}  // namespace bezcam
