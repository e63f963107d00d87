#pragma once
/// Unknown keys in bezcam's JSON files (jobs and machine profiles) and in
/// `--set KEY=VALUE`: every key bezcam does not know is refused, because
/// it would otherwise be ignored (a misspelt `tolerence` cutting at the
/// default, a `depth` that is not `cut_z`). The refusal names the known key
/// it resembles or stands for. Keys starting with "x-" are the user's own
/// and are left alone.
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

/// Whether `key` is one of the user's own (metadata): it starts with "x-".
bool user_key(std::string_view key);

/// Why an unknown key is refused, and the known key it is taken for.
struct UnknownKey {
  /// Within typo_edits() of a known key: a likely typo (the error ids
  /// `*.key-typo`), not a key of another meaning (`*.unknown-key`).
  bool typo = false;
  std::optional<std::string> meant;  ///< the known key it resembles or stands for
  std::string message;               ///< "unknown key "depth": did you mean "cut_z"? (...)"
};
/// The refusal of `key`, which is not in `known`: a likely typo names the
/// key it resembles; a word bezcam knows under another name (`depth`,
/// `stock`, `diameter`, `rpm` ...) names that key when it is in `known`;
/// any other key says how to keep data of one's own ("x-"). `prefix`
/// (such as "tabs.") is put before the key and the known key in the
/// message.
UnknownKey unknown_key(std::string_view key, std::span<const std::string_view> known, std::string_view prefix = {});

/// What is wrong with a line of G-code given as a template (a job's
/// `before` / `after`): a line break, a '{' with no '}', or a placeholder
/// not in `known` (naming the one it resembles); nothing when it is fine.
std::optional<std::string> template_problem(std::string_view text, std::span<const std::string_view> known);

}  // namespace bezcam
