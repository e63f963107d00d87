#include "bezcam/cam/program.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>

#include "bezcam/cam/cut_order.hpp"
#include "bezcam/cam/program_limits.hpp"
#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/nesting.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/machine/path_bound.hpp"
#include "bezcam/warnings.hpp"
#include "cut_emitters.hpp"
#include "hole_cut.hpp"
#include "measure_path.hpp"

namespace bezcam {

OutputMode parse_output_mode(const std::string& s) {
  if (s == "lines") return OutputMode::lines;
  if (s == "arcs") return OutputMode::arcs;
  if (s == "nurbs") return OutputMode::nurbs;
  throw InputError(errc::usage_output, Place::at_setting("output"),
                   "expected lines, arcs or nurbs, found \"" + s + "\"");
}

const char* to_string(OutputMode m) {
  switch (m) {
    case OutputMode::lines: return "lines";
    case OutputMode::arcs: return "arcs";
    case OutputMode::nurbs: return "nurbs";
  }
  return "?";
}

std::string output_name(const Program& p) {
  if (p.best) return "best";
  if (p.per_entity_output) return "per entity";
  return to_string(p.output);
}

namespace {
// The profile's defaults in the job's units (a profile's are in mm), and
// tool 1 where the profile names none.
JobParams profile_defaults(const Job& job, const MachineProfile& m) {
  JobParams prof = m.defaults;
  const double k = 1.0 / mm_per_unit(job.units);
  for (auto* v : {&prof.feed, &prof.plunge_feed, &prof.safe_z, &prof.cut_z, &prof.tool_radius})
    if (*v) **v *= k;
  if (!prof.tool) prof.tool = 1;
  return prof;
}
}  // namespace

CutParams cut_params(const Job& job, const Entity& e, const MachineProfile& m) {
  const JobParams defaults = profile_defaults(job, m);
  const JobParams p = entity_params(job, e, defaults);  // the tool table's diameter applied
  auto need = [&](const std::optional<double>& v, const char* key) {
    if (!v)
      throw InputError(errc::job_missing, Place::in_json(job.source, e.json_path() + "." + key),
                       std::string("no ") + key + " is set by the entity, the job or machine profile \"" + m.name +
                           "\"; add \"" + key + "\" to the file's \"job\" object");
    return *v;
  };
  CutParams c;
  c.feed = need(p.feed, "feed");
  c.plunge_feed = need(p.plunge_feed, "plunge_feed");
  c.safe_z = need(p.safe_z, "safe_z");
  c.cut_z = need(p.cut_z, "cut_z");
  c.spindle_rpm = p.spindle_rpm.value_or(0);
  c.tool_radius = p.tool_radius.value_or(0);
  c.tool = p.tool.value_or(1);
  c.coolant = p.coolant.value_or(Coolant::off);
  c.clearance = p.clearance;
  c.top_z = p.top_z.value_or(0);
  if (p.before) c.before = *p.before;
  if (p.after) c.after = *p.after;
  c.side = p.side.value_or(CutSide::on);
  c.tool_diameter = p.tool_diameter;
  c.step_down = p.step_down;
  c.stock_to_leave = p.stock_to_leave.value_or(0);
  c.direction = p.direction.value_or(CutDirection::as_drawn);
  c.lead = p.lead;
  c.tabs = p.tabs;
  c.controller_compensation = p.controller_compensation.value_or(false);
  c.tolerance_side = p.tolerance_side.value_or(ToleranceSide::both);
  if (const ToolEntry* t = entity_tool_entry(job, e, defaults); t && !e.surface && e.curve.dim == 2)
    c.flute_length = t->flute_length;
  c.pocket = p.pocket;
  c.drill = p.drill;
  if (c.clearance && c.top_z + *c.clearance <= c.cut_z && !e.surface)
    throw InputError(errc::job_range, Place::in_json(job.source, e.json_path() + ".clearance"),
                     "the clearance plane (top_z " + fmt_num(c.top_z) + " + clearance " + fmt_num(*c.clearance) +
                         ") is not above cut_z = " + fmt_num(c.cut_z) +
                         ": the tool would rapid into the cut; raise "
                         "\"clearance\" or \"top_z\"");
  if (c.cut_z >= c.safe_z)
    throw InputError(errc::job_range, Place::in_json(job.source, e.json_path() + ".cut_z"),
                     "expected cut_z below safe_z (" + fmt_num(c.safe_z) + "), found " + fmt_num(c.cut_z));
  return c;
}

std::string expand_entity_template(const std::string& text, const Entity& e, const CutParams& c, int decimals) {
  auto num = [&](double v) {
    const double q = quantize(v, decimals);
    char b[64];
    return std::string(b, std::to_chars(b, b + sizeof b, q == 0 ? 0.0 : q).ptr);  // never "-0"
  };
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const size_t close = text[i] == '{' ? text.find('}', i) : std::string::npos;
    if (close == std::string::npos) {
      out += text[i];
      continue;
    }
    const std::string name = text.substr(i + 1, close - i - 1);
    if (name == "entity")
      out += e.label();
    else if (name == "tool")
      out += std::to_string(c.tool);
    else if (name == "rpm")
      out += std::to_string(std::llround(c.spindle_rpm));
    else if (name == "feed")
      out += fmt_num(std::round(c.feed * 10) / 10);
    else if (name == "plunge_feed")
      out += fmt_num(std::round(c.plunge_feed * 10) / 10);
    else if (name == "cut_z")
      out += num(c.cut_z);
    else if (name == "safe_z")
      out += num(c.safe_z);
    else if (name == "top_z")
      out += num(c.top_z);
    else
      throw std::logic_error("unchecked placeholder {" + name + "}");
    i = close;
  }
  return out;
}

