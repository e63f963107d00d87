// Surface entities become moves: finishing passes over a patch (zigzag,
// raster or its boundary) and curves traced on a patch, with the tool tip
// on the surface (r = 0) or a ball-end tool's tip (r > 0), after the gouge
// check the job asks for. Every cutting polyline comes from
// flatten_surface.hpp with its proven bound; passes from plan_passes(), so
// neighbouring passes are verified to be within the stepover. In nurbs
// output on a profile with 3D NURBS blocks, each run is cut instead as the
// blocks of its exact curve (r = 0) or of a proven approximation of its tip
// curve (r > 0, approximate_tip() and reduce_degree()), measured
// independently against the tip curve (docs/surfaces.md). In arcs output
// each run is cut as helical G02/G03 arcs in the plane (G17, G18 or G19)
// whose axis the run moves least along, fitted to the same exact or proven
// tip curve with fit_arcs() (helical, bound proven in 3D), G01 where no arc
// fits, and measured the same way; a run that no arc shortens keeps its
// lines.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "bezcam/cam/gouge.hpp"
#include "bezcam/cam/pass_plan.hpp"
#include "bezcam/error.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/degree_reduce.hpp"
#include "bezcam/flatten/exact_blocks.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "cut_emitters.hpp"

namespace bezcam::detail {

namespace {

// A stretch of polyline to cut without lifting the tool, with where it
// sits on its pass (for linking zigzag passes along the border): whether it
// starts at the end of the pass the tool enters by and ends at the one it
// leaves by (t = 0 and t = 1, swapped when the pass is run backwards).
struct Run {
  std::vector<Vec3> points;
  bool from_start = false;
  bool to_end = false;
  double t0 = 0, t1 = 0;  // the pass's parameters at points.front() and points.back()
};

// The polyline minus every segment that touches a gouge span: runs of at
// least one segment.
std::vector<Run> cut_out(const TipPolyline& p, const std::vector<GougeSpan>& spans) {
  std::vector<Run> runs;
  Run cur;
  auto close = [&](bool at_end) {
    if (cur.points.size() >= 2) {
      cur.to_end = at_end;
      runs.push_back(cur);
    }
    cur = Run{};
  };
  for (size_t i = 0; i + 1 < p.points.size(); ++i) {
    const double a = p.params[i], b = p.params[i + 1];
    bool bad = false;
    for (const auto& s : spans) bad = bad || (a <= s.t1 && b >= s.t0);
    if (bad) {
      close(false);
      continue;
    }
    if (cur.points.empty()) {
      cur.points.push_back(p.points[i]);
      cur.from_start = i == 0;
      cur.t0 = a;
    }
    cur.points.push_back(p.points[i + 1]);
    cur.t1 = b;
  }
  close(true);
  return runs;
}

std::string fmt_uv(double u, double v) {
  return "u = " + fmt_num(std::round(u * 1e6) / 1e6) + ", v = " + fmt_num(std::round(v * 1e6) / 1e6);
}

class SurfaceEmitter {
 public:
  SurfaceEmitter(CutContext& c, MotionState& st)
      : c_(c),
        st_(st),
        e_(c.entity),
        s_(*c.entity.surface),
        r_(c.params.tool_radius),
        safe_(quantize(c.params.safe_z, c.decimals)),
        policy_(e_.params.over(c.job.params).gouge.value_or(GougePolicy::refuse)) {
    rep_.label = e_.label();
    rep_.type = e_.type;
    rep_.entity = static_cast<int>(e_.index);
    rep_.degree = std::max(s_.degree_u(), s_.degree_v());
    // Exact-curve blocks need a dialect that moves all three axes in one
    // block (Fanuc G06.2); LinuxCNC's G5.x move in X and Y only.
    arcs_ = c.output == OutputMode::arcs && c.machine.arcs;
    blocks_ = arcs_ || (c.output == OutputMode::nurbs && c.machine.nurbs == NurbsDialect::fanuc);
    // Passes: the printed blocks may stray from the verified polylines by
    // twice the tolerance, so the passes are planned 4 tolerances closer
    // (plan_passes() needs at least 4 tolerances of its own).
    if (blocks_ && e_.type != "curve_on_surface" && e_.toolpath.pattern != "boundary" && e_.toolpath.stepover &&
        *e_.toolpath.stepover < 8 * c.tolerance)
      blocks_ = arcs_ = false;
  }

