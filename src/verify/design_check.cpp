#include "bezcam/verify/design_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "bezcam/cam/program.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "wall_field.hpp"

namespace bezcam {

using verify_detail::Region;
using verify_detail::Wall;
using verify_detail::WallField;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Differences below this are the rounding of the floors' arithmetic, not
// material (mm).
constexpr double kNoise = 1e-9;

// The design's walls are flattened this much finer than the job's
// tolerance: their bound stays a hundredth of what is judged.
constexpr double kDesignFlatten = 0.01;

// One entity of the design as the check reads it (mm).
struct DesignEntity {
  std::size_t index = 0;
  Wall wall;
  bool groove = false;  // `side` on: the tool's shape along the curve
  bool pocket = false;  // a pocket region: all of it cleared where the tool reaches
  std::string region;   // the pocket's region
  double top = 0, cut = 0, stock_to_leave = 0, tab_height = 0;
  std::optional<ToolShape> tool;
};

// Per column, folded over the entities.
struct Columns {
  std::vector<double> gouge;    // the distance of the column's lowest removed point to the waste (mm)
  std::vector<int> owner;       // the entity it was measured from (-1: none)
  std::vector<double> allowed;  // the lowest floor the waste allows there (the design's top where none)
};

double flatness(const CurveGeometry& c) {
  const Box3 b = c.bounds();
  return b.empty() ? 0 : b.hi.z - b.lo.z;
}

// Why an entity is not in the 2.5D model, or nothing when it is.
std::optional<std::string> not_modelled(const Entity& e, const std::optional<ToolShape>& tool) {
  if (e.surface) return "a surface: the verifier compares walls and grooves of curves only";
  if (e.point && !tool) return "no tool: a point's hole is as wide as the tool that drills it";
  if (e.curve.pieces.empty() && !e.point) return "no curve to compare";
  if (e.curve.dim == 3 && flatness(e.curve) > 1e-9) return "a curve that is not flat: compared walls are vertical";
  if (!tool) return "no tool: the entity gives no `tool_diameter` and the tools table no entry for its tool";
  return std::nullopt;
}

// The tool an entity's own settings describe (mm): `tool_diameter`'s flat
// end mill, or for a surface cut with `tool_radius` its ball end.
std::optional<ToolShape> settings_tool(const Entity& e, const CutParams& c, double k) {
  if (c.tool_diameter && *c.tool_diameter > 0) return ToolShape::flat(*c.tool_diameter * k);
  if (c.tool_radius > 0)
    return e.surface ? ToolShape::ball(2 * c.tool_radius * k) : ToolShape::flat(2 * c.tool_radius * k);
  return std::nullopt;
}

std::optional<ToolShape> entity_tool(const Entity& e, const CutParams& c, double k, const StockTools& tools) {
  if (auto it = tools.find(c.tool); it != tools.end()) return it->second;
  return settings_tool(e, c, k);
}

bool waste_inside_or_left(const CutParams& c, const std::vector<Vec3>& pts, bool closed) {
  if (!closed) return c.side == CutSide::left;
  double area2 = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Vec3& a = pts[k];
    const Vec3& b = pts[(k + 1) % pts.size()];
    area2 += a.x * b.y - b.x * a.y;
  }
  const bool ccw = area2 > 0;
  switch (c.side) {
    case CutSide::inside: return true;
    case CutSide::outside: return false;
    case CutSide::left: return ccw;
    case CutSide::right: return !ccw;
    case CutSide::on: return false;
  }
  return false;
}

DesignEntity read_entity(const Job& job, const Entity& e, const CutParams& c, double k, const ToolShape& tool,
                         double& bound) {
  DesignEntity d;
  d.index = e.index;
  FlattenOptions fo;
  fo.tolerance = job.tolerance * kDesignFlatten;
  const FlattenResult f = flatten(e.curve.pieces, fo);
  bound = std::max(bound, f.bound * k);
  for (const Vec3& p : f.points) d.wall.points.push_back({p.x * k, p.y * k, 0});
  d.wall.closed = e.curve.closed && d.wall.points.size() > 2;
  if (d.wall.closed && d.wall.points.front().x == d.wall.points.back().x &&
      d.wall.points.front().y == d.wall.points.back().y)
    d.wall.points.pop_back();
  d.groove = c.side == CutSide::on;
  d.wall.waste_inside_or_left = !d.groove && waste_inside_or_left(c, d.wall.points, d.wall.closed);
  d.top = c.top_z * k;
  d.cut = c.cut_z * k;
  d.stock_to_leave = c.stock_to_leave * k;
  d.tab_height = c.tabs ? c.tabs->height * k : 0;
  d.tool = tool;
  return d;
}

