// The only kernel file family that knows JSON: reads a version-1 curve file
// (docs/job-format.md) into a validated Job.
#include "bezcam/job/job_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "bezcam/job/job_builder.hpp"
#include "bezcam/job/keys.hpp"
#include "bezcam/job/settings.hpp"
#include "bezcam/job/tools.hpp"
#include "bezcam/limits.hpp"
#include "job_json_detail.hpp"

namespace bezcam {

namespace detail {

namespace {
// The JSON path (`entities[0].points[1][0]`) of the value that starts at
// byte `at` of `text`, which is well-formed JSON up to there: a scan that
// follows the containers, the keys and the array indices.
std::string json_path_at(std::string_view text, size_t at) {
  struct Level {
    bool array;
    size_t index = 0;
    std::string key;
  };
  std::vector<Level> levels;
  bool key_next = false;
  for (size_t i = 0; i < at && i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      std::string s;
      size_t j = i + 1;
      for (; j < text.size() && text[j] != '"'; ++j) {
        if (text[j] == '\\') ++j;
        if (j < text.size()) s += text[j];
      }
      if (key_next && !levels.empty() && !levels.back().array) levels.back().key = std::move(s), key_next = false;
      i = j;
    } else if (c == '{') {
      levels.push_back({false, 0, {}});
      key_next = true;
    } else if (c == '[') {
      levels.push_back({true, 0, {}});
    } else if ((c == '}' || c == ']') && !levels.empty()) {
      levels.pop_back();
    } else if (c == ',' && !levels.empty()) {
      if (levels.back().array)
        ++levels.back().index;
      else
        key_next = true;
    }
  }
  std::string path;
  for (const auto& l : levels) {
    if (l.array)
      path += "[" + std::to_string(l.index) + "]";
    else
      path += (path.empty() ? "" : ".") + l.key;
  }
  return path;
}
}  // namespace

std::string describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case json::value_t::string: {
      std::string s = v.get<std::string>();
      if (s.size() > 40) s = s.substr(0, 40) + "...";
      return "the string \"" + s + "\"";
    }
    case json::value_t::array:
      return v.empty() ? "an empty array"
                       : "an array of " + std::to_string(v.size()) + (v.size() == 1 ? " element" : " elements");
    case json::value_t::object: return "an object";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
    case json::value_t::number_float: return fmt_num(v.get<double>());
    default: return "a value of another kind";
  }
}

