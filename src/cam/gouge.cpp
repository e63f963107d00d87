#include "bezcam/cam/gouge.hpp"

#include <algorithm>
#include <cmath>

namespace bezcam {

std::vector<GougeSpan> find_gouges(const SurfaceGeometry& s, const SurfaceCurve& c, double radius, int samples) {
  std::vector<GougeSpan> out;
  if (!(radius > 0)) return out;
  struct Probe {
    bool bad;
    double k;  // concave curvature
    bool under;
  };
  auto probe = [&](double t) {
    const auto [u, v] = uv_at(c, t);
    const Curvatures k = principal_curvatures(s, u, v);
    const bool under = unit_normal(s, u, v).z < 0;
    // An undefined normal is left to the flattener, which names it.
    return Probe{k.defined && (k.k_max * radius > 1 || under), k.k_max, under};
  };
  auto edge = [&](double good, double bad) {  // bisection to 1e-9
    while (std::abs(bad - good) > 1e-9) {
      const double m = 0.5 * (good + bad);
      (probe(m).bad ? bad : good) = m;
    }
    return bad;
  };
  const int n = std::max(samples, 2);
  Probe prev = probe(0);
  GougeSpan cur;
  bool open = false;
  auto worst = [&](double t, const Probe& p) {
    if (!open || (p.under && !cur.undercut) || (!cur.undercut && p.k > 1 / std::max(cur.curvature_radius, 1e-300))) {
      const auto [u, v] = uv_at(c, t);
      cur.worst_t = t, cur.worst_u = u, cur.worst_v = v;
      cur.undercut = p.under;
      cur.curvature_radius = p.under ? 0 : 1 / p.k;
    }
  };
  if (prev.bad) {
    cur = GougeSpan{};
    worst(0, prev);
    open = true;
    cur.t0 = 0;
  }
  for (int i = 1; i <= n; ++i) {
    const double t = double(i) / n, tp = double(i - 1) / n;
    const Probe p = probe(t);
    if (p.bad && !open) {
      cur = GougeSpan{};
      cur.t0 = edge(tp, t);
      worst(t, p);
      open = true;
    } else if (p.bad) {
      worst(t, p);
    } else if (open) {
      cur.t1 = edge(t, tp);
      out.push_back(cur);
      open = false;
    }
    prev = p;
  }
  if (open) {
    cur.t1 = 1;
    out.push_back(cur);
  }
  return out;
}

}  // namespace bezcam
