#include "bezcam/flatten/exact_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "bezcam/error.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/flatten/degree_reduce.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/kernel/knot_vector.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"

namespace bezcam {

namespace {

// One exact piece, printed: the true piece (standard form when rational),
// the controller's piece and the proven distance between them.
struct PrintedPiece {
  Bezier truth, printed;
  double bound = 0;
};

class Planner {
 public:
  Planner(const CurveGeometry& g, const ExactOptions& o) : g_(g), o_(o) {
    const ToleranceBudget tb = check_tolerance(o.tolerance, o.decimals, g.dim, control_magnitude(g.pieces));
    rmax_ = tb.rounding;
    budget_ = tb.budget;
    maxdeg_ = o.dialect == NurbsDialect::linuxcnc ? 3 : std::clamp(o.max_rank, 2, 4) - 1;
  }

  std::vector<ExactBlock> run() {
    if (g_.pieces.empty()) return {};
    cur_ = quantize(g_.pieces.front().front(), o_.decimals);
    cur_true_ = g_.pieces.front().front();
    for (const auto& seg : g_.segments) {
      if (o_.dialect == NurbsDialect::fanuc && seg.nurbs && seg.nurbs->degree <= maxdeg_ && source_block(seg)) continue;
      for (size_t k = 0; k < seg.piece_count; ++k) piece(g_.pieces[seg.first_piece + k]);
    }
    close_chain();
    close_fallback();
    return std::move(out_);
  }

 private:
  Vec3 q(const Vec3& p) const { return quantize(p, o_.decimals); }

  // Proven parametric distance, refined for the report once it is known to
  // fit (to 1e-4 of the tolerance); above the budget when it does not fit.
  double proven(const Bezier& a, const Bezier& b) const {
    const double d = parametric_distance(a, b, budget_);
    if (d > budget_) return d;
    return std::min(d, parametric_distance(a, b, -1, 1e-4 * o_.tolerance));
  }
  double qw(double w) const { return quantize(w, o_.weight_decimals); }

  // ---- Fanuc: a bspline segment as one block with its own knots ----------
  bool source_block(const CurveSegment& seg) {
    const NurbsCurve c = clamp(*seg.nurbs);
    const size_t n = c.points.size();
    // Knots mapped to [0, spans]: uniform knots become integers.
    std::vector<double> distinct;
    for (double u : c.knots)
      if (distinct.empty() || u != distinct.back()) distinct.push_back(u);
    if (distinct.size() < 2) return false;
    const double a = c.knots.front(), b = c.knots.back(), spans = double(distinct.size() - 1);
    std::vector<double> knots(c.knots.size());
    for (size_t i = 0; i < knots.size(); ++i) {
      knots[i] = quantize((c.knots[i] - a) / (b - a) * spans, o_.knot_decimals);
      // Rounding must keep the knot structure: equal stays equal, distinct stays distinct.
      if (i > 0 && (c.knots[i] == c.knots[i - 1]) != (knots[i] == knots[i - 1])) return false;
    }
    std::vector<Vec3> ctrl(n);
    std::vector<double> weights;
    ctrl[0] = cur_;
    for (size_t i = 1; i < n; ++i) ctrl[i] = q(c.points[i]);
    NurbsCurve truth = c;
    if (c.rational()) {
      // Same curve with the first weight 1 (a common factor changes nothing).
      for (auto& w : truth.weights) w /= c.weights.front();
      for (double w : truth.weights) weights.push_back(qw(w));
      if (*std::min_element(weights.begin(), weights.end()) <= 0) return false;
    }
    const NurbsCurve printed = NurbsCurve::make(c.degree, ctrl, knots, weights, g_.dim);
    const auto tp = to_bezier(truth), pp = to_bezier(printed);
    if (tp.size() != pp.size()) return false;
    double bound = 0;
    for (size_t k = 0; k < tp.size() && bound <= budget_; ++k) bound = std::max(bound, proven(tp[k], pp[k]));
    if (bound > budget_) return false;
    close_chain();
    close_fallback();
    ExactBlock blk;
    blk.kind = ExactKind::nurbs;
    blk.ctrl = std::move(ctrl);
    blk.weights = weights.empty() ? std::vector<double>(n, 1.0) : std::move(weights);
    blk.knots = std::move(knots);
    blk.order = c.degree + 1;
    blk.printed = pp;
    blk.source.assign(g_.pieces.begin() + seg.first_piece, g_.pieces.begin() + seg.first_piece + seg.piece_count);
    blk.bound = bound;
    out_.push_back(std::move(blk));
    cur_ = out_.back().ctrl.back();
    cur_true_ = out_.back().source.back().back();
    return true;
  }

