#pragma once
/// A warning's kind: each warning bezcam gives about a job ends with its
/// kind in brackets (`... material is left at (3, 4) [material-left]`),
/// the name `--no-warn KIND` silences (docs/cli.md, "Warnings").
#include <string>
#include <string_view>
#include <vector>

namespace bezcam {

/// The kinds, in the order docs/cli.md lists them.
inline constexpr std::string_view kWarningKinds[] = {
    "material-left",      // the tool cannot reach part of the curve
    "tabs-skipped",       // a stretch too short for its tabs is cut without them
    "lead-shortened",     // a lead shortened to fit
    "direction-ignored",  // `direction` on a curve cut on the line
    "nested-outside",     // a contour cut outside lies in another cut outside
    "nested-pocket",      // a pocket region inside another's curve
    "output-replaced",    // an output mode the machine lacks, or blocks not exact
    "gap-closed",         // a drawing's gap closed by the join tolerance
    "contours-cross",     // a drawing's contours cross (sides by nesting)
    "font-substituted",   // a drawing's text style names a font that is not installed
};

/// `text` with its kind appended: `text [kind]`. `kind` is one of kWarningKinds.
std::string tagged_warning(std::string text, std::string_view kind);
/// The kind a warning ends with; empty when it has none.
std::string warning_kind(std::string_view warning);
/// Whether `kind` is one of kWarningKinds.
bool is_warning_kind(std::string_view kind);
/// Warnings of one kind on one entity (the text before the first ": ")
/// as one line: the first of them, with how many there are; the others
/// keep their place. Untagged warnings are kept as they are.
std::vector<std::string> grouped_warnings(const std::vector<std::string>& warnings);

}  // namespace bezcam
