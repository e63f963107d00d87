// ASCII DXF, read group by group. Debian's libdime stores every coordinate
// as a float (dxfdouble is typedef'd to float in its headers, and the
// library is built so): a 7-digit reading of a drawing is not exact, so the
// groups are read here, each number parsed to the nearest double.
#include "bezcam/import/dxf_reader.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>

#include "bezcam/error.hpp"
#include "bezcam/import/conic.hpp"
#include "bezcam/kernel/knot_vector.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"
#include "bezcam/limits.hpp"
#include "dxf_reader_impl.hpp"

namespace bezcam::import::dxf {

void Reader::split(std::string_view text) {
  if (text.substr(0, 18) == "AutoCAD Binary DXF")
    throw InputError(errc::import_dxf_binary, Place::at_file(source_),
                     "expected an ASCII DXF, found a binary DXF (save it as ASCII DXF from the CAD program)");
  std::vector<std::pair<std::string_view, size_t>> lines;
  size_t n = 1;
  for (size_t p = 0; p < text.size();) {
    size_t e = text.find('\n', p);
    if (e == std::string_view::npos) e = text.size();
    std::string_view l = text.substr(p, e - p);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    lines.emplace_back(l, n++);
    p = e + 1;
  }
  const auto trim = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
  };
  for (size_t i = 0; i + 1 < lines.size() || (i < lines.size() && !trim(lines[i].first).empty()); i += 2) {
    const std::string_view c = trim(lines[i].first);
    int code = 0;
    const auto r = std::from_chars(c.data(), c.data() + c.size(), code);
    if (r.ec != std::errc() || r.ptr != c.data() + c.size() || c.empty()) {
      if (groups_.empty())
        throw InputError(errc::import_not_a_drawing, Place::at_file(source_),
                         "expected a DXF drawing (group code 0, then SECTION), found \"" +
                             std::string(c.substr(0, 20)) + "\" on line " + std::to_string(lines[i].second));
      fail(errc::import_dxf_syntax, lines[i].second,
           "expected a group code (an integer), found \"" + std::string(c.substr(0, 20)) + "\"");
    }
    if (i + 1 >= lines.size())
      fail(errc::import_dxf_syntax, lines[i].second,
           "the file ends after group code " + std::to_string(code) + ", before its value (truncated?)");
    std::string_view v = lines[i + 1].first;
    if (code == 999) continue;  // a comment (LibreCAD writes its name there)
    // Strings keep their spaces; numbers and names are trimmed.
    groups_.push_back({code, std::string(code == 1 || code == 3 ? v : trim(v)), lines[i].second});
  }
  if (groups_.empty() || !(groups_[0].code == 0 && groups_[0].value == "SECTION"))
    throw InputError(errc::import_not_a_drawing, Place::at_file(source_),
                     "expected a DXF drawing (group code 0, then SECTION), found " +
                         (groups_.empty() ? std::string("no groups") : "\"" + groups_[0].value.substr(0, 20) + "\""));
  const Group& last = groups_.back();
  if (!(last.code == 0 && last.value == "EOF"))
    fail(errc::import_dxf_syntax, last.line,
         "expected the file to end with group 0 EOF, found group code " + std::to_string(last.code) + " \"" +
             last.value.substr(0, 20) + "\" (the file is truncated)");
}

Entity Reader::entity() {
  Entity e;
  e.type = groups_[at_].value;
  e.line = groups_[at_].line;
  for (++at_; at_ < groups_.size() && groups_[at_].code != 0; ++at_) e.groups.push_back(groups_[at_]);
  if (e.type == "POLYLINE") {
    while (at(0, "VERTEX")) e.vertices.push_back(entity());
    if (at(0, "SEQEND")) entity();
  }
  return e;
}

