// The setup sheet as one HTML page: inline style, the picture inline as
// SVG, no script and nothing fetched, readable on screen and on paper.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/kernel/surface.hpp"
#include "bezcam/report/motion_report.hpp"
#include "bezcam/report/setup_sheet.hpp"
#include "bezcam/version.hpp"

namespace bezcam {

namespace {

std::string esc(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string num(double v) { return format_significant(v, 6); }

const char kStyle[] = R"(
body{font:14px/1.4 "DejaVu Sans",Arial,sans-serif;color:#111;margin:24px auto;max-width:1100px;padding:0 16px}
h1{font-size:22px;margin:0 0 4px}
h2{font-size:17px;margin:22px 0 6px;border-bottom:2px solid #333;padding-bottom:2px}
.sub{color:#444;margin:0 0 12px}
.cards{display:flex;gap:12px;flex-wrap:wrap;margin:8px 0}
.card{border:1px solid #999;border-radius:4px;padding:6px 10px;min-width:160px}
.card b{display:block;font-size:18px}
.card span{color:#444;font-size:12px}
table{border-collapse:collapse;width:100%;margin:4px 0}
th,td{border:1px solid #aaa;padding:4px 6px;text-align:left;vertical-align:top}
th{background:#e8e8e8}
td.n{text-align:right;white-space:nowrap}
tr.tool td:first-child,tr.operation td:first-child{font-weight:bold}
#picture svg{width:100%;height:auto;border:1px solid #ccc}
pre{background:#f4f4f4;border:1px solid #ccc;padding:8px;overflow-x:auto;font-size:12px}
.warn{color:#a00}
p.note{color:#444;font-size:12px;margin:2px 0}
@media print{body{margin:0;max-width:none}h2{break-after:avoid}table,svg{break-inside:avoid}}
)";

std::string side_text(CutSide s) {
  switch (s) {
    case CutSide::on: return "on the line";
    case CutSide::left: return "left of the curve";
    case CutSide::right: return "right of the curve";
    case CutSide::inside: return "inside";
    case CutSide::outside: return "outside";
  }
  return "";
}

std::string direction_text(CutDirection d) {
  switch (d) {
    case CutDirection::as_drawn: return "as drawn";
    case CutDirection::climb: return "climb";
    case CutDirection::conventional: return "conventional";
  }
  return "";
}

std::string tool_name(int number) { return number < 0 ? "default" : "T" + std::to_string(number); }

// The part's extents in program coordinates: its entities' exact bounds,
// moved as the program moves them.
Box3 part_bounds(const Job& job, const Program& p) {
  Box3 b;
  for (const Entity& e : job.entities) {
    if (e.surface)
      b.add(bounds(*e.surface));
    else if (!e.curve.pieces.empty())
      b.add(e.curve.bounds());
  }
  if (!b.empty()) {
    b.lo = b.lo + p.offset;
    b.hi = b.hi + p.offset;
  }
  return b;
}

// How far the tools reach in XY: the cutting moves (sampled along curved
// blocks) widened by the radius of the tool that cuts each entity;
// `centre_only` is set when an entity's tool has no diameter given.
Box3 tool_reach(const Program& p, bool& centre_only) {
  centre_only = false;
  std::vector<double> radius;
  for (const EntityReport& r : p.entities) {
    if (r.entity < 0) continue;
    if (radius.size() <= static_cast<size_t>(r.entity)) radius.resize(static_cast<size_t>(r.entity) + 1, 0);
    double d = r.tool_width;
    const auto t = std::find_if(p.tools.begin(), p.tools.end(), [&](const JobTool& j) { return j.number == r.tool; });
    if (d <= 0 && t != p.tools.end() && t->diameter) d = *t->diameter;
    centre_only = centre_only || d <= 0;
    radius[static_cast<size_t>(r.entity)] = d / 2;
  }
  Box3 b;
  for (const MotionBlock& m : program_motion(p)) {
    if (!is_feed(m) || m.entity < 0) continue;
    const double r = static_cast<size_t>(m.entity) < radius.size() ? radius[static_cast<size_t>(m.entity)] : 0;
    const int n = m.kind == BlockKind::linear ? 1 : 32;
    for (int i = 0; i <= n; ++i) {
      const Vec3 q = i == 0 ? m.from : i == n ? m.to : evaluate_block(m, static_cast<double>(i) / n);
      b.add(q - Vec3{r, r, 0});
      b.add(q + Vec3{r, r, 0});
    }
  }
  return b;
}

// Where 0 lies on [lo, hi]: an edge, the middle, or a distance from `low`.
std::string origin_axis(double lo, double hi, const char* low, const char* high, const char* axis) {
  const double eps = 1e-9 * std::max({1.0, std::abs(lo), std::abs(hi)});
  if (std::abs(lo) <= eps) return std::string("the part's ") + low + " edge";
  if (std::abs(hi) <= eps) return std::string("the part's ") + high + " edge";
  if (std::abs(lo + hi) <= 2 * eps) return "the part's centre";
  return std::string(axis) + " " + num(-lo) + " from the part's " + low + " edge" +
         (lo > 0 || hi < 0 ? " (outside the part)" : "");
}

void stock_section(std::ostringstream& h, const SetupSheetInput& in, const std::vector<SheetTool>& tools) {
  const Program& p = *in.program;
  const char* u = to_string(p.units);
  const Box3 b = part_bounds(*in.job, p);
  double top = -INFINITY, deepest = INFINITY;
  for (const SheetTool& t : tools) {
    top = std::max(top, t.top_z);
    deepest = std::min(deepest, t.deepest_z);
  }
  if (!std::isfinite(top)) top = deepest = 0;
  h << "<section id=\"stock\"><h2>Stock and origin</h2><table>";
  if (!b.empty()) {
    h << "<tr><th>Part (X)</th><td>" << num(b.lo.x) << " to " << num(b.hi.x) << " " << u << " (" << num(b.hi.x - b.lo.x)
      << " " << u << ")</td></tr>";
    h << "<tr><th>Part (Y)</th><td>" << num(b.lo.y) << " to " << num(b.hi.y) << " " << u << " (" << num(b.hi.y - b.lo.y)
      << " " << u << ")</td></tr>";
  }
  bool centre_only = false;
  if (const Box3 r = tool_reach(p, centre_only); !r.empty())
    h << "<tr><th>The tools reach</th><td>X " << num(r.lo.x) << " to " << num(r.hi.x) << ", Y " << num(r.lo.y) << " to "
      << num(r.hi.y) << " " << u
      << (centre_only ? " (about: the tool centre where no tool diameter is given, tool edges elsewhere)"
                      : " (about, tool edges included)")
      << "</td></tr>";
  h << "<tr><th>Stock top</th><td>Z " << num(top) << " " << u << "</td></tr>";
  h << "<tr><th>Deepest cut</th><td>Z " << num(deepest) << " " << u << " (" << num(top - deepest) << " " << u
    << " below the stock top)</td></tr>";
  h << "<tr><th>Safe Z</th><td>Z " << num(p.safe_z) << " " << u << " (rapids at or above it)</td></tr>";
  h << "<tr><th>Work offset G54</th><td>";
  if (!b.empty())
    h << "X0 at " << esc(origin_axis(b.lo.x, b.hi.x, "left", "right", "X")) << "; Y0 at "
      << esc(origin_axis(b.lo.y, b.hi.y, "front", "back", "Y")) << "; ";
  h << "Z0 " << (std::abs(top) < 1e-12 ? "on the stock top" : "at " + num(-top) + " " + u + " from the stock top")
    << "</td></tr>";
  if (p.offset.x != 0 || p.offset.y != 0)
    h << "<tr><th>Moved</th><td>the drawing moved by X " << num(p.offset.x) << ", Y " << num(p.offset.y) << " " << u
      << "</td></tr>";
  h << "</table></section>\n";
}

void tools_section(std::ostringstream& h, const SetupSheetInput& in, const std::vector<SheetTool>& tools) {
  const char* u = to_string(in.program->units);
  h << "<section id=\"tools\"><h2>Tools</h2><table><tr><th>Tool</th><th>Shape</th><th>Diameter</th>"
       "<th>Corner / angle</th><th>Flute length</th><th>Cuts</th><th>Z range</th><th>Time</th></tr>";
  for (const SheetTool& t : tools) {
    h << "<tr class=\"tool\" data-tool=\"" << t.number << "\"><td>" << tool_name(t.number) << "</td><td>"
      << esc(t.shape) << "</td><td class=\"n\">" << (t.diameter ? num(*t.diameter) + " " + u : "not given")
      << "</td><td class=\"n\">"
      << (t.corner_radius ? "r " + num(*t.corner_radius) + " " + u
          : t.angle       ? num(*t.angle) + "&deg;"
                          : "")
      << "</td><td class=\"n\">" << (t.flute_length ? num(*t.flute_length) + " " + u : "") << "</td><td>";
    for (size_t i = 0; i < t.entities.size(); ++i) h << (i ? ", " : "") << esc(t.entities[i]);
    h << "</td><td class=\"n\">Z " << num(t.top_z) << " to " << num(t.deepest_z) << " " << u << "</td><td class=\"n\">"
      << esc(format_seconds(t.time_s)) << "</td></tr>";
  }
  h << "</table><p class=\"note\">Time: the moves of the tool's entities ("
    << (in.plan ? "planned on the machine's motion model" : "feeds as programmed, rapids at the maximum feed")
    << "); tool changes and the moves between tools count in the cycle time only.</p></section>\n";
}

std::string depth_text(const CutParams& c, const char* u) {
  std::string s = "Z " + num(c.top_z) + " to " + num(c.cut_z);
  if (c.step_down)
    s += ", step-down " + num(*c.step_down) + " " + u;
  else if (const auto d = c.pass_depth())
    s += ", passes of " + num(*d) + " " + u + " (flute length)";
  return s;
}

void operations_section(std::ostringstream& h, const SetupSheetInput& in) {
  const Program& p = *in.program;
  const Job& job = *in.job;
  const char* u = to_string(p.units);
  h << "<section id=\"operations\"><h2>Operations, in cutting order</h2><table><tr><th>#</th><th>Entity</th>"
       "<th>Tool</th><th>Side</th><th>Feed ("
    << u
    << "/min)</th><th>Spindle</th><th>Depth</th><th>More</th>"
       "<th>Chord error ("
    << u << ") measured / proven</th></tr>";
  int k = 0;
  for (const EntityReport& r : p.entities) {
    h << "<tr class=\"operation\" data-entity=\"" << r.entity << "\"><td>" << ++k << "</td><td>" << esc(r.label)
      << "<br><small>" << esc(r.type) << "</small></td><td>" << tool_name(r.tool) << "</td>";
    if (r.entity < 0 || static_cast<size_t>(r.entity) >= job.entities.size()) {
      h << "<td colspan=\"5\"></td>";
    } else {
      const CutParams c = cut_params(job, job.entities[static_cast<size_t>(r.entity)], *in.machine);
      std::string more;
      const auto add = [&](const std::string& s) { more += (more.empty() ? "" : "; ") + s; };
      if (c.pocket.operation == Operation::drill) {
        const double q = c.drill.peck.value_or(0), dwell = c.drill.dwell.value_or(0);
        add(std::string("drilled") + (q > 0 ? ", pecks of " + num(q) + " " + u : std::string()) +
            (q > 0 && c.drill.chip_break.value_or(false) ? " breaking the chip" : "") +
            (dwell > 0 ? ", dwell " + num(dwell) + " s" : std::string()));
      }
      if (c.pocket.operation == Operation::bore) add("bored: a helix down, a full circle at the bottom");
      if (c.direction != CutDirection::as_drawn) add(direction_text(c.direction));
      if (r.offset > 0) add("tool centre " + num(r.offset) + " " + u + " from the curve");
      if (c.stock_to_leave != 0) add("leaves " + num(c.stock_to_leave) + " " + u);
      if (c.lead) add("lead r " + num(c.lead->radius) + ", length " + num(c.lead->length));
      if (c.tabs)
        add(std::to_string(c.tabs->count) + " tabs " + num(c.tabs->width) + " wide, " + num(c.tabs->height) + " high");
      if (c.controller_compensation) add("cutter compensation G41/G42 on the controller");
      if (c.coolant != Coolant::off) add(std::string("coolant ") + to_string(c.coolant));
      h << "<td>" << side_text(c.side) << "</td><td class=\"n\">" << num(c.feed) << "<br><small>plunge "
        << num(c.plunge_feed) << "</small></td><td class=\"n\">" << num(c.spindle_rpm) << " rpm</td><td>"
        << esc(depth_text(c, u)) << "</td><td>" << esc(more) << "</td>";
    }
    const auto sig = [](double v) { return format_significant(v, 4); };
    h << "<td class=\"n\">" << esc(measured_text(r.measured, r.bound, p.tolerance, sig)) << " / "
      << esc(format_bound(r.bound, 4)) << "</td></tr>";
  }
  h << "</table></section>\n";
}

void times_section(std::ostringstream& h, const SetupSheetInput& in) {
  const ProgramReport& rep = *in.report;
  const char* u = to_string(rep.units);
  h << "<section id=\"times\"><h2>Times</h2><p id=\"cycle-time\">" << esc(sheet_cycle_time(in)) << "</p><table>";
  if (const MotionPlan* q = in.plan)
    h << "<tr><th>Planned on the motion model</th><td>cycle " << esc(format_seconds(q->cycle_time_s)) << ": cutting "
      << esc(format_seconds(q->cutting_time_s)) << ", rapids " << esc(format_seconds(q->rapid_time_s))
      << ", pauses (tool changes, dwells) " << esc(format_seconds(q->pause_time_s)) << "; mean feed "
      << format_significant(q->mean_feed_ratio * 100, 3) << " % of programmed</td></tr>";
  h << "<tr><th>Feeds as programmed</th><td>" << esc(format_seconds(rep.total.time_s()))
    << " (no acceleration): " << num(rep.total.feed_length) << " " << u << " at feed, " << num(rep.total.rapid_length)
    << " " << u << " rapid at " << num(rep.rapid_rate) << " " << u << "/min</td></tr>";
  h << "</table></section>\n";
}

void guarantees_section(std::ostringstream& h, const SetupSheetInput& in) {
  const Program& p = *in.program;
  const char* u = to_string(p.units);
  h << "<section id=\"guarantees\"><h2>Guarantees</h2><p id=\"chord-error\">" << esc(sheet_chord_error(p))
    << "</p><ul>";
  h << "<li>Every cutting block stays within the proven bound of the true curve (the figure includes the rounding "
       "of the printed coordinates); the measured figure is an independent check of the printed program.</li>";
  bool offsets = false;
  for (const EntityReport& r : p.entities) offsets = offsets || r.offset > 0;
  if (offsets)
    h << "<li>Offset paths: the bound is the distance of the tool centre's path from the exact offset of the curve "
         "(tool radius plus stock to leave).</li>";
  for (const EntityReport& r : p.entities)
    for (const MaterialLeft& l : r.left)
      h << "<li class=\"warn\">" << esc(r.label) << ": material left over " << num(l.length) << " " << u
        << " of the curve, up to " << num(l.depth) << " " << u << " deep, from " << esc(fmt_point(l.from, 2, 6))
        << " to " << esc(fmt_point(l.to, 2, 6)) << " (the tool cannot reach it)</li>";
  for (const auto& w : p.warnings) h << "<li class=\"warn\">warning: " << esc(w) << "</li>";
  for (const auto& n : p.notes) h << "<li>" << esc(n) << "</li>";
  h << "</ul></section>\n";
}

}  // namespace

std::string setup_sheet_html(const SetupSheetInput& in) {
  if (!in.job || !in.program || !in.machine || !in.report)
    throw std::invalid_argument("setup_sheet_html: job, program, machine and report are required");
  const Program& p = *in.program;
  const std::vector<SheetTool> tools = sheet_tools(in);
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Setup sheet: " << esc(in.title)
    << "</title><style>" << kStyle << "</style></head><body>\n";
  h << "<h1>Setup sheet: " << esc(in.title) << "</h1><p class=\"sub\">machine " << esc(in.machine->name) << ", "
    << to_string(p.units) << ", output " << output_name(p)
    << (p.program_number ? ", program " + std::to_string(*p.program_number) : std::string()) << "; bezcam " << kVersion
    << "</p>\n";
  h << "<div class=\"cards\"><div class=\"card\"><span>cycle time</span><b>"
    << esc(format_clock(sheet_cycle_seconds(in))) << "</b></div><div class=\"card\"><span>tools</span><b>"
    << tools.size() << "</b></div><div class=\"card\"><span>operations</span><b>" << p.entities.size()
    << "</b></div><div class=\"card\"><span>tolerance / proven bound</span><b>" << num(p.tolerance) << " / "
    << format_bound(p.max_bound, 4) << " " << to_string(p.units) << "</b></div></div>\n";
  std::string svg = in.picture_svg;
  if (svg.rfind("<?xml", 0) == 0) svg.erase(0, svg.find("?>") + 2);
  h << "<section id=\"picture\"><h2>The part</h2>" << svg << "</section>\n";
  stock_section(h, in, tools);
  tools_section(h, in, tools);
  operations_section(h, in);
  times_section(h, in);
  guarantees_section(h, in);
  h << "<section id=\"header\"><h2>The program's header</h2><pre>";
  for (const auto& l : in.header) h << esc(l) << "\n";
  h << "</pre></section>\n</body></html>\n";
  return h.str();
}

}  // namespace bezcam
