#include "bezcam/verify/verify_report.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

#include "bezcam/format.hpp"

namespace bezcam {

namespace {

using json = nlohmann::ordered_json;

json place(const StockPlace& p) { return json::array({p.x, p.y, p.z}); }

json tool_json(int number, const ToolShape& t) {
  json j{{"tool", number}, {"shape", to_string(t.kind())}, {"diameter", t.diameter()}};
  if (t.kind() == ToolShapeKind::bull) j["corner_radius"] = t.corner_radius();
  if (t.kind() == ToolShapeKind::vee) j["angle"] = t.angle_deg();
  if (t.kind() == ToolShapeKind::drill) j["point_angle"] = t.angle_deg();
  return j;
}

json entity_json(const EntityCheck& e) {
  json j{{"entity", e.label}};
  if (!e.json_path.empty()) j["path"] = e.json_path;
  if (!e.compared) {
    j["compared"] = false;
    j["reason"] = e.not_compared;
    return j;
  }
  j["gouge"] =
      json{{"largest", e.gouge}, {"at", place(e.gouge_at)}, {"columns", e.gouge_columns}, {"volume", e.gouge_volume}};
  if (e.gouge_at_least) j["gouge"]["at_least"] = true;
  j["excess"] = json{
      {"largest", e.excess}, {"at", place(e.excess_at)}, {"columns", e.excess_columns}, {"volume", e.excess_volume}};
  return j;
}

std::string mm(double v) { return format_significant(v, 4) + " mm"; }
std::string at(const StockPlace& p) {
  return "(" + format_fixed(p.x, 3) + ", " + format_fixed(p.y, 3) + ", " + format_fixed(p.z, 3) + ")";
}

}  // namespace

std::string verify_report_json(const VerifyFigures& f) {
  json j;
  j["program"] = f.program;
  j["machine"] = f.machine;
  j["units"] = "mm";
  j["program_units"] = to_string(f.units);
  j["stock"] = json{{"box", json::array({f.box.x0, f.box.y0, f.box.z0, f.box.x1, f.box.y1, f.box.z1})},
                    {"cell", f.cell},
                    {"columns", json::array({f.nx, f.ny})},
                    {"memory_bytes", f.memory_bytes}};
  j["heightmap"] = json{{"shape", json::array({f.ny, f.nx})},
                        {"first_column_center", json::array({f.box.x0 + f.cell / 2, f.box.y0 + f.cell / 2})},
                        {"cell", f.cell}};
  json tools = json::array();
  for (const auto& [n, t] : f.tools) tools.push_back(tool_json(n, t));
  j["tools"] = tools;
  j["blocks"] = f.blocks;
  j["column_evaluations"] = json{{"all", f.sweep.columns}, {"searched", f.sweep.searched_columns}};
  j["removed_volume"] = f.removed_volume;
  j["deepest_floor"] = json{{"z", f.deepest.z}, {"x", f.deepest.x}, {"y", f.deepest.y}};
  j["hash"] = f.hash;
  j["added_error"] = f.added_error;
  j["rapids_through_material"] = json{{"count", f.rapid_cuts}};
  if (f.rapid_cuts) j["rapids_through_material"]["first_line"] = f.first_rapid_cut_line;
  if (f.cycle_time_s) j["cycle_time_s"] = *f.cycle_time_s;
  j["verify_time_s"] = f.verify_seconds;
  if (f.design) {
    const DesignCheck& d = *f.design;
    json dj{{"job", f.design_file},
            {"tolerance", d.tolerance},
            {"design_bound", d.design_bound},
            {"largest_gouge", d.max_gouge()},
            {"gouged", d.gouged()}};
    json ents = json::array();
    for (const EntityCheck& e : d.entities) ents.push_back(entity_json(e));
    dj["entities"] = ents;
    if (d.elsewhere.gouge > 0) dj["elsewhere"] = entity_json(d.elsewhere);
    j["design"] = dj;
  }
  return j.dump(2) + "\n";
}

std::string verify_summary(const VerifyFigures& f) {
  std::ostringstream o;
  o << "stock " << fmt_num(f.box.x0) << "," << fmt_num(f.box.y0) << "," << fmt_num(f.box.z0) << "," << fmt_num(f.box.x1)
    << "," << fmt_num(f.box.y1) << "," << fmt_num(f.box.z1) << " mm at " << mm(f.cell) << " cells (" << f.nx << " x "
    << f.ny << " columns, " << format_significant(f.memory_bytes / (1 << 20), 3) << " MiB)\n";
  o << "removed " << format_significant(f.removed_volume, 6) << " mm^3; deepest floor z "
    << format_fixed(f.deepest.z, 4) << " mm at (" << format_fixed(f.deepest.x, 3) << ", "
    << format_fixed(f.deepest.y, 3) << ")\n";
  if (f.cycle_time_s) o << "cycle time " << format_fixed(*f.cycle_time_s, 1) << " s on machine " << f.machine << "\n";
  if (f.added_error > 0) o << "curve blocks swept within " << mm(f.added_error) << " of their exact path\n";
  if (f.rapid_cuts)
    o << "warning: " << f.rapid_cuts << " rapid move" << (f.rapid_cuts == 1 ? "" : "s")
      << " cut material, the first at line " << f.first_rapid_cut_line << "\n";
  if (f.design) {
    const DesignCheck& d = *f.design;
    for (const EntityCheck& e : d.entities) {
      if (!e.compared) {
        o << e.label << ": not compared: " << e.not_compared << "\n";
        continue;
      }
      o << e.label << ": largest gouge " << (e.gouge_at_least ? "at least " : "") << mm(e.gouge);
      if (e.gouge > 0) o << " at " << at(e.gouge_at);
      o << ", largest excess " << mm(e.excess);
      if (e.excess > 0) o << " at " << at(e.excess_at);
      o << "\n";
    }
    if (d.elsewhere.gouge > 0)
      o << "away from every wall: gouge " << (d.elsewhere.gouge_at_least ? "at least " : "") << mm(d.elsewhere.gouge)
        << " at " << at(d.elsewhere.gouge_at) << "\n";
    o << (d.gouged() ? "GOUGED: the part is cut deeper than the tolerance " : "no gouge beyond the tolerance ")
      << mm(d.tolerance) << "\n";
  }
  o << "hash " << f.hash << "\n";
  return o.str();
}

}  // namespace bezcam