// A hole (docs/holes.md) is a pocket of one wall, waste inside: the
// circle drawn, or for a point the circle of the tool's diameter about it
// (a polygon whose sagitta goes to the design's bound). A drill's point
// goes below cut_z by its length unless cut_z is the tip's (`"to":
// "tip"`): the floor allowed is the tip's.
DesignEntity read_hole(const Job& job, const Entity& e, const CutParams& c, double k, const ToolShape& tool,
                       double& bound) {
  DesignEntity d;
  if (e.point) {
    d.index = e.index;
    const double r = tool.radius();
    constexpr int n = 720;
    for (int i = 0; i < n; ++i) {
      const double a = 2 * std::numbers::pi * i / n;
      d.wall.points.push_back({e.point->x * k + r * std::cos(a), e.point->y * k + r * std::sin(a), 0});
    }
    bound = std::max(bound, r * (1 - std::cos(std::numbers::pi / n)));
    d.top = c.top_z * k;
    d.cut = c.cut_z * k;
    d.stock_to_leave = c.stock_to_leave * k;
    d.tool = tool;
  } else {
    d = read_entity(job, e, c, k, tool, bound);
  }
  d.pocket = true;
  d.groove = false;
  d.region = "hole " + e.label();
  d.wall.closed = true;
  d.wall.waste_inside_or_left = true;
  d.tab_height = 0;
  if (c.pocket.operation == Operation::drill && tool.kind() == ToolShapeKind::drill && !c.drill.to_tip.value_or(false))
    d.cut -= tool.cutting_height();
  return d;
}

// The band around a wall the check examines (mm): the tool's reach past
// the stock to leave, and a tool's width more for the centres it needs.
double band_of(const DesignEntity& d) { return d.stock_to_leave + 3 * d.tool->radius() + 1; }

// The distance from the point (rho, z) of a tool's half section (rho from
// its axis, z above its tip) to the tool's surface: its profile h over
// [0, R] and the cylinder above h(R). Each profile is made of segments and
// quarter circles, so the distance is exact.
double profile_distance(const ToolShape& t, double rho, double z) {
  const double R = t.radius();
  auto segment = [&](double x0, double z0, double x1, double z1) {
    const double dx = x1 - x0, dz = z1 - z0, len2 = dx * dx + dz * dz;
    const double u = len2 > 0 ? std::clamp(((rho - x0) * dx + (z - z0) * dz) / len2, 0.0, 1.0) : 0;
    return std::hypot(rho - (x0 + u * dx), z - (z0 + u * dz));
  };
  // The quarter circle about (cx, cz) of radius r from its bottom to its
  // side (the lower outer quarter).
  auto quarter = [&](double cx, double cz, double r) {
    if (rho >= cx && z <= cz) return std::abs(std::hypot(rho - cx, z - cz) - r);
    return std::min(std::hypot(rho - cx, z - (cz - r)), std::hypot(rho - (cx + r), z - cz));
  };
  const double top = t.cutting_height();
  const double side = std::hypot(rho - R, std::max(0.0, top - z));  // the cylinder above h(R)
  switch (t.kind()) {
    case ToolShapeKind::flat: return std::min(side, segment(0, 0, R, 0));
    case ToolShapeKind::ball: return std::min(side, quarter(0, R, R));
    case ToolShapeKind::bull: {
      const double rc = t.corner_radius();
      return std::min({side, segment(0, 0, R - rc, 0), quarter(R - rc, rc, rc)});
    }
    case ToolShapeKind::vee:
    case ToolShapeKind::drill: return std::min(side, segment(0, 0, R, top));
  }
  return side;
}

