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
/// no layer and no id of the drawing (contours and texts), naming the
/// layers and ids it has, and a text's key (`font`, `text`) whose selector
/// picks no text.
void check_selectors(const Drawing& d, const ImportOptions& opt);

/// The contours of `kept` that `opt.only` selects (all when empty) and
/// `opt.skip` does not, in their order.
std::vector<const Contour*> select_contours(const std::vector<const Contour*>& kept, const ImportOptions& opt);

/// The members (key, JSON text) of the entity a contour becomes beyond its
/// geometry: `side` by nesting (empty: none) unless a scoped setting gives
/// one, then the scoped settings that select it, merged in order.
std::vector<std::pair<std::string, std::string>> entity_members(const std::string& layer, const std::string& id,
                                                                const ImportOptions& opt,
                                                                const std::string& nesting_side);
std::vector<std::pair<std::string, std::string>> entity_members(const Contour& c, const ImportOptions& opt,
                                                                const std::string& nesting_side);

/// Refuses a scoped setting whose selector is `<outside>` or `<inside>`
/// when no contour of `kept` has that side by nesting (`sides`, one per
/// contour of `kept`; empty when the job gives no side).
void check_nesting_selectors(const ImportOptions& opt, const std::vector<std::string>& sides,
                             const std::string& source);

/// Whether a scoped setting's key is a text's own (`font`, `text`): given
/// to the texts it picks, not to their cutting parameters.
bool is_text_key(const std::string& key);

/// A refusal of a contour's entity members `e` named at the scoped setting
/// that gave the refused key (`settings.SELECTOR:KEY` of file `source`);
/// `e` itself when no scoped setting gave it.
InputError at_scoped_setting(const InputError& e, const std::string& layer, const std::string& id,
                             const ImportOptions& opt, const std::string& source);
inline InputError at_scoped_setting(const InputError& e, const Contour& c, const ImportOptions& opt,
                                    const std::string& source) {
  return at_scoped_setting(e, c.layer, c.id, opt, source);
}

}  // namespace bezcam::import
