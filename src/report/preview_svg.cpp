#include "bezcam/report/preview_svg.hpp"
#include "bezcam/report/motion_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>

#include "bezcam/error.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/kernel/surface.hpp"
#include "bezcam/report/report.hpp"

namespace bezcam {

namespace {

// ---------------------------------------------------------------------------
// Deviation of cutting blocks
// ---------------------------------------------------------------------------

// What an entity looks like: the exact curves to draw (a curve entity's
// pieces; a curve on a surface composed with the surface; a surface's
// iso-parameter lines), its control polygons, and the curve its cut is
// measured against (empty for surfaces).
struct Shape {
  std::vector<std::vector<Bezier>> chains;
  std::vector<std::vector<Vec3>> polygons;
  std::vector<Vec3> control_points;
  std::vector<Bezier> measure;
  int dim = 2;
  bool closed = false;
  bool surface = false;
};

// Iso-parameter lines drawn per direction on a surface (borders included).
constexpr int kIsoLines = 10;

Shape entity_shape(const Entity& e) {
  Shape s;
  // A point where one piece or segment starts as the previous one ended is
  // drawn once.
  auto add_points = [&](const std::vector<Vec3>& pts) {
    for (size_t j = 0; j < pts.size(); ++j)
      if (j > 0 || s.control_points.empty() || !(s.control_points.back() == pts[j])) s.control_points.push_back(pts[j]);
  };
  auto add_polygons = [&](const std::vector<Bezier>& pieces) {
    for (const Bezier& pc : pieces) {
      s.polygons.push_back(pc.points);
      add_points(pc.points);
    }
  };
  if (!e.curve.pieces.empty()) {
    s.chains.push_back(e.curve.pieces);
    s.measure = e.curve.pieces;
    s.dim = e.curve.dim;
    s.closed = e.curve.closed;
    // The control polygon the user wrote: a B-spline's de Boor points, a
    // Bézier segment's own points (not the pieces of a decomposition).
    for (const CurveSegment& seg : e.curve.segments) {
      if (seg.nurbs) {
        s.polygons.push_back(seg.nurbs->points);
        add_points(seg.nurbs->points);
      } else {
        add_polygons(std::vector<Bezier>(e.curve.pieces.begin() + static_cast<long>(seg.first_piece),
                                         e.curve.pieces.begin() + static_cast<long>(seg.first_piece + seg.piece_count)));
      }
    }
  } else if (e.surface && !e.uv_curve.pieces.empty()) {
    // The exact 3D curve S(c(w)): what the tool follows.
    s.measure = map_curve(*e.surface, e.uv_curve, false).points;
    s.chains.push_back(s.measure);
    s.dim = 3;
    s.closed = e.uv_curve.closed;
    add_polygons(s.measure);
  } else if (e.surface) {
    s.surface = true;
    s.dim = 3;
    for (int k = 0; k <= kIsoLines; ++k) {
      const double at = double(k) / kIsoLines;
      s.chains.push_back(iso_curve(*e.surface, 'u', at, false).points);
      s.chains.push_back(iso_curve(*e.surface, 'v', at, false).points);
    }
    // The control net of every cell: its rows and its columns.
    for (const BezierPatch& c : e.surface->grid.cells) {
      for (int i = 0; i <= c.nu; ++i) {
        std::vector<Vec3> row;
        for (int j = 0; j <= c.nv; ++j) row.push_back(c.at(i, j)), s.control_points.push_back(c.at(i, j));
        s.polygons.push_back(std::move(row));
      }
      for (int j = 0; j <= c.nv; ++j) {
        std::vector<Vec3> col;
        for (int i = 0; i <= c.nu; ++i) col.push_back(c.at(i, j));
        s.polygons.push_back(std::move(col));
      }
    }
  }
  return s;
}

// An entity's curve as a dense on-curve polyline (2D curves in the XY plane).
struct DenseCurve {
  int entity = -1;
  int dim = 2;
  bool closed = false;
  std::vector<Vec3> pts;
};

DenseCurve dense_curve(const Entity& e, const Shape& sh, double tol) {
  DenseCurve d;
  d.entity = static_cast<int>(e.index);
  d.dim = sh.dim;
  const auto& pc = sh.measure;
  d.closed = sh.closed || (!pc.empty() && pc.front().front() == pc.back().back());
  // The flattener certifies its bound; a thousandth of the tolerance makes
  // the sampling error negligible next to what is measured.
  for (double frac : {1e-3, 1e-2}) {
    try {
      d.pts = flatten(pc, FlattenOptions{.tolerance = tol * frac, .decimals = -1, .on_curve = true}).points;
      return d;
    } catch (const InputError&) {
      // Too fine for double precision at these coordinates: coarser.
    }
  }
  d.pts = flatten(pc, FlattenOptions{.tolerance = tol * 0.1, .decimals = -1, .on_curve = true}).points;
  return d;
}

Vec3 flat_if_2d(const Vec3& p, int dim) { return dim == 2 ? Vec3{p.x, p.y, 0} : p; }

struct Near {
  double d = std::numeric_limits<double>::infinity();
  size_t seg = 0;
};

Near nearest_in(std::span<const Vec3> D, const Vec3& x, size_t a, size_t b) {
  Near n;
  for (size_t i = a; i < b; ++i) {
    const double d = dist_to_segment(x, D[i], D[i + 1]);
    if (d < n.d) n = {d, i};
  }
  return n;
}

// Nearest segment of the dense polyline, looking around `hint` first and
// everywhere when that answer is not small (the blocks advance along the
// curve, so the window almost always holds the answer).
Near nearest(std::span<const Vec3> D, const Vec3& x, size_t hint, double large) {
  if (D.size() < 2) return {D.empty() ? 0.0 : dist(x, D[0]), 0};
  const size_t nseg = D.size() - 1;
  constexpr size_t kWindow = 256;
  const size_t a = hint > kWindow ? hint - kWindow : 0, b = std::min(nseg, hint + kWindow + 1);
  Near n = nearest_in(D, x, a, b);
  if (n.d > large) n = nearest_in(D, x, 0, nseg);
  return n;
}

double dist_to_polyline(const Vec3& x, std::span<const Vec3> P) {
  if (P.size() == 1) return dist(x, P[0]);
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < P.size(); ++i) d = std::min(d, dist_to_segment(x, P[i], P[i + 1]));
  return d;
}

// Points along a block for measuring: its samples, each chord split in 16.
std::vector<Vec3> measuring_points(const MotionBlock& b, double tol, int dim) {
  const auto s = sample_block(b, tol * 1e-3);
  const int split = s.size() == 2 ? 16 : 2;
  std::vector<Vec3> out{flat_if_2d(s[0], dim)};
  for (size_t i = 1; i < s.size(); ++i)
    for (int k = 1; k <= split; ++k) out.push_back(flat_if_2d(lerp(s[i - 1], s[i], double(k) / split), dim));
  return out;
}

// Two-sided deviation of one block from the curve; `hint` follows the cut.
// `prev` and `next` are the blocks cut before and after it on that curve
// (empty: none). A curve point between the projections of the block's ends
// counts against the nearest of the three: at a turn sharper than the band
// is wide, vertices off the curve can project back along it, and the
// stretch of curve there is the neighbours' as much as this block's.
double measure_block(const DenseCurve& c, std::span<const Vec3> P, size_t& hint, double tol,
                     std::span<const Vec3> prev = {}, std::span<const Vec3> next = {}) {
  const std::span<const Vec3> D(c.pts);
  double dev = 0;
  // Block -> curve.
  Near first, last;
  size_t h = hint;
  for (size_t i = 0; i < P.size(); ++i) {
    const Near n = nearest(D, P[i], h, tol);
    dev = std::max(dev, n.d);
    h = n.seg;
    if (i == 0) first = n;
    last = n;
  }
  // Curve -> block: the dense points between the projections of the ends.
  auto span_max = [&](size_t a, size_t b) {
    for (size_t i = a; i <= b && i < D.size(); ++i) {
      double d = dist_to_polyline(D[i], P);
      if (d > dev && !prev.empty()) d = std::min(d, dist_to_polyline(D[i], prev));
      if (d > dev && !next.empty()) d = std::min(d, dist_to_polyline(D[i], next));
      dev = std::max(dev, d);
    }
  };
  if (last.seg >= first.seg) {
    span_max(first.seg + 1, last.seg);
  } else if (c.closed) {  // the cut runs over the closing joint
    span_max(first.seg + 1, D.size() - 1);
    span_max(0, last.seg);
  } else {
    span_max(last.seg + 1, first.seg);
  }
  hint = last.seg;
  return dev;
}

bool is_plunge(std::span<const MotionBlock> m, size_t i) {
  const MotionBlock& b = m[i];
  if (!is_feed(b) || b.from.x != b.to.x || b.from.y != b.to.y || !(b.to.z < b.from.z)) return false;
  return i == 0 || m[i - 1].kind == BlockKind::rapid;
}

// ---------------------------------------------------------------------------
// SVG text
// ---------------------------------------------------------------------------

std::string esc(std::string_view s) {
  std::string o;
  for (char ch : s) {
    switch (ch) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&apos;"; break;
      default:
        // Control characters are not allowed in XML 1.0.
        if (static_cast<unsigned char>(ch) < 0x20 && ch != '\t' && ch != '\n') o += '?';
        else o += ch;
    }
  }
  return o;
}