void JsonCtx::fail(const std::string& path, const std::string& id, const std::string& what) const {
  throw InputError(id, Place::in_json(source, path), what);
}
void JsonCtx::expected(const std::string& path, const std::string& what, const json& found) const {
  fail(path, errc::job_type, "expected " + what + ", found " + describe(found));
}
void JsonCtx::warn(const std::string& path, const std::string& what) const {
  if (warnings) warnings->push_back(source + ": " + path + ": " + what);
}
void JsonCtx::check_keys(const json& obj, const std::string& path, std::initializer_list<const char*> known) const {
  check_keys(obj, path, std::vector<std::string_view>(known.begin(), known.end()));
}
void JsonCtx::check_keys(const json& obj, const std::string& path, const std::vector<std::string_view>& known) const {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string& key = it.key();
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    if (user_key(key)) continue;
    const std::string at = path.empty() ? key : path + "." + key;
    const UnknownKey u = unknown_key(key, known);
    InputError e(u.typo ? errc::job_key_typo : errc::job_unknown_key, Place::in_json(source, at), u.message);
    if (!errors) throw e;
    errors->push_back(e);
  }
}
const json& JsonCtx::require(const json& obj, const std::string& path, const char* key) const {
  auto it = obj.find(key);
  if (it == obj.end())
    fail(path.empty() ? key : path + "." + key, errc::job_missing,
         std::string("the required key \"") + key + "\" is missing; add it");
  return *it;
}
double JsonCtx::number(const json& v, const std::string& path) const {
  if (!v.is_number()) expected(path, "a number", v);
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(path, errc::job_not_finite, "expected a finite number, found " + fmt_num(d));
  return d;
}
double JsonCtx::positive(const json& v, const std::string& path) const {
  const double d = number(v, path);
  if (!(d > 0)) fail(path, errc::job_not_positive, "expected a number > 0, found " + fmt_num(d));
  return d;
}
int JsonCtx::integer(const json& v, const std::string& path) const {
  if (!v.is_number_integer() && !(v.is_number_float() && std::nearbyint(v.get<double>()) == v.get<double>()))
    expected(path, "an integer", v);
  const double d = v.get<double>();
  if (std::abs(d) > 1e9) fail(path, errc::job_range, "expected an integer of at most 1e9, found " + fmt_num(d));
  return static_cast<int>(d);
}
std::string JsonCtx::string(const json& v, const std::string& path) const {
  if (!v.is_string()) expected(path, "a string", v);
  return v.get<std::string>();
}
bool JsonCtx::boolean(const json& v, const std::string& path) const {
  if (!v.is_boolean()) expected(path, "true or false", v);
  return v.get<bool>();
}
const json& JsonCtx::array(const json& v, const std::string& path, size_t min_size) const {
  const std::string at_least =
      "an array of at least " + std::to_string(min_size) + (min_size == 1 ? " element" : " elements");
  if (!v.is_array()) expected(path, min_size ? at_least : "an array", v);
  if (v.size() < min_size) expected(path, at_least, v);
  return v;
}
Vec3 JsonCtx::point(const json& v, const std::string& path, int* dim) const {
  if (!v.is_array() || (v.size() != 2 && v.size() != 3)) expected(path, "a point [x, y] or [x, y, z]", v);
  const int d = static_cast<int>(v.size());
  if (*dim == 0) *dim = d;
  if (d != *dim)
    fail(path, errc::job_dimension,
         "expected a " + std::to_string(*dim) + "D point like the entity's first point, found a " + std::to_string(d) +
             "D point");
  Vec3 p;
  for (int k = 0; k < d; ++k) p[k] = number(v[k], path + "[" + std::to_string(k) + "]");
  return p;
}
std::vector<Vec3> JsonCtx::points(const json& v, const std::string& path, int* dim, size_t min_size) const {
  array(v, path, min_size);
  count_points(v.size(), path);
  std::vector<Vec3> out;
  out.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) out.push_back(point(v[i], path + "[" + std::to_string(i) + "]", dim));
  return out;
}
std::vector<double> JsonCtx::numbers(const json& v, const std::string& path) const {
  array(v, path);
  std::vector<double> out;
  out.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) out.push_back(number(v[i], path + "[" + std::to_string(i) + "]"));
  return out;
}

void JsonCtx::count_points(std::size_t n, const std::string& path) const {
  entity_points += n;
  if (entity_points > kMaxEntityPoints)
    fail(path, errc::limit_points,
         "expected at most " + std::to_string(kMaxEntityPoints) + " points in one entity (docs/limits.md), found " +
             (entity_points == n ? std::to_string(n) : std::to_string(entity_points) + " with these") +
             "; split the geometry into several entities");
}
void JsonCtx::count_bezier_points(std::size_t n, const std::string& path) const {
  job_points += n;
  if (job_points > kMaxJobPoints)
    fail(path, errc::limit_points,
         "the job's curves and patches need " + std::to_string(job_points) +
             " control points in their exact Bézier form with this one, more than the limit of " +
             std::to_string(kMaxJobPoints) + " (docs/limits.md); split the job into several files");
}