// Folds one wall's gouge distances and allowed floors into `cols`, and
// measures its excess into `out`.
void fold_entity(const DexelGrid& g, const DesignEntity& d, double tol, Columns& cols, EntityCheck& out,
                 std::vector<ColumnClass>& classes) {
  const double band = band_of(d);
  const WallField f = verify_detail::wall_field(g, d.wall, band);
  const Region& r = f.region;
  const ToolShape& t = *d.tool;
  const double R = t.radius(), stl = d.stock_to_leave, c2 = g.cell() * g.cell();
  const double floor_design = std::max(d.cut, g.box().z0);  // below a flat tool
  // Where the tool's axis goes along the wall: the columns on the waste
  // side at the tool's radius past the stock to leave (a strip a cell's
  // diagonal wide, so that it has no gap between column centres). A
  // concave corner sharper than the tool has none near it.
  // In a pocket the axis may stand anywhere that far from every wall.
  std::vector<char> centres(r.size(), 0);
  const double strip = g.cell() * std::sqrt(2.0);
  if (!d.groove)
    for (std::size_t k = 0; k < r.size(); ++k)
      centres[k] = f.side[k] > 0 && f.distance[k] >= stl + R && (d.pocket || f.distance[k] < stl + R + strip);
  // The distance to the nearest such centre: the tool's surface reaches
  // down to cut_z + h(that distance) there (h nondecreasing).
  const std::vector<double> reach = d.groove ? std::vector<double>{} : verify_detail::reach(r, centres, g.cell());
  auto fold = [&](std::size_t col, double gouge, double allowed) {
    if (gouge < cols.gouge[col]) {
      cols.gouge[col] = gouge;
      cols.owner[col] = static_cast<int>(d.index);
    }
    cols.allowed[col] = std::min(cols.allowed[col], allowed);
  };
  // Material left: `e` its distance to the part, `above` its height over
  // the design's floor.
  auto excess = [&](std::size_t col, std::size_t i, std::size_t j, double e, double above) {
    if (e <= kNoise) return;
    if (e > out.excess) out.excess = e, out.excess_at = {g.x_center(i), g.y_center(j), g.floor(i, j)};
    if (e <= tol) return;
    ++out.excess_columns;
    out.excess_volume += above * c2;
    if (classes[col] == ColumnClass::none) classes[col] = ColumnClass::excess;
  };
  for (std::size_t k = 0; k < r.size(); ++k) {
    const std::size_t i = r.i0 + k % r.ni, j = r.j0 + k / r.ni, col = j * g.nx() + i;
    const double z = g.floor(i, j), dist = f.distance[k];
    if (d.groove) {
      if (dist > R + band) continue;
      // The groove is the tool's body swept along the curve: inside it
      // material may go; the distance to its surface measures both ways.
      const double design = dist <= R ? d.cut + t.height(dist) : kInf;
      const double normal = profile_distance(t, dist, z - d.cut);
      fold(col, z < design ? normal : 0.0, dist <= R ? design : d.top);
      if (z > std::max(design, g.box().z0)) excess(col, i, j, normal, z - std::max(design, g.box().z0));
      continue;
    }
    if (f.side[k] == 0) continue;
    const double s = f.side[k] > 0 ? dist : -dist;  // positive into the waste
    const bool waste = s >= stl;
    fold(col, std::hypot(std::max(0.0, stl - s), std::max(0.0, d.cut - z)), waste ? d.cut : d.top);
    if (!waste || (!d.pocket && s > stl + 2 * R)) continue;
    // The distance to the axis's path: at least |s - (stl + R)|, exactly
    // that where the path runs along the wall; the strip's transform is
    // within a strip of it there, and larger only where a concave corner
    // keeps the axis away.
    const double along = std::abs(s - (stl + R));
    const double axis = !d.pocket && reach[k] - along <= strip + g.cell() ? along : reach[k];
    if (axis > R * (1 + 1e-12)) continue;
    const double above = z - std::max(d.cut + t.height(axis), g.box().z0);
    if (above <= 0) continue;
    // Tabs stand along the whole wall as far as the design knows, with the
    // tool's own profile at their ends.
    if (d.tab_height > 0 && z - floor_design <= d.tab_height + t.cutting_height() + tol) continue;
    // Measured normal to what the tool hugging the wall leaves: the wall
    // above the tool's cutting height, its profile below.
    // In a pocket, away from the walls, the floor is the design's surface.
    const double normal = profile_distance(t, axis, z - d.cut);
    excess(col, i, j, d.pocket ? std::max(normal, std::min(s - stl, above)) : normal, above);
  }
  if (!d.wall.closed || f.outside_side == 0) return;
  // A closed wall's sides hold beyond its band: the waste may be cut down
  // to the wall's floor everywhere on its side.
  for (std::size_t j = 0; j < g.ny(); ++j)
    for (std::size_t i = 0; i < g.nx(); ++i) {
      if (r.contains(i, j)) continue;
      const std::size_t col = j * g.nx() + i;
      if (f.outside_side > 0) fold(col, std::max(0.0, d.cut - g.floor(i, j)), d.cut);
    }
  for (std::size_t k = 0; k < r.size(); ++k) {
    if (f.distance[k] != kInf || f.side[k] <= 0) continue;
    const std::size_t i = r.i0 + k % r.ni, j = r.j0 + k / r.ni;
    fold(j * g.nx() + i, std::max(0.0, d.cut - g.floor(i, j)), d.cut);
  }
}

}  // namespace

double DesignCheck::max_gouge() const {
  double m = elsewhere.gouge;
  for (const EntityCheck& e : entities) m = std::max(m, e.gouge);
  return m;
}