// Pixel coordinates with 3 decimals (a thousandth of a pixel keeps
// deviations visible when zoomed in), trailing zeros trimmed.
std::string n3(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s = buf;
  if (s.find('.') != std::string::npos) {
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

std::string rgb(double r, double g, double b) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(std::lround(r)), int(std::lround(g)), int(std::lround(b)));
  return buf;
}

// Deviation colour, on a scale relative to the tolerance: within it a calm
// sequential scale, dark blue at 0 through teal to green at the tolerance
// (a program that uses 97 % of its tolerance keeps its promise and looks
// like it); above it a saturated red that no colour of the scale comes
// near, drawn wider and marked (a broken promise must stand out).
constexpr const char* kOverColour = "#ff0000";
bool over_tolerance(double d, double tol) { return d > tol * (1 + 1e-9); }
std::string deviation_colour(double d, double tol) {
  if (over_tolerance(d, tol)) return kOverColour;
  const double t = std::clamp(d / tol, 0.0, 1.0);
  struct C { double r, g, b; };
  const C lo{49, 54, 149}, mid{33, 145, 140}, hi{94, 201, 98};
  const C& a = t < 0.5 ? lo : mid;
  const C& b = t < 0.5 ? mid : hi;
  const double u = t < 0.5 ? t * 2 : (t - 0.5) * 2;
  return rgb(a.r + u * (b.r - a.r), a.g + u * (b.g - a.g), a.b + u * (b.b - a.b));
}

// The largest 1, 2 or 5 times a power of ten not above x.
double nice_below(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= x) return m * p;
  return p;
}

struct P2 {
  double x = 0, y = 0;
};

// A view: a projection of model space and its placement on the page.
struct View {
  std::string id, title;
  bool iso = false;
  double minx = HUGE_VAL, maxx = -HUGE_VAL, miny = HUGE_VAL, maxy = -HUGE_VAL;
  double s = 1, ox = 0, oy = 0;    // scale (px per unit) and origin
  double px = 0, py = 0, pw = 0, ph = 0;  // panel rectangle

  // Isometric drawing: the three axes at 120 degrees, lengths along them
  // kept (so one scale bar serves all three).
  P2 project(const Vec3& p) const {
    if (!iso) return {p.x, p.y};
    const double c = std::cos(std::numbers::pi / 6), sn = 0.5;
    return {(p.x - p.y) * c, (p.x + p.y) * sn + p.z};
  }
  void fit(const Vec3& p) {
    const P2 q = project(p);
    minx = std::min(minx, q.x), maxx = std::max(maxx, q.x);
    miny = std::min(miny, q.y), maxy = std::max(maxy, q.y);
  }
  void fit(const Box3& b) {
    if (b.empty()) return;
    for (int k = 0; k < 8; ++k)
      fit(Vec3{(k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y, (k & 4) ? b.hi.z : b.lo.z});
  }
  bool empty() const { return minx > maxx; }
  P2 screen(const Vec3& p) const {
    const P2 q = project(p);
    return {ox + (q.x - minx) * s, oy + (maxy - q.y) * s};
  }
  // Screen direction of a model direction at p.
  P2 screen_dir(const Vec3& p, const Vec3& d) const {
    const P2 a = screen(p), b = screen(p + d);
    const double l = std::hypot(b.x - a.x, b.y - a.y);
    if (!(l > 0)) return {1, 0};
    return {(b.x - a.x) / l, (b.y - a.y) / l};
  }
};

std::string path_d(const View& v, std::span<const Vec3> pts) {
  std::string d;
  d.reserve(pts.size() * 20);
  for (size_t i = 0; i < pts.size(); ++i) {
    const P2 q = v.screen(pts[i]);
    d += (i == 0 ? "M" : " L") + n3(q.x) + " " + n3(q.y);
  }
  return d;
}

// Arrowhead with its tip at `tip`, pointing along `d`.
std::string arrow_d(P2 tip, P2 d, double len, double half_width) {
  const P2 base{tip.x - d.x * len, tip.y - d.y * len};
  const P2 nrm{-d.y, d.x};
  return "M" + n3(tip.x) + " " + n3(tip.y) + " L" + n3(base.x + nrm.x * half_width) + " " +
         n3(base.y + nrm.y * half_width) + " L" + n3(base.x - nrm.x * half_width) + " " +
         n3(base.y - nrm.y * half_width) + " Z";
}

// Tangent of the curve at t, falling back to a nearby chord where the
// derivative vanishes (repeated control points).
Vec3 tangent(const Bezier& b, double t) {
  Vec3 d = derivative(b, t);
  if (norm(d) > 1e-12 * std::max(1.0, max_abs(b.front()))) return d;
  const double t2 = t < 0.5 ? t + 1e-3 : t - 1e-3;
  d = evaluate(b, t2) - evaluate(b, t);
  return t < 0.5 ? d : -d;
}

std::vector<std::string> wrap(const std::string& s, size_t width) {
  std::vector<std::string> out;
  std::string line;
  size_t i = 0;
  while (i < s.size()) {
    size_t j = s.find(' ', i);
    if (j == std::string::npos) j = s.size();
    const std::string word = s.substr(i, j - i);
    if (!line.empty() && line.size() + 1 + word.size() > width) out.push_back(line), line.clear();
    line += (line.empty() ? "" : " ") + word;
    i = j + 1;
  }
  if (!line.empty()) out.push_back(line);
  return out;
}

constexpr const char* kCurveColour = "#1f3b73";
constexpr const char* kControlColour = "#8c8c8c";
constexpr const char* kFeedColour = "#f28e2b";
constexpr const char* kRapidColour = "#d62728";

}  // namespace

// A part cut beside its curve (`side` other than "on"): its path is meant to
// be a tool's radius away, so it is not coloured by its distance from the
// curve (the program measured it against its offset: offset_measure.hpp).
bool beside_its_curve(const Job& job, const Entity& e) {
  const auto side = e.params.side ? e.params.side : job.params.side;
  return side && *side != CutSide::on;
}

