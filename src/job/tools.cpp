#include "bezcam/job/tools.hpp"

#include <algorithm>
#include <cmath>

#include "bezcam/error.hpp"

namespace bezcam {

namespace {

// What one entity says of its tool: a diameter, the shape where it says
// one, and where in the job that is set.
struct Claim {
  double diameter = 0;
  std::optional<ToolType> shape;
  size_t entity = 0;
  std::string where;
};

// Where the entity's value of `key` comes from: the entity, the job or
// the defaults.
template <class T>
std::string source_of(const Entity& e, const Job& job, const std::optional<T> JobParams::*member, const char* key) {
  if (e.params.*member) return e.json_path() + "." + key;
  if (job.params.*member) return std::string("job.") + key;
  return std::string("the machine profile's defaults.") + key;
}

// The diameter the entity is cut for: a surface's ball end (tool_radius
// > 0), a curve's tool_diameter (its offset, its slot); nothing when its
// cut uses neither.
std::optional<Claim> claim_of(const Entity& e, const Job& job, const JobParams& p) {
  Claim c;
  c.entity = e.index;
  if (e.surface) {
    if (!p.tool_radius || !(*p.tool_radius > 0)) return std::nullopt;
    c.diameter = 2 * *p.tool_radius;
    c.shape = ToolType::ball;
    c.where = source_of(e, job, &JobParams::tool_radius, "tool_radius");
    return c;
  }
  if (!p.tool_diameter) return std::nullopt;
  c.diameter = *p.tool_diameter;
  c.where = source_of(e, job, &JobParams::tool_diameter, "tool_diameter");
  return c;
}

bool same_diameter(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

// Where the entity or its job gives `key`: the JSON path, or nothing.
template <class T>
std::optional<std::string> given_at(const Entity& e, const Job& job, const std::optional<T> JobParams::*member,
                                    const char* key) {
  if (e.params.*member) return e.json_path() + "." + key;
  if (job.params.*member) return std::string("job.") + key;
  return std::nullopt;
}

// " for entity ID" where a job-wide key is refused for one entity.
std::string for_entity(const std::string& at, const Entity& e) {
  return at.starts_with("job.") ? " for " + e.label() : std::string();
}

// The entry's diameter (or a ball's radius) in place of what the entity
// would take from the defaults; a different value given by the entity or
// the job is refused, naming both.
void apply_entry(const Job& job, const Entity& e, const ToolEntry& t, JobParams& given) {
  const std::string u = to_string(job.units);
  const std::string entry = tool_entry_path("tools", std::to_string(t.number));
  const std::string tool = "tool " + std::to_string(t.number) + " is a " + fmt_num(t.diameter) + " " + u + " " +
                           to_string(t.shape) + " in the job's tool table (" + entry + ".diameter)";
  if (e.surface) {
    const auto at = given_at(e, job, &JobParams::tool_radius, "tool_radius");
    const double r = t.diameter / 2;
    if (at && *given.tool_radius > 0 && (t.shape != ToolType::ball || !same_diameter(*given.tool_radius, r)))
      throw InputError(errc::job_tool, Place::in_json(job.source, *at),
                       tool + ", but " + *at + " gives a ball end of radius " + fmt_num(*given.tool_radius) + " " + u +
                           for_entity(*at, e) + ": " +
                           (t.shape == ToolType::ball
                                ? "remove \"tool_radius\" (the table gives " + fmt_num(r) + ") or make the two agree"
                                : std::string("remove \"tool_radius\", or pick a ball tool")));
    if (!at) given.tool_radius = t.shape == ToolType::ball ? r : 0.0;
    return;
  }
  if (const auto at = given_at(e, job, &JobParams::tool_diameter, "tool_diameter")) {
    if (!same_diameter(*given.tool_diameter, t.diameter))
      throw InputError(errc::job_tool, Place::in_json(job.source, *at),
                       tool + ", but " + *at + " gives " + fmt_num(*given.tool_diameter) + " " + u +
                           for_entity(*at, e) +
                           ": one tool has one diameter; remove \"tool_diameter\" (the table gives it) or make the "
                           "two agree");
  }
  given.tool_diameter = t.diameter;
  if (t.flute_length && given.step_down && *given.step_down > *t.flute_length * (1 + 1e-9)) {
    const std::string at = *given_at(e, job, &JobParams::step_down, "step_down");
    throw InputError(errc::job_cut, Place::in_json(job.source, at),
                     "step_down " + fmt_num(*given.step_down) + " " + u + for_entity(at, e) +
                         " is deeper than the flute length of tool " + std::to_string(t.number) + ", " +
                         fmt_num(*t.flute_length) + " " + u + " (" + entry +
                         ".flute_length): one pass would bury the tool beyond its flutes; make step_down at most " +
                         fmt_num(*t.flute_length) + ", or leave it out: the passes are then split at the flute length");
  }
}

}  // namespace

const ToolEntry* entity_tool_entry(const Job& job, const Entity& e, const JobParams& defaults) {
  if (job.tools.empty()) return nullptr;
  const std::optional<int> n = e.params.tool ? e.params.tool : job.params.tool ? job.params.tool : defaults.tool;
  return n ? job.tools.find(*n) : nullptr;
}

JobParams entity_params(const Job& job, const Entity& e, const JobParams& defaults) {
  JobParams given = e.params.over(job.params);
  if (job.tools.empty()) return given.over(defaults);
  const std::optional<int> n = given.tool ? given.tool : defaults.tool;
  if (!n) return given.over(defaults);  // the machine's default tool, not known yet
  const ToolEntry* t = job.tools.find(*n);
  if (!t) {
    const auto at = given_at(e, job, &JobParams::tool, "tool");
    const std::string which = at ? "tool " + std::to_string(*n) + for_entity(*at, e)
                                 : e.label() + " names no tool, so it is cut with the machine profile's default tool " +
                                       std::to_string(*n) + ", which";
    throw InputError(errc::job_tool, Place::in_json(job.source, at ? *at : e.json_path()),
                     which + " is not in the job's tool table (it has tool" +
                         (job.tools.entries.size() == 1 ? " " : "s ") + job.tools.numbers() +
                         "): add it to \"tools\", or pick a tool the table has");
  }
  apply_entry(job, e, *t, given);
  return given.over(defaults);
}

std::vector<JobTool> job_tools(const Job& job, const JobParams& defaults) {
  std::vector<JobTool> tools;
  std::vector<std::optional<Claim>> first;  // per tool: the claim the others must agree with
  for (const Entity& e : job.entities) {
    const JobParams p = entity_params(job, e, defaults);
    const int number = p.tool.value_or(-1);
    auto it = std::find_if(tools.begin(), tools.end(), [&](const JobTool& t) { return t.number == number; });
    if (it == tools.end()) {
      tools.push_back({number, std::nullopt, ToolType::flat, std::nullopt, {}});
      first.emplace_back();
      it = tools.end() - 1;
    }
    it->entities.push_back(e.index);
    if (const ToolEntry* t = entity_tool_entry(job, e, defaults)) {  // the table's, checked by entity_params()
      it->diameter = t->diameter;
      it->shape = t->shape;
      it->entry = *t;
      continue;
    }
    const std::optional<Claim> c = claim_of(e, job, p);
    if (!c) continue;
    std::optional<Claim>& f = first[static_cast<size_t>(it - tools.begin())];
    if (!f) {
      f = c;
      it->diameter = c->diameter;
      if (c->shape) it->shape = *c->shape;
      continue;
    }
    const bool diameters = !same_diameter(f->diameter, c->diameter);
    if (!diameters && !(f->shape && c->shape && *f->shape != *c->shape)) {
      if (c->shape) it->shape = *c->shape;
      continue;
    }
    const std::string u = to_string(job.units);
    const auto told = [&](const Claim& k) {
      return fmt_num(k.diameter) + " " + u + (k.shape ? std::string(" ") + to_string(*k.shape) : std::string()) +
             " for " + job.entities[k.entity].label() + " (" + k.where + ")";
    };
    const std::string tool =
        number < 0 ? std::string("the default tool (no \"tool\" given)") : "tool " + std::to_string(number);
    throw InputError(errc::job_tool, Place::in_json(job.source, e.json_path()),
                     tool + " is given two " + (diameters ? "diameters: " : "shapes: ") + told(*f) + " and " +
                         told(*c) +
                         "; one tool number is one tool, and whichever is loaded cuts one of them wrong: give each "
                         "its own \"tool\" number, or both one " +
                         (diameters ? "diameter" : "shape"));
  }
  return tools;
}

}  // namespace bezcam
