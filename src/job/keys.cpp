#include "bezcam/job/keys.hpp"

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

namespace bezcam {

int edit_distance(std::string_view a, std::string_view b) {
  // Optimal string alignment (Damerau-Levenshtein without repeated edits
  // of one substring): "tolerence" -> "tolerance" 1, "cutz" -> "cut_z" 1.
  const size_t n = a.size(), m = b.size();
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1));
  for (size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (size_t i = 1; i <= n; ++i)
    for (size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

int typo_edits(std::string_view key) { return key.size() <= 4 ? 1 : 2; }

std::optional<std::string> resembled_key(std::string_view key, std::span<const std::string_view> known) {
  std::optional<std::string> best;
  int best_d = typo_edits(key) + 1;
  for (std::string_view k : known) {
    // Case alone is a typo too ("Tolerance").
    std::string lower(key);
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const int d = lower == k ? 1 : edit_distance(key, k);
    if (d < best_d) {
      best_d = d;
      best = std::string(k);
    }
  }
  return best;
}

bool user_key(std::string_view key) { return key.starts_with("x-"); }

namespace {
// Words machinists and other programs use for a key bezcam names
// otherwise: the word, and the key it stands for.
constexpr std::pair<std::string_view, std::string_view> kKeyWords[] = {{"depth", "cut_z"},
                                                                       {"cut_depth", "cut_z"},
                                                                       {"stock", "stock_to_leave"},
                                                                       {"allowance", "stock_to_leave"},
                                                                       {"diameter", "tool_diameter"},
                                                                       {"tool_dia", "tool_diameter"},
                                                                       {"radius", "tool_radius"},
                                                                       {"rpm", "spindle_rpm"},
                                                                       {"speed", "spindle_rpm"},
                                                                       {"spindle", "spindle_rpm"},
                                                                       {"feedrate", "feed"},
                                                                       {"feed_rate", "feed"},
                                                                       {"plunge", "plunge_feed"},
                                                                       {"plunge_rate", "plunge_feed"},
                                                                       {"pass_depth", "step_down"}};
}  // namespace

UnknownKey unknown_key(std::string_view key, std::span<const std::string_view> known, std::string_view prefix) {
  UnknownKey u;
  const std::string quoted = "\"" + std::string(prefix) + std::string(key) + "\"";
  for (const auto& [word, meant] : kKeyWords)
    if (key == word && std::find(known.begin(), known.end(), meant) != known.end()) u.meant = std::string(meant);
  if (!u.meant) {
    u.meant = resembled_key(key, known);
    u.typo = u.meant.has_value();
  }
  if (u.typo)
    u.message = "unknown key " + quoted + ": did you mean \"" + std::string(prefix) + *u.meant +
                "\"? (a misspelt key is refused: it would otherwise take the default)";
  else if (u.meant)
    u.message = "unknown key " + quoted + ": did you mean \"" + std::string(prefix) + *u.meant +
                "\"? (a key bezcam does not know is refused: it would otherwise be ignored)";
  else
    u.message = "unknown key " + quoted +
                " (a key bezcam does not know is refused: it would otherwise be ignored; "
                "keys of your own start with \"x-\")";
  return u;
}

std::optional<std::string> template_problem(std::string_view text, std::span<const std::string_view> known) {
  if (text.find_first_of("\r\n") != std::string_view::npos)
    return std::string("expected one line of G-code, found a line break; give the lines as an array");
  for (size_t open = text.find('{'); open != std::string_view::npos; open = text.find('{', open + 1)) {
    const size_t close = text.find('}', open);
    if (close == std::string_view::npos)
      return "\"" + std::string(text) + "\": a '{' with no '}' (placeholders are written {name})";
    const std::string_view name = text.substr(open + 1, close - open - 1);
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string list;
    for (auto k : known) list += (list.empty() ? "{" : ", {") + std::string(k) + "}";
    const auto like = resembled_key(name, known);
    return "unknown placeholder {" + std::string(name) + "} in \"" + std::string(text) +
           "\" (it would be printed as it is); " +
           (like           ? "did you mean {" + *like + "}?"
            : list.empty() ? std::string("these lines take no placeholder")
                           : "the lines take " + list);
  }
  return std::nullopt;
}

}  // namespace bezcam