void Reader::header() {
  for (; at_ < groups_.size() && !at(0, "ENDSEC"); ++at_) {
    if (groups_[at_].code == 9 && groups_[at_].value == "$INSUNITS" && at_ + 1 < groups_.size()) {
      const Group& g = groups_[at_ + 1];
      static const std::map<std::string, double> mm = {
          {"0", 1},     {"1", 25.4},  {"2", 304.8},   {"3", 1609344}, {"4", 1},      {"5", 10},
          {"6", 1000},  {"7", 1e6},   {"8", 2.54e-5}, {"9", 0.0254},  {"10", 914.4}, {"11", 1e-7},
          {"12", 1e-6}, {"13", 1e-3}, {"14", 100},    {"15", 1e4},    {"16", 1e5}};
      const auto it = mm.find(g.value);
      if (g.code != 70 || it == mm.end())
        fail(errc::import_units, g.line,
             "$INSUNITS, group code " + std::to_string(g.code) +
                 ": expected units 0 to 16 (0 unitless, 1 inch, 4 mm, 5 cm, 6 m ...), found \"" + g.value + "\"");
      unit_ = it->second;
      static const char* const names[] = {"",          "inch",       "foot",      "mile",      "mm",        "cm",
                                          "m",         "km",         "microinch", "mil",       "yard",      "angstrom",
                                          "nanometre", "micrometre", "decimetre", "decametre", "hectometre"};
      const int code = std::stoi(g.value);
      d_.mm_per_unit = unit_;
      d_.declared_units = names[code];
      if (code != 0) d_.declared_units += " ($INSUNITS " + g.value + ")";
      d_.declared_mm = code == 0 ? 0 : unit_;
    }
  }
}

void Reader::blocks() {
  while (at_ < groups_.size() && !at(0, "ENDSEC")) {
    if (!at(0, "BLOCK")) {
      ++at_;
      continue;
    }
    Entity head = entity();
    Block b;
    for (const Group& g : head.groups)
      if (g.code == 2) b.name = g.value;
    b.base = vec(head, 10);
    while (at_ < groups_.size() && !at(0, "ENDBLK") && !at(0, "ENDSEC")) b.entities.push_back(entity());
    if (at(0, "ENDBLK")) entity();
    blocks_[b.name] = std::move(b);
  }
}

// The arbitrary axis algorithm (DXF reference, "Object Coordinate
// Systems"): the OCS's x and y axes from the extrusion direction N, as the
// xy part of an affine map (elevation along N included).
Affine ocs(const Vec3& n_in, double elevation) {
  const double len = norm(n_in);
  const Vec3 n = len > 0 ? n_in / len : Vec3{0, 0, 1};
  Vec3 ax = (std::abs(n.x) < 1.0 / 64 && std::abs(n.y) < 1.0 / 64) ? cross(Vec3{0, 1, 0}, n) : cross(Vec3{0, 0, 1}, n);
  ax = ax / norm(ax);
  const Vec3 ay = cross(n, ax);
  return {ax.x, ax.y, ay.x, ay.y, elevation * n.x, elevation * n.y};
}

void Reader::add(Contour c, const Affine& m, const std::string& kind) {
  for (Piece& p : c.pieces)
    for (Vec3& q : p.points) q = m.apply(q) * unit_, q.z = 0;
  for (Vec3& q : c.interpolation.through) q = m.apply(q) * unit_, q.z = 0;
  // A piece whose control points coincide (an INSERT scaled by 0, a
  // polyline of one vertex) cuts nothing.
  std::erase_if(c.pieces, [](const Piece& p) {
    return std::all_of(p.points.begin(), p.points.end(), [&](const Vec3& q) { return q == p.points.front(); });
  });
  if (c.pieces.empty() && !c.is_interpolation) {
    d_.layers[c.layer].skipped[kind + " of size 0"] += 1;
    return;
  }
  for (const Piece& p : c.pieces)
    for (const Vec3& q : p.points)
      if (!std::isfinite(q.x) || !std::isfinite(q.y))
        throw InputError(errc::import_not_finite, Place::at_file(source_),
                         c.element + ": expected finite coordinates once placed (units, insert scales), found " +
                             fmt_num(q.x) + ", " + fmt_num(q.y));
  // Blocks inserting blocks many times multiply: stop long before memory.
  if (d_.contours.size() >= 10 * kMaxEntities)
    throw InputError(errc::limit_entities, Place::at_file(source_),
                     c.element + ": the drawing expands to more than " + std::to_string(10 * kMaxEntities) +
                         " curves (blocks inserted in blocks); bezcam reads at most " + std::to_string(kMaxEntities) +
                         " entities");
  // Joints meet exactly.
  for (size_t i = 1; i < c.pieces.size(); ++i)
    if (!c.pieces[i].bspline) c.pieces[i].points.front() = c.pieces[i - 1].end();
  if (c.closed && !c.pieces.empty() && !c.pieces.back().bspline)
    c.pieces.back().points.back() = c.pieces.front().start();
  d_.layers[c.layer].read[kind] += 1;
  d_.contours.push_back(std::move(c));
}

