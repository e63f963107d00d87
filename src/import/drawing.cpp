#include "bezcam/import/drawing.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/flatten/nesting.hpp"
#include "bezcam/import/conic.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/job/settings.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"

namespace bezcam::import {
namespace {

bool clamped_end(const Piece& p) {
  const size_t k = p.knots.size(), q = static_cast<size_t>(p.degree);
  if (k < q + 2) return false;
  for (size_t i = k - q - 1; i < k; ++i)
    if (p.knots[i] != p.knots[k - 1]) return false;
  return true;
}
bool clamped_start(const Piece& p) {
  const size_t q = static_cast<size_t>(p.degree);
  if (p.knots.size() < q + 2) return false;
  for (size_t i = 0; i <= q; ++i)
    if (p.knots[i] != p.knots[0]) return false;
  return true;
}

Vec3 start_of(const Piece& p) {
  if (!p.bspline || clamped_start(p)) return p.points.front();
  return evaluate(NurbsCurve::make(p.degree, p.points, p.knots, p.weights), p.knots[static_cast<size_t>(p.degree)]);
}

Piece reversed(Piece p) {
  std::reverse(p.points.begin(), p.points.end());
  std::reverse(p.weights.begin(), p.weights.end());
  if (p.bspline) {
    const double a = p.knots.front(), b = p.knots.back();
    std::reverse(p.knots.begin(), p.knots.end());
    for (double& k : p.knots) k = a + b - k;
  }
  return p;
}
Contour reversed(Contour c) {
  std::reverse(c.pieces.begin(), c.pieces.end());
  for (Piece& p : c.pieces) p = reversed(std::move(p));
  return c;
}
Vec3 c_start(const Contour& c) { return start_of(c.pieces.front()); }
Vec3 c_end(const Contour& c) { return c.pieces.back().end(); }

// Makes `next` start exactly where `prev` ends (they are within the join
// distance): the end control point moves when it is the curve's end,
// otherwise a bridging line of that length is added.
void meet(std::vector<Piece>& pieces, size_t i) {
  Piece& prev = pieces[i - 1];
  Piece& next = pieces[i];
  const Vec3 e = prev.end();
  if (start_of(next) == e) return;
  if (!next.bspline || clamped_start(next)) {
    next.points.front() = e;
    return;
  }
  Piece bridge;
  bridge.points = {e, start_of(next)};
  pieces.insert(pieces.begin() + static_cast<std::ptrdiff_t>(i), bridge);
}

// ---- JSON text --------------------------------------------------------------

// Every number at full double precision: the shortest text that reads
// back as the same double (messages round, a job file must not).
std::string exact(double v) {
  char b[64];
  return std::string(b, std::to_chars(b, b + sizeof b, v).ptr);
}
std::string num(double v, double scale) { return exact(v * scale); }
std::string quoted(const std::string& s) {
  std::string o = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      o += '\\';
      o += ch;
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      o += buf;
    } else {
      o += ch;
    }
  }
  return o + "\"";
}
std::string point(const Vec3& p, double scale) { return "[" + num(p.x, scale) + ", " + num(p.y, scale) + "]"; }
std::string points(const std::vector<Vec3>& ps, double scale) {
  std::string o = "[";
  for (size_t i = 0; i < ps.size(); ++i) o += (i ? ", " : "") + point(ps[i], scale);
  return o + "]";
}
std::string numbers(const std::vector<double>& vs) {
  std::string o = "[";
  for (size_t i = 0; i < vs.size(); ++i) o += (i ? ", " : "") + exact(vs[i]);
  return o + "]";
}
std::string job_text(const Drawing& d, const ImportOptions& opt, std::vector<std::string>* warnings);