namespace detail {

void change_tool_and_spindle(Program& p, const MachineProfile& m, const CutParams& cp, double safe, MotionState& ms,
                             int entity) {
  auto push = [&](auto what) { p.moves.push_back(Move{what, entity}); };
  if (cp.tool != ms.tool) {
    const bool first = ms.tool < 0;
    if (!first) {
      // Nothing runs through a tool change: coolant and spindle first.
      if (ms.coolant != Coolant::off) push(CoolantMove{Coolant::off});
      if (ms.rpm > 0) push(SpindleMove{0});
      ms.coolant = Coolant::off;
    }
    if (ms.pos_known && ms.pos.z < safe) {
      RapidMove up;
      up.to = {ms.pos.x, ms.pos.y, safe};
      push(up);
      ms.pos = up.to;
    }
    if (!m.tool_change_position.empty() && (m.tool_changer || !first)) {
      push(ToolChangePosition{});
      ms.pos_known = false;  // somewhere up: the next approach sets Z first
    }
    if (m.tool_changer) {
      push(ToolChange{cp.tool});
    } else if (first) {
      push(Comment{"tool " + std::to_string(cp.tool) + ": load it before starting"});
    } else {
      // No changer: the program stops; the operator changes the tool and
      // resumes. Cutting on with the old tool is what a comment would do.
      push(ProgramStop{"change to tool " + std::to_string(cp.tool) + ", then resume"});
      const std::string w = "machine " + m.name + " has no tool changer: the program stops (M0) for tool " +
                            std::to_string(cp.tool) + "; change it by hand and resume";
      if (std::find(p.warnings.begin(), p.warnings.end(), w) == p.warnings.end()) p.warnings.push_back(w);
    }
    ms.tool = cp.tool;
    ms.rpm = -1;
  }
  if (cp.spindle_rpm != ms.rpm) {
    push(SpindleMove{cp.spindle_rpm});
    if (cp.spindle_rpm > 0 && m.spindle_dwell_s > 0) push(Dwell{m.spindle_dwell_s});
    ms.rpm = cp.spindle_rpm;
  }
  if (cp.coolant != ms.coolant) {
    push(CoolantMove{cp.coolant});
    ms.coolant = cp.coolant;
  }
}

Vec3 cut_point(const CutContext& c, const Vec3& p) {
  if (c.entity.curve.dim == 2) return {p.x, p.y, quantize(c.params.cut_z, c.decimals)};
  return p;
}

void emit_lines(CutContext& c, EntityReport& r) {
  FlattenOptions fo{c.tolerance, c.decimals};
  std::vector<Vec3> poly;
  const double bound = flatten_into(c.entity.curve.pieces, fo, poly);
  emit_polyline(c, r, std::move(poly), bound);
}

void emit_polyline(CutContext& c, EntityReport& r, std::vector<Vec3> poly, double bound) {
  const auto& pieces = c.entity.curve.pieces;
  r.bound = bound;
  // The first vertex is where the plunge put the tool.
  for (size_t i = 1; i < poly.size(); ++i) {
    LineMove l;
    l.to = cut_point(c, poly[i]);
    l.feed = c.params.feed;
    c.program.moves.push_back({l, static_cast<int>(c.entity.index)});
  }
  r.blocks = poly.size() - 1;
  if (c.measure)
    c.measure_with(r, [pieces = std::span<const Bezier>(pieces), poly = std::move(poly), tol = c.tolerance, bound,
                       label = r.label] {
      const double m = measure_printed(pieces, poly, tol, bound, 0);
      if (m > tol)
        throw std::logic_error("internal check failed: " + label + " deviates by " + fmt_num(m) +
                               " beyond the tolerance " + fmt_num(tol));
      return m;
    });
}

// Retract (straight up) if not at this entity's safe Z, rapid over the
// start, rapid down to the clearance plane `clear` (when below safe), plunge
// at the plunge feed. Leaves `ms.pos` where it was: the caller takes the
// position from the cut that follows.
void approach(Program& p, int entity, const Vec3& start, double safe, double clear, double plunge_feed,
              const detail::MotionState& ms) {
  auto push = [&](Move mv) { p.moves.push_back(std::move(mv)); };
  if (!ms.pos_known || ms.pos.z != safe) {
    RapidMove up;
    up.to = {ms.pos_known ? ms.pos.x : 0, ms.pos_known ? ms.pos.y : 0, safe};
    if (!ms.pos_known) up.axes = kAxisZ;  // position unknown: move Z only
    push({up, entity});
  }
  RapidMove over;
  over.to = {start.x, start.y, safe};
  push({over, entity});
  if (clear < safe) {
    RapidMove down;
    down.to = {start.x, start.y, clear};
    push({down, entity});
  }
  LineMove plunge;
  plunge.to = start;
  plunge.feed = plunge_feed;
  push({plunge, entity});
}

Measurements::~Measurements() {
  {
    std::lock_guard lk(m_);
    stop_ = true;
  }
  more_.notify_all();
  for (auto& t : pool_) t.join();
}

void Measurements::add(size_t report, std::function<double()> measure) {
  auto t = std::make_unique<Task>();
  t->report = report;
  t->measure = std::move(measure);
  std::lock_guard lk(m_);
  tasks_.push_back(std::move(t));
}

void Measurements::release() {
  {
    std::lock_guard lk(m_);
    if (released_ == tasks_.size()) return;
    released_ = tasks_.size();
    // The workers start with the first task: the calling thread builds
    // on, the other cores measure.
    if (pool_.empty())
      for (unsigned k = 1; k < std::max(1u, std::thread::hardware_concurrency()); ++k)
        pool_.emplace_back([this] { work(false); });
  }
  more_.notify_all();
}

// Takes released tasks in order and runs them; a worker waits for more
// until stopped, finish()'s thread returns when none is left to take.
void Measurements::work(bool until_empty) {
  std::unique_lock lk(m_);
  for (;;) {
    if (!until_empty) more_.wait(lk, [&] { return stop_ || next_ < released_; });
    if (stop_ || next_ >= released_) return;
    const size_t i = next_++;
    Task& t = *tasks_[i];
    // Past an earlier failure: its reading is not needed.
    if (i < failed_) {
      lk.unlock();
      try {
        t.reading = t.measure();
      } catch (...) {
        t.error = std::current_exception();
      }
      t.measure = nullptr;  // the path it held
      lk.lock();
      if (t.error) failed_ = std::min(failed_, i);
    }
    if (++finished_ == tasks_.size()) done_.notify_all();
  }
}

const std::vector<std::unique_ptr<Measurements::Task>>& Measurements::finish() {
  release();
  work(true);
  std::unique_lock lk(m_);
  done_.wait(lk, [&] { return finished_ == tasks_.size(); });
  if (failed_ != SIZE_MAX) std::rethrow_exception(tasks_[failed_]->error);
  return tasks_;
}

}  // namespace detail