// A polyline's segment from a to b with bulge `bulge` (tan of a quarter of
// the included angle, positive counter-clockwise).
std::vector<Piece> bulge_segment(const Vec3& a, const Vec3& b, double bulge) {
  if (bulge == 0 || (a.x == b.x && a.y == b.y)) return {line_piece(a, b)};
  const double theta = 4 * std::atan(bulge);
  const Vec3 chord = b - a;
  const double dl = norm(chord);
  const Vec3 mid = (a + b) / 2, left{-chord.y / dl, chord.x / dl, 0};
  const Vec3 c = mid + left * (dl / 2 * (1 - bulge * bulge) / (2 * bulge));
  const double r = dist(a, c);
  std::vector<Piece> ps = ellipse_arc(c, {r, 0, 0}, {0, r, 0}, std::atan2(a.y - c.y, a.x - c.x), theta);
  ps.front().points.front() = a;
  ps.back().points.back() = b;
  return ps;
}

// A spline given by fit points and both end tangents, as CAD programs
// define it (and ezdxf's fit_points_to_cad_cv): the cubic B-spline through
// the points by global interpolation with end derivatives (The NURBS Book,
// 9.2.2), chord-length parameters on [0, 1], the inner parameters as its
// inner knots, each end derivative the tangent's direction times the total
// chord length. Empty when two consecutive points are equal.
std::optional<Piece> fit_spline(const std::vector<Vec3>& q, Vec3 t0, Vec3 t1) {
  const size_t n = q.size() - 1;
  std::vector<double> t(n + 1, 0.0);
  double total = 0;
  for (size_t k = 1; k <= n; ++k) {
    const double dk = dist(q[k], q[k - 1]);
    if (!(dk > 0)) return std::nullopt;
    total += dk;
    t[k] = total;
  }
  for (double& v : t) v /= total;
  t[n] = 1;
  std::vector<double> u(4, 0.0);
  for (size_t k = 1; k < n; ++k) u.push_back(t[k]);
  u.insert(u.end(), 4, 1.0);
  const Vec3 d0 = t0 / norm(t0) * total, d1 = t1 / norm(t1) * total;
  // Rows: P0 = Q0; P1 - P0 = D0 u4 / 3; sum N_i(t_k) P_i = Q_k (k = 1..n-1);
  // P_{n+2} - P_{n+1} = Dn (1 - u_{m-4}) / 3; P_{n+2} = Qn. Banded (|c - r| <= 3),
  // totally positive: eliminated without pivoting.
  const size_t rows = n + 3;
  constexpr int w = 3;
  std::vector<std::array<double, 2 * w + 1>> a(rows);
  for (auto& r : a) r.fill(0);
  std::vector<Vec3> b(rows);
  const auto at = [&](size_t r, size_t c) -> double& {
    return a[r][static_cast<size_t>(static_cast<long>(c) - static_cast<long>(r) + w)];
  };
  at(0, 0) = 1, b[0] = q[0];
  at(1, 0) = -1, at(1, 1) = 1, b[1] = d0 * (u[4] / 3);
  for (size_t k = 1; k < n; ++k) {
    const int span = find_span(u, 3, t[k]);
    double nb[4];
    basis_functions(u, 3, span, t[k], nb);
    for (int j = 0; j < 4; ++j) {
      const size_t c = static_cast<size_t>(span - 3 + j);
      if (nb[j] != 0) at(k + 1, c) = nb[j];
    }
    b[k + 1] = q[k];
  }
  at(n + 1, n + 1) = -1, at(n + 1, n + 2) = 1, b[n + 1] = d1 * ((1 - u[u.size() - 5]) / 3);
  at(n + 2, n + 2) = 1, b[n + 2] = q[n];
  for (size_t i = 0; i < rows; ++i) {
    for (size_t r = i + 1; r < std::min(rows, i + w + 1); ++r) {
      const double f = at(r, i) / at(i, i);
      if (f == 0) continue;
      for (size_t c = i; c < std::min(rows, i + w + 1); ++c) at(r, c) -= f * at(i, c);
      b[r] -= b[i] * f;
    }
  }
  std::vector<Vec3> p(rows);
  for (size_t i = rows; i-- > 0;) {
    Vec3 v = b[i];
    for (size_t c = i + 1; c < std::min(rows, i + w + 1); ++c) v -= p[c] * at(i, c);
    p[i] = v / at(i, i);
  }
  Piece pc;
  pc.bspline = true;
  pc.degree = 3;
  pc.points = std::move(p);
  pc.knots = std::move(u);
  return pc;
}