json parse_json_text(std::string_view text, const std::string& source) {
  try {
    return json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    // Turn the byte offset into line and column.
    size_t line = 1, col = 1;
    for (size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n')
        ++line, col = 1;
      else
        ++col;
    }
    // nlohmann's text repeats the line and column: keep what follows them.
    std::string what = e.what();
    if (auto p = what.find("column "); p != std::string::npos && what.find(": ", p) != std::string::npos)
      what = what.substr(what.find(": ", p) + 2);
    std::string hint;
    if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
      hint = "; the file is empty";
    else if (what.find("unexpected end of input") != std::string::npos)
      hint = "; the file ends too early (is a closing bracket or brace missing?)";
    else if (what.find("unexpected") != std::string::npos && what.find("literal") != std::string::npos &&
             (what.find("expected '}'") != std::string::npos || what.find("expected ']'") != std::string::npos))
      hint = "; is a comma missing before it?";
    Place where = Place::at_file(source);
    where.line = static_cast<long long>(line);
    where.column = static_cast<long long>(col);
    throw InputError(errc::job_syntax, std::move(where), "this is not valid JSON: " + what + hint);
  } catch (const json::out_of_range& e) {
    // The only range error while parsing: a number too large for a double
    // (JSON has no NaN or infinity, so this is how non-finite values come).
    std::string what = e.what(), token;
    if (auto a = what.find('\''), b = what.rfind('\''); a != std::string::npos && b > a)
      token = what.substr(a + 1, b - a - 1);
    Place where = Place::at_file(source);
    if (const size_t at = token.empty() ? std::string_view::npos : text.find(token); at != std::string_view::npos) {
      size_t line = 1, col = 1;
      for (size_t i = 0; i < at; ++i) {
        if (text[i] == '\n')
          ++line, col = 1;
        else
          ++col;
      }
      // The document did not parse, so its path comes from the text.
      if (std::string path = detail::json_path_at(text, at); !path.empty()) where.json_path = std::move(path);
      where.line = static_cast<long long>(line);
      where.column = static_cast<long long>(col);
    }
    throw InputError(errc::job_not_finite, std::move(where),
                     "expected a finite number, found " + (token.empty() ? std::string("a number") : token) +
                         ", which is too large for a double (about 1.8e308 at most)");
  }
}

CurveSegment parse_curve_object(const JsonCtx& ctx, const json& obj, const std::string& path, int* dim,
                                std::vector<Bezier>& pieces, bool in_path) {
  if (!obj.is_object()) ctx.expected(path, "a curve object", obj);
  const std::string type = ctx.string(ctx.require(obj, path, "type"), path + ".type");
  CurveSegment seg;
  seg.kind = type;
  seg.first_piece = pieces.size();
  if (type == "bezier") {
    if (in_path) ctx.check_keys(obj, path, {"type", "points", "weights"});
    auto pts = ctx.points(ctx.require(obj, path, "points"), path + ".points", dim, 2);
    std::vector<double> w;
    if (obj.contains("weights")) w = ctx.numbers(obj["weights"], path + ".weights");
    ctx.count_bezier_points(pts.size(), path + ".points");
    pieces.push_back(ctx.at(path, [&] { return Bezier::make(std::move(pts), std::move(w), *dim); }));
    seg.degree = pieces.back().degree();
    seg.rational = pieces.back().rational();
  } else if (type == "bspline") {
    if (in_path) ctx.check_keys(obj, path, {"type", "degree", "points", "knots", "weights"});
    parse_bspline_segment(ctx, obj, path, dim, pieces, seg);
  } else {
    ctx.fail(path + ".type", errc::job_segment_type,
             std::string("expected \"bezier\" or \"bspline\"") + (in_path ? " in a path" : "") + ", found " +
                 describe(obj["type"]));
  }
  seg.piece_count = pieces.size() - seg.first_piece;
  return seg;
}

