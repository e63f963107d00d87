#pragma once
/// Unknown keys in bezcam's JSON files (jobs and machine profiles): a key
/// within a few edits of a known one is a likely typo and is refused (a
/// misspelt `tolerence` must never cut at the default); other unknown keys
/// are warnings, or refusals when the reader is strict.
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace bezcam {

/// Edits (insertions, deletions, substitutions, swaps of neighbours)
/// between `a` and `b`.
int edit_distance(std::string_view a, std::string_view b);

/// How many edits make an unknown key a likely typo of a known one: 2, and
/// 1 for keys of 4 characters or fewer (two edits turn any short key into
/// another: `xy` would "resemble" `id`).
int typo_edits(std::string_view key);

/// The known key `key` most likely misspells (fewest edits, the first of
/// equals), or nothing when none is within typo_edits(key).
std::optional<std::string> resembled_key(std::string_view key, std::span<const std::string_view> known);

/// What is wrong with a line of G-code given as a template (a job's
/// `before` / `after`): a line break, a '{' with no '}', or a placeholder
/// not in `known` (naming the one it resembles); nothing when it is fine.
std::optional<std::string> template_problem(std::string_view text, std::span<const std::string_view> known);

}  // namespace bezcam
