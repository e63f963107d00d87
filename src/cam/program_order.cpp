// `order: "shortest"` (the default; docs/cut-order.md): the job's entities
// in the planned order, one tool at a time where the nesting allows it.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <span>

#include "bezcam/cam/cut_order.hpp"
#include "bezcam/format.hpp"
#include "bezcam/kernel/bezier.hpp"
#include "bezcam/kernel/curve.hpp"
#include "bezcam/kernel/surface.hpp"
#include "cut_emitters.hpp"
#include "hole_cut.hpp"

namespace bezcam::detail {
namespace {

// Each entity as a contour for the planner: a curve by four points per
// Bézier piece (closed ones may start at any joint), a surface as a
// contour that keeps its place.
std::vector<OrderContour> order_contours(const Job& job, const MachineProfile& m, std::vector<int>& tools) {
  std::vector<OrderContour> cs;
  for (const Entity& e : job.entities) {
    OrderContour c;
    const CutParams hp = cut_params(job, e, m);
    if (const auto centre = hole_centre(e, hp)) {
      c.outline = {*centre};  // a hole: a point, drilled or bored from its centre
      tools.push_back(hp.tool);
    } else if (e.surface || e.curve.pieces.empty()) {
      const Box3 b = e.surface ? bounds(*e.surface) : Box3{};
      c.outline = {b.empty() ? Vec3{} : b.lo, b.empty() ? Vec3{} : b.hi};
      c.movable = false;
      tools.push_back(-1);
    } else {
      const auto& pieces = e.curve.pieces;
      const double scale = std::max(1.0, control_magnitude(pieces));
      c.closed = e.curve.closed || dist(pieces.front().front(), pieces.back().back()) <= 1e-9 * scale;
      for (const Bezier& b : pieces) {
        if (c.closed) c.starts.push_back(c.outline.size());
        for (double t : {0.0, 0.25, 0.5, 0.75}) c.outline.push_back(t == 0 ? b.front() : evaluate(b, t));
      }
      c.outline.push_back(c.closed ? pieces.front().front() : pieces.back().back());
      const CutParams cp = cut_params(job, e, m);
      // Reversing an open curve changes its left and right: only a curve
      // cut on the line, as drawn, with the tolerance on both sides.
      c.reversible = !c.closed && cp.side == CutSide::on && cp.direction == CutDirection::as_drawn &&
                     cp.tolerance_side == ToleranceSide::both;
      tools.push_back(cp.tool);
    }
    cs.push_back(std::move(c));
  }
  return cs;
}

// Where the tool is after cutting step `s`.
Vec3 end_of(const OrderContour& c, const OrderStep& s) {
  if (c.closed) return c.outline[s.start_vertex];
  return s.reversed ? c.outline.front() : c.outline.back();
}

Vec3 start_of(const OrderContour& c, const OrderStep& s) {
  if (c.closed) return c.outline[s.start_vertex];
  return s.reversed ? c.outline.back() : c.outline.front();
}

// The XY rapid length from the origin through `steps`.
double rapid_length(std::span<const OrderContour> cs, std::span<const OrderStep> steps) {
  double len = 0;
  Vec3 at{};
  for (const OrderStep& s : steps) {
    const Vec3 from = start_of(cs[s.contour], s);
    len += std::hypot(from.x - at.x, from.y - at.y);
    at = end_of(cs[s.contour], s);
  }
  return len;
}

double rapid_as_written(std::span<const OrderContour> cs) {
  std::vector<OrderStep> steps(cs.size());
  for (size_t i = 0; i < cs.size(); ++i) steps[i].contour = i;
  return rapid_length(cs, steps);
}

size_t tool_changes(const std::vector<int>& tools, const std::vector<size_t>& sequence) {
  size_t n = 0;
  for (size_t i = 1; i < sequence.size(); ++i) n += tools[sequence[i]] != tools[sequence[i - 1]];
  return n;
}

// The tools in the order they may cut: a tool whose contours lie inside a
// contour of another tool goes before that tool; among those free to go
// next, the one written first. Empty when the nesting asks for a tool both
// before and after another (then the contours are planned all together).
std::vector<int> tool_sequence(const std::vector<int>& tools, const std::vector<std::pair<size_t, size_t>>& nesting) {
  std::map<int, size_t> first;
  for (size_t i = 0; i < tools.size(); ++i) first.emplace(tools[i], i);
  std::set<std::pair<int, int>> before;  // (a, b): a's contours go before b's
  for (const auto& [inner, outer] : nesting)
    if (tools[inner] != tools[outer]) before.insert({tools[inner], tools[outer]});
  std::vector<int> out;
  std::set<int> done;
  while (out.size() < first.size()) {
    std::optional<int> next;
    for (const auto& [t, at] : first) {
      if (done.count(t)) continue;
      const bool free = std::none_of(before.begin(), before.end(),
                                     [&](const auto& ab) { return ab.second == t && !done.count(ab.first); });
      if (free && (!next || at < first[*next])) next = t;
    }
    if (!next) return {};
    out.push_back(*next);
    done.insert(*next);
  }
  return out;
}

struct Plan {
  std::vector<OrderStep> steps;
  bool by_tool = false;
  size_t unmet_nesting = 0;  ///< nestings a contour that keeps its place kept from being met
};

// The plan: with every entity movable and more than one tool, each tool's
// contours planned among themselves, from where the previous tool ended;
// otherwise all contours together.
Plan plan_order(const std::vector<OrderContour>& cs, const std::vector<int>& tools,
                const std::vector<std::pair<size_t, size_t>>& nesting) {
  const bool all_movable = std::all_of(cs.begin(), cs.end(), [](const OrderContour& c) { return c.movable; });
  const std::vector<int> seq = all_movable ? tool_sequence(tools, nesting) : std::vector<int>{};
  if (seq.size() < 2) {
    const CutOrder whole = plan_cut_order(cs, Vec3{});
    return {whole.steps, false, whole.unmet_nesting};
  }
  Plan p;
  p.by_tool = true;
  Vec3 home{};
  for (int t : seq) {
    std::vector<size_t> members;
    std::vector<OrderContour> sub;
    for (size_t i = 0; i < cs.size(); ++i)
      if (tools[i] == t) {
        members.push_back(i);
        sub.push_back(cs[i]);
      }
    const CutOrder part = plan_cut_order(sub, home);
    for (OrderStep st : part.steps) {
      home = end_of(sub[st.contour], st);
      st.contour = members[st.contour];
      p.steps.push_back(st);
    }
  }
  return p;
}

// The entity cut from another start (a closed curve's pieces rotated) or
// the other way (an open one reversed): one segment of its pieces (the
// source NURBS form no longer matches them).
Entity moved_entity(const Entity& from, const OrderContour& c, const OrderStep& st) {
  Entity e = from;
  const size_t k = st.start_vertex / 4;  // outline vertices: four per piece
  const auto& pieces = e.curve.pieces;
  const bool rotate = c.closed && k > 0 && k < pieces.size();
  if (!rotate && !st.reversed) return e;
  std::vector<Bezier> moved;
  if (rotate) {
    moved.assign(pieces.begin() + static_cast<long>(k), pieces.end());
    moved.insert(moved.end(), pieces.begin(), pieces.begin() + static_cast<long>(k));
  } else {
    moved = reversed(std::span<const Bezier>(pieces));
  }
  CurveSegment seg;
  seg.kind = e.curve.kind;
  seg.degree = e.curve.max_degree();
  seg.rational = e.curve.rational();
  const bool closed = e.curve.closed;
  e.curve = make_single(seg, std::move(moved), e.curve.dim);
  e.curve.closed = closed;
  return e;
}

std::string order_note(const OrderFigures& f, const std::string& u) {
  auto mm = [](double v) { return fmt_num(std::round(v * 10) / 10); };
  const double saved = f.rapid_as_written - f.rapid_planned;
  std::string s = "order shortest: " + std::to_string(f.nested) + " nested contour" + (f.nested == 1 ? "" : "s") +
                  " cut before what encloses them; rapids " + mm(f.rapid_planned) + " " + u + " in XY instead of " +
                  mm(f.rapid_as_written) + " " + u + " as written (";
  if (std::round(saved * 10) >= 0)
    s += mm(saved) + " " + u + " saved)";
  else
    s += mm(-saved) + " " + u + " more: nested contours first" + (f.by_tool ? ", one tool at a time)" : ")");
  if (f.tool_changes_planned != f.tool_changes_as_written)
    s += "; " + std::to_string(f.tool_changes_planned) + " tool change" + (f.tool_changes_planned == 1 ? "" : "s") +
         " between contours instead of " + std::to_string(f.tool_changes_as_written);
  return s;
}

}  // namespace

Job ordered(const Job& job, const MachineProfile& m, Program& p) {
  std::vector<int> tools;
  const std::vector<OrderContour> cs = order_contours(job, m, tools);
  const auto nesting = find_nesting(cs);
  const Plan plan = plan_order(cs, tools, nesting);
  // A pocket region is cleared whole where its first member comes in the
  // plan: its members go there, as written (the region's outline first).
  std::map<std::string, std::vector<size_t>> regions;
  std::vector<std::string> region(cs.size());
  for (size_t i = 0; i < cs.size(); ++i) {
    const Entity& e = job.entities[i];
    if (!cs[i].movable) continue;
    const CutParams cp = cut_params(job, e, m);
    if (cp.pocket.operation != Operation::pocket) continue;
    region[i] = region_of(e, cp);
    regions[region[i]].push_back(i);
  }
  Job out = job;
  out.entities.clear();
  std::vector<size_t> written(cs.size()), planned;
  for (size_t i = 0; i < cs.size(); ++i) written[i] = i;
  std::vector<OrderStep> steps;  // as cut
  std::set<std::string> cleared;
  for (const OrderStep& st : plan.steps) {
    if (region[st.contour].empty()) {
      out.entities.push_back(moved_entity(job.entities[st.contour], cs[st.contour], st));
      steps.push_back(st);
    } else if (cleared.insert(region[st.contour]).second) {
      for (size_t i : regions[region[st.contour]]) {
        out.entities.push_back(job.entities[i]);
        steps.push_back({i, 0, false});
      }
    }
  }
  for (const OrderStep& st : steps) planned.push_back(st.contour);
  if (cs.size() < 2) return out;  // nothing to order: no word about it
  OrderFigures f;
  f.nested = nesting.size() - plan.unmet_nesting;
  f.rapid_as_written = rapid_as_written(cs);
  f.rapid_planned = rapid_length(cs, steps);
  f.by_tool = plan.by_tool;
  f.tool_changes_as_written = tool_changes(tools, written);
  f.tool_changes_planned = tool_changes(tools, planned);
  p.notes.push_back(order_note(f, to_string(job.units)));
  p.order_summary = p.notes.back();
  p.order = f;
  return out;
}

}  // namespace bezcam::detail
