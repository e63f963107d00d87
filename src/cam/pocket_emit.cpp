// A pocket's moves (cut_emitters.hpp emit_pocket()): the region from its
// entities, the refusals, the passes at every depth level with their
// entries, and the certificate of the moves made.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/nesting.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/format.hpp"
#include "bezcam/job/tools.hpp"
#include "cut_emitters.hpp"
#include "pocket_memo.hpp"
#include "pocket_plan.hpp"
#include "speed_stretches.hpp"

namespace bezcam::detail {

namespace {

// A pass's block at depth z, its end rounded as every move's.
Move pass_move(const FitMove& f, double z, double feed, int decimals, int entity) {
  const Vec3 to = quantize(Vec3{f.to.x, f.to.y, z}, decimals);
  if (f.kind == FitKind::line) {
    LineMove l;
    l.to = to;
    l.feed = feed;
    return {l, entity};
  }
  ArcMove a;
  a.to = to;
  a.center = {f.center.x, f.center.y, to.z};
  a.ccw = f.kind == FitKind::arc_ccw;
  a.feed = feed;
  return {a, entity};
}

// The planned cycle time (`model`) of `moves` alone, in `units`.
double moves_time(Units units, std::span<const Move> moves, const MotionModel& model) {
  Program p;
  p.units = units;
  p.moves.assign(moves.begin(), moves.end());
  return plan_motion(program_timeline(p), model, PlanDetail::summary).cycle_time_s;
}

class PocketCut {
 public:
  /// `lines`: the passes as lines output cuts them, whatever the output.
  PocketCut(CutContext& c, MotionState& ms, EntityReport& r, double safe, double clear,
            const std::vector<const Entity*>& members, bool lines = false)
      : c_(c),
        ms_(ms),
        r_(r),
        safe_(safe),
        clear_(clear),
        members_(members),
        cp_(c.params),
        keys_(cp_.pocket),
        lines_(lines) {}
  /// Whether run() cut passes in lines that arcs output would cut in arcs
  /// (cut_levels()).
  bool lines_taken() const { return lines_taken_; }

  void run() {
    first_move_ = c_.program.moves.size();
    start_ = ms_.pos_known ? ms_.pos : Vec3{0, 0, safe_};
    read_region();
    read_keys();
    plan();
    fit_passes();
    plan_depths();
    cut_levels();
    up(safe_);
    certify();
  }

 private:
  // Refuses, naming the key where it was set: the first member's, else the job's.
  [[noreturn]] void fail(const std::string& key, const std::string& why) const {
    const Entity& e = c_.entity;
    const std::string path = e.json_path() + (key.empty() ? "" : "." + key);
    throw InputError(errc::job_pocket, Place::in_json(c_.job.source, path), why);
  }
  std::string name() const {
    return "pocket region \"" + region_ + "\" (" + std::to_string(members_.size()) +
           (members_.size() == 1 ? " curve)" : " curves)");
  }

  void read_region();
  void read_keys();
  void plan();
  void fit_passes();
  double planned_pass_time(const std::vector<Vec3>& pass, const std::vector<FitMove>& moves) const;
  void plan_depths();
  void cut_levels();
  double planned_time() const {
    const auto& m = c_.program.moves;
    return moves_time(c_.program.units, {m.begin() + static_cast<std::ptrdiff_t>(first_move_), m.end()},
                      *c_.machine.motion);
  }
  void cut_level(size_t k);
  struct Entry {
    bool helix = false;
    Vec3 at;   // where the tool goes down
    Vec3 cen;  // the helix's centre
  };
  Entry entry_for(const std::vector<Vec3>& pass, bool count);
  Entry entry_of(const PocketPass& p, bool count);
  void enter(const Entry& e, const std::vector<Vec3>& pass, double z_from, double z);
  void helix(const Entry& e, double z_from, double z);
  void ramp(const std::vector<Vec3>& pass, double z_from, double z);
  void certify();