  EntityReport run() {
    check_safe_z();
    rep_.tool = c_.params.tool;
    if (c_.params.clearance) {
      // Passes link at the clearance above the surface's top (or the
      // stock's, when higher), never lower.
      clear_ =
          std::min(safe_, quantize(std::max(bounds(s_).hi.z, c_.params.top_z) + *c_.params.clearance, c_.decimals));
      if (clear_ < safe_) rep_.clear_z = clear_;
    } else {
      clear_ = safe_;
    }
    try {
      if (e_.type == "curve_on_surface") {
        cut_curve_on_surface();
      } else if (e_.toolpath.pattern == "boundary") {
        cut_boundary();
      } else {
        cut_passes();
      }
    } catch (const InputError& err) {
      // The geometry layers know no file: name the entity.
      if (!err.place().empty()) throw;
      throw InputError(err.id(), place(), err.message());
    }
    retract();
    st_.pos_known = true;
    return rep_;
  }

 private:
  CutContext& c_;
  MotionState& st_;
  const Entity& e_;
  const SurfaceGeometry& s_;
  double r_, safe_, clear_ = 0;
  bool started_ = false;  // the tool has cut this entity: links go at the clearance plane
  GougePolicy policy_;
  bool blocks_ = false;  // cut runs as blocks: NURBS (nurbs output, Fanuc dialect) or arcs
  bool arcs_ = false;    // ... as arcs (arcs output)
  EntityReport rep_;
  size_t skipped_ = 0;

  // The entity in its job file (`rest`: a key inside the entity).
  Place place(const std::string& rest = {}) const { return Place::in_json(c_.job.source, e_.json_path(), rest); }
  // The entity as warnings name it.
  std::string where() const { return c_.job.source + ": " + e_.json_path(); }
  FlattenOptions fo() const { return {c_.tolerance, c_.decimals}; }

  void check_safe_z() {
    // The tip is never above the surface (r (N.z - 1) <= 0), and rapids at
    // safe Z must clear the whole patch.
    const Box3 b = bounds(s_);
    if (b.hi.z > c_.params.safe_z)
      throw InputError(errc::job_above_safe_z, place(),
                       "the surface rises to z = " + fmt_num(b.hi.z) + ", above safe_z = " + fmt_num(c_.params.safe_z) +
                           "; rapid moves at safe_z would cross it: raise safe_z");
    if (c_.params.tool_radius < 0) throw std::logic_error("negative tool radius");
  }

