#pragma once
// A drawing's texts as the job's `text` entities: which are kept, and the
// text, font, em size, baseline point, alignment and angle each becomes.
#include <set>
#include <string>
#include <vector>

#include "bezcam/import/drawing.hpp"
#include "bezcam/job/text.hpp"

namespace bezcam::import {

/// The texts of the kept layers that --only and --skip keep, in the
/// drawing's order.
std::vector<const DrawingText*> kept_texts(const Drawing& d, const std::set<std::string>& keep,
                                           const ImportOptions& opt);

/// The `text` entity `t` becomes (millimetres): its font the one a scoped
/// `font` setting gives, else the style's (fontconfig's sans-serif when it
/// is not installed, a warning of kind font-substituted appended to
/// `warnings`); the em size that makes the capitals `t.height` high (or,
/// aligned, the line as long as its two points are apart); the baseline's
/// point for the alignment. Throws InputError: import.text for a stroke
/// font no setting replaces, text.unavailable without opt.fonts.
TextSpec text_spec(const DrawingText& t, const ImportOptions& opt, const std::string& source,
                   std::vector<std::string>* warnings);

}  // namespace bezcam::import
