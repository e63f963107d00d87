// --output nurbs: exact-curve blocks in the profile's dialect.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "bezcam/error.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/exact_blocks.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/kernel/curve.hpp"
#include "bezcam/warnings.hpp"
#include "cut_emitters.hpp"
#include "measure_path.hpp"
#include "speed_stretches.hpp"

namespace bezcam::detail {

namespace {

// Says once per program that the machine has no NURBS words.
void note_fallback(CutContext& c) {
  const std::string n = "machine " + c.machine.name + " has no NURBS words: nurbs output cuts with " +
                        (c.machine.arcs ? "arcs (G02/G03) and G01 lines" : "G01 lines");
  auto& notes = c.program.notes;
  if (std::find(notes.begin(), notes.end(), n) != notes.end()) return;
  notes.push_back(n);
  c.program.warnings.push_back(tagged_warning(n, "output-replaced"));
}

// G-code lines a block takes: Fanuc one per control point plus one per knot
// beyond them; G5.2 its start line, one per further point, G5.3; G5/G5.1 one.
size_t block_lines(const ExactBlock& b, NurbsDialect d) {
  if (b.kind != ExactKind::nurbs) return 1;
  if (d == NurbsDialect::fanuc) return b.knots.size();
  return b.ctrl.size() + 1;
}

// The chord tolerance at which a block's printed curve is sampled for the
// independent measurement: kSampleShare of the tolerance, not finer than
// double precision allows at this size (flatten_curve.hpp).
double exact_sample_tolerance(const ExactBlock& b, double tolerance) {
  double scale = 0;
  for (const auto& p : b.ctrl) scale = std::max(scale, max_abs(p));
  return std::max(kSampleShare * tolerance, 1e-11 * std::max(scale, 1.0));
}

}  // namespace

size_t append_exact_block(CutContext& c, const ExactBlock& b, const std::function<Vec3(const Vec3&)>& at) {
  const int entity = static_cast<int>(c.entity.index);
  if (b.kind == ExactKind::line) {
    LineMove l;
    l.to = at(b.ctrl.back());
    l.feed = c.params.feed;
    c.program.moves.push_back({l, entity});
  } else {
    CurveMove cv;
    CurveShape& sh = *cv.shape;
    sh.form = b.kind == ExactKind::bezier ? CurveMove::Form::bezier : CurveMove::Form::nurbs;
    cv.to = at(b.ctrl.back());
    cv.feed = c.params.feed;
    cv.axes = c.machine.nurbs == NurbsDialect::linuxcnc ? 3u : 7u;  // G5.x never moves Z
    sh.ctrl.reserve(b.ctrl.size());
    for (const auto& p : b.ctrl) sh.ctrl.push_back(at(p));
    sh.weights = b.weights;
    sh.knots = b.knots;
    sh.order = b.kind == ExactKind::nurbs ? b.order : static_cast<int>(b.ctrl.size());
    c.program.moves.push_back({std::move(cv), entity});
  }
  return block_lines(b, c.machine.nurbs);
}

namespace {

ExactOptions exact_options(const CutContext& c) {
  const MachineProfile& m = c.machine;
  ExactOptions eo;
  eo.dialect = m.nurbs;
  eo.max_rank = m.nurbs_max_rank;
  eo.tolerance = c.tolerance;
  eo.decimals = c.decimals;
  eo.knot_decimals = m.knot_decimals;
  eo.weight_decimals = m.weight_decimals;
  return eo;
}

// Appends planned exact blocks (fallbacks as arcs or lines) and the printed
// curve to `path` (densely when measuring); returns the proven bound and
// raises `sampled` to the chord the printed curves were sampled at.
double append_blocks(CutContext& c, const std::vector<ExactBlock>& blocks, std::vector<Vec3>& path, size_t& count,
                     double& sampled) {
  double bound = 0;
  for (const ExactBlock& b : blocks) {
    if (b.kind == ExactKind::fallback) {
      bound = std::max(bound, append_arcs_or_lines(c, b.source, path, count) + b.snap);
      continue;
    }
    count += append_exact_block(c, b, [&](const Vec3& p) { return cut_point(c, p); });
    bound = std::max(bound, b.bound);
    if (c.measure) {
      const double chord = exact_sample_tolerance(b, c.tolerance);
      const auto f = flatten(b.printed, {.tolerance = chord, .decimals = -1, .on_curve = true}).points;
      path.insert(path.end(), f.begin() + 1, f.end());
      sampled = std::max(sampled, chord);
    } else {
      path.push_back(quantize(b.printed.back().back(), c.decimals));
    }
  }
  return bound;
}

// The blocks of a run of planar pieces as one path of Bézier segments;
// nullopt when one of them is not exact for a reason `notes` (what the
// entity's header comment says is not exact) does not give.
std::optional<std::vector<ExactBlock>> exact_run(const CutContext& c, std::span<const Bezier> run,
                                                 const std::string& notes) {
  std::vector<CurveSegment> segs;
  for (size_t i = 0; i < run.size(); ++i) segs.push_back({"bezier", run[i].degree(), run[i].rational(), i, 1, nullptr});
  const CurveGeometry g = make_path(std::move(segs), {run.begin(), run.end()}, false, run.front().dim);
  std::vector<ExactBlock> blocks = plan_exact_blocks(g, exact_options(c));
  for (const ExactBlock& b : blocks)
    if (!b.note.empty() && notes.find(b.note) == std::string::npos) return std::nullopt;
  return blocks;
}

// On a controller whose arcs accelerate more slowly than its lines (its
// interpreter turns NURBS blocks into arcs): the exact blocks where the
// tool cruises at the feed, lines where it changes speed
// (append_cruise()), when the plan says that is faster (ties: the fewer
// G-code lines). Replaces the entity's moves from `first` on, its path,
// blocks and bound.
void cruise_if_faster(CutContext& c, EntityReport& r, std::vector<Vec3>& path, double& sampled, size_t first,
                      const std::string& notes) {
  const auto& pieces = c.entity.curve.pieces;
  std::vector<Vec3> cpath{quantize(pieces.front().front(), c.decimals)};
  double csampled = sampled, cbound = 0;
  const auto kept = keep_faster_cut(c, pieces, first, r.blocks, [&]() -> std::optional<size_t> {
    size_t n = 0;
    bool exact = true;
    cbound = append_cruise(c, pieces, cpath, n, [&](std::span<const Bezier> run, Vec3& dir) {
      const auto blocks = exact_run(c, run, notes);
      if (!blocks || blocks->empty()) {
        exact = false;
        return 0.0;
      }
      const double b = append_blocks(c, *blocks, cpath, n, csampled);
      // The direction the last printed block ends in.
      const auto& ctrl = blocks->back().ctrl;
      const Vec3 d = ctrl.back() - ctrl[ctrl.size() - 2];
      const double l = std::hypot(d.x, d.y);
      dir = l > 0 ? Vec3{d.x / l, d.y / l, 0} : Vec3{};
      return b;
    });
    return exact ? std::optional<size_t>(n) : std::nullopt;
  });
  if (kept) {
    path = std::move(cpath);
    r.blocks = *kept;
    r.bound = cbound;
    sampled = csampled;
  }
}

}  // namespace

void emit_nurbs(CutContext& c, EntityReport& r) {
  const MachineProfile& m = c.machine;
  if (m.nurbs == NurbsDialect::none) {
    note_fallback(c);
    if (m.arcs)
      emit_arcs(c, r);
    else
      emit_lines(c, r);
    return;
  }
  const auto& g = c.entity.curve;
  const std::vector<ExactBlock> blocks = plan_exact_blocks(g, exact_options(c));

  const int entity = static_cast<int>(c.entity.index);
  std::vector<Vec3> path{quantize(g.pieces.front().front(), c.decimals)};
  // What is not exact, said before the moves (a comment line).
  std::string notes;
  for (const ExactBlock& b : blocks)
    if (!b.note.empty() && notes.find(b.note) == std::string::npos) notes += (notes.empty() ? "" : "; ") + b.note;
  if (!notes.empty()) {
    c.program.moves.push_back({Comment{"not exact: " + notes}, entity});
    // Every fallback is said on stderr, not only in the program.
    c.program.warnings.push_back(
        tagged_warning(c.entity.label() + ": not cut as exact blocks in nurbs output: " + notes, "output-replaced"));
  }
  r.blocks = 0;
  double sampled = kSampleShare * c.tolerance;  // how far the path's chords stray from the printed moves
  const size_t first = c.program.moves.size();
  r.bound = append_blocks(c, blocks, path, r.blocks, sampled);
  const auto& mm = m.motion;
  if (mm && arcs_accelerate_slower(*mm) && c.params.tolerance_side == ToleranceSide::both &&
      std::all_of(g.pieces.begin(), g.pieces.end(), [](const Bezier& b) { return planar_xy(b); }))
    cruise_if_faster(c, r, path, sampled, first, notes);
  if (c.measure)
    c.measure_with(r, [pieces = std::span<const Bezier>(g.pieces), path = std::move(path), tol = c.tolerance,
                       bound = r.bound, sampled, label = r.label] {
      const double got = measure_printed(pieces, path, tol, bound, sampled);
      if (got > tol)
        throw std::logic_error("internal check failed: " + label + " deviates by " + fmt_num(got) +
                               " beyond the tolerance " + fmt_num(tol));
      return got;
    });
}

}  // namespace bezcam::detail