namespace {

// One of `names` (the enum's values in order), or a refusal listing them.
template <class E, size_t N>
std::optional<E> choice(const JsonCtx& ctx, const json& obj, const std::string& path, const char* key,
                        const std::array<const char*, N>& names) {
  auto it = obj.find(key);
  if (it == obj.end()) return std::nullopt;
  const std::string kp = path.empty() ? key : path + "." + key;
  const std::string v = ctx.string(*it, kp);
  std::string list;
  for (size_t i = 0; i < N; ++i) {
    if (v == names[i]) return static_cast<E>(i);
    list += std::string(i == 0 ? "" : i + 1 == N ? " or " : ", ") + "\"" + names[i] + "\"";
  }
  ctx.fail(kp, errc::job_cut, "expected " + list + ", found " + describe(*it));
}

JobParams parse_params(const JsonCtx& ctx, const json& obj, const std::string& path, bool entity_level) {
  JobParams p;
  auto num = [&](const char* key, std::optional<double>& out, bool must_be_positive) {
    auto it = obj.find(key);
    if (it == obj.end()) return;
    const std::string kp = path.empty() ? key : path + "." + key;
    out = must_be_positive ? ctx.positive(*it, kp) : ctx.number(*it, kp);
  };
  num("feed", p.feed, true);
  num("plunge_feed", p.plunge_feed, true);
  num("safe_z", p.safe_z, false);
  num("cut_z", p.cut_z, false);
  num("spindle_rpm", p.spindle_rpm, false);
  num("tool_radius", p.tool_radius, false);
  if (p.spindle_rpm && *p.spindle_rpm < 0)
    ctx.fail(path + ".spindle_rpm", errc::job_range, "expected a speed >= 0, found " + fmt_num(*p.spindle_rpm));
  if (p.tool_radius && *p.tool_radius < 0)
    ctx.fail(path + ".tool_radius", errc::job_range, "expected a radius >= 0, found " + fmt_num(*p.tool_radius));
  if (auto it = obj.find("gouge"); it != obj.end()) {
    const std::string kp = path.empty() ? "gouge" : path + ".gouge";
    const std::string g = ctx.string(*it, kp);
    if (g == "refuse")
      p.gouge = GougePolicy::refuse;
    else if (g == "skip")
      p.gouge = GougePolicy::skip;
    else
      ctx.fail(kp, errc::job_gouge, "expected \"refuse\" or \"skip\", found " + describe(*it));
  }
  if (auto it = obj.find("coolant"); it != obj.end()) {
    const std::string kp = path.empty() ? "coolant" : path + ".coolant";
    p.coolant = coolant_from(ctx.string(*it, kp));
    if (!p.coolant) ctx.fail(kp, errc::job_coolant, "expected \"flood\", \"mist\" or \"off\", found " + describe(*it));
  }
  if (auto it = obj.find("tool"); it != obj.end()) {
    p.tool = ctx.integer(*it, path + ".tool");
    if (*p.tool < 0)
      ctx.fail(path + ".tool", errc::job_range, "expected a tool number >= 0, found " + std::to_string(*p.tool));
  }
  num("clearance", p.clearance, false);
  num("top_z", p.top_z, false);
  if (p.clearance && *p.clearance < 0)
    ctx.fail(path + ".clearance", errc::job_range,
             "expected a height >= 0 above top_z, found " + fmt_num(*p.clearance));
  auto sequence = [&](const char* key, std::optional<std::vector<std::string>>& out) {
    auto it = obj.find(key);
    if (it == obj.end()) return;
    const std::string kp = path.empty() ? key : path + "." + key;
    std::vector<std::string> lines;
    if (it->is_string()) {
      lines.push_back(it->get<std::string>());
    } else {
      const json& a = ctx.array(*it, kp);
      for (size_t i = 0; i < a.size(); ++i) lines.push_back(ctx.string(a[i], kp + "[" + std::to_string(i) + "]"));
    }
    for (size_t i = 0; i < lines.size(); ++i) {
      const std::string at = it->is_string() ? kp : kp + "[" + std::to_string(i) + "]";
      if (auto why = template_problem(lines[i], kEntityPlaceholders)) ctx.fail(at, errc::job_template, *why);
    }
    out = std::move(lines);
  };
  sequence("before", p.before);
  sequence("after", p.after);
  // Part cutting (docs/job-format.md, "Cutting a part, not only a curve").
  p.side = choice<CutSide>(ctx, obj, path, "side", std::array{"on", "left", "right", "inside", "outside"});
  p.direction = choice<CutDirection>(ctx, obj, path, "direction", std::array{"as-drawn", "climb", "conventional"});
  p.tolerance_side =
      choice<ToleranceSide>(ctx, obj, path, "tolerance_side", std::array{"both", "left", "right", "waste"});
  if (auto c = choice<int>(ctx, obj, path, "compensation", std::array{"cam", "controller"}))
    p.controller_compensation = *c == 1;
  num("tool_diameter", p.tool_diameter, true);
  num("stock_to_leave", p.stock_to_leave, false);
  num("step_down", p.step_down, true);
  auto sub = [&](const char* key) { return path.empty() ? std::string(key) : path + "." + key; };
  if (auto it = obj.find("lead"); it != obj.end()) {
    const std::string kp = sub("lead");
    if (!it->is_object()) ctx.expected(kp, "an object {\"radius\": R, \"length\": L}", *it);
    ctx.check_keys(*it, kp, std::vector<std::string_view>(kLeadKeys.begin(), kLeadKeys.end()));
    Lead l;
    l.radius = ctx.positive(ctx.require(*it, kp, "radius"), kp + ".radius");
    l.length = it->contains("length") ? ctx.number((*it)["length"], kp + ".length") : 0;
    if (l.length < 0) ctx.fail(kp + ".length", errc::job_cut, "expected a length >= 0, found " + fmt_num(l.length));
    p.lead = l;
  }
  if (auto it = obj.find("tabs"); it != obj.end()) {
    const std::string kp = sub("tabs");
    if (!it->is_object()) ctx.expected(kp, "an object {\"count\": N, \"width\": W, \"height\": H}", *it);
    ctx.check_keys(*it, kp, std::vector<std::string_view>(kTabsKeys.begin(), kTabsKeys.end()));
    Tabs t;
    t.count = static_cast<int>(ctx.integer(ctx.require(*it, kp, "count"), kp + ".count"));
    if (t.count < 1)
      ctx.fail(kp + ".count", errc::job_cut, "expected at least 1 tab, found " + std::to_string(t.count));
    t.width = ctx.positive(ctx.require(*it, kp, "width"), kp + ".width");
    t.height = ctx.positive(ctx.require(*it, kp, "height"), kp + ".height");
    p.tabs = t;
  }
  p.pocket = parse_pocket_keys(ctx, obj, path);
  p.drill = parse_drill_keys(ctx, obj, path);
  if (!entity_level) {
    std::vector<std::string_view> keys(kParamKeys.begin(), kParamKeys.end());
    if (path != "job") keys.pop_back();  // `order` is the job's
    if (path == "job") keys.push_back("program_number");
    ctx.check_keys(obj, path, keys);
  }
  if (p.safe_z && p.cut_z && *p.cut_z >= *p.safe_z)
    ctx.fail(path + ".cut_z", errc::job_range,
             "expected cut_z below safe_z (" + fmt_num(*p.safe_z) + "), found " + fmt_num(*p.cut_z));
  return p;
}

// The entity at `index` of the file, appended to `out` (a text: its glyph
// contours, job_json_text.cpp).
void parse_entity(const JsonCtx& ctx, const json& obj, size_t index, std::vector<Entity>& out) {
  const std::string path = "entities[" + std::to_string(index) + "]";
  if (!obj.is_object()) ctx.expected(path, "an entity object", obj);
  Entity e;
  e.index = index;
  ctx.entity_points = 0;
  e.type = ctx.string(ctx.require(obj, path, "type"), path + ".type");
  if (auto it = obj.find("id"); it != obj.end()) e.id = ctx.string(*it, path + ".id");
  e.params = parse_params(ctx, obj, path, true);
  auto keys = [&](std::initializer_list<const char*> own) {
    std::vector<std::string_view> all(own.begin(), own.end());
    all.insert(all.end(), kParamKeys.begin(), kParamKeys.end() - 1);  // `order` is the job's
    all.push_back("id");
    all.push_back("type");
    ctx.check_keys(obj, path, all);
  };
  int dim = 0;
  if (e.type == "bezier" || e.type == "bspline") {
    keys({"points", "weights", "degree", "knots"});
    std::vector<Bezier> pieces;
    CurveSegment seg = parse_curve_object(ctx, obj, path, &dim, pieces, false);
    e.curve = make_single(seg, std::move(pieces), dim);
  } else if (e.type == "path") {
    keys({"segments", "closed"});
    const json& segs = ctx.array(ctx.require(obj, path, "segments"), path + ".segments", 1);
    std::vector<Bezier> pieces;
    std::vector<CurveSegment> ss;
    for (size_t i = 0; i < segs.size(); ++i)
      ss.push_back(parse_curve_object(ctx, segs[i], path + ".segments[" + std::to_string(i) + "]", &dim, pieces, true));
    bool closed = false;
    if (obj.contains("closed")) closed = ctx.boolean(obj["closed"], path + ".closed");
    e.curve = ctx.at(path, [&] { return make_path(std::move(ss), std::move(pieces), closed, dim); });
  } else if (e.type == "interpolate") {
    keys({"through", "method", "closed", "tangents", "end_tangents"});
    parse_interpolate_entity(ctx, obj, path, e);
  } else if (e.type == "bezier_patch") {  // surfaces: job_json_surfaces.cpp
    keys({"points", "weights", "toolpath"});
    parse_bezier_patch_entity(ctx, obj, path, e);
  } else if (e.type == "coons_patch") {
    keys({"boundaries", "blend", "toolpath"});
    parse_coons_patch_entity(ctx, obj, path, e);
  } else if (e.type == "curve_on_surface") {
    keys({"surface", "curve"});
    parse_curve_on_surface_entity(ctx, obj, path, e);
  } else if (e.type == "point") {
    keys({"at"});
    const json& at = ctx.require(obj, path, "at");
    if (!at.is_array() || at.size() != 2) ctx.expected(path + ".at", "a point [x, y]", at);
    e.point = ctx.point(at, path + ".at", &dim);
  } else if (e.type == "text") {
    keys({"text", "font", "size", "at", "align", "angle"});
    parse_text_entity(ctx, obj, path, e, out);
    return;
  } else {
    ctx.fail(path + ".type", errc::job_entity_type,
             "expected one of \"bezier\", \"bspline\", \"path\", \"interpolate\", \"bezier_patch\", "
             "\"coons_patch\", \"curve_on_surface\", \"text\", \"point\", found " +
                 describe(obj["type"]));
  }
  out.push_back(std::move(e));
}

}  // namespace
}  // namespace detail

