#include "bezcam/machine/machine_profile.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "bezcam/error.hpp"
#include "bezcam/job/keys.hpp"

namespace bezcam {

namespace {

using json = nlohmann::json;

// The keys a profile may hold, per object (docs/machines.md).
const std::vector<std::pair<std::string, std::vector<std::string_view>>>& known_keys() {
  static const std::vector<std::pair<std::string, std::vector<std::string_view>>> k = {
      {"",
       {"name",
        "description",
        "header",
        "footer",
        "line_numbers",
        "decimals",
        "max_decimals",
        "feed_decimals",
        "words",
        "tool_change",
        "spindle_on",
        "spindle_off",
        "preamble",
        "tool_length",
        "tool_changer",
        "spindle_dwell_s",
        "comments",
        "modal",
        "program_number",
        "tool_change_position",
        "arcs",
        "arc_tolerance_mm",
        "cutter_compensation",
        "tool_diameters_mm",
        "nurbs",
        "canned_cycles",
        "travel_mm",
        "max_feed_mm_min",
        "defaults",
        "motion"}},
      {"motion",
       {"max_velocity_mm_min", "max_acceleration_mm_s2", "max_jerk_mm_s3", "period_s", "min_segment_periods",
        "block_rate_hz", "lookahead_blocks", "blend_tolerance_mm", "tool_change_s", "spindle_start_s", "planner"}},
      {"line_numbers", {"enabled", "start", "step"}},
      {"decimals", {"mm", "inch"}},
      {"max_decimals", {"mm", "inch"}},
      {"words", {"rapid", "feed", "cw", "ccw"}},
      {"canned_cycles", {"dialect", "g73_retract_mm", "g83_clearance_mm"}},
      {"nurbs", {"dialect", "start_word", "max_rank", "knot_decimals", "weight_decimals", "fixed_decimals"}},
      {"travel_mm", {"x", "y", "z"}},
      {"defaults", {"feed", "plunge_feed", "safe_z", "cut_z", "spindle_rpm", "tool_radius", "tool", "coolant"}},
  };
  return k;
}

// The placeholders each template may use (the writer replaces them).
const std::vector<std::pair<std::string, std::vector<std::string_view>>>& known_placeholders() {
  static const std::vector<std::pair<std::string, std::vector<std::string_view>>> p = {
      {"header", {"safe_z", "program"}},
      {"footer", {"safe_z", "program"}},
      {"tool_change", {"tool"}},
      {"spindle_on", {"rpm"}},
      {"spindle_off", {}},
      {"preamble", {}},
      {"tool_length", {"tool"}},
      {"tool_change_position", {}},
  };
  return p;
}

struct Reader {
  std::string source;
  MachineProfile* m = nullptr;
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(errc::machine_invalid, Place::in_json(source, path), what);
  }
  // Profiles follow the job's rules: a key bezcam does not know is
  // refused (it would otherwise be ignored), naming the key it resembles;
  // keys starting with "x-" are the user's own.
  void check_keys(const json& doc) const {
    for (const auto& [object, keys] : known_keys()) {
      const json* o = object.empty() ? &doc : opt(doc, object.c_str());
      if (!o || !o->is_object()) continue;
      for (auto it = o->begin(); it != o->end(); ++it) {
        if (std::find(keys.begin(), keys.end(), it.key()) != keys.end() || user_key(it.key())) continue;
        const std::string at = object.empty() ? it.key() : object + "." + it.key();
        const UnknownKey u = unknown_key(it.key(), keys);
        throw InputError(u.typo ? errc::machine_key_typo : errc::machine_unknown_key, Place::in_json(source, at),
                         u.message);
      }
    }
  }
  // A template's placeholders: `{name}` from its list, nothing else.
  void check_placeholders(const std::string& path, const std::string& text) const {
    const auto& all = known_placeholders();
    const auto it = std::find_if(all.begin(), all.end(), [&](const auto& e) { return path.starts_with(e.first); });
    const std::vector<std::string_view> none;
    const auto& allowed = it == all.end() ? none : it->second;
    std::string list;
    for (auto a : allowed) list += (list.empty() ? "{" : ", {") + std::string(a) + "}";
    for (size_t open = text.find('{'); open != std::string::npos; open = text.find('{', open + 1)) {
      const size_t close = text.find('}', open);
      if (close == std::string::npos)
        fail(path, "\"" + text + "\": a '{' with no '}' (placeholders are written {name})");
      const std::string name = text.substr(open + 1, close - open - 1);
      if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
        std::string hint = list.empty() ? "this template takes no placeholder" : "this template takes " + list;
        if (const auto like = resembled_key(name, allowed)) hint = "did you mean {" + *like + "}?";
        throw InputError(
            errc::machine_placeholder, Place::in_json(source, path),
            "unknown placeholder {" + name + "} in \"" + text + "\" (it would be printed as it is); " + hint);
      }
    }
  }
  const json* opt(const json& o, const char* k) const {
    auto it = o.find(k);
    return it == o.end() ? nullptr : &*it;
  }
  double num(const json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, "expected a number");
    return v.get<double>();
  }
  int integer(const json& v, const std::string& path) const {
    if (!v.is_number_integer()) fail(path, "expected an integer");
    return v.get<int>();
  }
  std::string str(const json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, "expected a string");
    return v.get<std::string>();
  }
  std::vector<std::string> lines(const json& v, const std::string& path) const {
    if (!v.is_array()) fail(path, "expected an array of strings");
    std::vector<std::string> out;
    for (size_t i = 0; i < v.size(); ++i) out.push_back(str(v[i], path + "[" + std::to_string(i) + "]"));
    return out;
  }
};

