// Which entities make one pocket region, and regions that lie inside one
// another (docs/pocket.md, "Regions").
#include <algorithm>
#include <map>

#include "bezcam/flatten/nesting.hpp"
#include "cut_emitters.hpp"

namespace bezcam::detail {

std::string region_of(const Entity& x, const CutParams& c) {
  return c.pocket.region.value_or(x.id.empty() ? x.label() : x.id);
}

std::vector<const Entity*> pocket_members(const Job& job, const Entity& e, const MachineProfile& m, const Program& p) {
  const std::string region = region_of(e, cut_params(job, e, m));
  for (const EntityReport& r : p.entities)
    if (r.type == "pocket" && r.label == region) return {};
  std::vector<const Entity*> out{&e};
  for (const Entity& o : job.entities) {
    if (&o == &e) continue;
    const CutParams c = cut_params(job, o, m);
    if (c.pocket.operation == Operation::pocket && region_of(o, c) == region) out.push_back(&o);
  }
  return out;
}

std::vector<std::string> nested_pocket_warnings(const Job& job, const MachineProfile& m) {
  std::vector<std::vector<Bezier>> curves;
  std::vector<const Entity*> who;
  std::vector<std::string> region;
  for (const Entity& e : job.entities) {
    if (e.surface || e.curve.pieces.empty()) continue;
    const CutParams c = cut_params(job, e, m);
    if (c.pocket.operation != Operation::pocket) continue;
    curves.push_back(e.curve.pieces);
    who.push_back(&e);
    region.push_back(region_of(e, c));
  }
  if (curves.size() < 2) return {};
  const Nesting n = nest_closed_curves(curves);
  std::vector<std::string> out;
  std::map<std::pair<std::string, std::string>, bool> said;
  for (size_t i = 0; i < curves.size(); ++i) {
    if (!n.parent[i] || region[*n.parent[i]] == region[i]) continue;
    const std::string& outer = region[*n.parent[i]];
    if (said[{region[i], outer}]) continue;
    said[{region[i], outer}] = true;
    out.push_back("pocket region \"" + region[i] + "\" (" + who[i]->label() + ") lies inside pocket region \"" + outer +
                  "\", which clears over it: right for a deeper pocket in a shallower one; to keep it as an island "
                  "of \"" +
                  outer + "\", give both the same \"region\" (a drawing: the setting region=NAME)");
  }
  return out;
}

}  // namespace bezcam::detail
