#include "bezcam/job/settings.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>

#include "bezcam/error.hpp"
#include "bezcam/job/keys.hpp"
#include "job_json_detail.hpp"

namespace bezcam {

namespace {

using ojson = nlohmann::ordered_json;

// The settings that go to the top level of the document; every other key
// goes to `job`.
constexpr std::array<std::string_view, 3> kTopKeys = {"tolerance", "units", "machine"};

[[noreturn]] void refuse(const std::string& key, const std::string& what) {
  throw InputError(errc::usage_setting, Place::at_setting("settings." + key), what);
}

// KEY's names, split at the dots; each must be a name.
std::vector<std::string> names_of(const std::string& key) {
  std::vector<std::string> out;
  size_t at = 0;
  for (;;) {
    const size_t dot = key.find('.', at);
    out.push_back(key.substr(at, dot == std::string::npos ? std::string::npos : dot - at));
    if (out.back().empty())
      refuse(key,
             "expected KEY=VALUE with KEY a name or names joined by dots (tabs.count), found the key \"" + key + "\"");
    if (dot == std::string::npos) return out;
    at = dot + 1;
  }
}

// The key's names checked against the job file's keys: the first a
// top-level or `job` key, the second (under `lead` or `tabs`) one of
// theirs; anything under a user's key ("x-...") is theirs.
void check_names(const std::string& key, const std::vector<std::string>& names) {
  std::vector<std::string_view> known(kTopKeys.begin(), kTopKeys.end());
  known.insert(known.end(), detail::kParamKeys.begin(), detail::kParamKeys.end());
  known.push_back("program_number");
  const std::string& first = names.front();
  const auto unknown = [&](const std::string& name, std::span<const std::string_view> keys, const std::string& in) {
    refuse(key, unknown_key(name, keys, in).message);
  };
  if (user_key(first)) return;
  if (std::find(known.begin(), known.end(), first) == known.end()) unknown(first, known, "");
  if (names.size() == 1) return;
  std::span<const std::string_view> sub;
  if (first == "lead")
    sub = detail::kLeadKeys;
  else if (first == "tabs")
    sub = detail::kTabsKeys;
  else
    refuse(key, "\"" + first + "\" takes a value, not keys; give it as " + first + "=VALUE");
  if (std::find(sub.begin(), sub.end(), names[1]) == sub.end()) unknown(names[1], sub, first + ".");
  if (names.size() > 2)
    refuse(key, "\"" + first + "." + names[1] + "\" takes a value, not keys; give it as " + first + "." + names[1] +
                    "=VALUE");
}

// VALUE as JSON, a number written the C way, or else the text itself. A
// value that starts as JSON would (an object, an array, a quoted string)
// must be JSON: a brace too few must not turn it into a string.
ojson value_of(const std::string& key, const std::string& text) {
  ojson v;
  try {
    v = ojson::parse(text);
  } catch (const ojson::out_of_range&) {
    refuse(key, "expected a finite number, found " + text + ", which is too large for a double");
  } catch (const ojson::parse_error& e) {
    const size_t first = text.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && (text[first] == '{' || text[first] == '[' || text[first] == '"')) {
      std::string what = e.what();
      if (const size_t p = what.find("column "); p != std::string::npos && what.find(": ", p) != std::string::npos)
        what = what.substr(what.find(": ", p) + 2);
      refuse(key, "the value " + text + " is not valid JSON: " + what);
    }
    double d = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), d);
    if (!text.empty() && r.ec == std::errc() && r.ptr == text.data() + text.size() && std::isfinite(d))
      v = d;
    else
      v = text;
  }
  try {
    (void)v.dump();
  } catch (const ojson::type_error&) {
    refuse(key, "expected UTF-8 text, found other bytes in the value");
  }
  return v;
}

// `value` set at `names` under `at`: objects made on the way; an object
// merged into the object there, anything else replacing what is there.
void put(ojson& at, const std::vector<std::string>& names, size_t i, ojson value) {
  ojson& slot = at[names[i]];
  if (i + 1 < names.size()) {
    if (!slot.is_object()) slot = ojson::object();
    put(slot, names, i + 1, std::move(value));
  } else if (slot.is_object() && value.is_object()) {
    for (auto it = value.begin(); it != value.end(); ++it) slot[it.key()] = it.value();
  } else {
    slot = std::move(value);
  }
}

}  // namespace

SettingsJson settings_json(std::span<const std::pair<std::string, std::string>> settings) {
  ojson top = ojson::object(), job = ojson::object();
  for (const auto& [key, text] : settings) {
    const std::vector<std::string> names = names_of(key);
    check_names(key, names);
    const bool at_top = std::find(kTopKeys.begin(), kTopKeys.end(), names.front()) != kTopKeys.end();
    put(at_top ? top : job, names, 0, value_of(key, text));
  }
  SettingsJson out;
  for (auto it = top.begin(); it != top.end(); ++it) out.top.emplace_back(it.key(), it.value().dump());
  for (auto it = job.begin(); it != job.end(); ++it) out.job.emplace_back(it.key(), it.value().dump());
  return out;
}

}  // namespace bezcam