// The `motion` object: every key but the jerk is required, each within
// the range a real controller can have.
MotionModel parse_motion(const Reader& r, const json& v) {
  if (!v.is_object()) r.fail("motion", "expected an object of motion settings (docs/machines.md)");
  MotionModel mm;
  auto need = [&](const char* k) -> const json& {
    auto it = v.find(k);
    if (it == v.end()) r.fail(std::string("motion.") + k, "missing: the motion model needs it (docs/machines.md)");
    return *it;
  };
  auto ranged = [&](const char* k, double lo, double hi, const char* what) {
    const std::string p = std::string("motion.") + k;
    const double x = r.num(need(k), p);
    if (!(x >= lo && x <= hi)) r.fail(p, std::string("expected ") + what);
    return x;
  };
  auto axes = [&](const char* k, double lo, double hi, const char* what) {
    const std::string p = std::string("motion.") + k;
    const json& o = need(k);
    if (!o.is_object()) r.fail(p, "expected {\"x\": ..., \"y\": ..., \"z\": ...}");
    std::array<double, 3> out{};
    const char* names[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      auto it = o.find(names[i]);
      if (it == o.end()) r.fail(p + "." + names[i], "missing: give a value for every axis");
      out[i] = r.num(*it, p + "." + names[i]);
      if (!(out[i] > lo && out[i] <= hi)) r.fail(p + "." + names[i], std::string("expected ") + what);
    }
    for (auto it = o.begin(); it != o.end(); ++it)
      if (it.key() != "x" && it.key() != "y" && it.key() != "z")
        r.fail(p + "." + it.key(), "unknown axis: expected x, y and z");
    return out;
  };
  mm.max_velocity_mm_min = axes("max_velocity_mm_min", 0, 1e6, "a velocity above 0 and at most 1000000 mm/min");
  mm.max_acceleration_mm_s2 =
      axes("max_acceleration_mm_s2", 0, 1e6, "an acceleration above 0 and at most 1000000 mm/s^2");
  if (v.contains("max_jerk_mm_s3"))
    mm.max_jerk_mm_s3 = axes("max_jerk_mm_s3", 0, 1e9, "a jerk above 0 and at most 1e9 mm/s^3");
  mm.period_s = ranged("period_s", 1e-5, 0.1, "a period from 0.00001 to 0.1 s");
  mm.min_segment_periods = ranged("min_segment_periods", 0, 100, "from 0 (no cap) to 100 periods");
  mm.block_rate_hz = ranged("block_rate_hz", 0, 1e6, "from 0 (no cap) to 1000000 blocks per second");
  const double look = ranged("lookahead_blocks", 1, 100000, "a whole number of blocks from 1 to 100000");
  if (look != std::floor(look)) r.fail("motion.lookahead_blocks", "expected a whole number of blocks from 1 to 100000");
  mm.lookahead_blocks = static_cast<int>(look);
  mm.blend_tolerance_mm = ranged("blend_tolerance_mm", 0, 10, "from 0 (exact stop) to 10 mm");
  if (v.contains("tool_change_s")) mm.tool_change_s = ranged("tool_change_s", 0, 3600, "from 0 to 3600 s");
  if (v.contains("spindle_start_s")) mm.spindle_start_s = ranged("spindle_start_s", 0, 3600, "from 0 to 3600 s");
  if (v.contains("planner")) {
    const std::string p = r.str(v["planner"], "motion.planner");
    if (p == "generic")
      mm.planner = MotionModel::Planner::generic;
    else if (p == "linuxcnc")
      mm.planner = MotionModel::Planner::linuxcnc;
    else
      r.fail("motion.planner", "expected \"generic\" or \"linuxcnc\", found \"" + p + "\"");
  }
  return mm;
}

