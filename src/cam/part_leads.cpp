// The leads of a part's cut (part_cut.hpp): a quarter arc and a line on
// the waste side into and out of each stretch, joined at right angles to
// the part's normal, made shorter or refused where they would cut into the
// part, and where a closed path starts so that its lead fits.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "bezcam/error.hpp"
#include "bezcam/flatten/arc_fit.hpp"
#include "bezcam/warnings.hpp"
#include "part_cut.hpp"

namespace bezcam::detail {

namespace {

constexpr double kPi = std::numbers::pi;
// How many of a closed path's longest stretches are tried for its start
// where a lead fits there.
constexpr size_t kLeadStarts = 16;

}  // namespace

Vec3 unit_tangent(const Bezier& b, double t) {
  Vec3 d = derivative(b, t);
  if (std::hypot(d.x, d.y) == 0) d = t < 0.5 ? b.points[1] - b.points[0] : b.back() - b.points[b.points.size() - 2];
  const double l = std::hypot(d.x, d.y);
  return l > 0 ? Vec3{d.x / l, d.y / l, 0} : Vec3{1, 0, 0};
}

Vec3 lead_direction(PartDistance& part, const Vec3& p, const Vec3& along, int waste, int away, double scale) {
  const Vec3 q = part.nearest(p);
  const double dx = p.x - q.x, dy = p.y - q.y, l = std::hypot(dx, dy);
  if (!(l > 1e-6 * scale)) return along;
  const Vec3 w{away * dx / l, away * dy / l, 0};  // towards the waste
  return Vec3{w.y, -w.x, 0} * waste;
}

// A quarter arc and a line on the waste side (+1 left, -1 right of travel).
std::vector<Bezier> lead_in(const Vec3& s, const Vec3& t, int waste, const Lead& l) {
  const Vec3 w = Vec3{-t.y, t.x, 0} * waste;
  const Vec3 c = s + w * l.radius, p1 = s - t * l.radius + w * l.radius;
  std::vector<ArcSeg> segs;
  if (l.length > 0) segs.push_back(ArcSeg::line(p1 + w * l.length, p1));
  segs.push_back(ArcSeg::make_arc(p1, s, c, waste * kPi / 2));
  segs.back().b = s;
  return bezier_pieces(segs);
}
std::vector<Bezier> lead_out(const Vec3& e, const Vec3& t, int waste, const Lead& l) {
  const Vec3 w = Vec3{-t.y, t.x, 0} * waste;
  const Vec3 c = e + w * l.radius, p2 = e + t * l.radius + w * l.radius;
  std::vector<ArcSeg> segs{ArcSeg::make_arc(e, p2, c, waste * kPi / 2)};
  segs.back().a = e;
  if (l.length > 0) segs.push_back(ArcSeg::line(p2, p2 + w * l.length));
  return bezier_pieces(segs);
}

// Under compensation the programmed lead is the tool's radius larger and
// the line's outer end, where the tool stands before G41 and after G40, is
// not offset.
std::vector<PathPiece> PartCut::lead_path(const Vec3& at, const Vec3& t, bool lead_in_end, const Lead& x) const {
  const Vec3 w = Vec3{-t.y, t.x, 0} * waste;
  std::vector<PathPiece> pieces;
  for (const Bezier& b : lead_in_end ? lead_in(at + w * tool_r, t, waste, x) : lead_out(at + w * tool_r, t, waste, x))
    pieces.push_back(PathPiece::of(b));
  if (controller) {
    const Lead programmed{x.radius + tool_r, x.length};
    const auto shape = lead_in_end ? lead_in(at, t, waste, programmed) : lead_out(at, t, waste, programmed);
    const Vec3 outer = lead_in_end ? shape.front().front() : shape.back().back();
    pieces.push_back(PathPiece::line(outer, outer));
  }
  return pieces;
}

// How near the lead comes to the part, less what it must keep (lead_clear,
// or what the path's own end keeps where that is less: that is the path's
// reading, measured on its own).
double PartCut::room(const Vec3& at, const Vec3& t, bool lead_in_end, const Lead& x) {
  const Vec3 centre = at + Vec3{-t.y, t.x, 0} * (waste * tool_r);
  const double own = dist(centre, part_distance->nearest(centre)) - 1e-9 * scale;
  return part_distance->min_distance(lead_path(at, t, lead_in_end, x)) - std::min(lead_clear, own);
}

bool PartCut::lead_fits(const Vec3& at, const Vec3& t, const Lead& x) {
  return room(at, t, true, x) >= 0 && room(at, t, false, x) >= 0;
}

// The lead (a quarter arc back along the path) needs room, which a corner
// of a pocket does not give, nor a bend of the part tighter than the lead:
// the chain starts in the middle of its longest stretch where the lead fits.
std::vector<ArcSeg> PartCut::start_where_lead_fits(std::vector<ArcSeg> chain) {
  std::vector<size_t> order(chain.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t x, size_t y) { return chain[x].length() > chain[y].length(); });
  size_t longest = order.front();
  for (size_t i = 0; part_distance && i < order.size() && i < kLeadStarts; ++i) {
    const Vec3 at = chain[order[i]].point(0.5);
    if (lead_fits(at, lead_direction(*part_distance, at, chain[order[i]].tangent(0.5), waste, away, scale),
                  *lead_used)) {
      longest = order[i];
      break;
    }
  }
  std::vector<ArcSeg> turned{chain[longest].sub(0.5, 1)};
  for (size_t i = 1; i < chain.size(); ++i) turned.push_back(chain[(longest + i) % chain.size()]);
  turned.push_back(chain[longest].sub(0, 0.5));
  turned.back().a = turned[turned.size() - 2].b;
  turned.back().b = turned.front().a;
  return turned;
}