void Reader::emit(const Entity& e, const Affine& m, const std::string& layer_in, const std::string& prefix) {
  // Entities on layer 0 of a block take the INSERT's layer.
  const std::string layer = (!prefix.empty() && e.layer() == "0") ? layer_in : e.layer();
  Contour c;
  c.layer = layer;
  c.id = layer + ":" + prefix + (e.handle().empty() ? "line" + std::to_string(e.line) : e.handle());
  c.element = e.type + (e.handle().empty() ? " on line " + std::to_string(e.line) : " (handle " + e.handle() + ")");
  // The extrusion direction (group codes 210, 220, 230), read and checked
  // for every entity.
  const Vec3 ext = vec(e, 210, {0, 0, 1});
  if (e.type == "LINE")
    emit_line(e, std::move(c), m);
  else if (e.type == "CIRCLE" || e.type == "ARC")
    emit_arc(e, std::move(c), m, ext);
  else if (e.type == "ELLIPSE")
    emit_ellipse(e, std::move(c), m, ext);
  else if (e.type == "LWPOLYLINE" || e.type == "POLYLINE")
    emit_polyline(e, std::move(c), m, ext);
  else if (e.type == "SPLINE")
    emit_spline(e, std::move(c), m);
  else if (e.type == "INSERT")
    emit_insert(e, m, ext, layer, prefix);
  else if (e.type == "TEXT" || e.type == "MTEXT")
    emit_text(e, m, layer, prefix, ext);
  else
    d_.layers[layer].skipped[e.type] += 1;
}

void Reader::emit_line(const Entity& e, Contour c, const Affine& m) {
  c.pieces.push_back(line_piece(vec(e, 10), vec(e, 11)));
  if (c.pieces[0].points[0].x == c.pieces[0].points[1].x && c.pieces[0].points[0].y == c.pieces[0].points[1].y) {
    d_.layers[c.layer].skipped["LINE of length 0"] += 1;
    return;
  }
  add(std::move(c), m, e.type);
}

void Reader::emit_arc(const Entity& e, Contour c, const Affine& m, const Vec3& ext) {
  const Vec3 ctr = vec(e, 10);
  const double r = num(e, 40);
  double t0 = 0, sweep = kTwoPi;
  if (e.type == "ARC") {
    t0 = num(e, 50) * kDegree;
    sweep = std::fmod(num(e, 51) * kDegree - t0, kTwoPi);
    if (sweep <= 0) sweep += kTwoPi;
  }
  if (!(r > 0)) {  // a point drawn as a circle cuts nothing (LibreCAD's library has such arcs)
    if (r < 0) fail(errc::import_dxf_syntax, e, nullptr, "expected a radius >= 0 (group code 40), found " + fmt_num(r));
    d_.layers[c.layer].skipped[e.type + " of radius 0"] += 1;
    return;
  }
  c.pieces = ellipse_arc({ctr.x, ctr.y, 0}, {r, 0, 0}, {0, r, 0}, t0, sweep);
  c.closed = e.type == "CIRCLE";
  add(std::move(c), m.after(ocs(ext, ctr.z)), e.type);
}

void Reader::emit_ellipse(const Entity& e, Contour c, const Affine& m, const Vec3& ext) {
  const Vec3 ctr = vec(e, 10), major = vec(e, 11);
  const double ratio = num(e, 40, 1), t0 = num(e, 41, 0), t1 = num(e, 42, kTwoPi);
  const Vec3 n = norm(ext) > 0 ? ext / norm(ext) : Vec3{0, 0, 1};
  const Vec3 minor = cross(n, major) * ratio;
  double sweep = t1 - t0;
  sweep = std::fmod(sweep, kTwoPi);
  if (sweep <= 0) sweep += kTwoPi;
  if (std::abs(t1 - t0) >= kTwoPi) sweep = kTwoPi;
  c.closed = std::abs(sweep - kTwoPi) < 1e-12;
  c.pieces = ellipse_arc(ctr, major, minor, t0, c.closed ? kTwoPi : sweep);
  add(std::move(c), m, e.type);
}