namespace {
using WhileMeasuring = std::function<void(const Program&)>;
Program build_program_unchecked(const Job& job, const MachineProfile& m, const ConvertOptions& opt,
                                const WhileMeasuring& while_measuring);
Program build_program_checked(const Job& job, const MachineProfile& m, const ConvertOptions& opt,
                              const WhileMeasuring& while_measuring);
}  // namespace

MachineProfile with_compensation_registers(const MachineProfile& m, const Program& p) {
  MachineProfile out = m;
  for (const Move& mv : p.moves)
    if (const auto* cc = std::get_if<CompensationMove>(&mv.what))
      if (cc->side != 0) out.tool_diameters_mm[cc->d] = 2 * cc->radius * mm_per_unit(p.units);
  return out;
}

Program build_program(const Job& job, const MachineProfile& m, const ConvertOptions& opt) {
  return build_program(job, m, opt, nullptr);
}

Program build_program(const Job& job, const MachineProfile& m, const ConvertOptions& opt,
                      const std::function<void(const Program&)>& while_measuring) {
  // The caller's failure is kept aside while the measurements finish (a
  // failed one is thrown first), and thrown as it is: not through the
  // tolerance wording below, which is for the build's own refusals.
  std::exception_ptr during;
  WhileMeasuring guarded;
  if (while_measuring)
    guarded = [&](const Program& p) {
      try {
        while_measuring(p);
      } catch (...) {
        during = std::current_exception();
      }
    };
  Program p = build_program_checked(job, m, opt, guarded);
  if (during) std::rethrow_exception(during);
  return p;
}