  // ---- moves ----------------------------------------------------------
  void push(Move mv) {
    mv.entity = static_cast<int>(e_.index);
    c_.program.moves.push_back(std::move(mv));
  }
  void comment(const std::string& text) { push({Comment{text}}); }
  void begin_entity(const std::string& what) {
    change_tool_and_spindle(c_.program, c_.machine, c_.params, safe_, st_, static_cast<int>(e_.index));
    comment("entity " + e_.label() + ": " + e_.type + ", degree " + std::to_string(s_.degree_u()) + " x " +
            std::to_string(s_.degree_v()) + (s_.rational() ? ", rational" : "") + ", " + what +
            (r_ > 0 ? ", ball-end tool radius " + fmt_num(r_) : ", tool tip on the surface"));
    for (const auto& line : c_.params.before)
      push({Verbatim{expand_entity_template(line, e_, c_.params, c_.decimals)}});
    if (arcs_)
      comment(std::string("cut as G02/G03 arcs in the G17, G18 or G19 plane (helical where the run climbs), G01 where "
                          "no arc fits, within the tolerance of ") +
              (r_ > 0 ? "the ball-end tip curves" : "the exact curves on the surface"));
    else if (blocks_)
      comment(r_ > 0
                  ? "cut as NURBS blocks: cubic pieces within a proven distance of the ball-end tip curves"
                  : "cut as NURBS blocks: the exact curves on the surface (reduced to cubics where of higher degree)");
    const OutputMode out = c_.output;
    if (out != OutputMode::lines && !blocks_ && rep_.blocks == 0) {
      std::string why;
      if (out == OutputMode::arcs && !c_.machine.arcs)
        why = "machine " + c_.machine.name + " does not take arcs";
      else if (out == OutputMode::arcs)
        why = "the stepover is less than 8 tolerances, too little room for arcs beside the pass spacing";
      else if (c_.machine.nurbs == NurbsDialect::linuxcnc)
        why = "machine " + c_.machine.name +
              "'s NURBS blocks (G5/G5.1/G5.2) move in X and Y only, and surface "
              "passes move in Z too";
      else if (c_.machine.nurbs == NurbsDialect::none)
        why = "machine " + c_.machine.name + " has no NURBS words";
      else
        why = "the stepover is less than 8 tolerances, too little room for blocks beside the pass spacing";
      c_.program.warnings.push_back(e_.label() + ": surface passes are cut with G01 lines in " +
                                    (out == OutputMode::arcs ? "arcs" : "nurbs") + " output: " + why);
    }
  }
  void retract() {
    if (st_.pos_known && st_.pos.z == safe_) return;
    RapidMove up;
    up.to = {st_.pos_known ? st_.pos.x : 0, st_.pos_known ? st_.pos.y : 0, safe_};
    if (!st_.pos_known) up.axes = kAxisZ;  // position unknown: Z only
    push({up});
    st_.pos = up.to;
    st_.pos_known = true;
  }
  void go_to(const Vec3& p) {  // retract, rapid over, plunge
    if (st_.pos_known && st_.pos == p) return;
    if (started_ && clear_ < safe_) {
      // Between passes: up to the clearance plane only, across, down.
      if (st_.pos.z < clear_) {
        RapidMove up;
        up.to = {st_.pos.x, st_.pos.y, clear_};
        push({up});
      }
      RapidMove over;
      over.to = {p.x, p.y, std::max(clear_, st_.pos.z)};
      push({over});
    } else {
      retract();
      RapidMove over;
      over.to = {p.x, p.y, safe_};
      push({over});
      if (clear_ < safe_) {
        RapidMove down;
        down.to = {p.x, p.y, clear_};
        push({down});
      }
    }
    started_ = true;
    LineMove plunge;
    plunge.to = p;
    plunge.feed = c_.params.plunge_feed;
    push({plunge});
    st_.pos = p;
  }
  void feed_to(const Vec3& p) {
    if (st_.pos == p) return;
    LineMove l;
    l.to = p;
    l.feed = c_.params.feed;
    push({l});
    ++rep_.blocks;
    rep_.length += dist(st_.pos, p);
    st_.pos = p;
  }
  void cut(const std::vector<Vec3>& pts) {
    for (const auto& q : pts) feed_to(q);
  }

  // ---- geometry ---------------------------------------------------------
  // Flattens a curve, measures it, and returns the cut runs (after the
  // gouge policy).
  std::vector<Run> prepare(const SurfaceCurve& curve, const TipPolyline& poly, const std::string& what) {
    if (!blocks_) record_lines(curve, poly, what);
    std::vector<GougeSpan> spans;
    if (r_ > 0) spans = find_gouges(s_, curve, r_, std::max<int>(256, 4 * static_cast<int>(poly.points.size())));
    if (!spans.empty()) {
      if (policy_ == GougePolicy::refuse) refuse(spans, what);
      for (const auto& sp : spans)
        comment("skipped " + what + " where the tool would gouge: around " + fmt_uv(sp.worst_u, sp.worst_v) +
                (sp.undercut ? " (the surface faces down)" : ", concave radius " + fmt_num(sp.curvature_radius)));
      skipped_ += spans.size();
    }
    return cut_out(poly, spans);
  }

  // The bound and the independent measurement of a polyline that is cut.
  void record_lines(const SurfaceCurve& curve, const TipPolyline& poly, const std::string& what) {
    rep_.bound = std::max(rep_.bound, poly.bound);
    if (c_.measure) {
      const double m = measure_tip(curve, r_, poly).max();
      rep_.measured = std::max(rep_.measured, m);
      if (m > c_.tolerance * (1 + 1e-6))
        throw std::logic_error("internal check failed: " + rep_.label + " " + what + " deviates by " + fmt_num(m) +
                               " beyond the tolerance " + fmt_num(c_.tolerance));
    }
  }