JobParams JobParams::over(const JobParams& base) const {
  JobParams r = base;
  if (feed) r.feed = feed;
  if (plunge_feed) r.plunge_feed = plunge_feed;
  if (safe_z) r.safe_z = safe_z;
  if (cut_z) r.cut_z = cut_z;
  if (spindle_rpm) r.spindle_rpm = spindle_rpm;
  if (tool_radius) r.tool_radius = tool_radius;
  if (tool) r.tool = tool;
  if (gouge) r.gouge = gouge;
  if (coolant) r.coolant = coolant;
  if (clearance) r.clearance = clearance;
  if (top_z) r.top_z = top_z;
  if (before) r.before = before;
  if (after) r.after = after;
  if (side) r.side = side;
  if (tool_diameter) r.tool_diameter = tool_diameter;
  if (stock_to_leave) r.stock_to_leave = stock_to_leave;
  if (step_down) r.step_down = step_down;
  if (direction) r.direction = direction;
  if (lead) r.lead = lead;
  if (tabs) r.tabs = tabs;
  if (controller_compensation) r.controller_compensation = controller_compensation;
  if (tolerance_side) r.tolerance_side = tolerance_side;
  r.pocket = pocket.over(base.pocket);
  r.drill = drill.over(base.drill);
  return r;
}