namespace {

Program build_program_checked(const Job& job, const MachineProfile& m, const ConvertOptions& opt,
                              const WhileMeasuring& while_measuring) {
  try {
    return build_program_unchecked(job, m, opt, while_measuring);
  } catch (const InputError& e) {
    // The flattener knows neither the file nor the machine: say where the
    // tolerance came from and whose decimals it meets.
    // (Also the flattener's own segment limit, found while flattening.)
    const ErrorId id = e.id();
    const bool tolerance = id == errc::flatten_tolerance || id == errc::flatten_tolerance_below_precision ||
                           id == errc::flatten_tolerance_below_rounding;
    if (!tolerance && !(id == errc::limit_segments && e.place().relative_path() == "tolerance")) throw;
    throw InputError(
        e.id(), opt.tolerance ? Place::at_setting("tolerance") : Place::in_json(job.source, "tolerance"),
        e.message() + " (machine \"" + m.name + "\" prints " + std::to_string(m.decimals(job.units)) + " decimals in " +
            to_string(job.units) +
            (m.max_decimals(job.units) > m.decimals(job.units)
                 ? ", at most " + std::to_string(m.max_decimals(job.units)) + " when the tolerance needs them"
                 : std::string()) +
            ")");
  }
}

// Waits for the measurements (run on every core as the program was
// built), fills the reports and the program's largest reading; the
// earliest failure (an internal check) is rethrown here.
void run_measurements(Program& p, detail::Measurements& later) {
  for (const auto& t : later.finish()) {
    // An entity cut in several runs (part cutting) has several readings.
    auto& m = p.entities[t->report].measured;
    m = std::max(m, t->reading);
    p.max_measured = std::max(p.max_measured, t->reading);
  }
}

// Adds the offset (rounded to the program's decimals) to every X and Y,
// and rounds again: a decimal plus a decimal is the decimal the
// controller reads, so the measured deviation holds for the moved part.
void move_part(Program& p, const Vec3& offset) {
  const Vec3 d{quantize(offset.x, p.decimals), quantize(offset.y, p.decimals), 0};
  if (d.x == 0 && d.y == 0) return;
  p.offset = d;
  auto shift = [&](Vec3& v) {
    v.x = quantize(v.x + d.x, p.decimals);
    v.y = quantize(v.y + d.y, p.decimals);
  };
  for (Move& mv : p.moves)
    std::visit(
        [&](auto& x) {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_base_of_v<Motion, T>) shift(x.to);
          if constexpr (std::is_same_v<T, ArcMove>) shift(x.center);
          if constexpr (std::is_same_v<T, CannedCycle>) shift(x.at);
          if constexpr (std::is_same_v<T, CurveMove>) {
            x.shape = std::make_shared<CurveShape>(*x.shape);  // copies of the move keep their own
            for (auto& c : x.shape->ctrl) shift(c);
          }
        },
        mv.what);
  const bool rounded = d.x != offset.x || d.y != offset.y;
  p.notes.push_back("the part is moved by X" + fmt_num(d.x) + " Y" + fmt_num(d.y) +
                    (rounded ? " (the offset rounded to " + std::to_string(p.decimals) + " decimals)" : ""));
}