  void line(const Vec3& to, double feed) {
    LineMove l;
    l.to = quantize(to, c_.decimals);
    l.feed = feed;
    c_.program.moves.push_back({l, entity()});
    ms_.pos = l.to;
  }
  void rapid(const Vec3& to, unsigned axes = kAxesXYZ) {
    RapidMove m;
    m.to = quantize(to, c_.decimals);
    m.axes = axes;
    c_.program.moves.push_back({m, entity()});
    ms_.pos = m.to;
    ms_.pos_known = true;
  }
  void up(double z) {
    if (!ms_.pos_known)
      rapid({0, 0, z}, kAxisZ);
    else if (ms_.pos.z < z)
      rapid({ms_.pos.x, ms_.pos.y, z});
  }
  int entity() const { return static_cast<int>(c_.entity.index); }
  bool arcs_out() const { return !lines_ && c_.machine.arcs && c_.output != OutputMode::lines; }

  CutContext& c_;
  MotionState& ms_;
  EntityReport& r_;
  const double safe_, clear_;
  const std::vector<const Entity*>& members_;
  const CutParams& cp_;
  const PocketKeys& keys_;
  const bool lines_;
  bool lines_taken_ = false;
  std::string region_;
  PocketLoops walls_;
  double wall_bound_ = 0, radius_ = 0, stepover_ = 0, margin_ = 0, load_ = 0;
  PocketPattern pattern_ = PocketPattern::offset;
  PocketEntry entry_;
  PocketPlan plan_;
  /// Arcs output: how far the passes' arcs may stand from their polylines
  /// (0: lines), and each pass's moves in XY.
  double fit_ = 0, sag_ = 0;
  std::vector<std::vector<FitMove>> fits_;
  /// The passes faster in lines than in arcs (fit_passes()), by index.
  std::vector<std::pair<size_t, std::vector<FitMove>>> faster_;
  std::vector<double> levels_;
  size_t helix_fallbacks_ = 0;
  size_t first_move_ = 0;
  Vec3 start_;
};

void PocketCut::read_region() {
  const Entity& first = c_.entity;
  region_ = keys_.region.value_or(first.id.empty() ? first.label() : first.id);
  std::vector<std::vector<Bezier>> curves;
  // Arcs output spends a share of the tolerance on drawing the passes as
  // arcs (read_keys()): the walls take a quarter of what they take with
  // lines, with their vertices on the curve, so that an offset ring's
  // vertices lie on the exact offset and only its chords dip inside (half
  // the band's spread about it, which the arcs through its vertices cover).
  const double h = c_.tolerance / (arcs_out() ? 16 : 4);
  for (const Entity* e : members_) {
    const auto& g = e->curve;
    if (e->surface || g.pieces.empty())
      fail("operation", e->label() + " is not a curve: only closed curves bound a pocket");
    const Vec3 a = g.pieces.front().front(), b = g.pieces.back().back();
    if (!g.closed && dist_xy(a, b) > c_.tolerance)
      throw InputError(errc::job_pocket, Place::in_json(c_.job.source, e->json_path() + ".operation"),
                       e->label() + " is open (its ends (" + fmt_num(a.x, 6) + ", " + fmt_num(a.y, 6) + ") and (" +
                           fmt_num(b.x, 6) + ", " + fmt_num(b.y, 6) +
                           ") do not meet): a pocket is bounded by closed curves; close it or cut it as a profile");
    curves.push_back(g.pieces);
    std::vector<Vec3> poly;
    FlattenOptions fo{h, -1};
    fo.on_curve = arcs_out();
    wall_bound_ = std::max(wall_bound_, flatten_into(g.pieces, fo, poly));
    if (poly.size() > 1 && dist_xy(poly.front(), poly.back()) <= c_.tolerance) poly.pop_back();
    for (Vec3& v : poly) v.z = 0;
    walls_.push_back(std::move(poly));
  }
  const Nesting n = nest_closed_curves(curves);
  if (!n.crossing.empty()) {
    const auto [i, j] = n.crossing.front();
    throw InputError(errc::job_pocket, Place::in_json(c_.job.source, members_[j]->json_path()),
                     members_[j]->label() + " crosses " + members_[i]->label() + " in " + name() +
                         ": an island must lie wholly inside the outline (or wholly outside it); give it "
                         "another \"region\" or correct the drawing");
  }
}

void PocketCut::read_keys() {
  const double d = cp_.tool_diameter ? *cp_.tool_diameter : 2 * cp_.tool_radius;
  if (!(d > 0)) fail("tool_diameter", "a pocket needs the tool's diameter: give \"tool_diameter\"");
  radius_ = d / 2;
  stepover_ = keys_.stepover.value_or(0.4 * d);
  if (stepover_ > d)
    fail("stepover", "the stepover " + fmt_num(stepover_) + " is above the tool's diameter " + fmt_num(d) +
                         ": the passes would leave ridges between them; give at most " + fmt_num(d));
  if (keys_.rest_from && !(*keys_.rest_from > d))
    fail("rest_from", "rest_from " + fmt_num(*keys_.rest_from) + " is not larger than this tool's diameter " +
                          fmt_num(d) +
                          ": rest machining cuts what a larger tool left; give the diameter of the tool that "
                          "cleared before, or remove \"rest_from\" to clear the whole region");
  pattern_ = keys_.pattern.value_or(PocketPattern::offset);
  load_ = keys_.load.value_or(0.15 * d);
  if (keys_.load && pattern_ != PocketPattern::adaptive)
    fail("load", "\"load\" is the radial depth of cut of \"pattern\": \"adaptive\"; remove it or set the pattern");
  if (pattern_ == PocketPattern::adaptive && !(load_ <= radius_))
    fail("load", "the load " + fmt_num(load_) + " is above the tool's radius " + fmt_num(radius_) +
                     ": the engagement arccos(1 - load / r) would pass 90 degrees; give at most " + fmt_num(radius_));
  if (cp_.stock_to_leave < 0)
    fail("stock_to_leave", "a pocket leaves stock_to_leave >= 0 on its walls, found " + fmt_num(cp_.stock_to_leave));
  entry_ = keys_.entry.value_or(PocketEntry{});
  JobParams which;
  which.tool = cp_.tool;
  if (const ToolEntry* t = entity_tool_entry(c_.job, c_.entity, which)) {
    if (t->shape == ToolType::vee || t->shape == ToolType::drill)
      fail("tool", "tool " + std::to_string(t->number) + " (" + t->description() +
                       ") cannot clear a pocket: its side does not cut a wall; use an end mill (flat, ball or bull)");
    if (entry_.kind == PocketEntry::Kind::plunge && !t->center_cutting)
      fail("entry", "tool " + std::to_string(t->number) + " (" + t->description() +
                        ") is not center-cutting: it cannot plunge; give \"entry\": \"helix\" or \"ramp\" (or "
                        "\"center_cutting\": true in the tool table if it is)");
  }
  if (!entry_.radius) entry_.radius = radius_ / 2;
  const double rho = max_rounding_displacement(c_.decimals, 2);
  margin_ = wall_bound_ + rho + c_.tolerance * 1e-3;
  // Arcs (and NURBS: the passes are arcs and lines, which G02/G03 print
  // exactly): each pass is drawn as arcs within fit_ of its polyline, so the polylines keep fit_
  // more off the walls. A ring's vertices lie on the exact offset of the
  // walls, its chords dip inside by the walls' bound and the offsets' two
  // errors (sag_, finer than with lines): fit_ covers that and the rounding
  // of the centre words.
  if (arcs_out()) {
    sag_ = c_.tolerance / 80;
    fit_ = wall_bound_ + 2 * sag_ + 2 * rho + c_.tolerance * 1e-3;
    margin_ += fit_;
  }
}

void PocketCut::plan() {
  PocketPlanInput in;
  in.walls = walls_;
  in.wall_bound = wall_bound_;
  in.radius = radius_;
  in.stock = cp_.stock_to_leave;
  in.finish = keys_.finish_stock.value_or(0);
  in.stepover = stepover_;
  in.pattern = pattern_;
  in.load = load_;
  if (keys_.rest_from) in.rest_from = *keys_.rest_from / 2;
  in.angle_deg = keys_.angle.value_or(0);
  in.climb = cp_.direction != CutDirection::conventional;
  in.tolerance = c_.tolerance;
  in.margin = margin_;
  in.cell = c_.tolerance;
  in.helix_radius = entry_.kind == PocketEntry::Kind::helix ? *entry_.radius : 0;
  in.fit = fit_;
  in.sag = sag_;
  plan_ = memo_plan(c_.memo, in);
  for (auto& pass : plan_.passes)
    for (Vec3& v : pass.pts) v = quantize(v, c_.decimals);
  if (plan_.centres.empty())
    fail("tool_diameter",
         "the tool (diameter " + fmt_num(2 * radius_) +
             (cp_.stock_to_leave > 0 ? " with stock_to_leave " + fmt_num(cp_.stock_to_leave) : std::string()) +
             ") fits nowhere in " + name() + ": use a smaller tool");
  if (entry_.kind == PocketEntry::Kind::helix && plan_.centres.eroded(*entry_.radius / 4, c_.tolerance * 1e-4).empty())
    fail("entry", "a helix of radius " + fmt_num(*entry_.radius / 4) + " or more fits nowhere in " + name() +
                      ": give \"entry\": {\"ramp\": {\"angle\": 3}} (or a smaller helix radius)");
}

// The passes as arcs and lines within fit_ of their polylines (pocket_arcs.cpp:
// the bound proven after rounding), in XY.
void PocketCut::fit_passes() {
  if (fit_ <= 0) return;
  const double rtol = c_.machine.arc_tolerance_mm / mm_per_unit(c_.job.units);
  for (const PocketPass& p : plan_.passes) fits_.push_back(polyline_arcs(p.pts, fit_, c_.decimals, rtol));
  // On a planner that gives arcs less acceleration than lines, a pass that
  // speeds up and slows down often (an adaptive pass's tight turns) can be
  // slower in arcs than in its own polyline's lines (the polyline itself:
  // no farther from it than its arcs). Each pass is planned both ways on
  // the machine's model, alone, from rest to rest; those faster in lines
  // by more than kCruiseGain of their time are kept for cut_levels().
  const auto& model = c_.machine.motion;
  if (!model || !arcs_accelerate_slower(*model)) return;
  for (size_t i = 0; i < fits_.size(); ++i) {
    const auto& pts = plan_.passes[i].pts;
    std::vector<FitMove> lines;
    for (size_t j = 1; j < pts.size(); ++j)
      if (dist_xy(pts[j], pts[j - 1]) > 0) {
        FitMove l;
        l.to = pts[j];
        lines.push_back(l);
      }
    if (lines.size() <= fits_[i].size()) continue;  // (the fit is its lines already)
    if (take_cruise(planned_pass_time(pts, fits_[i]), fits_[i].size(), planned_pass_time(pts, lines), lines.size()))
      faster_.emplace_back(i, std::move(lines));
  }
}

// The passes at every level; on a planner that gives arcs less
// acceleration, also with the passes faster in lines cut in lines, and the
// pocket that way when its plan saves more than kCruiseGain of the time.
void PocketCut::cut_levels() {
  const Vec3 pos = ms_.pos;
  const bool known = ms_.pos_known;
  const size_t fallbacks = helix_fallbacks_;
  for (size_t k = 0; k < levels_.size(); ++k) cut_level(k);
  if (faster_.empty()) return;
  auto& moves = c_.program.moves;
  const double arcs_s = planned_time();
  std::vector<Move> arcs = split_off(moves, first_move_);
  const Vec3 arcs_pos = ms_.pos;
  const bool arcs_known = ms_.pos_known;
  const size_t arcs_fallbacks = helix_fallbacks_;
  ms_.pos = pos, ms_.pos_known = known, helix_fallbacks_ = fallbacks;
  for (auto& [i, lines] : faster_) std::swap(fits_[i], lines);
  for (size_t k = 0; k < levels_.size(); ++k) cut_level(k);
  if (take_cruise(arcs_s, arcs.size(), planned_time(), moves.size() - first_move_)) {
    lines_taken_ = true;
    return;
  }
  moves.resize(first_move_);
  moves.insert(moves.end(), std::make_move_iterator(arcs.begin()), std::make_move_iterator(arcs.end()));
  ms_.pos = arcs_pos, ms_.pos_known = arcs_known, helix_fallbacks_ = arcs_fallbacks;
}

// The planned time (machine.motion) of a pass's moves at the feed, from
// rest at its start to rest at its end (a plunge before, a retract after).
double PocketCut::planned_pass_time(const std::vector<Vec3>& pass, const std::vector<FitMove>& moves) const {
  Program p;
  p.units = c_.program.units;
  const int e = entity();
  const double z = 0, above = kPlungeDepth / mm_per_unit(c_.program.units);
  RapidMove over;
  over.to = Vec3{pass.front().x, pass.front().y, above};
  p.moves.push_back({over, e});
  LineMove down;
  down.to = Vec3{pass.front().x, pass.front().y, z};
  down.feed = cp_.plunge_feed > 0 ? cp_.plunge_feed : cp_.feed;
  p.moves.push_back({down, e});
  const size_t own = p.moves.size();
  for (const FitMove& f : moves) p.moves.push_back(pass_move(f, z, cp_.feed, c_.decimals, e));
  const Vec3 end = moves.empty() ? down.to : Vec3{moves.back().to.x, moves.back().to.y, z};
  RapidMove up;
  up.to = Vec3{end.x, end.y, above};
  p.moves.push_back({up, e});
  const MotionPlan plan = plan_motion(program_timeline(p), *c_.machine.motion, PlanDetail::full);
  double t = 0;
  for (size_t i = own; i + 1 < plan.blocks.size(); ++i) t += plan.blocks[i].time_s;
  return t;
}

void PocketCut::plan_depths() {
  if (const std::optional<double> step = cp_.pass_depth()) {  // step_down, or the flute length
    if (cp_.top_z <= cp_.cut_z)
      fail("step_down", "passes step down from top_z (" + fmt_num(cp_.top_z) + ") to cut_z (" + fmt_num(cp_.cut_z) +
                            "), but top_z is not above cut_z: set \"top_z\" to the stock's top");
    const int n = std::max(1, static_cast<int>(std::ceil((cp_.top_z - cp_.cut_z) / *step - 1e-9)));
    for (int k = 1; k <= n; ++k)
      levels_.push_back(quantize(k == n ? cp_.cut_z : cp_.top_z - (cp_.top_z - cp_.cut_z) * k / n, c_.decimals));
  } else {
    levels_.push_back(quantize(cp_.cut_z, c_.decimals));
  }
  if (clear_ <= levels_.front())
    fail("clearance", "the clearance plane z = " + fmt_num(clear_) + " is not above the first level z = " +
                          fmt_num(levels_.front()) + ": raise \"clearance\" or \"top_z\"");
}

void PocketCut::cut_level(size_t k) {
  const double z = levels_[k];
  const double z_from = k == 0 ? std::min(quantize(cp_.top_z, c_.decimals), clear_) : levels_[k - 1];
  for (size_t i = 0; i < plan_.passes.size(); ++i) {
    const auto& pass = plan_.passes[i].pts;
    const Vec3 start{pass.front().x, pass.front().y, z};
    if (i > 0 && plan_.passes[i].linked) {
      line(start, cp_.feed);
    } else {
      // Over the clearance plane to the pass, down through what the level
      // above cleared, then in.
      if (!ms_.pos_known) rapid({0, 0, safe_}, kAxisZ);
      if (ms_.pos.z < clear_) rapid({ms_.pos.x, ms_.pos.y, clear_});
      const Entry e = entry_of(plan_.passes[i], k == 0);
      if (ms_.pos.x != e.at.x || ms_.pos.y != e.at.y) rapid({e.at.x, e.at.y, ms_.pos.z});
      if (ms_.pos.z > clear_) rapid({e.at.x, e.at.y, clear_});
      if (z_from < clear_) line({e.at.x, e.at.y, z_from}, cp_.plunge_feed);
      if (plan_.passes[i].in_cleared)
        line(start, cp_.plunge_feed);  // down through what this level's passes cleared
      else
        enter(e, pass, z_from, z);
    }
    if (fits_.empty()) {
      for (size_t j = 1; j < pass.size(); ++j) line({pass[j].x, pass[j].y, z}, cp_.feed);
      continue;
    }
    for (const FitMove& f : fits_[i]) {
      c_.program.moves.push_back(pass_move(f, z, cp_.feed, c_.decimals, entity()));
      ms_.pos = motion_of(c_.program.moves.back())->to;
    }
  }
}

// The planner's helix (adaptive: its bore is counted as cleared), the start
// itself for a pass in cleared material, else a helix near the start.
PocketCut::Entry PocketCut::entry_of(const PocketPass& p, bool count) {
  if (p.helix) return {true, p.pts.front(), quantize(*p.helix, c_.decimals)};
  if (p.in_cleared) return {false, p.pts.front(), {}};
  return entry_for(p.pts, count);
}

PocketCut::Entry PocketCut::entry_for(const std::vector<Vec3>& pass, bool count) {
  Entry e;
  e.at = pass.front();
  if (entry_.kind != PocketEntry::Kind::helix) return e;
  double used = 0;
  const double rho = max_rounding_displacement(c_.decimals, 2);
  const auto found = helix_centre(plan_.centres, e.at, *entry_.radius, 2 * rho, used);
  if (!found) {
    helix_fallbacks_ += count;
    return e;
  }
  e.helix = true;
  e.cen = quantize(*found, c_.decimals);
  const double far = dist_xy(e.cen, e.at);
  // The circle's point nearest the pass's start: the helix runs through it.
  e.at = quantize(Vec3{e.cen.x + (e.at.x - e.cen.x) * used / far, e.cen.y + (e.at.y - e.cen.y) * used / far, 0},
                  c_.decimals);
  return e;
}

void PocketCut::enter(const Entry& e, const std::vector<Vec3>& pass, double z_from, double z) {
  const Vec3 p{pass.front().x, pass.front().y, z};
  if (e.helix) {
    helix(e, z_from, z);
    line(p, cp_.feed);
  } else if (entry_.kind == PocketEntry::Kind::plunge) {
    line(p, cp_.plunge_feed);
  } else {
    ramp(pass, z_from, z);
  }
}

// A helix about e.cen through e.at (its circle in the centres' area,
// rounding included): half turns down to z at the entry's angle, then a
// full turn at z.
void PocketCut::helix(const Entry& e, double z_from, double z) {
  const Vec3 cen = e.cen, s0 = e.at;
  const double rad = dist_xy(cen, s0);
  const double drop = std::numbers::pi * rad * std::tan(entry_.angle * std::numbers::pi / 180);
  int n = std::max(2, static_cast<int>(std::ceil((z_from - z) / drop)));
  n += n % 2;
  const Vec3 q{2 * cen.x - s0.x, 2 * cen.y - s0.y, 0};
  const bool ccw = cp_.direction != CutDirection::conventional;
  auto arc = [&](const Vec3& to, double zz) {
    ArcMove a;
    a.to = quantize(Vec3{to.x, to.y, zz}, c_.decimals);
    a.center = {cen.x, cen.y, a.to.z};
    a.ccw = ccw;
    a.feed = cp_.plunge_feed;
    c_.program.moves.push_back({a, entity()});
    ms_.pos = a.to;
  };
  for (int h = 1; h <= n; ++h) arc(h % 2 ? q : s0, z_from + (z - z_from) * h / n);
  arc(q, z);
  arc(s0, z);
}

// Down along the pass and back at the entry's angle until at z.
void PocketCut::ramp(const std::vector<Vec3>& pass, double z_from, double z) {
  double len = 0;
  for (size_t i = 1; i < pass.size(); ++i) len += dist_xy(pass[i - 1], pass[i]);
  const double need = (z_from - z) / std::tan(entry_.angle * std::numbers::pi / 180);
  const double half = std::min(len, need / 2);
  if (!(half > 0)) {
    line({pass.front().x, pass.front().y, z}, cp_.plunge_feed);
    return;
  }
  const int trips = std::max(1, static_cast<int>(std::ceil(need / (2 * half))));
  const double total = 2 * half * trips;
  // The points of the pass up to `half` along it.
  std::vector<Vec3> out{pass.front()};
  std::vector<double> at{0};
  for (size_t i = 1; i < pass.size() && at.back() < half; ++i) {
    const double l = dist_xy(pass[i - 1], pass[i]);
    if (at.back() + l <= half) {
      out.push_back(pass[i]);
      at.push_back(at.back() + l);
    } else {
      const double t = (half - at.back()) / l;
      out.push_back(
          {pass[i - 1].x + t * (pass[i].x - pass[i - 1].x), pass[i - 1].y + t * (pass[i].y - pass[i - 1].y), 0});
      at.push_back(half);
    }
  }
  double walked = 0;
  for (int t = 0; t < trips; ++t) {
    for (size_t i = 1; i < out.size(); ++i) {
      walked += at[i] - at[i - 1];
      line({out[i].x, out[i].y, z_from + (z - z_from) * walked / total}, cp_.plunge_feed);
    }
    for (size_t i = out.size() - 1; i-- > 0;) {
      walked += at[i + 1] - at[i];
      line({out[i].x, out[i].y, z_from + (z - z_from) * std::min(1.0, walked / total)}, cp_.plunge_feed);
    }
  }
}

void PocketCut::certify() {
  PocketCheckInput in;
  in.walls = walls_;
  in.wall_bound = wall_bound_;
  in.radius = radius_;
  in.stock = cp_.stock_to_leave;
  in.tolerance = c_.tolerance;
  in.top_z = std::min(quantize(cp_.top_z, c_.decimals), clear_);
  in.levels = levels_;
  in.moves = &c_.program.moves;
  in.from = first_move_;
  in.to = c_.program.moves.size();
  in.start = start_;
  if (pattern_ == PocketPattern::adaptive) in.load = load_;
  in.cleared_before = plan_.before.loops();
  const PocketCertificate cert = memo_check(c_.memo, in);
  const double keep = radius_ + cp_.stock_to_leave;
  const std::string units = to_string(c_.job.units);
  r_.label = region_;
  r_.type = "pocket";
  r_.degree = 1;
  r_.length = cert.perimeter;
  r_.blocks = in.to - in.from;
  r_.bound = wall_bound_;
  r_.measured = std::max(0.0, keep - cert.wall_distance);
  r_.tool = cp_.tool;
  r_.offset = keep;
  r_.tool_width = 2 * radius_;
  r_.pocket = cert;
  auto& p = c_.program;
  if (cert.rapids_in_material > 0 || !cert.walls_kept(radius_, cp_.stock_to_leave, c_.tolerance))
    throw std::logic_error("internal check failed: " + name() + ": " +
                           certificate_lines(region_, cert, radius_, cp_.stock_to_leave, units)[1] + "; " +
                           certificate_lines(region_, cert, radius_, cp_.stock_to_leave, units)[2]);
  for (auto& line : certificate_lines(region_, cert, radius_, cp_.stock_to_leave, units))
    p.notes.push_back(std::move(line));
  if (!cert.covered())
    p.warnings.push_back(name() + ": the check finds " + fmt_num(cert.uncut_area, 4) + " " + units +
                         "^2 uncut that the tool could reach, beyond the limit " + fmt_num(cert.uncut_limit, 4) +
                         ", near (" + fmt_num(cert.uncut_at.x, 4) + ", " + fmt_num(cert.uncut_at.y, 4) + ")");
  if (!cert.engagement_kept()) {
    std::string w = name() + ": the check reads an engagement of " + fmt_num(cert.engagement_deg, 4) +
                    " degrees near (" + fmt_num(cert.engagement_at.x, 4) + ", " + fmt_num(cert.engagement_at.y, 4) +
                    "), above the bound " + fmt_num(cert.engagement_bound, 4) + " that load " + fmt_num(load_) +
                    " gives";
    const auto& hot = cert.engagement_corners;
    if (!hot.empty()) {
      w += "; in places that wrap the tool (corners sharper than it, its edge within the load of material it cannot "
           "reach, or gaps where walls either side lie nearer together than the tool and a load each side): ";
      for (size_t i = 0; i < hot.size() && i < 6; ++i)
        w += (i ? ", " : "") + fmt_num(hot[i].deg, 4) + " at (" + fmt_num(hot[i].at.x, 4) + ", " +
             fmt_num(hot[i].at.y, 4) + ")";
      if (hot.size() > 6) w += " and " + std::to_string(hot.size() - 6) + " more";
      w += "; elsewhere at most " + fmt_num(cert.engagement_away_deg, 4);
    }
    p.warnings.push_back(w);
  }
  if (!cert.unreachable.empty()) {
    std::string w = name() + ": " + fmt_num(cert.unreachable_area, 4) + " " + units +
                    "^2 of material the tool (diameter " + fmt_num(2 * radius_) +
                    ") cannot reach (corners sharper than the tool, gaps narrower than it) is left: ";
    for (size_t i = 0; i < cert.unreachable.size() && i < 6; ++i)
      w += (i ? ", " : "") + fmt_num(cert.unreachable[i].area, 4) + " at (" + fmt_num(cert.unreachable[i].at.x, 4) +
           ", " + fmt_num(cert.unreachable[i].at.y, 4) + ")";
    if (cert.unreachable.size() > 6) w += " and " + std::to_string(cert.unreachable.size() - 6) + " more";
    p.warnings.push_back(w);
  }
  if (helix_fallbacks_ > 0)
    p.warnings.push_back(name() + ": " + std::to_string(helix_fallbacks_) +
                         (helix_fallbacks_ == 1
                              ? " entry has no room for the helix and ramps down along its pass"
                              : " entries have no room for the helix and ramp down along their pass") +
                         " instead");
}

}  // namespace

void emit_pocket(CutContext& c, MotionState& ms, EntityReport& r, double safe, double clear,
                 const std::vector<const Entity*>& members) {
  PocketCut arcs(c, ms, r, safe, clear, members);
  const size_t first = c.program.moves.size(), notes = c.program.notes.size(), warnings = c.program.warnings.size();
  const EntityReport report = r;
  const Vec3 pos = ms.pos;
  const bool known = ms.pos_known;
  arcs.run();
  if (!arcs.lines_taken()) return;
  // Some passes ran faster as lines: the arcs output's plan keeps its
  // passes a little farther from the walls, and an adaptive plan made so
  // can differ from lines output's and run longer. The pocket as lines
  // output cuts it is planned too, and taken when it saves more than
  // kCruiseGain of the time.
  auto& p = c.program;
  std::vector<Move> arcs_moves = split_off(p.moves, first);
  std::vector<std::string> arcs_notes = split_off(p.notes, notes), arcs_warnings = split_off(p.warnings, warnings);
  const EntityReport arcs_report = r;
  const Vec3 arcs_pos = ms.pos;
  const bool arcs_known = ms.pos_known;
  r = report, ms.pos = pos, ms.pos_known = known;
  PocketCut(c, ms, r, safe, clear, members, true).run();
  std::vector<Move> lines_moves = split_off(p.moves, first);
  // (only a pocket its check finds as well cut: covered, the engagement
  // kept, no more warnings)
  auto sound = [](const EntityReport& e) { return e.pocket && e.pocket->covered() && e.pocket->engagement_kept(); };
  const bool take_lines = (sound(r) || !sound(arcs_report)) && p.warnings.size() - warnings <= arcs_warnings.size() &&
                          take_cruise(moves_time(p.units, arcs_moves, *c.machine.motion), arcs_moves.size(),
                                      moves_time(p.units, lines_moves, *c.machine.motion), lines_moves.size());
  if (!take_lines) {
    p.notes.resize(notes);
    p.warnings.resize(warnings);
    p.notes.insert(p.notes.end(), arcs_notes.begin(), arcs_notes.end());
    p.warnings.insert(p.warnings.end(), arcs_warnings.begin(), arcs_warnings.end());
    r = arcs_report, ms.pos = arcs_pos, ms.pos_known = arcs_known;
  }
  std::vector<Move>& kept = take_lines ? lines_moves : arcs_moves;
  p.moves.insert(p.moves.end(), std::make_move_iterator(kept.begin()), std::make_move_iterator(kept.end()));
  note_once(p, "G01 for the pocket passes that are faster in lines: machine " + c.machine.name +
                   " gives arcs less acceleration than lines");
}

}  // namespace bezcam::detail