  // Cuts a run, the tool at its first point: as blocks when the mode asks
  // and they can be proven, else as its G01 lines.
  void cut_run(const SurfaceCurve& curve, const TipPolyline& poly, const Run& run, bool backwards,
               const std::string& what) {
    if (blocks_ && (arcs_ ? cut_arcs(curve, run, backwards, what) : cut_blocks(curve, run, backwards, what))) return;
    if (blocks_) record_lines(curve, poly, what);
    cut(run.points);
  }

  // The run's stretch of the pass's curve, in cutting direction.
  static SurfaceCurve run_curve(const SurfaceCurve& curve, const Run& run, bool backwards) {
    SurfaceCurve sub = restrict(curve, std::min(run.t0, run.t1), std::max(run.t0, run.t1));
    return backwards ? reversed(sub) : sub;
  }

  // The run as NURBS blocks: the tip curve on [t0, t1] as Bézier pieces
  // (exact for r = 0, within a proven e1 for r > 0), reduced to the
  // dialect's degree within a proven e2 where higher, then planned and
  // rounded by plan_exact_blocks() within what is left of the tolerance.
  // False (nothing emitted) when a part cannot be proven: the caller cuts
  // the run with its lines.
  bool cut_blocks(const SurfaceCurve& curve, const Run& run, bool backwards, const std::string& what) {
    const double tol = c_.tolerance;
    const SurfaceCurve sub = run_curve(curve, run, backwards);
    const auto ap = approximate_tip(sub, r_, 0.25 * tol);
    if (!ap) return false;
    const int maxdeg = std::clamp(c_.machine.nurbs_max_rank, 2, 4) - 1;
    std::vector<Bezier> pieces;
    std::vector<double> lo, hi;  // each piece's parameter interval on `sub`
    double e2 = 0;
    for (size_t k = 0; k < ap->pieces.size(); ++k) {
      const Bezier& b = ap->pieces[k];
      const double a = ap->breaks[k], w = ap->breaks[k + 1] - a;
      if (b.degree() <= maxdeg) {
        pieces.push_back(b);
        lo.push_back(a);
        hi.push_back(a + w);
        continue;
      }
      const auto red = reduce_degree(b, maxdeg, 0.35 * tol);
      if (!red) return false;
      for (const ReducedPiece& rp : *red) {
        pieces.push_back(rp.approx);
        lo.push_back(a + rp.t0 * w);
        hi.push_back(a + rp.t1 * w);
        e2 = std::max(e2, rp.bound);
      }
    }
    CurveGeometry g;
    g.kind = "path";
    g.dim = 3;
    g.pieces = pieces;
    CurveSegment seg;
    seg.kind = "bezier";
    seg.degree = maxdeg;
    seg.piece_count = pieces.size();
    g.segments = {seg};
    ExactOptions eo;
    eo.dialect = c_.machine.nurbs;
    eo.max_rank = c_.machine.nurbs_max_rank;
    eo.tolerance = tol - ap->bound - e2;
    eo.decimals = c_.decimals;
    eo.knot_decimals = c_.machine.knot_decimals;
    eo.weight_decimals = c_.machine.weight_decimals;
    std::vector<ExactBlock> blocks;
    try {
      blocks = plan_exact_blocks(g, eo);
    } catch (const InputError&) {
      return false;  // what is left is below what rounding needs: lines
    }
    size_t printed = 0;
    for (const ExactBlock& b : blocks) {
      if (b.kind == ExactKind::fallback) return false;
      printed += b.printed.size();
    }
    if (printed != pieces.size()) return false;
    // The printed pieces in order, each over its interval of `sub`'s
    // parameter (each follows its piece in the same parameter).
    std::vector<Bezier> printed_pieces;
    for (const ExactBlock& b : blocks) printed_pieces.insert(printed_pieces.end(), b.printed.begin(), b.printed.end());
    std::vector<double> breaks = lo;
    breaks.push_back(hi.back());
    double bound = 0;
    for (const ExactBlock& b : blocks) bound = std::max(bound, b.bound);
    bound += ap->bound + e2;
    if (c_.measure) {
      const double m = measure_tip_pieces(sub, r_, printed_pieces, breaks).max();
      rep_.measured = std::max(rep_.measured, m);
      if (m > tol * (1 + 1e-6))
        throw std::logic_error("internal check failed: " + rep_.label + " " + what + " as NURBS blocks deviates by " +
                               fmt_num(m) + " beyond the tolerance " + fmt_num(tol));
    }
    rep_.bound = std::max(rep_.bound, bound);
    // The blocks start at the rounded start of the first piece; the tool
    // is at the run's first vertex, the rounded tip there: both within the
    // tolerance of the same tip point (a move of a last digit, if any).
    feed_to(blocks.front().ctrl.front());
    for (const ExactBlock& b : blocks) rep_.blocks += append_exact_block(c_, b, [](const Vec3& p) { return p; });
    for (const Bezier& pc : printed_pieces) rep_.length += length(pc);
    st_.pos = blocks.back().ctrl.back();
    return true;
  }