// An entity with `operation: "pocket"`: its region is cut with the first
// of its entities (pocket_emit.cpp). False for any other entity.
bool cut_pocket_region(const Job& job, const MachineProfile& m, const ConvertOptions& opt, const Entity& e,
                       const CutParams& cp, double safe, detail::MotionState ms, Program& p,
                       detail::Measurements& later, ProgramLength& length) {
  if (cp.pocket.operation != Operation::pocket) return false;
  const auto members = detail::pocket_members(job, e, m, p);
  if (members.empty()) return true;
  auto push = [&](Move mv) { p.moves.push_back(std::move(mv)); };
  detail::change_tool_and_spindle(p, m, cp, safe, ms, -1);
  EntityReport r;
  r.entity = static_cast<int>(e.index);
  detail::CutContext ctx{job,         e,           m, cp,     opt.output_of(e.index), p.decimals,
                         p.tolerance, opt.measure, p, &later, p.entities.size()};
  ctx.memo = opt.memo.get();
  const double clear = cp.clearance ? std::min(safe, quantize(cp.top_z + *cp.clearance, p.decimals)) : safe;
  if (clear < safe) r.clear_z = clear;
  push({Comment{"pocket: " + std::to_string(members.size()) + (members.size() == 1 ? " curve" : " curves") + " from " +
                e.label()}});
  for (const auto& line : cp.before) push({Verbatim{expand_entity_template(line, e, cp, p.decimals)}, r.entity});
  detail::emit_pocket(ctx, ms, r, safe, clear, members);
  for (const auto& line : cp.after) push({Verbatim{expand_entity_template(line, e, cp, p.decimals)}, r.entity});
  p.max_measured = std::max(p.max_measured, r.measured);
  p.max_bound = std::max(p.max_bound, r.bound);
  p.entities.push_back(r);
  later.release();
  length.after_entity(p, job, e);
  return true;
}

// An entity with `operation: "drill"` or `"bore"`: its hole (hole_cut.cpp).
// `joins` says whether the hole before left the drill at the R plane for
// this one, and is set for the next. False for any other entity.
bool cut_hole_entity(const Job& job, const MachineProfile& m, const ConvertOptions& opt, const Entity& e,
                     const CutParams& cp, double safe, detail::MotionState ms, Program& p, detail::Measurements& later,
                     ProgramLength& length, bool& joins) {
  const OutputMode mode = opt.output_of(e.index);
  detail::CutContext hc{job, e, m, cp, mode, p.decimals, p.tolerance, opt.measure, p, &later, p.entities.size()};
  const size_t i = static_cast<size_t>(&e - job.entities.data());
  const bool joins_next =
      detail::holes_join(job, m, e, i + 1 < job.entities.size() ? &job.entities[i + 1] : nullptr, p.decimals);
  const bool hole = detail::cut_hole(hc, ms, safe, joins, joins_next, mode != OutputMode::lines && m.arcs);
  joins = hole && joins_next;
  if (!hole) return false;
  later.release();
  length.after_entity(p, job, e);
  return true;
}

// A pocket's region or a hole (the two above); false for any other entity.
bool cut_op(const Job& job, const MachineProfile& m, const ConvertOptions& opt, const Entity& e, const CutParams& cp,
            double safe, detail::MotionState ms, Program& p, detail::Measurements& later, ProgramLength& length,
            bool& joins) {
  return cut_pocket_region(job, m, opt, e, cp, safe, ms, p, later, length) ||
         cut_hole_entity(job, m, opt, e, cp, safe, ms, p, later, length, joins);
}