std::optional<Coolant> coolant_from(std::string_view text) {
  for (Coolant c : {Coolant::off, Coolant::mist, Coolant::flood})
    if (text == to_string(c)) return c;
  return std::nullopt;
}

const char* to_string(Coolant c) {
  switch (c) {
    case Coolant::off: return "off";
    case Coolant::mist: return "mist";
    case Coolant::flood: return "flood";
  }
  return "off";
}

namespace {

// The job's settings: the top-level units, tolerance and machine, the
// `job` object's cutting parameters and program number, the order.
void read_settings(detail::JsonCtx& ctx, const detail::json& doc, Job& job) {
  using detail::json;
  if (auto it = doc.find("units"); it != doc.end()) {
    const std::string u = ctx.string(*it, "units");
    if (u == "mm")
      job.units = Units::mm;
    else if (u == "inch")
      job.units = Units::inch;
    else
      ctx.fail("units", errc::job_units, "expected \"mm\" or \"inch\", found " + detail::describe(*it));
  }
  job.tolerance = kDefaultToleranceMm / mm_per_unit(job.units);
  if (auto it = doc.find("tolerance"); it != doc.end()) job.tolerance = ctx.positive(*it, "tolerance");
  if (auto it = doc.find("machine"); it != doc.end()) job.machine = ctx.string(*it, "machine");
  if (auto it = doc.find("job"); it != doc.end()) {
    if (!it->is_object()) ctx.expected("job", "an object", *it);
    job.params = detail::parse_params(ctx, *it, "job", false);
    if (auto pn = it->find("program_number"); pn != it->end()) {
      const long n = ctx.integer(*pn, "job.program_number");
      if (n < 1 || n > 99999999)
        ctx.fail("job.program_number", errc::job_range,
                 "expected a program number from 1 to 99999999, found " + std::to_string(n));
      job.program_number = n;
    }
  }
  for (const std::string where : {"order", "job.order"}) {
    const json* o = where == "order"
                        ? (doc.contains("order") ? &doc["order"] : nullptr)
                        : (doc.contains("job") && doc["job"].contains("order") ? &doc["job"]["order"] : nullptr);
    if (!o) continue;
    const std::string v = ctx.string(*o, where);
    if (v != "shortest" && v != "as-written")
      ctx.fail(where, errc::job_cut, "expected \"as-written\" or \"shortest\", found " + detail::describe(*o));
    job.order_shortest = v == "shortest";
  }
}

void parse_document(std::string_view text, const std::string& source, detail::JsonCtx& ctx, Job& job,
                    std::vector<InputError>& errors) {
  using detail::json;
  if (text.size() > kMaxJobBytes)
    throw InputError(errc::limit_file_size, Place::at_file(source),
                     "the job file is " + std::to_string(text.size() >> 20) + " MiB, more than bezcam reads (" +
                         std::to_string(kMaxJobBytes >> 20) + " MiB, docs/limits.md); split it into smaller files");
  json doc = detail::parse_json_text(text, source);
  if (!doc.is_object()) ctx.expected("(top level)", "a JSON object", doc);
  ctx.check_keys(doc, "", {"bezcam", "units", "tolerance", "machine", "job", "entities", "order", "tools"});
  if (!doc.contains("bezcam"))
    ctx.fail("bezcam", errc::job_missing,
             "the file does not say its format version; add \"bezcam\": 1 at the top level (is this a bezcam job?)");
  const json& ver = ctx.require(doc, "", "bezcam");
  job.version = ctx.integer(ver, "bezcam");
  if (job.version != 1)
    ctx.fail("bezcam", errc::job_version, "expected format version 1, found " + std::to_string(job.version));
  read_settings(ctx, doc, job);
  if (auto it = doc.find("tools"); it != doc.end()) job.tools = detail::parse_tools_object(ctx, *it, "tools", errors);
  (void)ctx.array(ctx.require(doc, "", "entities"), "entities", 1);
  json& ents = doc["entities"];
  const auto given = detail::apply_entity_settings(ctx, ents);
  if (ents.size() > kMaxEntities)
    ctx.fail("entities", errc::limit_entities,
             "expected at most " + std::to_string(kMaxEntities) + " entities in one job (docs/limits.md), found " +
                 std::to_string(ents.size()) + "; split the job into several files");
  // Entities are independent: a refused one does not hide the next.
  for (size_t i = 0; i < ents.size(); ++i) {
    std::vector<Entity> read;
    try {
      detail::parse_entity(ctx, ents[i], i, read);
    } catch (const InputError& e) {
      errors.push_back(detail::at_entity_setting(e, i, given, source));
      continue;
    }
    if (job.entities.size() + read.size() > kMaxEntities)  // a text's glyphs
      ctx.fail("entities[" + std::to_string(i) + "]", errc::limit_entities,
               "expected at most " + std::to_string(kMaxEntities) +
                   " entities in one job (docs/limits.md), found more with the glyphs of this text; split the job "
                   "into several files");
    for (Entity& e : read) {
      e.index = job.entities.size();
      if (e.index != i) e.file_index = i;
      job.entities.push_back(std::move(e));
    }
  }
  if (!errors.empty()) return;
  detail::resolve_surface_references(ctx, ents, job);  // curve_on_surface naming a patch by id
  (void)job_tools(job);                                // one diameter and shape per tool number
}

}  // namespace

