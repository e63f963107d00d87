#include "bezcam/warnings.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace bezcam {

std::string tagged_warning(std::string text, std::string_view kind) {
  return std::move(text) + " [" + std::string(kind) + "]";
}

std::string warning_kind(std::string_view w) {
  if (w.empty() || w.back() != ']') return {};
  const size_t open = w.rfind(" [");
  if (open == std::string_view::npos) return {};
  const std::string kind(w.substr(open + 2, w.size() - open - 3));
  return is_warning_kind(kind) ? kind : std::string();
}

bool is_warning_kind(std::string_view kind) {
  return std::find(std::begin(kWarningKinds), std::end(kWarningKinds), kind) != std::end(kWarningKinds);
}

std::vector<std::string> grouped_warnings(const std::vector<std::string>& warnings) {
  // (entity, kind) -> the warnings' positions
  std::map<std::pair<std::string, std::string>, std::vector<size_t>> groups;
  for (size_t i = 0; i < warnings.size(); ++i) {
    const std::string kind = warning_kind(warnings[i]);
    const size_t colon = warnings[i].find(": ");
    if (kind.empty() || colon == std::string::npos) continue;
    groups[{warnings[i].substr(0, colon), kind}].push_back(i);
  }
  std::vector<std::string> out;
  for (size_t i = 0; i < warnings.size(); ++i) {
    const std::string kind = warning_kind(warnings[i]);
    const size_t colon = warnings[i].find(": ");
    if (kind.empty() || colon == std::string::npos) {
      out.push_back(warnings[i]);
      continue;
    }
    const auto& at = groups[{warnings[i].substr(0, colon), kind}];
    if (at.front() != i) continue;  // said with the first of its group
    if (at.size() == 1) {
      out.push_back(warnings[i]);
      continue;
    }
    const std::string& w = warnings[i];
    const size_t tag = w.size() - kind.size() - 3;
    out.push_back(w.substr(0, tag) + " (" + std::to_string(at.size()) + " warnings of this kind on " +
                  w.substr(0, colon) + "; the first shown)" + w.substr(tag));
  }
  return out;
}

}  // namespace bezcam
