// Selecting a drawing's contours by layer or id with shell globs, and the
// settings each selected contour's entity gets.
#include "selection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fnmatch.h>
#include <optional>
#include <string_view>

#include "bezcam/job/settings.hpp"
#include "bezcam/kernel/bezier.hpp"

namespace bezcam::import {
namespace {

// Settings of the job as a whole, which no single entity takes.
constexpr std::array<std::string_view, 5> kJobOnly = {"tolerance", "units", "machine", "order", "program_number"};

std::string scoped_name(const ScopedSetting& s) { return "settings." + s.selector + ":" + s.key; }

InputError renamed(const InputError& e, const std::string& setting, const std::string& file) {
  Place where = Place::at_setting(setting);
  if (!file.empty()) where.file = file;
  return InputError(e.id(), where, e.message());
}

// At most `n` names, quoted, then how many more.
std::string listed(const std::vector<std::string>& names, size_t n) {
  std::string o;
  for (size_t i = 0; i < names.size() && i < n; ++i) o += (i ? ", \"" : "\"") + names[i] + "\"";
  if (names.size() > n) o += " and " + std::to_string(names.size() - n) + " more";
  return o;
}

// `circle<D` or `circle>D`: the comparison and the diameter D.
struct CircleSelector {
  char op;
  double d;
};
std::optional<CircleSelector> circle_selector(const std::string& s) {
  constexpr std::string_view kWord = "circle";
  if (s.size() <= kWord.size() + 1 || s.compare(0, kWord.size(), kWord) != 0) return std::nullopt;
  const char op = s[kWord.size()];
  if (op != '<' && op != '>') return std::nullopt;
  const char* text = s.c_str() + kWord.size() + 1;
  char* end = nullptr;
  const double d = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(d > 0) || !std::isfinite(d)) return std::nullopt;
  return CircleSelector{op, d};
}

// `<outside>` or `<inside>`: the side by nesting it picks.
std::optional<std::string> nesting_selector(const std::string& s) {
  if (s == "<outside>") return std::string("outside");
  if (s == "<inside>") return std::string("inside");
  return std::nullopt;
}

// The diameter of a closed contour that is a circle: its Bézier pieces,
// sampled, all at one distance from the centre of the samples' box, and
// the box square (to 1e-9 of the drawing's scale).
std::optional<double> circle_diameter(const Contour& c) {
  if (!c.closed || c.pieces.empty() || c.is_interpolation) return std::nullopt;
  std::vector<Vec3> pts;
  for (const Piece& p : c.pieces) {
    if (p.bspline) return std::nullopt;
    const Bezier b = Bezier::make(p.points, p.weights);
    for (int k = 0; k < 16; ++k) pts.push_back(evaluate(b, k / 16.0));
  }
  double lx = pts[0].x, hx = lx, ly = pts[0].y, hy = ly;
  for (const Vec3& q : pts) {
    lx = std::min(lx, q.x), hx = std::max(hx, q.x);
    ly = std::min(ly, q.y), hy = std::max(hy, q.y);
  }
  const double w = hx - lx, h = hy - ly, eps = 1e-9 * std::max({w, h, std::abs(lx), std::abs(ly), 1.0});
  if (!(w > 0) || std::abs(w - h) > 2 * eps) return std::nullopt;
  const double cx = (lx + hx) / 2, cy = (ly + hy) / 2, r = (w + h) / 4;
  for (const Vec3& q : pts)
    if (std::abs(std::hypot(q.x - cx, q.y - cy) - r) > 2 * eps) return std::nullopt;
  return 2 * r;
}

// The diameters of the drawing's circles, for a selector that picks none.
std::string circles_of(const Drawing& d) {
  std::vector<double> ds;
  for (const Contour& c : d.contours)
    if (const auto dia = circle_diameter(c)) ds.push_back(*dia);
  if (ds.empty()) return "; it has no circles";
  std::sort(ds.begin(), ds.end());
  ds.erase(std::unique(ds.begin(), ds.end(), [](double a, double b) { return std::abs(a - b) <= 1e-9 * b; }), ds.end());
  std::string o = "; its circles' diameters are ";
  for (size_t i = 0; i < ds.size() && i < 20; ++i) {
    char b[32];
    std::snprintf(b, sizeof b, "%s%.6g", i ? ", " : "", ds[i]);
    o += b;
  }
  return o;
}

bool picks_text(const Drawing& d, const std::string& selector) {
  return std::any_of(d.texts.begin(), d.texts.end(),
                     [&](const DrawingText& t) { return selects(selector, t.layer, t.id); });
}

void check_selector(const Drawing& d, const std::string& selector, const std::string& setting) {
  if (nesting_selector(selector)) {
    if (setting.rfind("settings.", 0) == 0) return;  // checked once the sides are known
    throw InputError(
        errc::usage_setting, Place::at_setting(setting),
        "\"" + selector +
            "\" picks by the sides the nesting gives, which are found among the entities kept: it picks the "
            "entities a setting goes to (" +
            selector + ":KEY=VALUE), not which entities are cut");
  }
  if (std::any_of(d.contours.begin(), d.contours.end(), [&](const Contour& c) { return selects(selector, c); }) ||
      picks_text(d, selector))
    return;
  std::vector<std::string> layers, ids;
  for (const auto& [name, s] : d.layers)
    if (!name.empty()) layers.push_back(name);
  for (const Contour& c : d.contours) ids.push_back(c.id);
  for (const DrawingText& t : d.texts) ids.push_back(t.id);
  throw InputError(
      errc::import_setting, Place::at_setting(setting),
      d.source + " has no layer and no entity matching \"" + selector + "\"; " +
          (layers.empty() ? std::string("it has no named layers") : "its layers are " + listed(layers, 20)) +
          ", its entities " + listed(ids, 20) + circles_of(d));
}

}  // namespace