void Reader::emit_polyline(const Entity& e, Contour c, const Affine& m, const Vec3& ext) {
  std::vector<Vec3> vs;
  std::vector<double> bulges;
  if (e.type == "LWPOLYLINE") {
    for (const Group& g : e.groups) {
      if (g.code == 10)
        vs.push_back({number(e, g), 0, 0}), bulges.push_back(0);
      else if (g.code == 20 && !vs.empty())
        vs.back().y = number(e, g);
      else if (g.code == 42 && !vs.empty())
        bulges.back() = number(e, g);
    }
  } else {
    if ((integer(e, 70, 0) & (16 | 64)) != 0) {  // meshes are not curves
      d_.layers[c.layer].skipped["POLYLINE mesh"] += 1;
      return;
    }
    for (const Entity& v : e.vertices) {
      if ((integer(v, 70, 0) & 16) != 0) continue;  // a spline frame's control point
      vs.push_back(vec(v, 10));
      bulges.push_back(num(v, 42));
    }
  }
  const bool closed = (integer(e, 70, 0) & 1) != 0;
  for (size_t i = 0; i + 1 < vs.size() + (closed ? 1 : 0); ++i)
    for (Piece& p : bulge_segment(vs[i], vs[(i + 1) % vs.size()], bulges[i])) c.pieces.push_back(std::move(p));
  if (c.pieces.empty()) return;
  c.closed = closed;
  const double elevation = e.type == "LWPOLYLINE" ? num(e, 38) : vec(e, 10).z;
  add(std::move(c), m.after(ocs(ext, elevation)), e.type);
}

// A SPLINE's control points, knots and weights as a B-spline piece, checked
// as the job reader checks them (the place: the entity and its groups).
Piece Reader::spline_piece(const Entity& e, int degree, std::vector<Vec3> cps, std::vector<double> knots,
                           std::vector<double> weights) const {
  const Group* kg = nullptr;
  for (const Group& g : e.groups)
    if (g.code == 40) {
      if (kg && number(e, g) < number(e, *kg))
        fail(errc::import_knots, e, &g,
             "expected a knot >= " + kg->value + " (knots must not decrease), found " + g.value);
      kg = &g;
    }
  if (knots.size() != cps.size() + static_cast<size_t>(degree) + 1)
    fail(errc::import_knots, e, nullptr,
         "expected " + std::to_string(cps.size() + static_cast<size_t>(degree) + 1) + " knots (group code 40) for " +
             std::to_string(cps.size()) + " control points of degree " + std::to_string(degree) + ", found " +
             std::to_string(knots.size()));
  if (!weights.empty() && weights.size() != cps.size())
    fail(errc::import_knots, e, nullptr,
         "expected one weight (group code 41) per control point (" + std::to_string(cps.size()) + "), found " +
             std::to_string(weights.size()));
  if (std::all_of(weights.begin(), weights.end(), [&](double w) { return w == weights.front(); })) weights.clear();
  Piece p;
  p.bspline = true;
  p.degree = degree;
  p.points = std::move(cps);
  p.knots = std::move(knots);
  p.weights = std::move(weights);
  // Everything else the job reader would refuse (degree, weights,
  // knot multiplicity, an empty domain) is refused here, naming the entity.
  try {
    (void)NurbsCurve::make(p.degree, p.points, p.knots, p.weights);
  } catch (const Error& err) {
    fail(errc::import_knots, e, nullptr, err.where() + ": " + err.message());
  }
  return p;
}