// How numbers and words are printed: line numbers, decimals, the motion
// words.
void parse_format(const Reader& r, const json& doc, MachineProfile& m) {
  if (auto v = r.opt(doc, "line_numbers")) {
    if (!v->is_object()) r.fail("line_numbers", "expected an object");
    m.line_numbers = v->value("enabled", false);
    if (auto s = r.opt(*v, "start")) m.line_start = r.integer(*s, "line_numbers.start");
    if (auto s = r.opt(*v, "step")) m.line_step = r.integer(*s, "line_numbers.step");
    if (m.line_step <= 0) r.fail("line_numbers.step", "expected a step > 0");
  }
  if (auto v = r.opt(doc, "decimals")) {
    if (auto s = r.opt(*v, "mm")) m.decimals_mm = r.integer(*s, "decimals.mm");
    if (auto s = r.opt(*v, "inch")) m.decimals_inch = r.integer(*s, "decimals.inch");
    if (m.decimals_mm < 0 || m.decimals_mm > 9 || m.decimals_inch < 0 || m.decimals_inch > 9)
      r.fail("decimals", "expected decimals between 0 and 9");
  }
  if (auto v = r.opt(doc, "max_decimals")) {
    if (!v->is_object()) r.fail("max_decimals", "expected an object {\"mm\": N, \"inch\": N}");
    if (auto s = r.opt(*v, "mm")) m.max_decimals_mm = r.integer(*s, "max_decimals.mm");
    if (auto s = r.opt(*v, "inch")) m.max_decimals_inch = r.integer(*s, "max_decimals.inch");
    if (m.max_decimals_mm > 9 || m.max_decimals_inch > 9) r.fail("max_decimals", "expected at most 9 decimals");
    if ((m.max_decimals_mm >= 0 && m.max_decimals_mm < m.decimals_mm) ||
        (m.max_decimals_inch >= 0 && m.max_decimals_inch < m.decimals_inch))
      r.fail("max_decimals", "expected at least the profile's decimals (" + std::to_string(m.decimals_mm) + " mm, " +
                                 std::to_string(m.decimals_inch) + " inch)");
  }
  if (auto v = r.opt(doc, "feed_decimals")) m.feed_decimals = r.integer(*v, "feed_decimals");
  if (auto v = r.opt(doc, "words")) {
    if (auto s = r.opt(*v, "rapid")) m.word_rapid = r.str(*s, "words.rapid");
    if (auto s = r.opt(*v, "feed")) m.word_feed = r.str(*s, "words.feed");
    if (auto s = r.opt(*v, "cw")) m.word_cw = r.str(*s, "words.cw");
    if (auto s = r.opt(*v, "ccw")) m.word_ccw = r.str(*s, "words.ccw");
  }
}

// The tool change: its templates, whether there is a changer, the position
// it goes to first.
void parse_tool_change(const Reader& r, const json& doc, MachineProfile& m) {
  if (auto v = r.opt(doc, "tool_change")) m.tool_change = r.str(*v, "tool_change");
  if (auto v = r.opt(doc, "spindle_on")) m.spindle_on = r.str(*v, "spindle_on");
  if (auto v = r.opt(doc, "spindle_off")) m.spindle_off = r.str(*v, "spindle_off");
  if (auto v = r.opt(doc, "preamble")) m.preamble = r.lines(*v, "preamble");
  if (auto v = r.opt(doc, "tool_length")) m.tool_length = r.str(*v, "tool_length");
  if (auto v = r.opt(doc, "tool_changer")) {
    if (!v->is_boolean()) r.fail("tool_changer", "expected true or false");
    m.tool_changer = v->get<bool>();
  }
  if (auto v = r.opt(doc, "tool_change_position")) m.tool_change_position = r.lines(*v, "tool_change_position");
  for (size_t i = 0; i < m.tool_change_position.size(); ++i)
    r.check_placeholders("tool_change_position[" + std::to_string(i) + "]", m.tool_change_position[i]);
}