bool selects(const std::string& selector, const std::string& layer, const std::string& id) {
  if (fnmatch(selector.c_str(), id.c_str(), 0) == 0) return true;
  return !layer.empty() && fnmatch(selector.c_str(), layer.c_str(), 0) == 0;
}

bool selects(const std::string& selector, const Contour& c, const std::string& nesting_side) {
  if (const auto cs = circle_selector(selector)) {
    const auto d = circle_diameter(c);
    return d && (cs->op == '<' ? *d < cs->d : *d > cs->d);
  }
  if (const auto side = nesting_selector(selector)) return *side == nesting_side;
  return selects(selector, c.layer, c.id);
}

bool is_text_key(const std::string& key) { return key == "font" || key == "text"; }

void check_options(const ImportOptions& opt) {
  for (const ScopedSetting& s : opt.scoped) {
    const std::string name = scoped_name(s);
    if (s.selector.empty())
      throw InputError(errc::usage_setting, Place::at_setting(name),
                       "expected SELECTOR:KEY=VALUE with SELECTOR a layer or an entity id (a glob), found an empty "
                       "selector");
    const std::string first = s.key.substr(0, s.key.find('.'));
    if (std::find(kJobOnly.begin(), kJobOnly.end(), first) != kJobOnly.end())
      throw InputError(errc::usage_setting, Place::at_setting(name),
                       "\"" + first +
                           "\" is a setting of the whole job, not of an entity; give it without a selector (" + s.key +
                           "=" + s.value + ")");
    if (is_text_key(s.key)) {
      if (s.value.empty())
        throw InputError(errc::usage_setting, Place::at_setting(name),
                         "expected a value for the text's \"" + s.key + "\", found nothing after =");
      continue;
    }
    try {
      const std::pair<std::string, std::string> kv{s.key, s.value};
      (void)settings_json(std::span(&kv, 1));
    } catch (const InputError& e) {
      throw renamed(e, name, "");
    }
  }
}