// A closed contour cut "outside" whose innermost enclosing contour (among
// those cut inside or outside) is cut "outside" too is a hole in that
// part: cut on its outside, it comes out larger by the tool's diameter,
// into the part. Worth a word, naming both (docs/job-format.md).
std::vector<std::string> nested_outside_warnings(const Job& job) {
  std::vector<const Entity*> es;
  std::vector<CutSide> sides;
  std::vector<std::vector<Bezier>> curves;
  size_t outside = 0;
  for (const Entity& e : job.entities) {
    const auto& g = e.curve;
    if (e.surface || g.pieces.empty()) continue;
    const JobParams p = e.params.over(job.params);
    if (!p.side || (*p.side != CutSide::inside && *p.side != CutSide::outside)) continue;
    const double scale = std::max(1.0, control_magnitude(g.pieces));
    if (!g.closed && dist(g.pieces.front().front(), g.pieces.back().back()) > 1e-9 * scale) continue;
    es.push_back(&e);
    sides.push_back(*p.side);
    curves.push_back(g.pieces);
    outside += *p.side == CutSide::outside;
  }
  if (outside < 2) return {};
  const Nesting nest = nest_closed_curves(curves);
  const auto name = [](const Entity& e) {
    return e.json_path() + (e.id.empty() ? std::string() : " (id \"" + e.id + "\")");
  };
  std::vector<std::string> out;
  for (size_t i = 0; i < es.size(); ++i) {
    if (sides[i] != CutSide::outside || !nest.parent[i] || sides[*nest.parent[i]] != CutSide::outside) continue;
    const Entity& e = *es[i];
    const Entity& around = *es[*nest.parent[i]];
    const bool own = e.params.side.has_value();
    out.push_back(
        name(e) + " is cut \"outside\"" + (own ? "" : " (the job's side)") + " but lies inside " + name(around) +
        ", also cut \"outside\": it is a hole in that part, and cut on its outside it comes out larger by the "
        "tool's diameter, cut into the part; give it \"side\": \"inside\"");
  }
  return out;
}

// The cut along an entity's curve in the output mode, the range of its
// moves and, on a machine with a motion model, its exact path's bound.
void cut_along(detail::CutContext& ctx, OutputMode mode, EntityReport& r) {
  r.cut_first = ctx.program.moves.size();
  switch (mode) {
    case OutputMode::lines: detail::emit_lines(ctx, r); break;
    case OutputMode::arcs: detail::emit_arcs(ctx, r); break;
    case OutputMode::nurbs: detail::emit_nurbs(ctx, r); break;
  }
  r.cut_end = ctx.program.moves.size();
  if (const auto& mo = ctx.machine.motion)
    r.time_bound_s =
        exact_path_time_bound(ctx.entity.curve.pieces, ctx.params.feed, *mo, ctx.program.units, cuts_from_rest(*mo));
}

// The refusals of a job's entities: each reported once, a drawing's
// entity located in the drawing.
class Refusals {
 public:
  void add(const InputError& x, const Entity& e) {
    add_one(x, e);
    for (const Error& more : x.more()) add_one(more, e);
  }
  void throw_if_any() const {
    if (all_.empty()) return;
    InputError first = all_.front();
    for (size_t i = 1; i < all_.size(); ++i) first.add_more(all_[i]);
    throw first;
  }

 private:
  void add_one(const Error& x, const Entity& e) {
    for (const InputError& seen : all_)
      if (seen.id() == x.id() && seen.where() == x.where() && seen.message() == x.message()) return;
    if (e.origin.empty() || x.message().find(e.origin) != std::string::npos)
      all_.emplace_back(x.id(), x.place(), x.message());
    else
      all_.emplace_back(x.id(), x.place(), x.message() + " [" + e.origin + "]");
  }
  std::vector<InputError> all_;
};