  // The run as helical arcs: the tip curve on [t0, t1] as Bézier pieces
  // (exact for r = 0, within a proven e1 for r > 0), in the coordinates of
  // the plane whose axis the run moves least along, fitted by fit_arcs()
  // (helical) within what is left of the tolerance; measured independently
  // against the tip curve. False (nothing emitted) when no arc shortens the
  // run or the fit cannot be proven: the caller cuts its lines.
  bool cut_arcs(const SurfaceCurve& curve, const Run& run, bool backwards, const std::string& what) {
    const double tol = c_.tolerance;
    const SurfaceCurve sub = run_curve(curve, run, backwards);
    const auto ap = approximate_tip(sub, r_, 0.25 * tol);
    if (!ap) return false;
    // The plane: the one whose axis the control points (a hull of the run)
    // spread least along; its arcs then climb least. When its fit saves
    // less than a quarter of the run's lines (half a turn round Y spreads
    // less along Z than along X, and G17 arcs follow it poorly), the two
    // other planes are tried too: the fewest moves win. A surface pass is
    // long and worth the extra fits (a twisted pass can take a third of the
    // blocks); a curve tries them only when the first plane does not beat
    // its lines at all (cut_arcs.cpp: on climbing cubics the wider rule
    // costs time and saves no block).
    ArcFitOptions ao;
    ao.tolerance = tol - ap->bound;
    ao.decimals = c_.decimals;
    ao.radius_tolerance = c_.machine.arc_tolerance_mm / mm_per_unit(c_.job.units);
    const auto shortens = [&](const ArcFitResult& f) {
      return f.moves.size() < run.points.size() - 1 &&
             std::any_of(f.moves.begin(), f.moves.end(), [](const FitMove& m) { return m.kind != FitKind::line; });
    };
    const Plane first = least_climb_plane(ap->pieces);
    ArcFitResult fit;
    try {
      fit = fit_helical_arcs(ap->pieces, ao, first);
      if (!shortens(fit) || 4 * fit.moves.size() > 3 * (run.points.size() - 1))
        for (const Plane p : {Plane::xy, Plane::zx, Plane::yz}) {
          if (p == first) continue;
          ArcFitResult other = fit_helical_arcs(ap->pieces, ao, p);
          if (shortens(other) && (!shortens(fit) || other.moves.size() < fit.moves.size())) fit = std::move(other);
        }
    } catch (const InputError&) {
      return false;  // what is left is below what rounding needs: lines
    }
    if (!shortens(fit)) return false;
    const Plane pl = fit.plane;
    const int axis = world_axis(pl, 2);
    // The printed moves in world coordinates, each over its interval of
    // `sub`'s parameter.
    struct Printed {
      Arc arc;  // lines: from, to only
      bool line;
      std::optional<ArcPoints> pts;  // arcs: their points, measured many times
    };
    std::vector<Printed> moves;
    std::vector<double> breaks{0.0};
    Vec3 from = fit.start;
    for (const FitMove& f : fit.moves) {
      const Vec3& to = f.to;
      moves.push_back({Arc{from, to, f.center, f.kind == FitKind::arc_ccw, pl}, f.kind == FitKind::line, {}});
      if (!moves.back().line) moves.back().pts.emplace(moves.back().arc);
      breaks.push_back(ap->breaks[f.piece] + f.t * (ap->breaks[f.piece + 1] - ap->breaks[f.piece]));
      from = to;
    }
    const double bound = fit.bound + ap->bound;
    if (c_.measure) {
      const auto at = [&](size_t j, double s) {
        const Printed& m = moves[j];
        return m.line ? m.arc.from + (m.arc.to - m.arc.from) * s : m.pts->at(s);
      };
      const double m = measure_tip_moves(sub, r_, moves.size(), at, breaks).max();
      rep_.measured = std::max(rep_.measured, m);
      if (m > tol * (1 + 1e-6))
        throw std::logic_error("internal check failed: " + rep_.label + " " + what + " as arcs deviates by " +
                               fmt_num(m) + " beyond the tolerance " + fmt_num(tol));
    }
    rep_.bound = std::max(rep_.bound, bound);
    // The tool is at the run's first vertex, the rounded tip there: the
    // fit starts at the same point (a move of a last digit, if any).
    feed_to(moves.front().arc.from);
    for (const Printed& m : moves) {
      if (m.line) {
        feed_to(m.arc.to);
        continue;
      }
      ArcMove am;
      am.to = m.arc.to;
      am.center = m.arc.center;
      am.ccw = m.arc.ccw;
      am.plane = pl;
      am.feed = c_.params.feed;
      push({am});
      ++rep_.blocks;
      rep_.length +=
          std::hypot(0.5 * (m.arc.r_start() + m.arc.r_end()) * m.arc.sweep(), m.arc.to[axis] - m.arc.from[axis]);
      st_.pos = am.to;
    }
    return true;
  }