// A drawing's `side` "outside" is the part's outside, "inside" the
// outline's inside (docs/import.md, "Sides of a part"): each kept closed
// contour gets the side of its even-odd depth among the others (even: the
// side asked for; odd: the other one). Empty: the setting is not one of
// those two, every entity keeps the job's side. Contours that cross each
// other are warned about.
std::vector<std::string> sides_by_nesting(const Drawing& d, const ImportOptions& opt, std::vector<std::string>* warnings) {
  std::string side;  // the value as JSON text
  for (const auto& [k, v] : settings_json(opt.settings).job)
    if (k == "side") side = v;
  if (side != "\"outside\"" && side != "\"inside\"") return {};
  side = side.substr(1, side.size() - 2);
  // The curves as the job reader builds them (B-splines and interpolations
  // included), from the geometry alone.
  ImportOptions geometry;
  geometry.layers = opt.layers;
  const Job job = parse_job(job_text(d, geometry, nullptr), d.source);
  std::vector<size_t> closed;
  std::vector<std::vector<Bezier>> curves;
  for (size_t k = 0; k < job.entities.size(); ++k)
    if (job.entities[k].curve.closed && !job.entities[k].curve.pieces.empty()) {
      closed.push_back(k);
      curves.push_back(job.entities[k].curve.pieces);
    }
  const Nesting nest = nest_closed_curves(curves);
  const std::string other = side == "outside" ? "inside" : "outside";
  std::vector<std::string> out(job.entities.size());
  for (size_t i = 0; i < closed.size(); ++i) out[closed[i]] = nest.depth[i] % 2 == 0 ? side : other;
  if (warnings)
    for (const auto& [a, b] : nest.crossing)
      warnings->push_back("side \"" + side + "\": contours " + quoted(job.entities[closed[a]].id) + " and " +
                          quoted(job.entities[closed[b]].id) +
                          " cross each other, so neither is inside the other: each is cut on the side its nesting "
                          "among the rest gives it, and the tool runs through the other's region");
  return out;
}

}  // namespace

Vec3 Piece::end() const {
  if (!bspline || clamped_end(*this)) return points.back();
  return evaluate(NurbsCurve::make(degree, points, knots, weights), knots[knots.size() - 1 - static_cast<size_t>(degree)]);
}

double Drawing::size() const {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  bool any = false;
  for (const Contour& c : contours) {
    const auto add = [&](const Vec3& p) {
      any = true;
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    };
    for (const Piece& p : c.pieces)
      for (const Vec3& q : p.points) add(q);
    for (const Vec3& q : c.interpolation.through) add(q);
  }
  if (!any) return 0;
  return std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
}

void join_contours(Drawing& d) {
  const double eps = 1e-6 * d.size();
  const auto near = [&](const Vec3& a, const Vec3& b) { return dist(a, b) <= eps; };
  std::vector<Contour> out;
  std::vector<bool> used(d.contours.size(), false);
  for (size_t i = 0; i < d.contours.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    Contour chain = d.contours[i];
    if (chain.closed || chain.is_interpolation || chain.pieces.empty()) {
      out.push_back(std::move(chain));
      continue;
    }
    size_t joined = 0;
    for (bool grew = true; grew;) {
      grew = false;
      if (near(c_end(chain), c_start(chain))) break;  // closes: take nothing more
      for (size_t j = i + 1; j < d.contours.size(); ++j) {
        const Contour& c = d.contours[j];
        if (used[j] || c.closed || c.is_interpolation || c.pieces.empty() || c.layer != chain.layer) continue;
        const Vec3 e = c_end(chain), s = c_start(chain);
        if (near(e, c_start(c)) || near(e, c_end(c))) {
          Contour next = near(e, c_start(c)) ? c : reversed(c);
          for (Piece& p : next.pieces) chain.pieces.push_back(std::move(p));
        } else if (near(s, c_end(c)) || near(s, c_start(c))) {
          Contour prev = near(s, c_end(c)) ? c : reversed(c);
          for (Piece& p : chain.pieces) prev.pieces.push_back(std::move(p));
          chain.pieces = std::move(prev.pieces);
        } else {
          continue;
        }
        used[j] = true;
        ++joined;
        grew = true;
      }
    }
    for (size_t k = 1; k < chain.pieces.size(); ++k) meet(chain.pieces, k);
    if (chain.pieces.size() > 1 && near(c_end(chain), c_start(chain))) {
      chain.closed = true;
      // The end meets the start exactly: move the end point, or bridge.
      Piece& last = chain.pieces.back();
      const Vec3 s = c_start(chain);
      if (!(last.end() == s)) {
        if (!last.bspline || clamped_end(last)) {
          last.points.back() = s;
        } else {
          chain.pieces.push_back(line_piece(last.end(), s));
        }
      }
    }
    if (joined) chain.id += "+" + std::to_string(joined);
    out.push_back(std::move(chain));
  }
  d.contours = std::move(out);
}

std::string job_json(const Drawing& d, const ImportOptions& opt) { return job_text(d, opt, nullptr); }