  // ---- one Bézier piece ---------------------------------------------------
  void piece(const Bezier& b) {
    const bool lcnc = o_.dialect == NurbsDialect::linuxcnc;
    if (b.degree() == 1) return line(b);
    if (lcnc && !planar_xy(b)) return fallback(b, "z varies, and G5/G5.2 move in X and Y only");
    const bool direct =
        lcnc ? (!b.rational() || b.degree() + 1 <= o_.max_rank) && b.degree() <= 3 : b.degree() <= maxdeg_;
    if (direct) {
      if (auto pp = print(standard_form(b))) return exact(*pp, b);
      return fallback(b, "rounding of its weights does not fit the tolerance");
    }
    // Degree reduction, leaving room for the rounding of the points.
    const int target = maxdeg_;
    std::optional<std::vector<ReducedPiece>> red;
    if (target >= 2) red = reduce_degree(b, target, budget_ - rmax_);
    if (!red)
      return fallback(b, "degree " + std::to_string(b.degree()) + (b.rational() ? " rational" : "") +
                             " does not reduce to degree " + std::to_string(target) + " within the tolerance");
    note_ = "degree " + std::to_string(b.degree()) + (b.rational() ? " rational" : "") + " reduced to " +
            std::to_string(red->size()) + (red->size() == 1 ? " piece" : " pieces") + " of degree " +
            std::to_string(target);
    for (const auto& rp : *red) {
      auto pp = print(rp.approx);
      if (!pp) return fallback(b, "rounding does not fit the tolerance");  // cannot happen for polynomials
      // The controller's piece against the true part it replaces.
      pp->truth = rp.source;
      pp->bound = proven(rp.source, pp->printed);
      if (pp->bound > budget_) {
        fallback(rp.source, "the reduced piece does not fit after rounding");
        continue;
      }
      exact(*pp, rp.source);
    }
    note_.clear();
  }

  // The piece as the controller reads it back: first point = the current
  // printed position, the others rounded (LinuxCNC: I/J and P/Q relative to
  // the ends, Z unchanged), weights rounded. Bound included; nothing when a
  // weight rounds to zero or the bound exceeds the budget.
  std::optional<PrintedPiece> print(const Bezier& t) {
    const int n = t.degree();
    std::vector<Vec3> pts(n + 1);
    pts[0] = cur_;
    const bool lcnc = o_.dialect == NurbsDialect::linuxcnc;
    if (lcnc && !t.rational()) {
      // G5 / G5.1: I, J relative to the start, P, Q relative to the end.
      auto rel = [&](const Vec3& base, const Vec3& p) {
        return Vec3{base.x + quantize(p.x - base.x, o_.decimals), base.y + quantize(p.y - base.y, o_.decimals), cur_.z};
      };
      pts[n] = {quantize(t.points[n].x, o_.decimals), quantize(t.points[n].y, o_.decimals), cur_.z};
      pts[1] = rel(cur_, t.points[1]);
      if (n == 3) pts[2] = rel(pts[3], t.points[2]);
    } else {
      for (int i = 1; i <= n; ++i) pts[i] = q(t.points[i]);
      if (lcnc)
        for (auto& p : pts) p.z = cur_.z;  // G5.2 moves in X and Y only
    }
    std::vector<double> w;
    if (t.rational()) {
      for (double x : t.weights) w.push_back(qw(x));
      if (*std::min_element(w.begin(), w.end()) <= 0) return std::nullopt;
    }
    PrintedPiece pp{t, Bezier::make(pts, w, g_.dim), 0};
    pp.bound = proven(t, pp.printed);
    if (pp.bound > budget_) return std::nullopt;
    return pp;
  }

  void line(const Bezier& b) {
    close_chain();
    close_fallback();
    ExactBlock blk;
    blk.kind = ExactKind::line;
    const Vec3 to = q(b.back());
    blk.ctrl = {cur_, to};
    blk.printed = {Bezier::make({cur_, to}, {}, g_.dim)};
    blk.source = {b};
    // Two segments (a rational degree 1 piece is its segment too) whose ends
    // move by d0, d1 are within max(d0, d1) of each other.
    blk.bound = std::max(dist(cur_, b.front()), dist(to, b.back()));
    out_.push_back(std::move(blk));
    cur_ = to;
    cur_true_ = b.back();
  }