// What the controller can do: comments, modal words, program numbers,
// dwell, arcs, cutter compensation and its D registers.
void parse_capabilities(const Reader& r, const json& doc, MachineProfile& m) {
  for (const auto& [key, out] : {std::pair{"comments", &m.comments}, std::pair{"modal", &m.modal}})
    if (auto v = r.opt(doc, key)) {
      if (!v->is_boolean()) r.fail(key, "expected true or false");
      *out = v->get<bool>();
    }
  if (auto v = r.opt(doc, "program_number")) {
    if (!v->is_number_integer() || v->get<long>() < 1 || v->get<long>() > 99999999)
      r.fail("program_number", "expected a program number from 1 to 99999999");
    m.program_number = v->get<long>();
  }
  if (auto v = r.opt(doc, "spindle_dwell_s")) {
    m.spindle_dwell_s = r.num(*v, "spindle_dwell_s");
    if (!(m.spindle_dwell_s >= 0 && m.spindle_dwell_s <= 60))
      r.fail("spindle_dwell_s", "expected seconds from 0 to 60");
  }
  if (auto v = r.opt(doc, "arcs")) {
    if (!v->is_boolean()) r.fail("arcs", "expected true or false");
    m.arcs = v->get<bool>();
  }
  if (auto v = r.opt(doc, "arc_tolerance_mm")) m.arc_tolerance_mm = r.num(*v, "arc_tolerance_mm");
  if (auto v = r.opt(doc, "cutter_compensation")) {
    if (!v->is_boolean()) r.fail("cutter_compensation", "expected true or false");
    m.cutter_compensation = v->get<bool>();
  }
  if (auto v = r.opt(doc, "tool_diameters_mm")) {
    if (!v->is_object())
      r.fail("tool_diameters_mm", "expected an object {\"1\": 6.0, ...}: D register -> diameter in mm");
    for (const auto& [k, d] : v->items()) {
      const std::string p = "tool_diameters_mm." + k;
      int reg = -1;
      const auto [end, ec] = std::from_chars(k.data(), k.data() + k.size(), reg);
      if (ec != std::errc() || end != k.data() + k.size() || reg < 0 || reg > 99999)
        r.fail(p, "expected a register number 0 to 99999 as the key");
      const double dia = r.num(d, p);
      if (!(dia >= 0 && dia < 1e4)) r.fail(p, "expected a diameter from 0 to 10000 mm");
      m.tool_diameters_mm[reg] = dia;
    }
  }
}

// The `canned_cycles` object (after `nurbs`, whose dialect is the default).
void parse_cycles(const Reader& r, const json* v, MachineProfile& m) {
  using D = CannedCycles::Dialect;
  CannedCycles& c = m.cycles;
  c.dialect = m.nurbs == NurbsDialect::linuxcnc ? D::linuxcnc : D::fanuc;
  if (v) {
    if (!v->is_object()) r.fail("canned_cycles", "expected an object");
    if (auto d = r.opt(*v, "dialect")) {
      const std::string s = r.str(*d, "canned_cycles.dialect");
      if (s == "none")
        c.dialect = D::none;
      else if (s == "linuxcnc")
        c.dialect = D::linuxcnc;
      else if (s == "fanuc")
        c.dialect = D::fanuc;
      else
        r.fail("canned_cycles.dialect", "expected \"none\", \"linuxcnc\" or \"fanuc\", found \"" + s + "\"");
    }
  }
  const double d = c.dialect == D::fanuc ? kFanucPeckClearanceMm : kLinuxcncPeckClearanceMm;
  c.g73_retract_mm = c.g83_clearance_mm = d;
  if (!v) return;
  for (auto [key, field] : {std::pair{"g73_retract_mm", &c.g73_retract_mm}, {"g83_clearance_mm", &c.g83_clearance_mm}})
    if (auto x = r.opt(*v, key)) {
      const std::string path = std::string("canned_cycles.") + key;
      *field = r.num(*x, path);
      if (!(*field >= 0 && *field <= 100)) r.fail(path, "expected a distance from 0 to 100 mm");
    }
}