std::vector<BlockDeviation> block_deviations(const Job& job, std::span<const MotionBlock> motion, double tolerance,
                                             const EntityProgress& on_entity) {
  if (!(tolerance > 0)) throw InputError(errc::preview_tolerance, Place::at_setting("deviation"), "needs a tolerance > 0 to measure against");
  std::vector<BlockDeviation> out;
  const size_t total = job.entities.size();
  bool tagged = false;
  for (const auto& m : motion) tagged = tagged || m.entity >= 0;
  auto cutting = [&](size_t i) { return is_feed(motion[i]) && !is_plunge(motion, i); };
  // One curve against its blocks, in cutting order, each with its
  // neighbours (measure_block()); three blocks' points held at a time.
  auto measure_run = [&](const DenseCurve& c, const std::vector<size_t>& run) {
    size_t hint = 0;
    std::vector<Vec3> prev, cur, next = measuring_points(motion[run[0]], tolerance, c.dim);
    for (size_t k = 0; k < run.size(); ++k) {
      prev.swap(cur), cur.swap(next);  // prev <- cur <- next
      next = k + 1 < run.size() ? measuring_points(motion[run[k + 1]], tolerance, c.dim) : std::vector<Vec3>();
      out.push_back({run[k], c.entity, measure_block(c, cur, hint, tolerance, prev, next)});
    }
  };

  if (tagged) {
    // Each entity against its own blocks, in cutting order.
    std::map<int, std::vector<size_t>> by_entity;
    for (size_t i = 0; i < motion.size(); ++i)
      if (cutting(i) && motion[i].entity >= 0) by_entity[motion[i].entity].push_back(i);
    for (const Entity& e : job.entities) {
      if (on_entity) on_entity(e.index, total, e.label());
      auto it = by_entity.find(static_cast<int>(e.index));
      if (it == by_entity.end()) continue;
      const Shape sh = entity_shape(e);
      if (sh.measure.empty() || beside_its_curve(job, e)) continue;
      measure_run(dense_curve(e, sh, tolerance), it->second);
    }
  } else {
    // A program read from text: each block against the nearest curve.
    std::vector<DenseCurve> curves;
    for (const Entity& e : job.entities) {
      if (on_entity) on_entity(e.index, total, e.label());
      const Shape sh = entity_shape(e);
      if (!sh.measure.empty() && !beside_its_curve(job, e)) curves.push_back(dense_curve(e, sh, tolerance));
    }
    // Each block to the curve nearest its middle, then each curve against
    // its blocks in cutting order.
    std::vector<size_t> hints(curves.size(), 0);
    std::vector<std::vector<size_t>> blocks(curves.size());
    for (size_t i = 0; i < motion.size() && !curves.empty(); ++i) {
      if (!cutting(i)) continue;
      const auto& b = motion[i];
      size_t best = 0;
      Near best_n;
      const Vec3 mid = lerp(b.from, b.to, 0.5);
      for (size_t k = 0; k < curves.size(); ++k) {
        const Near n = nearest(curves[k].pts, flat_if_2d(mid, curves[k].dim), hints[k], tolerance);
        if (n.d < best_n.d) best_n = n, best = k;
      }
      hints[best] = best_n.seg;
      blocks[best].push_back(i);
    }
    for (size_t k = 0; k < curves.size(); ++k)
      if (!blocks[k].empty()) measure_run(curves[k], blocks[k]);
  }
  std::sort(out.begin(), out.end(), [](auto& a, auto& b) { return a.block < b.block; });
  if (on_entity) on_entity(total, total, "");
  return out;
}