namespace {

std::string job_text(const Drawing& d, const ImportOptions& opt, std::vector<std::string>* warnings) {
  // Layers asked for must exist.
  std::set<std::string> keep(opt.layers.begin(), opt.layers.end());
  for (const std::string& l : keep)
    if (!d.layers.count(l)) {
      std::string known;
      for (const auto& [name, s] : d.layers)
        if (!name.empty()) known += (known.empty() ? "" : ", ") + quoted(name);
      throw InputError(errc::import_layer, Place::at_setting("layers"),
                       d.source + " has no layer " + quoted(l) + "; " +
                           (known.empty() ? "it has no named layers (everything is on one unnamed layer: select none)"
                                          : "its layers are " + known));
    }
  double scale = 1;
  bool units = false;
  std::string top, job;
  const SettingsJson settings = settings_json(opt.settings);
  for (const auto& [k, v] : settings.top) {
    if (k == "units") units = true, scale = v == "\"inch\"" ? 1 / 25.4 : 1;
    top += (top.empty() ? "" : ",\n    ") + quoted(k) + ": " + v;
  }
  for (const auto& [k, v] : settings.job) job += (job.empty() ? "" : ",\n    ") + quoted(k) + ": " + v;
  std::ostringstream o;
  o << "{\n  \"bezcam\": 1,\n";
  if (!units) o << "  \"units\": \"mm\",\n";
  if (!top.empty()) {
    // top-level settings, one per line
    std::string t = top;
    for (size_t p = 0; (p = t.find(",\n    ", p)) != std::string::npos;) t.replace(p, 6, ",\n  "), p += 4;
    o << "  " << t << ",\n";
  }
  if (!job.empty()) o << "  \"job\": {\n    " << job << "\n  },\n";
  const std::vector<std::string> sides = sides_by_nesting(d, opt, warnings);
  o << "  \"entities\": [";
  size_t n = 0;
  for (const Contour& c : d.contours) {
    if (!keep.empty() && !keep.count(c.layer)) continue;
    const size_t k = n;
    o << (n++ ? ",\n" : "\n") << "    { \"id\": " << quoted(c.id) << ", ";
    if (k < sides.size() && !sides[k].empty()) o << "\"side\": \"" << sides[k] << "\", ";
    if (c.is_interpolation) {
      o << "\"type\": \"interpolate\", " << (c.interpolation.closed ? "\"closed\": true, " : "")
        << "\"through\": " << points(c.interpolation.through, scale) << " }";
      continue;
    }
    o << "\"type\": \"path\", " << (c.closed ? "\"closed\": true, " : "") << "\"segments\": [";
    for (size_t i = 0; i < c.pieces.size(); ++i) {
      const Piece& p = c.pieces[i];
      o << (i ? ",\n" : "\n") << "        { \"type\": \"" << (p.bspline ? "bspline" : "bezier") << "\", ";
      if (p.bspline) o << "\"degree\": " << p.degree << ", ";
      o << "\"points\": " << points(p.points, scale);
      if (!p.weights.empty()) o << ", \"weights\": " << numbers(p.weights);
      if (p.bspline) o << ", \"knots\": " << numbers(p.knots);
      o << " }";
    }
    o << " ] }";
  }
  if (n == 0)
    throw InputError(errc::import_empty, Place::at_file(d.source),
                     keep.empty() ? std::string("expected geometry to cut, found none")
                                  : "expected geometry to cut on the layers asked for, found none");
  o << "\n  ]\n}\n";
  return o.str();
}

}  // namespace

Job to_job(const Drawing& d, const ImportOptions& opt, std::vector<std::string>* warnings) {
  const std::string text = job_text(d, opt, warnings);
  JobReadOptions ro;
  ro.warnings = warnings;
  try {
    return parse_job(text, d.source, ro);
  } catch (const InputError& e) {
    // A refused setting is named by the option that gave it: the names
    // the refused path and the setting's key have in common (`--set lead`
    // for job.lead.lenght given whole, `--set tabs` for job.tabs.width
    // missing beside --set tabs.count).
    const std::string path = e.place().json_path.value_or("");
    const auto names = [](const std::string& p) {
      std::vector<std::string> out(1);
      for (const char c : p) {
        if (c == '.' || c == '[') out.emplace_back();
        else out.back() += c;
      }
      return out;
    };
    const std::vector<std::string> at = names(path.starts_with("job.") ? path.substr(4) : path);
    std::string best;
    for (const auto& [k, v] : opt.settings) {
      const std::vector<std::string> key = names(k);
      std::string common;
      for (size_t i = 0; i < key.size() && i < at.size() && key[i] == at[i]; ++i) common += (i ? "." : "") + key[i];
      if (common.empty() && path == "job" && e.message().find(quoted(k)) != std::string::npos) common = k;
      if (common.size() > best.size()) best = common;
    }
    if (!best.empty()) {
      Place where = Place::at_setting("settings." + best);
      where.file = d.source;
      throw InputError(e.id(), where, e.message());
    }
    throw;
  }
}

}  // namespace bezcam::import