// The `nurbs` object: the dialect of curve blocks and how they print.
void parse_nurbs(const Reader& r, const json& v, MachineProfile& m) {
  if (!v.is_object()) r.fail("nurbs", "expected an object");
  const std::string d = r.str(v.value("dialect", json("none")), "nurbs.dialect");
  if (d == "none")
    m.nurbs = NurbsDialect::none;
  else if (d == "fanuc")
    m.nurbs = NurbsDialect::fanuc;
  else if (d == "linuxcnc")
    m.nurbs = NurbsDialect::linuxcnc;
  else
    r.fail("nurbs.dialect", "expected \"none\", \"fanuc\" or \"linuxcnc\", found \"" + d + "\"");
  if (auto s = r.opt(v, "start_word")) m.nurbs_start_word = r.str(*s, "nurbs.start_word");
  if (auto s = r.opt(v, "max_rank")) m.nurbs_max_rank = r.integer(*s, "nurbs.max_rank");
  if (auto s = r.opt(v, "knot_decimals")) m.knot_decimals = r.integer(*s, "nurbs.knot_decimals");
  if (auto s = r.opt(v, "weight_decimals")) m.weight_decimals = r.integer(*s, "nurbs.weight_decimals");
  if (auto s = r.opt(v, "fixed_decimals")) {
    if (!s->is_boolean()) r.fail("nurbs.fixed_decimals", "expected true or false");
    m.nurbs_fixed_decimals = s->get<bool>();
  }
  if (m.knot_decimals < 0 || m.knot_decimals > 9 || m.weight_decimals < 0 || m.weight_decimals > 9)
    r.fail("nurbs", "expected knot_decimals and weight_decimals between 0 and 9");
  if (m.nurbs_max_rank < 2 || m.nurbs_max_rank > 4) r.fail("nurbs.max_rank", "expected a rank from 2 to 4");
}

// The `travel_mm` object: the axes' limits.
void parse_travel(const Reader& r, const json& v, MachineProfile& m) {
  const char* axes[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    auto a = r.opt(v, axes[k]);
    if (!a) continue;
    const std::string p = std::string("travel_mm.") + axes[k];
    if (!a->is_array() || a->size() != 2) r.fail(p, "expected [min, max]");
    m.travel_mm[k] = {r.num((*a)[0], p + "[0]"), r.num((*a)[1], p + "[1]")};
    if (!(m.travel_mm[k][0] < m.travel_mm[k][1])) r.fail(p, "expected min < max");
  }
}

// Every template's placeholders.
void check_templates(const Reader& r, const MachineProfile& m) {
  for (size_t i = 0; i < m.header.size(); ++i) r.check_placeholders("header[" + std::to_string(i) + "]", m.header[i]);
  for (size_t i = 0; i < m.footer.size(); ++i) r.check_placeholders("footer[" + std::to_string(i) + "]", m.footer[i]);
  r.check_placeholders("tool_change", m.tool_change);
  r.check_placeholders("spindle_on", m.spindle_on);
  r.check_placeholders("spindle_off", m.spindle_off);
  r.check_placeholders("tool_length", m.tool_length);
  for (size_t i = 0; i < m.preamble.size(); ++i)
    r.check_placeholders("preamble[" + std::to_string(i) + "]", m.preamble[i]);
}

// The `defaults` object: job settings a job may leave to the machine.
void parse_defaults(const Reader& r, const json& v, MachineProfile& m) {
  auto num = [&](const char* k, std::optional<double>& out) {
    if (auto s = r.opt(v, k)) out = r.num(*s, std::string("defaults.") + k);
  };
  num("feed", m.defaults.feed);
  num("plunge_feed", m.defaults.plunge_feed);
  num("safe_z", m.defaults.safe_z);
  num("cut_z", m.defaults.cut_z);
  num("spindle_rpm", m.defaults.spindle_rpm);
  num("tool_radius", m.defaults.tool_radius);
  if (auto s = r.opt(v, "tool")) m.defaults.tool = r.integer(*s, "defaults.tool");
  if (auto s = r.opt(v, "coolant")) {
    const std::string c = r.str(*s, "defaults.coolant");
    m.defaults.coolant = coolant_from(c);
    if (!m.defaults.coolant) r.fail("defaults.coolant", "expected \"flood\", \"mist\" or \"off\", found \"" + c + "\"");
  }
}

}  // namespace