// A curve entity that is not a pocket: tool and spindle, the approach, the
// cut in the output mode (or as a part: part_cut.cpp), the retract.
void cut_curve(const Job& job, const MachineProfile& m, const ConvertOptions& opt, const Entity& e, const CutParams& cp,
               double safe, detail::MotionState ms, Program& p, detail::Measurements& later, ProgramLength& length,
               std::deque<Entity>& owned) {
  auto push = [&](Move mv) { p.moves.push_back(std::move(mv)); };
  const auto& g = e.curve;
  if (g.dim == 3) {
    const Box3 b = g.bounds();
    if (b.hi.z > cp.safe_z)
      throw InputError(errc::job_above_safe_z, Place::in_json(job.source, e.json_path()),
                       "the curve rises to z = " + fmt_num(b.hi.z) + ", above safe_z = " + fmt_num(cp.safe_z) +
                           "; rapid moves at safe_z would cross it: raise safe_z");
  }
  detail::change_tool_and_spindle(p, m, cp, safe, ms, -1);
  const OutputMode mode = opt.output_of(e.index);
  // Each entity in its own mode: the program says which, where it is cut.
  push({Comment{"entity " + e.label() + ": " + e.type + ", degree " + std::to_string(g.max_degree()) +
                (g.rational() ? ", rational" : "") + (g.dim == 3 ? ", 3D" : ", 2D") +
                (p.per_entity_output ? std::string(", ") + to_string(mode) : "")}});

  EntityReport r;
  r.label = e.label();
  r.entity = static_cast<int>(e.index);
  r.type = e.type;
  r.degree = g.max_degree();
  r.length = g.length();
  detail::CutContext ctx{job, e, m, cp, mode, p.decimals, p.tolerance, opt.measure, p, &later, p.entities.size()};
  const Vec3 start = detail::cut_point(ctx, quantize(g.pieces.front().front(), p.decimals));
  const int entity = static_cast<int>(e.index);
  r.tool = cp.tool;
  double clear = safe;
  if (cp.clearance) {
    clear = std::min(safe, quantize(cp.top_z + *cp.clearance, p.decimals));
    if (clear <= start.z)
      throw InputError(errc::job_range, Place::in_json(job.source, e.json_path() + ".clearance"),
                       "the clearance plane z = " + fmt_num(clear) + " is not above the curve's start (z = " +
                           fmt_num(start.z) + "): the tool would rapid into the cut; raise \"clearance\" or \"top_z\"");
    if (clear < safe) r.clear_z = clear;
  }
  for (const auto& line : cp.before) push({Verbatim{expand_entity_template(line, e, cp, p.decimals)}, entity});
  if (cp.part_cut()) {
    ctx.owned = &owned;
    detail::emit_part(ctx, ms, r, safe, clear);  // ends retracted, pos set
  } else {
    detail::approach(p, entity, start, safe, clear, cp.plunge_feed, ms);
    cut_along(ctx, mode, r);
    ms.pos = motion_of(p.moves.back())->to;  // the cut ends with a motion
    RapidMove retract;
    retract.to = {ms.pos.x, ms.pos.y, safe};
    push({retract, entity});
    ms.pos = retract.to;
    ms.pos_known = true;
  }
  for (const auto& line : cp.after) push({Verbatim{expand_entity_template(line, e, cp, p.decimals)}, entity});
  p.max_measured = std::max(p.max_measured, r.measured);
  p.max_bound = std::max(p.max_bound, r.bound);
  p.entities.push_back(r);
  later.release();  // the entity is complete: its measurements may run
  length.after_entity(p, job, e);
}

