#pragma once
// Which contours of a drawing a job cuts (--only, --skip) and the settings
// of each (--set SELECTOR:KEY=VALUE).
#include <string>
#include <utility>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/import/drawing.hpp"

namespace bezcam::import {

/// Refuses a selector of `opt` (scoped settings, only, skip) that matches
/// no layer and no id of the drawing, naming the layers and ids it has.
void check_selectors(const Drawing& d, const ImportOptions& opt);

/// The contours of `kept` that `opt.only` selects (all when empty) and
/// `opt.skip` does not, in their order.
std::vector<const Contour*> select_contours(const std::vector<const Contour*>& kept, const ImportOptions& opt);

/// The members (key, JSON text) of the entity a contour becomes beyond its
/// geometry: `side` by nesting (empty: none) unless a scoped setting gives
/// one, then the scoped settings that select it, merged in order.
std::vector<std::pair<std::string, std::string>> entity_members(const Contour& c, const ImportOptions& opt,
                                                                const std::string& nesting_side);

/// A refusal of a contour's entity members `e` named at the scoped setting
/// that gave the refused key (`settings.SELECTOR:KEY` of file `source`);
/// `e` itself when no scoped setting gave it.
InputError at_scoped_setting(const InputError& e, const Contour& c, const ImportOptions& opt,
                             const std::string& source);

}  // namespace bezcam::import