MachineProfile parse_machine_profile(const std::string& text, const std::string& source) {
  Reader r{source};
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(errc::machine_syntax, Place::at_file(source),
                     std::string("the machine profile is not valid JSON (") + e.what() + ")");
  }
  if (!doc.is_object()) r.fail("(top level)", "expected a JSON object");
  MachineProfile m;
  r.m = &m;
  r.check_keys(doc);
  m.name = r.str(doc.value("name", json("")), "name");
  if (m.name.empty()) r.fail("name", "expected a non-empty profile name");
  if (auto v = r.opt(doc, "description")) m.description = r.str(*v, "description");
  if (auto v = r.opt(doc, "header")) m.header = r.lines(*v, "header");
  if (auto v = r.opt(doc, "footer")) m.footer = r.lines(*v, "footer");
  parse_format(r, doc, m);
  parse_tool_change(r, doc, m);
  parse_capabilities(r, doc, m);
  if (auto v = r.opt(doc, "nurbs")) parse_nurbs(r, *v, m);
  parse_cycles(r, r.opt(doc, "canned_cycles"), m);
  if (auto v = r.opt(doc, "travel_mm")) parse_travel(r, *v, m);
  if (auto v = r.opt(doc, "max_feed_mm_min")) m.max_feed_mm_min = r.num(*v, "max_feed_mm_min");
  if (auto v = r.opt(doc, "motion")) m.motion = parse_motion(r, *v);
  check_templates(r, m);
  if (auto v = r.opt(doc, "defaults")) parse_defaults(r, *v, m);
  return m;
}

std::vector<std::filesystem::path> machine_search_path(const std::vector<std::filesystem::path>& extra) {
  std::vector<std::filesystem::path> dirs;
  if (const char* env = std::getenv("BEZCAM_MACHINES"); env && *env) {
    std::string_view rest = env;
    while (!rest.empty()) {
      const size_t colon = rest.find(':');
      const std::string_view one = rest.substr(0, colon);
      if (!one.empty()) dirs.emplace_back(one);
      if (colon == std::string_view::npos) break;
      rest.remove_prefix(colon + 1);
    }
  }
  dirs.insert(dirs.end(), extra.begin(), extra.end());
  return dirs;
}

std::vector<std::string> machine_profile_names(const std::vector<std::filesystem::path>& dirs) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& dir : dirs)
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
      if (e.path().extension() == ".json" && e.path().stem() != "schema") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

MachineProfile load_machine_profile(const std::string& name_or_file, const std::vector<std::filesystem::path>& dirs) {
  std::filesystem::path file;
  const bool is_file =
      name_or_file.find('/') != std::string::npos || (name_or_file.size() > 5 && name_or_file.ends_with(".json"));
  if (is_file) {
    file = name_or_file;
  } else {
    for (char c : name_or_file)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_')
        throw InputError(errc::machine_unknown, Place{}, "\"" + name_or_file + "\" is not a valid profile name");
    std::error_code ec;
    for (const auto& dir : dirs)
      if (std::filesystem::exists(dir / (name_or_file + ".json"), ec)) {
        file = dir / (name_or_file + ".json");
        break;
      }
    if (file.empty()) {
      // Profile names ignore case ("LinuxCNC" is linuxcnc); else the
      // nearest name is suggested.
      const std::vector<std::string> names = machine_profile_names(dirs);
      const auto lower = [](std::string v) {
        std::transform(v.begin(), v.end(), v.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        return v;
      };
      for (const auto& n : names)
        if (lower(n) == lower(name_or_file)) return load_machine_profile(n, dirs);
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      const std::vector<std::string_view> views(names.begin(), names.end());
      const std::optional<std::string> near = resembled_key(lower(name_or_file), views);
      throw InputError(errc::machine_unknown, Place{},
                       "no machine profile named \"" + name_or_file + "\"" +
                           (near ? " (did you mean \"" + *near + "\"?)" : std::string()) +
                           "; known profiles: " + known + " (or give the path of a .json profile)");
    }
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw IoError(errc::io_read, Place::at_file(file.string()), "cannot open the machine profile");
  std::ostringstream ss;
  ss << in.rdbuf();
  MachineProfile m = parse_machine_profile(ss.str(), file.string());
  // The name is how jobs, programs and the controller refer to the
  // profile: it must be the one the file is found by.
  if (const std::string stem = file.stem().string(); m.name != stem)
    throw InputError(errc::machine_name, Place::in_json(file.string(), "name"),
                     "expected \"" + stem + "\" (the file's name, " + file.filename().string() + "), found \"" +
                         m.name + "\"; a profile is known by its file name: rename one or the other");
  return m;
}

}  // namespace bezcam