  void exact(const PrintedPiece& pp, const Bezier& source) {
    close_fallback();
    if (o_.dialect == NurbsDialect::linuxcnc) {
      ExactBlock blk;
      blk.kind = pp.printed.rational() ? ExactKind::nurbs : ExactKind::bezier;
      blk.ctrl = pp.printed.points;
      // LinuxCNC documents G5.1 with I and J both zero as an error: such a
      // quadratic is written as the same curve with G5.2 (weights 1).
      const bool degenerate = !pp.printed.rational() && pp.printed.degree() == 2 && blk.ctrl[1] == blk.ctrl[0];
      if (degenerate) blk.kind = ExactKind::nurbs;
      if (blk.kind == ExactKind::nurbs) {
        blk.weights = degenerate ? std::vector<double>(3, 1.0) : pp.printed.weights;
        blk.order = pp.printed.degree() + 1;
        // The interpreter's clamped uniform knots: one Bézier span.
        blk.knots.assign(blk.order, 0.0);
        blk.knots.resize(2 * static_cast<size_t>(blk.order), 1.0);
      }
      blk.printed = {pp.printed};
      blk.source = {source};
      blk.bound = pp.bound;
      blk.note = note_;
      out_.push_back(std::move(blk));
    } else {
      // Fanuc: extend the open chain when the degree agrees.
      if (chain_ && chain_->order != pp.printed.degree() + 1) close_chain();
      if (!chain_) {
        chain_ = ExactBlock{};
        chain_->kind = ExactKind::nurbs;
        chain_->order = pp.printed.degree() + 1;
        chain_->ctrl = {cur_};
        chain_->weights = {pp.printed.weight(0)};
        chain_->note = note_;
      } else if (!note_.empty() && chain_->note.find(note_) == std::string::npos) {
        chain_->note += (chain_->note.empty() ? "" : "; ") + note_;
      }
      for (int i = 1; i <= pp.printed.degree(); ++i) {
        chain_->ctrl.push_back(pp.printed.points[i]);
        chain_->weights.push_back(pp.printed.weight(i));
      }
      chain_->printed.push_back(pp.printed);
      chain_->source.push_back(source);
      chain_->bound = std::max(chain_->bound, pp.bound);
    }
    cur_ = pp.printed.back();
    cur_true_ = source.back();
  }

  // Knots of a chain: 0 (order times), then every joint (degree times), then
  // the last (order times): integers, exact at any number of decimals.
  void close_chain() {
    if (!chain_) return;
    const int p = chain_->order - 1;
    const size_t m = chain_->printed.size();
    chain_->knots.assign(static_cast<size_t>(p + 1), 0.0);
    for (size_t k = 1; k < m; ++k) chain_->knots.insert(chain_->knots.end(), static_cast<size_t>(p), double(k));
    chain_->knots.insert(chain_->knots.end(), static_cast<size_t>(p + 1), double(m));
    out_.push_back(std::move(*chain_));
    chain_.reset();
  }

  void fallback(const Bezier& b, const std::string& why) {
    close_chain();
    if (!fb_) {
      fb_ = ExactBlock{};
      fb_->kind = ExactKind::fallback;
      // Start exactly where the block before ended, so the fallback's
      // rounded start is the current printed position.
      Bezier s = b;
      fb_->snap = dist(s.points.front(), cur_true_);
      s.points.front() = cur_true_;
      fb_->source.push_back(std::move(s));
      fb_->note = why;
    } else {
      fb_->source.push_back(b);
      if (fb_->note.find(why) == std::string::npos) fb_->note += "; " + why;
    }
    cur_true_ = b.back();
    cur_ = q(b.back());
  }
  void close_fallback() {
    if (!fb_) return;
    out_.push_back(std::move(*fb_));
    fb_.reset();
  }

  const CurveGeometry& g_;
  const ExactOptions& o_;
  double rmax_ = 0, budget_ = 0;
  int maxdeg_ = 3;
  Vec3 cur_, cur_true_;
  std::string note_;
  std::optional<ExactBlock> chain_, fb_;
  std::vector<ExactBlock> out_;
};

}  // namespace

std::vector<ExactBlock> plan_exact_blocks(const CurveGeometry& g, const ExactOptions& o) { return Planner(g, o).run(); }

}  // namespace bezcam
