// Values given on the command line for a job file's entities (--set
// SELECTOR:KEY=VALUE): written into the entities' objects before they are
// read, so that they are checked as the file's own values are.
#include <algorithm>
#include <fnmatch.h>

#include "bezcam/job/settings.hpp"
#include "job_json_detail.hpp"

namespace bezcam::detail {

namespace {

// The keys only a text entity has; `text`, `font` and `align` are text.
constexpr std::array<std::string_view, 5> kTextKeys = {"text", "font", "size", "align", "at"};
constexpr std::array<std::string_view, 3> kStringKeys = {"text", "font", "align"};
constexpr std::array<std::string_view, 5> kJobOnly = {"tolerance", "units", "machine", "order", "program_number"};

template <size_t N>
bool among(const std::array<std::string_view, N>& keys, const std::string& k) {
  return std::find(keys.begin(), keys.end(), k) != keys.end();
}

std::string setting_name(const EntitySetting& s) { return "settings." + s.selector + ":" + s.key; }

[[noreturn]] void refuse(const JsonCtx& ctx, const EntitySetting& s, const std::string& what) {
  Place where = Place::at_setting(setting_name(s));
  where.file = ctx.source;
  throw InputError(errc::usage_setting, where, what);
}

// VALUE as JSON: a text's string keys take the text itself unless it is a
// quoted JSON string; the others as settings_json() reads them.
json value_of(const JsonCtx& ctx, const EntitySetting& s, const std::string& key) {
  if (among(kStringKeys, key)) {
    if (!s.value.empty() && s.value.front() == '"') {
      const json v = json::parse(s.value, nullptr, false);
      if (v.is_string()) return v;
    }
    return s.value;
  }
  if (among(kTextKeys, key)) {
    const json v = json::parse(s.value, nullptr, false);
    return v.is_discarded() ? json(s.value) : v;
  }
  const std::pair<std::string, std::string> kv{s.key, s.value};
  SettingsJson members;
  try {
    members = settings_json(std::span(&kv, 1));
  } catch (const InputError& e) {
    refuse(ctx, s, e.message());
  }
  if (members.job.size() != 1) refuse(ctx, s, "\"" + key + "\" is a setting of the whole job, not of an entity");
  return json::parse(members.job.front().second);
}

}  // namespace

std::map<std::pair<size_t, std::string>, std::string> apply_entity_settings(const JsonCtx& ctx, json& ents) {
  std::map<std::pair<size_t, std::string>, std::string> given;
  if (!ctx.options) return given;
  for (const EntitySetting& s : ctx.options->entity_settings) {
    const std::string key = s.key.substr(0, s.key.find('.'));
    if (s.selector.empty())
      refuse(ctx, s, "expected SELECTOR:KEY=VALUE with SELECTOR an entity id (a glob), found an empty selector");
    if (key == "id" || key == "type")
      refuse(ctx, s, "an entity's \"" + key + "\" is what selects it; edit the job file to change it");
    if (among(kJobOnly, key))
      refuse(ctx, s, "\"" + key + "\" is a setting of the whole job, not of an entity; edit the job file to change it");
    const json v = value_of(ctx, s, key);
    std::vector<std::string> ids;
    bool matched = false;
    for (size_t i = 0; i < ents.size(); ++i) {
      json& obj = ents[i];
      if (!obj.is_object() || !obj.contains("id") || !obj["id"].is_string()) continue;
      const std::string id = obj["id"].get<std::string>();
      ids.push_back(id);
      if (fnmatch(s.selector.c_str(), id.c_str(), 0) != 0) continue;
      matched = true;
      const bool text = obj.contains("type") && obj["type"] == "text";
      if (among(kTextKeys, key) && !text)
        refuse(ctx, s, "entity \"" + id + "\" is not a text: text, font, size, align and at are keys of a text entity");
      if (v.is_object() && obj.contains(key) && obj[key].is_object())
        obj[key].merge_patch(v);
      else
        obj[key] = v;
      given[{i, key}] = setting_name(s);
    }
    if (!matched) {
      std::string list;
      for (size_t k = 0; k < ids.size() && k < 20; ++k) list += (k ? ", \"" : "\"") + ids[k] + "\"";
      if (ids.size() > 20) list += " and " + std::to_string(ids.size() - 20) + " more";
      refuse(ctx, s,
             "no entity's id matches \"" + s.selector + "\"; " +
                 (ids.empty() ? std::string("the job's entities have no ids") : "the job's ids are " + list));
    }
  }
  return given;
}

InputError at_entity_setting(const InputError& e, size_t index,
                             const std::map<std::pair<size_t, std::string>, std::string>& given,
                             const std::string& source) {
  const std::string path = e.place().json_path.value_or("");
  const std::string head = "entities[" + std::to_string(index) + "].";
  if (!path.starts_with(head)) return e;
  const std::string key = path.substr(head.size(), path.find_first_of(".[", head.size()) - head.size());
  const auto it = given.find({index, key});
  if (it == given.end()) return e;
  Place where = Place::at_setting(it->second);
  where.file = source;
  return InputError(e.id(), where, e.message());
}

}  // namespace bezcam::detail