Program build_program_unchecked(const Job& original_job, const MachineProfile& m, const ConvertOptions& opt,
                                const WhileMeasuring& while_measuring) {
  Program p;
  const Job ordered_job = original_job.order_shortest ? detail::ordered(original_job, m, p) : Job{};
  const Job& job = original_job.order_shortest ? ordered_job : original_job;
  p.job_name = std::filesystem::path(job.source).filename().string();
  p.machine = m.name;
  p.units = job.units;
  p.output = opt.output;
  p.per_entity_output = !opt.entity_output.empty();
  p.tolerance = opt.tolerance.value_or(job.tolerance);
  p.decimals = m.decimals(job.units);
  // Decimals from the tolerance: where the profile's default would use up
  // the tolerance in rounding alone (check_tolerance() refuses from 90 %),
  // print as many more as the controller accepts to keep rounding under
  // half of it. Beyond the controller's most, the refusal stands.
  if (max_rounding_displacement(p.decimals, 3) >= 0.9 * p.tolerance) {
    const int most = m.max_decimals(job.units);
    int d = p.decimals;
    while (d < most && max_rounding_displacement(d, 3) >= 0.5 * p.tolerance) ++d;
    if (d != p.decimals)
      p.notes.push_back("coordinates with " + std::to_string(d) + " decimals for tolerance " +
                        [&] {
                          char b[32];
                          std::snprintf(b, sizeof b, "%g", p.tolerance);
                          return std::string(b);
                        }() +
                        " " + to_string(job.units) + " (machine " + m.name + ": " + std::to_string(p.decimals) +
                        " by default, at most " + std::to_string(most) + ")");
    p.decimals = d;
  }
  p.warnings = job.warnings;
  for (std::string& w : nested_outside_warnings(job))
    p.warnings.push_back(tagged_warning(std::move(w), "nested-outside"));
  for (std::string& w : detail::nested_pocket_warnings(job, m))
    p.warnings.push_back(tagged_warning(std::move(w), "nested-pocket"));
  p.program_number = opt.program_number ? opt.program_number : job.program_number;
  p.tools = job_tools(job, profile_defaults(job, m));
  auto push = [&](Move mv) { p.moves.push_back(std::move(mv)); };

  int cur_tool = -1;
  double cur_rpm = -1;
  Coolant cur_coolant = Coolant::off;
  Vec3 pos;
  bool pos_known = false, at_r = false;  // at_r: the drill waits at a hole's R plane (hole_cut.cpp)
  ProgramLength length;                  // stated limits (program_limits.hpp)
  std::deque<Entity> owned;              // part cutting's geometry, read by `later`
  detail::Measurements later;
  // Every independent refusal of an entity is reported, not only the
  // first: an entity refused, the next ones are still cut (the program is
  // not returned).
  Refusals refusals;
  const auto cut_entity = [&](const Entity& e) {
    const CutParams cp = cut_params(job, e, m);
    check_entity_limits(job, e, p.tolerance, p.decimals, cp.tool_radius,
                        opt.tolerance ? Place::at_setting("tolerance") : Place::in_json(job.source, "tolerance"));
    const double safe = quantize(cp.safe_z, p.decimals);
    p.safe_z = p.entities.empty() ? safe : std::min(p.safe_z, safe);
    const auto& g = e.curve;
    if (e.surface) {  // patches and curves on surfaces: surface_emitter.cpp
      detail::CutContext sc{job, e, m, cp, opt.output_of(e.index), p.decimals, p.tolerance, opt.measure, p, nullptr, 0};
      detail::MotionState ms{cur_tool, cur_rpm, pos, pos_known, cur_coolant};
      const EntityReport r = detail::emit_surface(sc, ms);
      for (const auto& line : cp.after)
        push({Verbatim{expand_entity_template(line, e, cp, p.decimals)}, static_cast<int>(e.index)});
      p.max_measured = std::max(p.max_measured, r.measured);
      p.max_bound = std::max(p.max_bound, r.bound);
      p.entities.push_back(r);
      length.after_entity(p, job, e);
      return;
    }
    if (cut_op(job, m, opt, e, cp, safe, {cur_tool, cur_rpm, pos, pos_known, cur_coolant}, p, later, length, at_r))
      return;
    if (g.pieces.empty()) return;
    cut_curve(job, m, opt, e, cp, safe, {cur_tool, cur_rpm, pos, pos_known, cur_coolant}, p, later, length, owned);
  };
  for (const Entity& e : job.entities) {
    if (opt.on_entity) opt.on_entity(e.index, job.entities.size(), e.label());
    try {
      const size_t first = p.entities.size();
      cut_entity(e);
      for (size_t i = first; i < p.entities.size(); ++i) {
        p.entities[i].plunge_feed = cut_params(job, e, m).plunge_feed;
        p.entities[i].output = opt.output_of(e.index);
      }
    } catch (const InputError& x) {
      refusals.add(x, e);
    }
  }
  refusals.throw_if_any();
  // The coolant stops with the cut; the profile's footer stops the spindle.
  if (cur_coolant != Coolant::off) push({CoolantMove{Coolant::off}});
  // The moves are final from here on (the measurements read only what their
  // tasks hold, never p.moves): the caller's work on them runs while the
  // last measurements do.
  move_part(p, opt.offset);
  if (opt.return_to) {
    // Up (Z only) to the higher of safe Z and the target, across, then down.
    const Vec3 to = quantize(*opt.return_to, p.decimals);
    const double high = std::max({pos_known ? pos.z : p.safe_z, p.safe_z, to.z});
    auto rapid = [&](const Vec3& where, unsigned axes) {
      RapidMove r;
      r.to = where;
      r.axes = axes;
      push({r});
    };
    if (!pos_known || pos.z != high) rapid({0, 0, high}, kAxisZ);
    rapid({to.x, to.y, high}, kAxisX | kAxisY);
    if (to.z < high) rapid(to, kAxisZ);
  }
  if (while_measuring) while_measuring(p);
  run_measurements(p, later);
  if (opt.on_entity) opt.on_entity(job.entities.size(), job.entities.size(), "");
  return p;
}

}  // namespace

}  // namespace bezcam
