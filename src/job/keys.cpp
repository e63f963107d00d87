#include "bezcam/job/keys.hpp"

#include <algorithm>
#include <cctype>
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
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
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
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    const int d = lower == k ? 1 : edit_distance(key, k);
    if (d < best_d) {
      best_d = d;
      best = std::string(k);
    }
  }
  return best;
}

}  // namespace bezcam