Job parse_job(std::string_view text, const std::string& source, const JobReadOptions& opt) {
  Job job;
  job.source = source;
  std::vector<InputError> errors;
  detail::JsonCtx ctx{source, &job.warnings};
  ctx.errors = &errors;
  ctx.options = &opt;
  ctx.job_params = &job.params;
  try {
    parse_document(text, source, ctx, job, errors);
  } catch (const InputError& e) {
    errors.push_back(e);  // a refusal that stops the reading: the last one
  }
  if (errors.empty()) return job;
  if (opt.warnings) *opt.warnings = job.warnings;
  InputError first = errors.front();
  for (size_t i = 1; i < errors.size(); ++i) first.add_more(errors[i]);
  throw first;
}

JobBuilder& JobBuilder::settings(std::span<const std::pair<std::string, std::string>> settings) {
  using detail::json;
  const SettingsJson given = settings_json(settings);
  // The settings as the members of a job document: each value is JSON text.
  json doc = json::object();
  for (const auto& [k, v] : given.top) doc[k] = json::parse(v);
  if (!given.job.empty()) {
    doc["job"] = json::object();
    for (const auto& [k, v] : given.job) doc["job"][k] = json::parse(v);
  }
  std::vector<InputError> errors;
  detail::JsonCtx ctx{job_.source, &job_.warnings};
  ctx.errors = &errors;
  const Units units = job_.units;
  const double tolerance = job_.tolerance;
  const JobParams params = job_.params;
  try {
    read_settings(ctx, doc, job_);
  } catch (const InputError& e) {
    errors.push_back(e);  // a refusal that stops the reading: the last one
  }
  if (errors.empty()) {
    // What the settings do not give keeps its value (a default tolerance
    // follows the units, as units() does).
    if (!doc.contains("tolerance"))
      job_.tolerance = tolerance == kDefaultToleranceMm / mm_per_unit(units)
                           ? kDefaultToleranceMm / mm_per_unit(job_.units)
                           : tolerance;
    job_.params = job_.params.over(params);
    return *this;
  }
  InputError first = errors.front();
  for (size_t i = 1; i < errors.size(); ++i) first.add_more(errors[i]);
  throw first;
}

JobParams entity_params(std::span<const std::pair<std::string, std::string>> members, const std::string& source,
                        const std::string& path) {
  using detail::json;
  json obj = json::object();
  for (const auto& [k, v] : members) obj[k] = json::parse(v);
  std::vector<InputError> errors;
  std::vector<std::string> warnings;
  detail::JsonCtx ctx{source, &warnings};
  ctx.errors = &errors;
  JobParams p;
  try {
    p = detail::parse_params(ctx, obj, path, false);
  } catch (const InputError& e) {
    errors.push_back(e);
  }
  if (errors.empty()) return p;
  InputError first = errors.front();
  for (size_t i = 1; i < errors.size(); ++i) first.add_more(errors[i]);
  throw first;
}

Job load_job(const std::filesystem::path& file, const JobReadOptions& opt) {
  JobReadOptions o = opt;
  if (o.folder.empty()) o.folder = file.parent_path();
  return parse_job(read_bounded(file, kMaxJobBytes, "job file"), file.string(), o);
}

}  // namespace bezcam