// A lead that would come nearer the part than the path (a pocket too small
// for it, a part too near) is made shorter, its line first; one whose arc
// alone does not fit is refused, with the radius that fits there.
Lead PartCut::fit_lead(size_t k, const Stretch& st) {
  Lead l = *lead_used;
  for (const bool lead_in_end : {true, false}) {
    const Vec3& at = lead_in_end ? st.s : st.e;
    const Vec3& t = lead_in_end ? st.ts : st.te;
    if (room(at, t, lead_in_end, l) >= 0) continue;
    if (!controller && room(at, t, lead_in_end, Lead{l.radius, 0}) >= 0) {
      double ok = 0, bad = l.length;
      for (int i = 0; i < 30; ++i) {
        const double mid = 0.5 * (ok + bad);
        (room(at, t, lead_in_end, Lead{l.radius, mid}) >= 0 ? ok : bad) = mid;
      }
      l.length = ok;
      continue;
    }
    double ok = 0, bad = l.radius;
    for (int i = 0; i < 30; ++i) {
      const double mid = 0.5 * (ok + bad);
      (room(at, t, lead_in_end, Lead{mid, controller ? l.length : 0}) >= 0 ? ok : bad) = mid;
    }
    const double fits = std::floor(ok * 1000) / 1000;
    const double near = part_distance->min_distance(lead_path(at, t, lead_in_end, l));
    fail("lead", std::string("the lead-") + (lead_in_end ? "in" : "out") + " at " + where(at) +
                     " would cut into the part: it comes within " +
                     fmt_num(std::round(std::max(near, 0.0) * 1000) / 1000) +
                     " of the curve, where the path keeps at least " +
                     fmt_num(std::round((radius - (dev_side > 0 ? 0 : tol)) * 1e4) / 1e4) +
                     (fits > 0 ? "; a lead of radius " + fmt_num(fits) + (controller ? "" : " and no line") +
                                     " fits there: make it smaller"
                               : "; no lead fits there (the path ends where the tool touches the part on both "
                                 "sides): remove the lead from this entity"));
  }
  if (l.length < lead_used->length)
    p.warnings.push_back(
        tagged_warning(ent.label() + ": the lead's line is made " + fmt_num(std::floor(l.length * 1000) / 1000) +
                           " long, not " + fmt_num(lead_used->length) + ", at " + where(st.s) +
                           (k > 0 || chains.size() > 1 ? " (stretch " + std::to_string(k + 1) + ")" : std::string()) +
                           ": a longer one would cut into the part",
                       "lead-shortened"));
  return l;
}

// The direction the leads join the path in: at right angles to the part's
// nearest point (the tool's centre stands on that normal, whatever the
// path's last piece does where a clipped offset ends), turned so that the
// waste is on the tool's side.
void PartCut::leads_of(size_t k, Stretch& st) {
  const auto& chain = chains[k];
  st.ts = unit_tangent(chain.front(), 0);
  st.te = unit_tangent(chain.back(), 1);
  if (part_distance) {
    st.ts = lead_direction(*part_distance, st.s, st.ts, waste, away, scale);
    st.te = lead_direction(*part_distance, st.e, st.te, waste, away, scale);
  }
  if (!lead_used) return;
  const Lead l = part_distance ? fit_lead(k, st) : *lead_used;
  // Under compensation the programmed lead arc is the tool's radius
  // larger: the tool's centre runs on the arc of the radius asked.
  const Lead programmed{l.radius + tool_r, l.length};
  st.in = lead_in(st.s, st.ts, waste, programmed);
  st.out = lead_out(st.e, st.te, waste, programmed);
}

}  // namespace bezcam::detail