namespace {

// Top of the feed scale: the highest programmed cutting feed.
double feed_scale_top(const MotionPlan& plan) {
  double top = 0;
  for (const PlannedBlock& b : plan.blocks)
    if (b.kind != BlockKind::rapid) top = std::max(top, b.programmed_feed);
  return top > 0 ? top : 1;
}

// The cutting moves as executed, coloured by the speed reached: each
// segment of the plan cut into short stretches, neighbours of one colour
// joined in one path; starved blocks get a dashed red overlay.
void svg_feed_path(std::string& o, const View& v, const PreviewInput& in, const std::string& unit) {
  const MotionPlan& plan = *in.plan;
  std::string coloured;
  const double top = feed_scale_top(plan);
  constexpr int kSteps = 24;  // colour steps
  std::string cur_colour, cur_d;
  int cur_step = -1;
  P2 last{};
  auto flush = [&] {
    if (!cur_d.empty())
      coloured += "<path class=\"feed feed-speed\" data-feed-step=\"" + std::to_string(cur_step) + "\" d=\"" + cur_d +
           "\" fill=\"none\" stroke=\"" + cur_colour +
           "\" stroke-width=\"3\" stroke-linecap=\"round\" stroke-linejoin=\"round\"/>\n";
    cur_d.clear();
  };
  std::string starved_d;
  for (const PlanSegment& sg : plan.segments) {
    if (sg.rapid || sg.length <= 0) continue;
    const bool starved = sg.block >= 0 && plan.blocks[static_cast<size_t>(sg.block)].starved;
    // Stretches: up to 8 per segment, each at least a pixel or two long.
    const double px = sg.length * v.s;
    const int n = std::clamp(static_cast<int>(px / 3), 1, 8);
    std::string seg_d;
    for (int k = 0; k < n; ++k) {
      const double s0 = sg.length * k / n, s1 = sg.length * (k + 1) / n, sm = 0.5 * (s0 + s1);
      // Speed at distance sm: the trapezoid's, by distance.
      const double a = sg.accel;
      double sp = std::min({sg.vpeak, std::sqrt(sg.v0 * sg.v0 + 2 * a * sm), std::sqrt(sg.v1 * sg.v1 + 2 * a * (sg.length - sm))});
      const int step = std::clamp(static_cast<int>(std::lround(sp * 60 / top * kSteps)), 0, kSteps);
      const P2 p0 = v.screen(sg.point_at(s0, plan.motion)), p1 = v.screen(sg.point_at(s1, plan.motion));
      if (step != cur_step || cur_d.empty() || std::hypot(p0.x - last.x, p0.y - last.y) > 1e-6) {
        if (step != cur_step || cur_d.empty()) {
          flush();
          cur_step = step;
          cur_colour = preview_feed_colour(double(step) / kSteps * top, top);
        }
        cur_d += (cur_d.empty() ? "M" : " M") + n3(p0.x) + " " + n3(p0.y);
      }
      cur_d += " L" + n3(p1.x) + " " + n3(p1.y);
      last = p1;
      if (starved) seg_d += (seg_d.empty() ? "M" + n3(p0.x) + " " + n3(p0.y) : std::string()) + " L" + n3(p1.x) + " " + n3(p1.y);
    }
    if (!seg_d.empty()) starved_d += (starved_d.empty() ? "" : " ") + seg_d;
  }
  flush();
  // Starved stretches: a red halo under the coloured path, so that the
  // speed stays readable on top of it.
  if (!starved_d.empty())
    o += "<path class=\"starved\" d=\"" + starved_d + "\" fill=\"none\" stroke=\"" + std::string(kOverColour) +
         "\" stroke-opacity=\"0.45\" stroke-width=\"9\" stroke-linecap=\"round\" stroke-linejoin=\"round\"><title>starved: "
         "the controller could not feed these blocks fast enough (block rate, minimum segment time or look-ahead)"
         "</title></path>\n";
  o += coloured;
  (void)unit;
}

// The tool path of one view, under the curves: the path is wide and light,
// the true curve thin and dark on top, so both stay visible where they agree.
// `msamples` are the blocks' points, `dev_of` their deviations (-1: not measured).
void svg_toolpath(std::string& o, const View& v, const PreviewInput& in, const std::vector<std::vector<Vec3>>& msamples,
                  const std::vector<double>& dev_of, const std::string& unit) {
  o += "<g class=\"toolpath\">\n";
  std::string rapid_d;
  // Without colours, a run of feed blocks of one entity is one path (a
  // smaller file, and no darker dots where translucent blocks overlap).
  std::string run_d, run_attrs;
  Vec3 run_end;
  auto flush_run = [&] {
    if (!run_d.empty())
      o += "<path " + run_attrs + " d=\"" + run_d + "\" fill=\"none\" stroke=\"" + kFeedColour +
           "\" stroke-width=\"3\" stroke-linecap=\"round\" stroke-linejoin=\"round\" stroke-opacity=\"0.75\"/>\n";
    run_d.clear();
  };
  // Part cutting: the tool's swept width along each entity's deepest pass
  // (its lowest feed moves), under everything else; marks where a pass
  // rises onto a holding tab.
  if (!v.iso) {
    std::map<int, double> deepest;
    for (const auto& m : in.motion)
      if (m.kind != BlockKind::rapid && m.entity >= 0 && static_cast<size_t>(m.entity) < in.entity_tool_radius.size() &&
          in.entity_tool_radius[static_cast<size_t>(m.entity)] > 0) {
        auto [it, fresh] = deepest.emplace(m.entity, m.to.z);
        if (!fresh) it->second = std::min(it->second, m.to.z);
      }
    for (const auto& [entity, z] : deepest) {
      std::string d, marks;
      for (size_t i = 0; i < in.motion.size(); ++i) {
        const auto& m = in.motion[i];
        if (m.entity != entity || m.kind == BlockKind::rapid) continue;
        const auto& s = msamples[i];
        const bool vertical = s.size() == 2 && s.front().x == s.back().x && s.front().y == s.back().y;
        if (vertical) {
          // Rising from the deepest pass but not to a retract: onto a tab.
          if (m.from.z == z && m.to.z > z && i + 1 < in.motion.size() && in.motion[i + 1].kind != BlockKind::rapid) {
            const P2 q = v.screen(m.to);
            marks += "<rect class=\"tab\" x=\"" + n3(q.x - 4) + "\" y=\"" + n3(q.y - 4) +
                     "\" width=\"8\" height=\"8\" fill=\"#ff9f1c\" stroke=\"#7a4a00\"><title>holding tab: the pass rises to z " +
                     fmt_num(m.to.z) + "</title></rect>\n";
          }
          continue;
        }
        if (m.from.z != z && m.to.z != z) continue;
        d += (d.empty() ? "" : " ") + path_d(v, s);
      }
      const double w = 2 * in.entity_tool_radius[static_cast<size_t>(entity)] * v.s;
      if (!d.empty())
        o += "<path class=\"swept\" data-entity=\"" + std::to_string(entity) + "\" d=\"" + d +
             "\" fill=\"none\" stroke=\"#9ecae1\" stroke-opacity=\"0.45\" stroke-width=\"" + n3(w) +
             "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"><title>the tool's width on its deepest pass (diameter " +
             fmt_num(2 * in.entity_tool_radius[static_cast<size_t>(entity)]) + " " + unit + ")</title></path>\n";
      o += marks;
    }
    for (size_t e = 0; e < in.entity_left.size(); ++e)
      for (const MaterialLeft& l : in.entity_left[e]) {
        const std::vector<Vec3> pts = l.points.empty() ? std::vector<Vec3>{l.from, l.to} : l.points;
        o += "<path class=\"material-left\" data-entity=\"" + std::to_string(e) + "\" d=\"" + path_d(v, pts) +
             "\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"7\" stroke-opacity=\"0.8\" stroke-linecap=\"round\"><title>material left: the tool cannot reach " +
             fmt_num(std::round(l.length * 1000) / 1000) + " " + unit + " of the curve here (" +
             fmt_num(std::round(l.depth * 1000) / 1000) + " " + unit + " deep)</title></path>\n";
      }
  }
  const bool by_feed = in.plan != nullptr;
  if (by_feed) svg_feed_path(o, v, in, unit);
  for (size_t i = 0; i < in.motion.size(); ++i) {
    const auto& m = in.motion[i];
    const auto& s = msamples[i];
    if (by_feed && m.kind != BlockKind::rapid) continue;
    const P2 a = v.screen(s.front()), b = v.screen(s.back());
    const bool zero = s.size() == 2 && std::hypot(a.x - b.x, a.y - b.y) < 1e-6;
    if (m.kind == BlockKind::rapid) {
      if (!zero) rapid_d += (rapid_d.empty() ? "" : " ") + path_d(v, s);
      continue;
    }
    if (zero) continue;  // a plunge seen from above
    std::string attrs = "class=\"feed\"";
    if (m.entity >= 0) attrs += " data-entity=\"" + std::to_string(m.entity) + "\"";
    if (dev_of[i] < 0) {
      if (run_d.empty() || attrs != run_attrs || !(s.front() == run_end)) {
        flush_run();
        run_attrs = attrs;
        run_d = path_d(v, s);
      } else {
        run_d += " " + path_d(v, std::span<const Vec3>(s).subspan(1)).replace(0, 1, "L");
      }
      run_end = s.back();
      continue;
    }
    flush_run();
    // One path per block, coloured by its deviation, with a tooltip.
    const bool over = over_tolerance(dev_of[i], in.tolerance);
    attrs += " data-deviation=\"" + fmt_num(dev_of[i]) + "\"";
    if (over) attrs.replace(0, std::string("class=\"feed\"").size(), "class=\"feed over-tolerance\"");
    const std::string pct = format_significant(100 * dev_of[i] / in.tolerance, 3) + " % of the tolerance";
    o += "<path " + attrs + " d=\"" + path_d(v, s) + "\" fill=\"none\" stroke=\"" +
         deviation_colour(dev_of[i], in.tolerance) + "\" stroke-width=\"" + (over ? "6" : "3") +
         "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"><title>deviation " + format_significant(dev_of[i], 3) +
         " " + unit + " (" + pct + (over ? ": ABOVE THE TOLERANCE" : "") + ")</title></path>\n";
    if (over) {  // a ring around it, visible at any zoom
      const P2 c = v.screen(s[s.size() / 2]);
      o += "<circle class=\"over-tolerance-mark\" cx=\"" + n3(c.x) + "\" cy=\"" + n3(c.y) +
           "\" r=\"9\" fill=\"none\" stroke=\"" + kOverColour + "\" stroke-width=\"2\"/>\n";
    }
  }
  flush_run();
  if (!rapid_d.empty())
    o += "<path class=\"rapid\" d=\"" + rapid_d + "\" fill=\"none\" stroke=\"" + kRapidColour +
         "\" stroke-width=\"1\" stroke-dasharray=\"6 4\"/>\n";
  o += "</g>\n";

}

// One entity in one view: its true curve (`pts`, one polyline per chain),
// control polygon (with `control`), start, direction and label.
void svg_entity(std::string& o, const View& v, const PreviewInput& in, const Entity& e, const Shape& sh,
                const std::vector<std::vector<Vec3>>& pts, const std::vector<std::vector<Vec3>>& msamples,
                bool control) {
  o += "<g class=\"entity\" data-entity=\"" + std::to_string(e.index) + "\" data-id=\"" + esc(e.id) + "\">\n";
  std::string what = e.label() + ": " + e.type;
  if (sh.surface) {
    what += ", degree " + std::to_string(e.surface->degree_u()) + " x " + std::to_string(e.surface->degree_v()) +
            (e.surface->rational() ? ", rational" : "") + ", surface";
  } else {
    int deg = 0;
    bool rat = false;
    for (const auto& pc : sh.measure) deg = std::max(deg, pc.degree()), rat = rat || pc.rational();
    what += ", degree " + std::to_string(deg) + (rat ? ", rational" : "") + (sh.dim == 3 ? ", 3D" : ", 2D");
  }
  o += "<title>" + esc(what) + "</title>\n";
  if (control && !sh.polygons.empty()) {
    std::string d;
    for (const auto& poly : sh.polygons) d += (d.empty() ? "" : " ") + path_d(v, poly);
    o += "<path class=\"control-polygon\" d=\"" + d + "\" fill=\"none\" stroke=\"" + kControlColour +
         "\" stroke-width=\"0.8\"/>\n";
    for (const auto& p : sh.control_points) {
      const P2 q = v.screen(p);
      o += "<circle class=\"control-point\" cx=\"" + n3(q.x) + "\" cy=\"" + n3(q.y) +
           "\" r=\"2.5\" fill=\"#ffffff\" stroke=\"" + kControlColour + "\" stroke-width=\"1\"/>\n";
    }
  }
  for (size_t c = 0; c < pts.size(); ++c) {
    // A surface's border lines (the first and last of each direction)
    // are drawn heavier than its inner iso lines.
    const bool border = !sh.surface || c < 2 || c + 2 >= pts.size();
    o += "<path class=\"curve" + std::string(sh.surface ? " iso-line" : "") + "\" d=\"" +
         path_d(v, pts[c]) + "\" fill=\"none\" stroke=\"" + kCurveColour + "\" stroke-width=\"" +
         (border ? "1.2" : "0.6") + "\" stroke-linejoin=\"round\"" + (border ? "" : " stroke-opacity=\"0.6\"") +
         "/>\n";
  }
  // Start point and direction: an arrow leaving the start, another at
  // the middle of the curve. A surface's are those of its first cut.
  Vec3 start, start_dir, mid_pt, mid_dir;
  bool have_start = false, have_mid = false;
  if (!sh.surface) {
    const auto& ch = sh.chains.front();
    start = ch.front().front();
    start_dir = tangent(ch.front(), 0);
    const Bezier& mid = ch[ch.size() / 2];
    const double tm = ch.size() % 2 == 1 ? 0.5 : 0.0;
    mid_pt = evaluate(mid, tm);
    mid_dir = tangent(mid, tm);
    have_start = have_mid = true;
  } else {
    for (size_t i = 0; i < in.motion.size() && !have_start; ++i) {
      const auto& b = in.motion[i];
      if (in.motion[i].entity != static_cast<int>(e.index) || !is_feed(b) || is_plunge(in.motion, i) ||
          b.from == b.to)
        continue;
      start = b.from;
      start_dir = msamples[i][1] - msamples[i][0];
      have_start = true;
    }
    if (!have_start) start = evaluate(*e.surface, 0, 0);
  }
  const P2 s0 = v.screen(start);
  const P2 d0 = have_start ? v.screen_dir(start, start_dir) : P2{1, 0};
  if (have_start) {
    o += "<circle class=\"start-point\" cx=\"" + n3(s0.x) + "\" cy=\"" + n3(s0.y) + "\" r=\"3.5\" fill=\"" +
         kCurveColour + "\"/>\n";
    o += "<path class=\"direction-arrow\" d=\"" + arrow_d({s0.x + d0.x * 18, s0.y + d0.y * 18}, d0, 10, 4.5) +
         "\" fill=\"" + kCurveColour + "\"/>\n";
  }
  if (have_mid) {
    const P2 sm = v.screen(mid_pt), dm = v.screen_dir(mid_pt, mid_dir);
    o += "<path class=\"direction-arrow\" d=\"" + arrow_d({sm.x + dm.x * 5, sm.y + dm.y * 5}, dm, 10, 4.5) +
         "\" fill=\"" + kCurveColour + "\"/>\n";
  }
  // The label sits beside the start, on the side away from the path: the
  // id, the tool and the depth the tool path cuts it at.
  std::string cut;
  const int entity = static_cast<int>(e.index);
  if (entity < static_cast<int>(in.entity_tool.size()) && in.entity_tool[e.index] >= 0)
    cut = "T" + std::to_string(in.entity_tool[e.index]);
  double zlo = HUGE_VAL, zhi = -HUGE_VAL;
  for (size_t i = 0; i < in.motion.size(); ++i) {
    const auto& b = in.motion[i];
    if (in.motion[i].entity != entity || !is_feed(b) || is_plunge(in.motion, i)) continue;
    zlo = std::min({zlo, b.from.z, b.to.z});
    zhi = std::max({zhi, b.from.z, b.to.z});
  }
  if (zlo <= zhi)
    cut += (cut.empty() ? "" : " ") + std::string("Z") + format_significant(zlo, 6) +
           (zhi - zlo > 1e-9 ? " to " + format_significant(zhi, 6) : "");
  const double lx = s0.x - d0.y * 10 + (d0.y > 0 ? 0 : 2), ly = s0.y + d0.x * 10 + (d0.x > 0 ? 10 : -4);
  const std::string anchor = d0.y > 0 ? " text-anchor=\"end\"" : "";
  o += "<text class=\"entity-label\" x=\"" + n3(lx) + "\" y=\"" + n3(ly) + "\" fill=\"" + kCurveColour +
       "\" font-size=\"11\"" + anchor + ">" + esc(e.label()) + "</text>\n";
  // Under it: the tool and the depth the tool path cuts it at.
  if (!cut.empty())
    o += "<text class=\"entity-cut\" x=\"" + n3(lx) + "\" y=\"" + n3(ly + 12) + "\" fill=\"#555555\" font-size=\"10\"" +
         anchor + ">" + esc(cut) + "</text>\n";
  o += "</g>\n";
}

// The top view's coordinates: ticks with their values along the bottom and
// the left of the drawing, and the origin (0, 0) marked where it is in view
// (said in a corner where it is not).
void svg_axes(std::string& o, const View& v) {
  if (v.iso) return;
  const double w = v.maxx - v.minx, h = v.maxy - v.miny;
  const double step = nice_below(std::max(w, h) / 4);
  const double bottom = v.oy + h * v.s, left = v.ox;
  o += "<g class=\"axis-ticks\" fill=\"#666666\" font-size=\"10\">\n";
  std::string d;
  for (double k = std::ceil(v.minx / step); k * step <= v.maxx + 1e-9 * step; ++k) {
    const double x = v.ox + (k * step - v.minx) * v.s;
    d += "M" + n3(x) + " " + n3(bottom + 8) + " L" + n3(x) + " " + n3(bottom + 13) + " ";
    o += "<text x=\"" + n3(x) + "\" y=\"" + n3(bottom + 24) + "\" text-anchor=\"middle\">" +
         format_significant(k * step == 0 ? 0.0 : k * step, 6) + "</text>\n";
  }
  for (double k = std::ceil(v.miny / step); k * step <= v.maxy + 1e-9 * step; ++k) {
    const double y = v.oy + (v.maxy - k * step) * v.s;
    d += "M" + n3(left - 13) + " " + n3(y) + " L" + n3(left - 8) + " " + n3(y) + " ";
    o += "<text x=\"" + n3(left - 15) + "\" y=\"" + n3(y + 3) + "\" text-anchor=\"end\">" +
         format_significant(k * step == 0 ? 0.0 : k * step, 6) + "</text>\n";
  }
  o += "<path d=\"" + d + "\" stroke=\"#666666\" stroke-width=\"1\" fill=\"none\"/>\n</g>\n";
  const double slack = 0.02 * std::max(w, h);
  if (v.minx - slack <= 0 && 0 <= v.maxx + slack && v.miny - slack <= 0 && 0 <= v.maxy + slack) {
    const P2 c = v.screen(Vec3{0, 0, 0});
    o += "<g class=\"origin\" stroke=\"#000000\" stroke-width=\"1.2\">"
         "<circle cx=\"" + n3(c.x) + "\" cy=\"" + n3(c.y) + "\" r=\"5\" fill=\"none\"/>"
         "<path d=\"M" + n3(c.x) + " " + n3(c.y) + " L" + n3(c.x + 24) + " " + n3(c.y) + " M" + n3(c.x) + " " +
         n3(c.y) + " L" + n3(c.x) + " " + n3(c.y - 24) + "\"/>"
         "<path d=\"" + arrow_d({c.x + 28, c.y}, {1, 0}, 7, 3) + " " + arrow_d({c.x, c.y - 28}, {0, -1}, 7, 3) +
         "\" fill=\"#000000\" stroke=\"none\"/>"
         "<text x=\"" + n3(c.x + 31) + "\" y=\"" + n3(c.y + 4) + "\" stroke=\"none\" font-size=\"10\">X</text>"
         "<text x=\"" + n3(c.x - 3) + "\" y=\"" + n3(c.y - 32) + "\" stroke=\"none\" font-size=\"10\">Y</text>"
         "<text x=\"" + n3(c.x - 8) + "\" y=\"" + n3(c.y + 16) + "\" stroke=\"none\" font-size=\"10\" "
         "text-anchor=\"end\">0, 0</text></g>\n";
  } else {
    o += "<text class=\"origin-off-view\" x=\"" + n3(v.px + v.pw - 8) + "\" y=\"" + n3(v.py + 16) +
         "\" text-anchor=\"end\" fill=\"#666666\">program zero (0, 0) lies outside this view</text>\n";
  }
}

// The scale bar of one view, bottom left; an isometric view's axis triad.
void svg_scale_bar(std::string& o, const View& v, double pad, const std::string& unit) {
  const double avail = (v.pw - 2 * pad) * 0.3 / v.s;
  const double L = nice_below(avail);
  const double bx = v.px + pad, by = v.py + v.ph - 14, bw = L * v.s;
  o += "<g class=\"scale-bar\" data-length=\"" + fmt_num(L) + "\">\n";
  o += "<path d=\"M" + n3(bx) + " " + n3(by - 5) + " L" + n3(bx) + " " + n3(by) + " L" + n3(bx + bw) + " " + n3(by) +
       " L" + n3(bx + bw) + " " + n3(by - 5) + "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.5\"/>\n";
  o += "<text x=\"" + n3(bx + bw + 6) + "\" y=\"" + n3(by) + "\">" + format_significant(L, 6) + " " + unit +
       (v.iso ? " (along the axes)" : "") + "</text>\n";
  o += "</g>\n";
  if (v.iso) {
    // Axis triad, bottom right.
    const double cx = v.px + v.pw - 60, cy = v.py + v.ph - 24;
    o += "<g class=\"axes\">\n";
    const char* names[3] = {"X", "Y", "Z"};
    const Vec3 dirs[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int a = 0; a < 3; ++a) {
      const P2 d = v.screen_dir(Vec3{}, dirs[a]);
      o += "<path d=\"M" + n3(cx) + " " + n3(cy) + " L" + n3(cx + d.x * 22) + " " + n3(cy + d.y * 22) +
           "\" stroke=\"#555555\" stroke-width=\"1\"/>";
      o += "<text x=\"" + n3(cx + d.x * 30 - 4) + "\" y=\"" + n3(cy + d.y * 30 + 4) + "\" font-size=\"10\">" +
           names[a] + "</text>\n";
    }
    o += "</g>\n";
  }
}

// The legend below the views: the line styles, and the deviation scale
// when coloured.
void svg_legend(std::string& o, const PreviewInput& in, const PreviewOptions& opt, const std::vector<double>& dev_of,
                double dev_max, double margin, double legend_y) {
  const std::string unit = to_string(in.units);
  o += "<g class=\"legend\">\n";
  double lx = margin;
  const double ly = legend_y + 12;
  auto key = [&](const std::string& cls, const std::string& sample, const std::string& label) {
    o += "<g class=\"legend-key " + cls + "\">" + sample + "<text x=\"" + n3(lx + 34) + "\" y=\"" + n3(ly + 4) + "\">" +
         esc(label) + "</text></g>\n";
    lx += 44 + 6.8 * double(label.size());
  };
  auto line = [&](const std::string& colour, double width, const char* dash) {
    return "<path d=\"M" + n3(lx) + " " + n3(ly) + " L" + n3(lx + 28) + " " + n3(ly) + "\" stroke=\"" + colour +
           "\" stroke-width=\"" + n3(width) + "\"" + (*dash ? std::string(" stroke-dasharray=\"") + dash + "\"" : "") +
           " fill=\"none\"/>";
  };
  key("key-curve", line(kCurveColour, 1.2, ""), "true curve (surfaces: iso lines)");
  if (opt.control) key("key-control", line(kControlColour, 0.8, ""), "control polygon");
  if (in.plan) {
    key("key-feed", line(preview_feed_colour(1, 1), 3, ""), "feed, coloured by the speed reached");
    key("key-starved", "<path d=\"M" + n3(lx) + " " + n3(ly) + " L" + n3(lx + 28) + " " + n3(ly) + "\" stroke=\"" +
                           kOverColour + "\" stroke-opacity=\"0.45\" stroke-width=\"9\" fill=\"none\"/>",
        "starved blocks (red halo)");
  } else if (opt.deviation) {
    key("key-feed", line(deviation_colour(0, 1), 3, ""), "feed, coloured by deviation");
    bool unmeasured = false;
    for (size_t i = 0; i < in.motion.size(); ++i)
      unmeasured = unmeasured || (is_feed(in.motion[i]) && !is_plunge(in.motion, i) && dev_of[i] < 0);
    if (unmeasured)
      key("key-feed-unmeasured", line(kFeedColour, 3, ""),
          in.program_measured >= 0 ? "surfaces, parts: measured when built" : "surfaces, parts: not measured");
  } else {
    key("key-feed", line(kFeedColour, 3, ""), "feed (cutting)");
  }
  key("key-rapid", line(kRapidColour, 1, "6 4"), "rapid");
  // Part cutting, when the drawing has it.
  bool swept = false, left = false;
  for (double r : in.entity_tool_radius) swept = swept || r > 0;
  for (const auto& l : in.entity_left) left = left || !l.empty();
  // (Only as many as the row holds; every mark has its own tooltip.)
  auto fits = [&](const std::string& label) { return lx + 44 + 6.8 * double(label.size()) <= opt.width - margin; };
  if (swept && fits("tool's width")) key("key-swept", line("#9ecae1", 9, ""), "tool's width");
  if (swept && o.find("class=\"tab\"") != std::string::npos && fits("holding tab"))
    key("key-tab", "<rect x=\"" + n3(lx + 10) + "\" y=\"" + n3(ly - 4) + "\" width=\"8\" height=\"8\" fill=\"#ff9f1c\" stroke=\"#7a4a00\"/>",
        "holding tab");
  if (left && fits("material left")) key("key-material-left", line("#d62728", 7, ""), "material left");
  key("key-start", "<circle cx=\"" + n3(lx + 6) + "\" cy=\"" + n3(ly) + "\" r=\"3.5\" fill=\"" + kCurveColour +
                       "\"/><path d=\"" + arrow_d({lx + 26, ly}, {1, 0}, 9, 4) + "\" fill=\"" + kCurveColour + "\"/>",
      "start and direction");
  if (in.plan) {
    const MotionPlan& plan = *in.plan;
    const double top = feed_scale_top(plan);
    const double gy = ly + 30, gx = margin, gw = 320;
    o += "<g class=\"feed-scale\" data-max=\"" + fmt_num(top) + "\">\n";
    o += "<text x=\"" + n3(gx) + "\" y=\"" + n3(gy - 6) + "\">feed reached on machine " + esc(in.machine) + ", " + unit +
         "/min (cycle " + esc(format_seconds(plan.cycle_time_s)) + ", mean " +
         format_significant(100 * plan.mean_feed_ratio, 3) + " % of the programmed feed)</text>\n";
    o += "<rect x=\"" + n3(gx) + "\" y=\"" + n3(gy) + "\" width=\"" + n3(gw) +
         "\" height=\"12\" fill=\"url(#feed-gradient)\" stroke=\"#888888\" stroke-width=\"0.5\"/>\n";
    for (double f : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const double x = gx + f * gw;
      o += "<path d=\"M" + n3(x) + " " + n3(gy + 12) + " L" + n3(x) + " " + n3(gy + 16) +
           "\" stroke=\"#000000\" stroke-width=\"1\"/>";
      o += "<text x=\"" + n3(x) + "\" y=\"" + n3(gy + 28) + "\" text-anchor=\"middle\" font-size=\"11\">" +
           format_significant(f * top, 4) + "</text>\n";
    }
    const double sx = gx + gw + 60;
    o += "<text class=\"starved-count\" x=\"" + n3(sx) + "\" y=\"" + n3(gy + 10) + "\"" +
         (plan.starved_blocks ? " fill=\"" + std::string(kOverColour) + "\" font-weight=\"bold\"" : "") +
         ">starved blocks (red halo): " +
         (plan.starved_blocks ? std::to_string(plan.starved_blocks) + " of " + std::to_string(plan.blocks.size())
                              : std::string("none")) + "</text>\n";
    o += "</g>\n";
  } else if (opt.deviation) {
    const double gy = ly + 30, gx = margin, gw = 240;
    size_t measured = 0, over = 0;
    for (double d : dev_of)
      if (d >= 0) ++measured, over += over_tolerance(d, in.tolerance);
    std::string largest;
    if (measured > 0)
      largest = "largest " + format_significant(dev_max, 3) + " " + unit + ", " +
                format_significant(100 * dev_max / in.tolerance, 3) + " % of the tolerance";
    else if (in.program_measured >= 0)
      largest = "no curve block to measure here; the program's own check measured " +
                format_significant(in.program_measured, 3) + " " + unit;
    else
      largest = "no curve block to measure";
    o += "<g class=\"deviation-scale\" data-max=\"" + fmt_num(in.tolerance) + "\">\n";
    o += "<text x=\"" + n3(gx) + "\" y=\"" + n3(gy - 6) + "\">deviation of each cutting block from the true curve, " +
         "relative to the tolerance " + format_significant(in.tolerance, 4) + " " + unit + " (" + esc(largest) +
         ")</text>\n";
    o += "<rect x=\"" + n3(gx) + "\" y=\"" + n3(gy) + "\" width=\"" + n3(gw) +
         "\" height=\"12\" fill=\"url(#deviation-gradient)\" stroke=\"#888888\" stroke-width=\"0.5\"/>\n";
    for (double f : {0.0, 0.5, 1.0}) {
      const double x = gx + f * gw;
      o += "<path d=\"M" + n3(x) + " " + n3(gy + 12) + " L" + n3(x) + " " + n3(gy + 16) +
           "\" stroke=\"#000000\" stroke-width=\"1\"/>";
      o += "<text x=\"" + n3(x) + "\" y=\"" + n3(gy + 28) + "\" text-anchor=\"middle\" font-size=\"11\">" +
           (f == 0 ? std::string("0") : f == 0.5 ? std::string("50 %") : "100 % = " + format_significant(in.tolerance, 4)) +
           "</text>\n";
    }
    const double sx = gx + gw + 90;
    o += "<rect x=\"" + n3(sx) + "\" y=\"" + n3(gy - 2) + "\" width=\"24\" height=\"16\" fill=\"" + kOverColour +
         "\"/><text class=\"over-tolerance-count\" x=\"" + n3(sx + 30) + "\" y=\"" + n3(gy + 10) + "\"" +
         (over ? " fill=\"" + std::string(kOverColour) + "\" font-weight=\"bold\"" : "") + ">above the tolerance (ringed): " +
         (over ? std::to_string(over) + " block" + (over == 1 ? "" : "s") : std::string("none")) + "</text>\n";
    o += "</g>\n";
  }
  o += "</g>\n";
}

}  // namespace

