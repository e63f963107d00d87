#include "bezcam/job/tools.hpp"

#include <algorithm>
#include <cmath>

#include "bezcam/error.hpp"

namespace bezcam {

const char* to_string(ToolEnd s) { return s == ToolEnd::ball ? "ball end mill" : "flat end mill"; }

namespace {

// What one entity says of its tool: a diameter, the shape where it says
// one, and where in the job that is set.
struct Claim {
  double diameter = 0;
  std::optional<ToolEnd> shape;
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
    c.shape = ToolEnd::ball;
    c.where = source_of(e, job, &JobParams::tool_radius, "tool_radius");
    return c;
  }
  if (!p.tool_diameter) return std::nullopt;
  c.diameter = *p.tool_diameter;
  c.where = source_of(e, job, &JobParams::tool_diameter, "tool_diameter");
  return c;
}

bool same_diameter(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

}  // namespace

std::vector<JobTool> job_tools(const Job& job, const JobParams& defaults) {
  std::vector<JobTool> tools;
  std::vector<std::optional<Claim>> first;  // per tool: the claim the others must agree with
  const JobParams base = job.params.over(defaults);
  for (const Entity& e : job.entities) {
    const JobParams p = e.params.over(base);
    const int number = p.tool.value_or(-1);
    auto it = std::find_if(tools.begin(), tools.end(), [&](const JobTool& t) { return t.number == number; });
    if (it == tools.end()) {
      tools.push_back({number, std::nullopt, ToolEnd::flat, {}});
      first.emplace_back();
      it = tools.end() - 1;
    }
    it->entities.push_back(e.index);
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