  [[noreturn]] void refuse(const std::vector<GougeSpan>& spans, const std::string& what) {
    const GougeSpan& g = spans.front();
    const std::string why = g.undercut ? "the surface faces down there, out of reach of a tool coming from above"
                                       : "the surface is concave there with a curvature radius of " +
                                             fmt_num(std::round(g.curvature_radius * 1e4) / 1e4) +
                                             ", less than the ball-end radius " + fmt_num(r_);
    throw InputError(errc::surface_gouge, place(),
                     "the tool would gouge the surface on " + what + " around " + fmt_uv(g.worst_u, g.worst_v) + ": " +
                         why +
                         "; use a smaller tool_radius, or set \"gouge\": \"skip\" (in \"job\" or on the "
                         "entity) to leave such regions uncut");
  }

  void note_skips() {
    if (skipped_ == 0) return;
    c_.program.warnings.push_back(where() + ": " + std::to_string(skipped_) +
                                  " region(s) left uncut where the ball-end tool would gouge (\"gouge\": \"skip\"); "
                                  "see the comments in the program");
  }

  // ---- patterns ---------------------------------------------------------
  void cut_curve_on_surface() {
    begin_entity("curve traced on the surface");
    const SurfaceCurve m = map_curve(s_, e_.uv_curve, r_ > 0);
    const TipPolyline poly = flatten_tip(m, r_, fo());
    for (const Run& run : prepare(m, poly, "the curve")) {
      go_to(run.points.front());
      cut_run(m, poly, run, false, "the curve");
    }
    note_skips();
  }

  void cut_boundary() {
    begin_entity("boundary pattern (the four border curves)");
    const bool nz = r_ > 0;
    const SurfaceCurve borders[4] = {iso_curve(s_, 'u', 0, nz), iso_curve(s_, 'v', 1, nz),
                                     reversed(iso_curve(s_, 'u', 1, nz)), reversed(iso_curve(s_, 'v', 0, nz))};
    const char* names[4] = {"border v = 0", "border u = 1", "border v = 1", "border u = 0"};
    for (int k = 0; k < 4; ++k) {
      const TipPolyline poly = flatten_tip(borders[k], r_, fo());
      for (const Run& run : prepare(borders[k], poly, names[k])) {
        // Borders meet end to end: continue without lifting when the run
        // starts where the tool is.
        go_to(run.points.front());
        cut_run(borders[k], poly, run, false, names[k]);
      }
    }
    note_skips();
  }