void Reader::emit_spline(const Entity& e, Contour c, const Affine& m) {
  const int flags = integer(e, 70, 0);
  const int degree = integer(e, 71, 3, 1, kMaxBezierDegree);
  std::vector<Vec3> cps = points(e, 10);
  std::vector<double> knots = all(e, 40), weights = all(e, 41);
  if (!cps.empty()) {
    c.pieces.push_back(spline_piece(e, degree, std::move(cps), std::move(knots), std::move(weights)));
    c.closed =
        (flags & 1) != 0 && dist(c.pieces[0].start(), c.pieces[0].end()) <= 1e-9 * (1 + max_abs(c.pieces[0].start()));
  } else if (std::vector<Vec3> fit = points(e, 11);
             fit.size() >= 2 && has(e, 12) && has(e, 13) && norm(vec(e, 12)) > 0 && norm(vec(e, 13)) > 0) {
    std::optional<Piece> p = fit_spline(fit, vec(e, 12), vec(e, 13));
    if (!p)
      fail(errc::import_knots, e, nullptr,
           "expected fit points (group code 11) that differ from one to the next, found two equal in a row");
    c.pieces.push_back(std::move(*p));
    c.closed = (flags & 1) != 0 && dist(fit.front(), fit.back()) <= 1e-9 * (1 + max_abs(fit.front()));
  } else {
    // Without both end tangents the CAD program's curve is not defined by
    // the file: a natural cubic spline through the points (docs/import.md).
    c.is_interpolation = true;
    c.interpolation.through = points(e, 11);
    c.interpolation.closed = (flags & 1) != 0;
    if (c.interpolation.through.size() < 2)
      fail(errc::import_knots, e, nullptr,
           "expected control points (group code 10) or at least 2 fit points (11), found neither");
  }
  add(std::move(c), m, e.type);
}

void Reader::emit_insert(const Entity& e, const Affine& m, const Vec3& ext, const std::string& layer,
                         const std::string& prefix) {
  std::string name;
  const Group* ng = nullptr;
  for (const Group& g : e.groups)
    if (g.code == 2) name = g.value, ng = &g;
  const auto it = blocks_.find(name);
  if (it == blocks_.end())
    fail(errc::import_dxf_syntax, e, ng, "expected the name of a block, found \"" + name + "\", which no block has");
  if (std::find(inserting_.begin(), inserting_.end(), name) != inserting_.end() || inserting_.size() > 32)
    fail(errc::import_block_recursion, e, ng,
         "block \"" + name + "\" inserts itself (through " + std::to_string(inserting_.size()) +
             " level(s) of INSERT); expected a block that does not contain itself");
  const Block& b = it->second;
  const Vec3 ins = vec(e, 10), s{num(e, 41, 1), num(e, 42, 1), num(e, 43, 1)};
  const double rot = num(e, 50) * kDegree;
  const Affine local = ocs(ext, ins.z)
                           .after(Affine{1, 0, 0, 1, ins.x, ins.y})
                           .after(Affine{std::cos(rot), std::sin(rot), -std::sin(rot), std::cos(rot), 0, 0})
                           .after(Affine{s.x, 0, 0, s.y, 0, 0})
                           .after(Affine{1, 0, 0, 1, -b.base.x, -b.base.y});
  inserting_.push_back(name);
  d_.layers[layer].read["INSERT"] += 1;
  const std::string h = e.handle().empty() ? "line" + std::to_string(e.line) : e.handle();
  for (const Entity& be : b.entities) emit(be, m.after(local), layer, prefix + h + "/");
  inserting_.pop_back();
}

Drawing Reader::read() {
  d_.source = source_;
  d_.format = "dxf";
  while (at_ < groups_.size()) {
    if (at(0, "SECTION") && at_ + 1 < groups_.size() && groups_[at_ + 1].code == 2) {
      const std::string name = groups_[at_ + 1].value;
      at_ += 2;
      if (name == "HEADER")
        header();
      else if (name == "BLOCKS")
        blocks();
      else if (name == "TABLES")
        tables();
      else if (name == "ENTITIES")
        while (at_ < groups_.size() && !at(0, "ENDSEC")) {
          if (groups_[at_].code == 0)
            entities_.push_back(entity());
          else
            ++at_;
        }
      else
        while (at_ < groups_.size() && !at(0, "ENDSEC")) ++at_;
    }
    ++at_;
  }
  for (const Entity& e : entities_) emit(e, Affine{}, e.layer(), "");
  if (d_.contours.empty() && d_.texts.empty())
    throw InputError(errc::import_empty, Place::at_file(source_),
                     "expected geometry (LINE, ARC, CIRCLE, ELLIPSE, LWPOLYLINE, POLYLINE, SPLINE, INSERT, TEXT, "
                     "MTEXT), found none");
  return std::move(d_);
}

}  // namespace bezcam::import::dxf

namespace bezcam::import {

Drawing read_dxf(std::string_view text, const std::string& source) { return dxf::Reader(text, source).read(); }

}  // namespace bezcam::import
