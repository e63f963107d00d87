#include "bezcam/verify/machined_program.hpp"

#include <algorithm>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/format.hpp"

namespace bezcam {

namespace {

Box3 block_extent_mm(const MotionBlock& b, Units units) {
  const MotionBlock m = block_in_mm(b, units);
  Box3 e;
  switch (m.kind) {
    case BlockKind::arc_cw:
    case BlockKind::arc_ccw: return Sweep::arc(block_arc(m)).extent();
    case BlockKind::nurbs:
    case BlockKind::bezier:
      // The convex hull of the control points holds the curve.
      for (const Vec3& c : m.ctrl) e.add(c);
      e.add(m.to);
      return e;
    default: break;
  }
  e.add(m.from);
  e.add(m.to);
  return e;
}

// Calls `f(extent_mm, tool)` for each feed move.
template <class F>
void for_each_feed(const Timeline& tl, const StockTools& tools, F&& f) {
  for (size_t i = 0; i < tl.blocks.size(); ++i) {
    const MotionBlock& b = tl.blocks[i];
    if (!is_feed(b)) continue;
    const int t = i < tl.tools.size() ? tl.tools[i] : 0;
    f(block_extent_mm(b, tl.units), stock_tool(tools, t, b.line));
  }
}

}  // namespace

StockBox program_stock_box(const Timeline& tl, const StockTools& tools) {
  Box3 all;
  double r = 0;
  for_each_feed(tl, tools, [&](const Box3& e, const ToolShape& t) {
    all.add(e);
    r = std::max(r, t.radius());
  });
  if (all.empty())
    throw InputError(errc::verify_empty, Place{},
                     "the program moves no tool at a feed, so nothing is machined: give a program that cuts");
  StockBox box{all.lo.x - r, all.lo.y - r, all.lo.z - 1, all.hi.x + r, all.hi.y + r, all.hi.z};
  if (box.z1 <= box.z0) box.z1 = box.z0 + 1;
  return box;
}

void check_stock_holds_program(const StockBox& box, const Timeline& tl, const StockTools& tools) {
  bool reaches = false;
  for_each_feed(tl, tools, [&](const Box3& e, const ToolShape& t) {
    const double r = t.radius();
    reaches = reaches || (e.hi.x + r > box.x0 && e.lo.x - r < box.x1 && e.hi.y + r > box.y0 && e.lo.y - r < box.y1 &&
                          e.lo.z < box.z1);
  });
  if (!reaches)
    throw InputError(errc::verify_stock_outside, Place::at_setting("stock"),
                     "no cutting move of the program reaches the stock " + fmt_num(box.x0) + "," + fmt_num(box.y0) +
                         "," + fmt_num(box.z0) + "," + fmt_num(box.x1) + "," + fmt_num(box.y1) + "," + fmt_num(box.z1) +
                         " (mm): give the box the part is cut from, in millimetres, in the program's coordinates");
}

void cut_timeline(StockCutter& cutter, const Timeline& tl) {
  for (size_t i = 0; i < tl.blocks.size(); ++i)
    cutter.cut(tl.blocks[i], i < tl.tools.size() ? tl.tools[i] : 0, tl.units);
}

}  // namespace bezcam
