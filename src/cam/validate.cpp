#include "bezcam/cam/validate.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/kernel/arc.hpp"

namespace bezcam {

namespace {

// Extent of an arc (in its plane) from `from` to `to` (the modal end point) around its
// centre: the kernel's Arc box, plus m.to as the move holds it.
Box3 arc_box(const Vec3& from, const Vec3& to, const ArcMove& m) {
  Box3 b = arc_extent(Arc{from, to, m.center, m.ccw, m.plane});
  b.add(m.to);
  return b;
}

}  // namespace

void validate_program(const Program& p, const MachineProfile& m) {
  const double k = 1.0 / mm_per_unit(p.units);
  const char* unit = to_string(p.units);
  // The job file and the entity's JSON path, with its id when it has one.
  auto where = [&](const Move& mv) {
    if (mv.entity < 0) return Place::at_file(p.job_name);
    const std::string path = "entities[" + std::to_string(mv.entity) + "]";
    std::string shown = path;
    for (const auto& r : p.entities)
      if (r.entity == mv.entity && r.label != path) shown += " (id \"" + r.label + "\")";
    return Place::in_json(p.job_name, shown);
  };
  auto check_box = [&](const Move& mv, const Box3& b, unsigned axes) {
    static const char* names = "XYZ";
    for (int a = 0; a < 3; ++a) {
      if (!(axes & (1u << a))) continue;
      const double lo = m.travel_mm[a][0] * k, hi = m.travel_mm[a][1] * k;
      const double v = b.lo[a] < lo ? b.lo[a] : (b.hi[a] > hi ? b.hi[a] : lo);
      if (b.lo[a] < lo || b.hi[a] > hi)
        throw InputError(errc::program_travel, where(mv),
                         std::string("the tool path reaches ") + names[a] + " = " + fmt_num(v) + " " + unit +
                             ", outside the travel of machine \"" + m.name + "\" (" + names[a] + " from " +
                             fmt_num(lo) + " to " + fmt_num(hi) + " " + unit +
                             "); move the part or use another machine profile");
    }
  };
  const double max_feed = m.max_feed_mm_min * k;
  // Each entity's clearance plane, by entity index (NaN: none).
  std::vector<double> clear;
  for (const auto& r : p.entities)
    if (r.entity >= 0) {
      if (clear.size() <= static_cast<size_t>(r.entity))
        clear.resize(r.entity + 1, std::numeric_limits<double>::quiet_NaN());
      clear[r.entity] = r.clear_z;
    }
  Vec3 pos;
  unsigned known = 0;
  for (const Move& mv : p.moves) {
    const Motion* mo = motion_of(mv);
    if (!mo) continue;
    const bool rapid = is_rapid(mv);
    if (!rapid && mo->feed > max_feed)
      throw InputError(errc::program_feed, where(mv),
                       "feed " + fmt_num(mo->feed) + " " + unit + "/min exceeds the maximum feed of machine \"" +
                           m.name + "\" (" + fmt_num(max_feed) + " " + unit +
                           "/min); lower \"feed\" or \"plunge_feed\"");
    if (!rapid && !(mo->feed > 0)) throw std::logic_error("cutting move without a feed");
    Box3 b;
    Vec3 to = pos;
    for (int a = 0; a < 3; ++a)
      if (mo->axes & (1u << a)) to[a] = mo->to[a];
    if (const auto* arc = std::get_if<ArcMove>(&mv.what)) {
      if (!m.arcs)
        throw InputError(errc::program_arcs, where(mv),
                         "machine \"" + m.name + "\" does not take arcs (\"arcs\": false)");
      // The emitters keep printed arcs within the controller's radius check.
      const Arc printed{pos, to, arc->center, arc->ccw, arc->plane};
      const double rs = printed.r_start(), re = printed.r_end();
      if (std::abs(rs - re) > m.arc_tolerance_mm * k * (1 + 1e-9))
        throw std::logic_error("internal check failed: an arc's radii differ by " + fmt_num(std::abs(rs - re)));
      b = arc_box(pos, to, *arc);
    } else {
      b.add(to);
      if (const auto* cv = std::get_if<CurveMove>(&mv.what))
        for (const auto& c : cv->shape->ctrl) b.add(c);  // NURBS / Bézier: hull contains the curve
    }
    check_box(mv, b, mo->axes | known);
    const bool moves_xy = (mo->axes & 3) && ((known & 3) != 3 || to.x != pos.x || to.y != pos.y);
    // An entity's clearance plane (surface passes linked above the
    // surface's top) is as safe as safe Z for that entity's own rapids.
    double floor = p.safe_z;
    if (mv.entity >= 0 && static_cast<size_t>(mv.entity) < clear.size() && clear[mv.entity] < floor)
      floor = clear[mv.entity];
    if (rapid && moves_xy && (to.z < floor || ((known & 4) && pos.z < floor)))
      throw InputError(errc::program_rapid_below_safe_z, where(mv),
                       "a rapid move would cross the part below safe Z (" + fmt_num(p.safe_z) + " " + unit + ")");
    pos = to;
    known |= mo->axes;
  }
}

}  // namespace bezcam