void check_selectors(const Drawing& d, const ImportOptions& opt) {
  for (const ScopedSetting& s : opt.scoped) {
    check_selector(d, s.selector, scoped_name(s));
    if (is_text_key(s.key) && !picks_text(d, s.selector)) {
      std::vector<std::string> texts;
      for (const DrawingText& t : d.texts) texts.push_back(t.id);
      throw InputError(
          errc::usage_setting, Place::at_setting(scoped_name(s)),
          "\"" + s.key + "\" is a key of a text, and \"" + s.selector + "\" picks no text of " + d.source + "; " +
              (texts.empty() ? std::string("it has no TEXT or MTEXT") : "its texts are " + listed(texts, 20)));
    }
  }
  for (const std::string& s : opt.only) check_selector(d, s, "only");
  for (const std::string& s : opt.skip) check_selector(d, s, "skip");
}

std::vector<const Contour*> select_contours(const std::vector<const Contour*>& kept, const ImportOptions& opt) {
  std::vector<const Contour*> out;
  const auto any = [](const std::vector<std::string>& sels, const Contour& c) {
    return std::any_of(sels.begin(), sels.end(), [&](const std::string& s) { return selects(s, c); });
  };
  for (const Contour* c : kept)
    if ((opt.only.empty() || any(opt.only, *c)) && !any(opt.skip, *c)) out.push_back(c);
  return out;
}

namespace {

// The members of an entity given the scoped settings that pick it.
std::vector<std::pair<std::string, std::string>> members_of(
    const std::vector<std::pair<std::string, std::string>>& given, const std::string& nesting_side) {
  std::vector<std::pair<std::string, std::string>> out;
  const SettingsJson members = settings_json(given);
  const bool side =
      std::any_of(members.job.begin(), members.job.end(), [](const auto& m) { return m.first == "side"; });
  if (!side && !nesting_side.empty()) out.emplace_back("side", "\"" + nesting_side + "\"");
  out.insert(out.end(), members.job.begin(), members.job.end());
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> entity_members(const std::string& layer, const std::string& id,
                                                                const ImportOptions& opt,
                                                                const std::string& nesting_side) {
  std::vector<std::pair<std::string, std::string>> given;
  for (const ScopedSetting& s : opt.scoped)
    if (!is_text_key(s.key) && selects(s.selector, layer, id)) given.emplace_back(s.key, s.value);
  return members_of(given, nesting_side);
}

std::vector<std::pair<std::string, std::string>> entity_members(const Contour& c, const ImportOptions& opt,
                                                                const std::string& nesting_side) {
  std::vector<std::pair<std::string, std::string>> given;
  for (const ScopedSetting& s : opt.scoped)
    if (!is_text_key(s.key) && selects(s.selector, c, nesting_side)) given.emplace_back(s.key, s.value);
  return members_of(given, nesting_side);
}

void check_nesting_selectors(const ImportOptions& opt, const std::vector<std::string>& sides,
                             const std::string& source) {
  for (const ScopedSetting& s : opt.scoped) {
    const auto side = nesting_selector(s.selector);
    if (!side || std::find(sides.begin(), sides.end(), *side) != sides.end()) continue;
    throw InputError(errc::import_setting, Place::at_setting(scoped_name(s)),
                     "\"" + s.selector + "\" picks the contours the nesting cuts " + *side + ", and " + source +
                         (sides.empty() ? std::string(" has no sides by nesting: give the job a side, side=outside (a "
                                                      "part) or side=inside (openings)")
                                        : " has none"));
  }
}

InputError at_scoped_setting(const InputError& e, const std::string& layer, const std::string& id,
                             const ImportOptions& opt, const std::string& source) {
  // The path's key after `entities[k].`: the last scoped setting of this
  // contour whose key starts with it gave it.
  const std::string path = e.place().json_path.value_or("");
  const size_t dot = path.find("].");
  if (dot == std::string::npos) return e;
  std::string key = path.substr(dot + 2);
  key = key.substr(0, key.find_first_of(".["));
  for (auto it = opt.scoped.rbegin(); it != opt.scoped.rend(); ++it)
    if (selects(it->selector, layer, id) && it->key.substr(0, it->key.find('.')) == key)
      return renamed(e, scoped_name(*it), source);
  return e;
}

}  // namespace bezcam::import