DesignCheck check_design(const DexelGrid& g, const Job& job, const MachineProfile& m, const StockTools& tools) {
  DesignCheck out;
  const double k = mm_per_unit(job.units);
  out.tolerance = job.tolerance * k;
  out.classes.assign(g.floors().size(), ColumnClass::none);
  out.elsewhere.label = "elsewhere";
  Columns cols{std::vector<double>(g.floors().size(), kInf), std::vector<int>(g.floors().size(), -1),
               std::vector<double>(g.floors().size(), kInf)};
  double top = -kInf;
  std::vector<DesignEntity> design;
  for (const Entity& e : job.entities) {
    EntityCheck ec;
    ec.label = e.label();
    ec.json_path = e.json_path();
    const CutParams c = cut_params(job, e, m);
    const std::optional<ToolShape> tool = entity_tool(e, c, k, tools);
    const PocketKeys pk = e.params.pocket.over(job.params.pocket);
    const bool pocket = pk.operation == Operation::pocket;
    const bool hole = pk.operation == Operation::drill || pk.operation == Operation::bore;
    const std::string region = pk.region.value_or(e.label());
    auto same = std::find_if(design.begin(), design.end(),
                             [&](const DesignEntity& d) { return d.pocket && d.region == region; });
    if (const auto why = not_modelled(e, tool)) {
      ec.compared = false;
      ec.not_compared = *why;
    } else if (hole) {
      design.push_back(read_hole(job, e, c, k, *tool, out.design_bound));
      top = std::max(top, design.back().top);
    } else if (pocket && same != design.end()) {
      // One region by the even-odd rule: the outline, its islands, ...
      DesignEntity more = read_entity(job, e, c, k, *tool, out.design_bound);
      same->wall.islands.push_back(std::move(more.wall.points));
      ec.compared = false;
      ec.not_compared = "compared with its pocket region \"" + region + "\" (" + out.entities[same->index].label + ")";
    } else {
      design.push_back(read_entity(job, e, c, k, *tool, out.design_bound));
      DesignEntity& d = design.back();
      if (pocket) {
        d.pocket = true;
        d.groove = false;
        d.region = region;
        d.wall.closed = true;
        d.wall.waste_inside_or_left = true;
      }
      top = std::max(top, d.top);
    }
    out.entities.push_back(ec);
  }
  for (const DesignEntity& d : design) fold_entity(g, d, out.tolerance, cols, out.entities[d.index], out.classes);
  if (design.empty()) return out;
  // Gouges: removed material that lies in no entity's waste, measured to
  // the nearest waste (or the design's top, when nearer).
  double band = 0;
  for (const DesignEntity& d : design) band = std::max(band, band_of(d));
  const double c2 = g.cell() * g.cell();
  for (std::size_t j = 0; j < g.ny(); ++j)
    for (std::size_t i = 0; i < g.nx(); ++i) {
      const std::size_t col = j * g.nx() + i;
      const double z = g.floor(i, j);
      const double allowed = std::min(cols.allowed[col], top);
      if (z >= allowed) continue;
      const bool far = cols.gouge[col] == kInf;
      const double size = std::min(far ? band : cols.gouge[col], top - z);
      if (size <= kNoise) continue;
      EntityCheck& ec = cols.owner[col] < 0 ? out.elsewhere : out.entities[static_cast<std::size_t>(cols.owner[col])];
      if (size > ec.gouge) {
        ec.gouge = size;
        ec.gouge_at = {g.x_center(i), g.y_center(j), z};
        ec.gouge_at_least = far && size == band;
      }
      if (size <= out.tolerance) continue;
      ++ec.gouge_columns;
      ec.gouge_volume += (allowed - z) * c2;
      out.classes[col] = ColumnClass::gouge;
    }
  return out;
}

StockTools design_stock_tools(const Job& job, const MachineProfile& m) {
  StockTools t = stock_tools(job.tools_mm());
  const double k = mm_per_unit(job.units);
  for (const Entity& e : job.entities) {
    const CutParams c = cut_params(job, e, m);
    if (t.count(c.tool)) continue;
    if (const auto shape = settings_tool(e, c, k)) t.emplace(c.tool, *shape);
  }
  return t;
}

std::optional<StockBox> design_stock_box(const Job& job, const MachineProfile& m, const StockTools& tools) {
  const double k = mm_per_unit(job.units);
  Box3 b;
  double top = -kInf, deepest = kInf, widest = 0;
  for (const Entity& e : job.entities) {
    const CutParams c = cut_params(job, e, m);
    if (const auto t = entity_tool(e, c, k, tools)) widest = std::max(widest, t->diameter());
    top = std::max(top, c.top_z * k);
    deepest = std::min(deepest, c.cut_z * k);
    Box3 eb = e.surface ? Box3{} : e.curve.bounds();
    if (e.point) eb.add(*e.point);
    if (!eb.empty()) {
      b.add(Vec3{eb.lo.x * k, eb.lo.y * k, 0});
      b.add(Vec3{eb.hi.x * k, eb.hi.y * k, 0});
    }
  }
  if (b.empty()) return std::nullopt;
  return StockBox{b.lo.x - widest, b.lo.y - widest, deepest - 1, b.hi.x + widest, b.hi.y + widest, top};
}

}  // namespace bezcam
