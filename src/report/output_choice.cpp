#include "output_choice.hpp"

#include <algorithm>
#include <cstdio>

#include "bezcam/report/motion_report.hpp"
#include "plan_json.hpp"

namespace bezcam::detail {

namespace {

const char* plural(size_t n, const char* one, const char* more) { return n == 1 ? one : more; }

// "output best: arcs for 4 entities, lines for 2 (cycle ... against ...)".
std::string best_line(const ProgramReport& r, const OutputChoice& c) {
  std::vector<std::pair<size_t, OutputMode>> counts;
  for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
    size_t n = 0;
    for (const EntityChoice& e : c.entities) n += c.output_of(e.entity) == mode;
    if (n) counts.push_back({n, mode});
  }
  std::stable_sort(counts.begin(), counts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string s = "bezcam: output best: ";
  for (size_t i = 0; i < counts.size(); ++i)
    s += std::string(i ? ", " : "") + to_string(counts[i].second) + " for " + (c.whole ? "all " : "") +
         std::to_string(counts[i].first) + (i == 0 ? plural(counts[i].first, " entity", " entities") : "");
  if (c.whole) s += " (that mode's program planned whole is shorter than the choice per entity)";
  if (r.planned) {
    s += " (cycle " + format_seconds(r.planned->cycle_time_s) + " against ";
    for (size_t i = 0; i < c.modes.size(); ++i)
      s += std::string(i ? ", " : "") + format_seconds(c.modes[i].cycle_time_s) + " in " + to_string(c.modes[i].output);
    s += ")";
  }
  return s + "\n";
}

// Each entity's planned time and blocks per mode, the shortest marked.
std::string entity_table(const OutputChoice& c, size_t max_entities) {
  size_t width = 6;
  for (const EntityChoice& e : c.entities) width = std::max(width, std::min<size_t>(e.label.size(), 24));
  std::string s =
      "  per entity, the planned time of its moves in each output mode (cutting blocks); * the shortest (within "
      "1 us: the fewest blocks):\n";
  char b[96];
  std::snprintf(b, sizeof b, "    %-*s", static_cast<int>(width), "entity");
  s += b;
  for (const OutputTiming& t : c.modes) {
    std::snprintf(b, sizeof b, "  %-24s", to_string(t.output));
    s += b;
  }
  while (s.back() == ' ') s.pop_back();
  s += "\n";
  for (size_t k = 0; k < c.entities.size() && k < max_entities; ++k) {
    const EntityChoice& e = c.entities[k];
    std::snprintf(b, sizeof b, "    %-*s", static_cast<int>(width), e.label.substr(0, width).c_str());
    s += b;
    for (const OutputTiming& t : c.modes) {
      const std::string cell = !t.entity_moves[e.entity] ? std::string("-")
                                                         : format_time(t.entity_time_s[e.entity]) + " (" +
                                                               std::to_string(t.entity_blocks[e.entity]) + ")" +
                                                               (t.output == e.output ? " *" : "");
      std::snprintf(b, sizeof b, "  %-24s", cell.c_str());
      s += b;
    }
    while (!s.empty() && s.back() == ' ') s.pop_back();
    s += "\n";
  }
  if (c.entities.size() > max_entities)
    s += "    ... and " + std::to_string(c.entities.size() - max_entities) + " more " +
         plural(c.entities.size() - max_entities, "entity", "entities") + "\n";
  return s;
}

}  // namespace

std::string output_choice_text(const ProgramReport& r, size_t max_entities) {
  if (!r.choice) return {};
  const OutputChoice& c = *r.choice;
  std::string s;
  if (r.output_name == "best") s += best_line(r, c);
  for (const std::string& why : c.left_out) s += "bezcam: output best: left out " + why + "\n";
  if (!r.alternatives.empty()) s += entity_table(c, max_entities);
  if (!c.nurbs_note.empty()) s += "  " + c.nurbs_note + "\n";
  return s;
}

std::string alternatives_text(const ProgramReport& r) {
  if (r.alternatives.empty()) return {};
  double shortest = r.alternatives.front().planned.cycle_time_s;
  for (const auto& a : r.alternatives) shortest = std::min(shortest, a.planned.cycle_time_s);
  std::string s = "  the same job in each output mode on machine " + r.machine + ":\n";
  const bool bound = r.path_bound_s > 0;
  s += std::string("    output  blocks   cycle        mean feed  starved") + (bound ? "  path/bound" : "") + "\n";
  for (const auto& a : r.alternatives) {
    char b[220], ratio[32] = "";
    if (bound && a.planned.path_time_s > 0)
      std::snprintf(ratio, sizeof ratio, "x%.3f", a.planned.path_time_s / r.path_bound_s);
    const bool self = a.best ? r.output_name == "best" : r.output_name != "best" && a.output == r.output;
    const bool fastest = a.planned.cycle_time_s == shortest;
    const std::string mark = self && fastest ? "   (this program, the shortest)"
                             : self          ? "   (this program)"
                             : fastest       ? "   (the shortest)"
                                             : "";
    std::snprintf(
        b, sizeof b,
        bound ? "    %-6s  %6zu   %-11s  %5.0f %%    %-7zu%s%s\n" : "    %-6s  %6zu   %-11s  %5.0f %%    %zu%s%s\n",
        a.best ? "best" : to_string(a.output), a.blocks, format_seconds(a.planned.cycle_time_s).c_str(),
        a.planned.mean_feed_ratio * 100, a.planned.starved_blocks, ratio, mark.c_str());
    s += b;
  }
  return s;
}

nlohmann::ordered_json output_choice_json(const ProgramReport& r) {
  nlohmann::ordered_json j;
  const OutputChoice& c = *r.choice;
  j["tie_s"] = kOutputTie;
  auto& modes = j["modes"] = nlohmann::ordered_json::array();
  for (const OutputTiming& t : c.modes)
    modes.push_back({{"output", to_string(t.output)},
                     {"cycle_time_s", round_to(t.cycle_time_s, 1e-6)},
                     {"cutting_blocks", t.blocks}});
  auto& ents = j["entities"] = nlohmann::ordered_json::array();
  for (const EntityChoice& e : c.entities) {
    nlohmann::ordered_json x;
    x["index"] = e.entity;
    x["label"] = e.label;
    x["shortest"] = to_string(e.output);
    if (r.output_name == "best") x["output"] = to_string(c.output_of(e.entity));
    x["offset"] = e.offset;
    auto& times = x["time_s"];
    auto& blocks = x["blocks"];
    for (const OutputTiming& t : c.modes) {
      if (!t.entity_moves[e.entity]) continue;
      times[to_string(t.output)] = round_to(t.entity_time_s[e.entity], 1e-9);
      blocks[to_string(t.output)] = t.entity_blocks[e.entity];
    }
    ents.push_back(std::move(x));
  }
  if (r.output_name == "best") {
    j["cycle_time_s"] = round_to(c.cycle_time_s, 1e-6);
    if (c.whole) j["whole_mode"] = to_string(*c.whole);
  }
  if (!c.nurbs_note.empty()) j["nurbs_note"] = c.nurbs_note;
  if (!c.left_out.empty()) j["left_out"] = c.left_out;
  return j;
}

}  // namespace bezcam::detail
