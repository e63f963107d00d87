// --output nurbs: exact-curve blocks in the profile's dialect.
#include <algorithm>
#include <stdexcept>

#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/exact_blocks.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/warnings.hpp"
#include "cut_emitters.hpp"
#include "measure_path.hpp"

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
  ExactOptions eo;
  eo.dialect = m.nurbs;
  eo.max_rank = m.nurbs_max_rank;
  eo.tolerance = c.tolerance;
  eo.decimals = c.decimals;
  eo.knot_decimals = m.knot_decimals;
  eo.weight_decimals = m.weight_decimals;
  const std::vector<ExactBlock> blocks = plan_exact_blocks(g, eo);

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
  r.bound = 0;
  double sampled = kSampleShare * c.tolerance;  // how far the path's chords stray from the printed moves
  for (const ExactBlock& b : blocks) {
    if (b.kind == ExactKind::fallback) {
      r.bound = std::max(r.bound, append_arcs_or_lines(c, b.source, path, r.blocks) + b.snap);
      continue;
    }
    r.blocks += append_exact_block(c, b, [&](const Vec3& p) { return cut_point(c, p); });
    r.bound = std::max(r.bound, b.bound);
    // The printed curve, densely, for the independent measurement.
    if (c.measure) {
      const double chord = exact_sample_tolerance(b, c.tolerance);
      const auto f = flatten(b.printed, {.tolerance = chord, .decimals = -1, .on_curve = true}).points;
      path.insert(path.end(), f.begin() + 1, f.end());
      sampled = std::max(sampled, chord);
    }
  }
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