std::string preview_deviation_colour(double d, double tol) { return deviation_colour(d, tol); }

std::string preview_feed_colour(double f, double top) {
  // Five stops of a perceptually even scale (viridis' ends and middle).
  static const double stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  const double x = std::clamp(top > 0 ? f / top : 0.0, 0.0, 1.0) * 4;
  const int i = std::min(3, static_cast<int>(x));
  const double t = x - i;
  char b[8];
  int c[3];
  for (int k = 0; k < 3; ++k) c[k] = static_cast<int>(std::lround(stops[i][k] + t * (stops[i + 1][k] - stops[i][k])));
  std::snprintf(b, sizeof b, "#%02x%02x%02x", c[0], c[1], c[2]);
  return b;
}

std::string preview_svg(const PreviewInput& in, const PreviewOptions& opt) {
  const Job* job = in.job;
  const bool has_entities = job && !job->entities.empty();
  if (!has_entities && in.motion.empty())
    throw InputError(errc::preview_empty, Place{}, "nothing to draw: the job has no entities and there is no tool path");
  if (opt.deviation && in.plan)
    throw InputError(errc::preview_deviation, Place::at_setting("deviation"),
                     "a preview is coloured by deviation or by feed, not both: choose one");
  if (opt.deviation && (!job || !(in.tolerance > 0)))
    throw InputError(errc::preview_deviation, Place::at_setting("deviation"),
                     "colouring by deviation needs the job's true curves and a tolerance; give the job file");
  const std::string unit = to_string(in.units);
  const double W = std::max(400.0, opt.width);

  // Deviation first: it is the slow part and reports progress.
  std::vector<BlockDeviation> devs;
  std::vector<double> dev_of(in.motion.size(), -1);
  double dev_max = 0;
  if (opt.deviation) {
    devs = block_deviations(*job, in.motion, in.tolerance, opt.on_entity);
    for (const auto& d : devs) dev_of[d.block] = d.deviation, dev_max = std::max(dev_max, d.deviation);
  }

  std::vector<Shape> shapes;
  if (job)
    for (const auto& e : job->entities) shapes.push_back(entity_shape(e));

  // Is there anything 3D to show in an isometric view?
  bool three_d = false;
  for (const auto& sh : shapes) three_d = three_d || (!sh.chains.empty() && sh.dim == 3);
  for (size_t i = 0; i < in.motion.size() && !three_d; ++i) {
    const auto& b = in.motion[i];
    if (!is_feed(b) || is_plunge(in.motion, i)) continue;
    three_d = b.from.z != b.to.z;
    for (const auto& c : b.ctrl) three_d = three_d || c.z != b.from.z;
  }

  std::vector<View> views(1);
  views[0].id = "top-view";
  views[0].title = "Top view (XY)";
  if (three_d) {
    views.emplace_back();
    views[1].id = "iso-view";
    views[1].title = "Isometric view";
    views[1].iso = true;
  }

  // Bounds: tight curve boxes, control points, tool path samples.
  Box3 all;
  for (const auto& sh : shapes) {
    for (const auto& ch : sh.chains)
      for (const auto& pc : ch) all.add(bounds(pc));
    if (opt.control)
      for (const auto& p : sh.control_points) all.add(p);
  }
  for (const auto& m : in.motion) {
    all.add(m.from);
    all.add(m.to);
  }
  const double size0 = all.empty() ? 1.0 : std::max(norm(all.hi - all.lo), 1e-9);
  std::vector<std::vector<Vec3>> msamples(in.motion.size());
  for (size_t i = 0; i < in.motion.size(); ++i) msamples[i] = sample_block(in.motion[i], size0 * 2e-4);
  for (auto& v : views) {
    for (const auto& sh : shapes) {
      for (const auto& ch : sh.chains)
        for (const auto& pc : ch) v.fit(bounds(pc));
      if (opt.control)
        for (const auto& p : sh.control_points) v.fit(p);
    }
    for (const auto& s : msamples)
      for (const auto& p : s) v.fit(p);
    if (v.empty()) v.fit(Vec3{0, 0, 0});
  }

  // Layout: header, the views side by side, the legend.
  const double margin = 20, pad = 36, bar_room = 34;
  const size_t chars = static_cast<size_t>((W - 2 * margin) / 6.8);
  std::vector<std::string> warn_lines;
  for (const auto& w : in.warnings)
    for (auto& l : wrap(w, chars)) warn_lines.push_back(l);
  const double header_h = 30 + 17.0 * double(in.notes.size()) + 17.0 * double(warn_lines.size()) + 8;
  const double nv = double(views.size());
  const double pw = (W - margin * (nv + 1)) / nv;
  const double max_inner_h = (views.size() == 1 ? 0.62 * W : 1.05 * pw) - 2 * pad - bar_room;
  double ph = 0;
  for (auto& v : views) {
    double wx = v.maxx - v.minx, wy = v.maxy - v.miny;
    const double big = std::max({wx, wy, 1e-9});
    // A straight line along an axis still gets a sensible scale.
    if (wx < 1e-3 * big) v.minx -= 0.5e-3 * big, v.maxx += 0.5e-3 * big, wx = v.maxx - v.minx;
    if (wy < 1e-3 * big) v.miny -= 0.5e-3 * big, v.maxy += 0.5e-3 * big, wy = v.maxy - v.miny;
    v.s = std::min((pw - 2 * pad) / wx, max_inner_h / wy);
    ph = std::max(ph, wy * v.s + 2 * pad + bar_room);
  }
  for (size_t k = 0; k < views.size(); ++k) {
    View& v = views[k];
    v.px = margin + double(k) * (pw + margin);
    v.py = header_h;
    v.pw = pw;
    v.ph = ph;
    v.ox = v.px + (pw - (v.maxx - v.minx) * v.s) / 2;
    v.oy = v.py + pad + (ph - 2 * pad - bar_room - (v.maxy - v.miny) * v.s) / 2;
  }
  const double legend_y = header_h + ph + 14;
  const double legend_h = opt.deviation || in.plan ? 92 : 46;
  const double H = legend_y + legend_h + 10;

  // The true curves, sampled finely: a fifth of a pixel, and never coarser
  // than a twentieth of the tolerance, so the tool path's deviation shows
  // when zoomed in.
  double smax = 0;
  for (const auto& v : views) smax = std::max(smax, v.s);
  double draw_tol = 0.2 / smax;
  if (in.tolerance > 0) draw_tol = std::min(draw_tol, in.tolerance / 20);
  auto sample_chain = [&](const std::vector<Bezier>& chain) {
    try {
      return flatten(chain, FlattenOptions{.tolerance = draw_tol, .decimals = -1, .on_curve = true}).points;
    } catch (const InputError&) {  // finer than double precision allows
      return flatten(chain, FlattenOptions{.tolerance = 0.2 / smax, .decimals = -1, .on_curve = true}).points;
    }
  };
  std::vector<std::vector<std::vector<Vec3>>> chain_pts(shapes.size());
  for (size_t k = 0; k < shapes.size(); ++k)
    for (const auto& ch : shapes[k].chains) chain_pts[k].push_back(sample_chain(ch));

  std::string o;
  o.reserve(1 << 16);
  o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + n3(W) + "\" height=\"" + n3(H) +
       "\" viewBox=\"0 0 " + n3(W) + " " + n3(H) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o += "<title>" + esc(in.title.empty() ? "bezcam preview" : in.title) + "</title>\n";
  o += "<desc>Drawn by bezcam: true curves from their exact Bézier pieces, control polygons, the tool path (feeds "
       "solid, rapids dashed). Units: " + unit + ".</desc>\n";
  if (in.plan) {
    o += "<defs><linearGradient id=\"feed-gradient\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">";
    for (double f : {0.0, 0.25, 0.5, 0.75, 1.0})
      o += "<stop offset=\"" + fmt_num(f) + "\" stop-color=\"" + preview_feed_colour(f, 1) + "\"/>";
    o += "</linearGradient></defs>\n";
  }
  if (opt.deviation)
    o += "<defs><linearGradient id=\"deviation-gradient\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">"
         "<stop offset=\"0\" stop-color=\"" + deviation_colour(0, 1) + "\"/><stop offset=\"0.5\" stop-color=\"" +
         deviation_colour(0.5, 1) + "\"/><stop offset=\"1\" stop-color=\"" + deviation_colour(1, 1) +
         "\"/></linearGradient></defs>\n";
  o += "<rect class=\"background\" x=\"0\" y=\"0\" width=\"" + n3(W) + "\" height=\"" + n3(H) + "\" fill=\"#ffffff\"/>\n";

  // Header.
  o += "<g class=\"header\">\n";
  double ty = 24;
  o += "<text class=\"title\" x=\"" + n3(margin) + "\" y=\"" + n3(ty) + "\" font-size=\"16\" font-weight=\"bold\">" +
       esc(in.title.empty() ? "bezcam preview" : in.title) + "</text>\n";
  o += "<text class=\"units\" x=\"" + n3(W - margin) + "\" y=\"" + n3(ty) + "\" text-anchor=\"end\">units: " + unit +
       "</text>\n";
  for (const auto& nline : in.notes) {
    ty += 17;
    o += "<text class=\"note\" x=\"" + n3(margin) + "\" y=\"" + n3(ty) + "\" fill=\"#333333\">" + esc(nline) + "</text>\n";
  }
  for (const auto& w : warn_lines) {
    ty += 17;
    o += "<text class=\"warning\" x=\"" + n3(margin) + "\" y=\"" + n3(ty) + "\" fill=\"#b00000\" font-weight=\"bold\">" +
         esc(w) + "</text>\n";
  }
  o += "</g>\n";

  for (const View& v : views) {
    o += "<g class=\"view\" id=\"" + v.id + "\">\n";
    o += "<rect class=\"frame\" x=\"" + n3(v.px) + "\" y=\"" + n3(v.py) + "\" width=\"" + n3(v.pw) + "\" height=\"" +
         n3(v.ph) + "\" fill=\"#fbfbfb\" stroke=\"#cccccc\"/>\n";
    o += "<text class=\"view-title\" x=\"" + n3(v.px + 8) + "\" y=\"" + n3(v.py + 16) + "\" font-weight=\"bold\">" +
         v.title + "</text>\n";

    svg_toolpath(o, v, in, msamples, dev_of, unit);

    // Entities.
    if (job) {
      o += "<g class=\"entities\">\n";
      for (size_t k = 0; k < job->entities.size(); ++k) {
        const Entity& e = job->entities[k];
        const Shape& sh = shapes[k];
        if (sh.chains.empty()) continue;
        svg_entity(o, v, in, e, sh, chain_pts[k], msamples, opt.control);
      }
      o += "</g>\n";
    }

    svg_axes(o, v);
    svg_scale_bar(o, v, pad, unit);
    o += "</g>\n";
  }

  svg_legend(o, in, opt, dev_of, dev_max, margin, legend_y);
  o += "</svg>\n";
  return o;
}

void add_part_cutting(PreviewInput& in, const Program& p, size_t entities) {
  in.entity_tool_radius.assign(entities, 0);
  in.entity_left.assign(entities, {});
  for (const auto& r : p.entities)
    if (r.entity >= 0 && static_cast<size_t>(r.entity) < entities) {
      in.entity_tool_radius[static_cast<size_t>(r.entity)] = r.tool_width / 2;
      in.entity_left[static_cast<size_t>(r.entity)] = r.left;
    }
}

}  // namespace bezcam