  void cut_passes() {
    const ToolpathSpec& tp = e_.toolpath;
    if (!tp.stepover)
      throw InputError(errc::job_missing, place("toolpath.stepover"),
                       "a \"" + tp.pattern +
                           "\" toolpath needs \"stepover\": the largest distance allowed between "
                           "neighbouring passes, in file units");
    PassOptions o;
    o.direction = tp.direction;
    o.stepover = *tp.stepover - (blocks_ ? 4 * c_.tolerance : 0);
    o.tolerance = c_.tolerance;
    o.decimals = c_.decimals;
    o.tool_radius = r_;
    PassPlan plan;
    try {
      plan = plan_passes(s_, o);
    } catch (const InputError& err) {
      if (!err.id().starts_with("toolpath.")) throw;
      throw InputError(err.id(), place("toolpath.stepover"), err.message());
    }
    const char across = tp.direction == 'u' ? 'v' : 'u';
    const bool zigzag = tp.pattern == "zigzag";
    begin_entity(tp.pattern + " along " + std::string(1, tp.direction) + ", stepover " + fmt_num(*tp.stepover) +
                 (blocks_ ? " (passes planned at " + fmt_num(o.stepover) + " for NURBS blocks)" : "") + ", " +
                 std::to_string(plan.passes.size()) + " passes");
    if (blocks_)
      // Each printed pass lies within the tolerance of its tip curve, which
      // lies within the flattening bound of the verified polyline.
      comment("neighbouring passes at most " +
              fmt_num(std::ceil((plan.gap_bound + 2 * (c_.tolerance + plan.bound)) * 1e4) / 1e4) +
              " apart (verified on the flattened passes, plus twice the tolerance of the printed blocks and of the "
              "flattening; stepover " +
              fmt_num(*tp.stepover) + ")");
    else
      comment("neighbouring passes at most " + fmt_num(std::round(plan.gap_bound * 1e4) / 1e4) +
              " apart (verified on the printed passes; stepover " + fmt_num(o.stepover) + ")");
    bool have_prev = false;
    bool prev_reversed = false;
    bool prev_reached_side = false;  // the last run ended on the side the next pass starts from
    double prev_at = 0;
    const size_t n = plan.passes.size();
    for (size_t k = 0; k < n; ++k) {
      const Pass& ps = plan.passes[k];
      const std::string label = "pass " + std::to_string(k + 1) + " of " + std::to_string(n) + " at " +
                                std::string(1, across) + " = " + fmt_num(std::round(ps.at * 1e6) / 1e6);
      comment(label);
      std::vector<Run> runs = prepare(ps.curve, ps.poly, label);
      const bool rev = zigzag && k % 2 == 1;
      if (rev) {
        std::reverse(runs.begin(), runs.end());
        for (auto& r : runs) {
          std::reverse(r.points.begin(), r.points.end());
          std::swap(r.from_start, r.to_end);
        }
      }
      for (size_t j = 0; j < runs.size(); ++j) {
        const Run& run = runs[j];
        const bool linkable = zigzag && j == 0 && have_prev && prev_reached_side && run.from_start;
        if (!(linkable && link(prev_at, ps.at, prev_reversed ? 0.0 : 1.0, run.points.front())))
          go_to(run.points.front());
        cut_run(ps.curve, ps.poly, run, rev, label);
        prev_reached_side = run.to_end;
      }
      if (runs.empty()) prev_reached_side = false;
      have_prev = true;
      prev_reversed = rev;
      prev_at = ps.at;
    }
    note_skips();
  }

  // Feeds along the border at `side` (the pass parameter there) from pass
  // `a` to pass `b`: the tip curve of the border, flattened like a pass, so
  // the link is as close to the surface as the passes. False (no moves)
  // where the link would gouge: the caller lifts the tool instead.
  bool link(double a, double b, double side, const Vec3& target) {
    const char across = e_.toolpath.direction == 'u' ? 'v' : 'u';
    const SurfaceCurve border = restrict(iso_curve(s_, across, side, r_ > 0), a, b);
    if (r_ > 0 && !find_gouges(s_, border, r_, 64).empty()) return false;
    const TipPolyline poly = flatten_tip(border, r_, fo());
    rep_.bound = std::max(rep_.bound, poly.bound);
    if (c_.measure) rep_.measured = std::max(rep_.measured, measure_tip(border, r_, poly).max());
    // Its ends are the printed ends of the two passes (up to a last-digit
    // difference of the rounding, which a tiny move absorbs).
    cut(poly.points);
    feed_to(target);
    return true;
  }
};

}  // namespace

EntityReport emit_surface(CutContext& c, MotionState& st) { return SurfaceEmitter(c, st).run(); }

}  // namespace bezcam::detail
