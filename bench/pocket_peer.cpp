// bezcam's pocket check on any program, for the comparison with FreeCAD's
// Adaptive (bench/pocket_peer.sh, docs/benchmarks.md). The cases are those
// of bench/pocket_peer/cases.json.
//
//   build/pocket_peer job CASES.json INDEX PATTERN   the case as a bezcam job (stdout)
//   build/pocket_peer check CASES.json INDEX PROGRAM.ngc
//
// `check` reads the program's text (LinuxCNC's dialect), replays its
// moves and runs check_pocket() on them against the case's walls, the
// same check bezcam's own programs carry in their header, with the case's
// `load` (adaptive's bound, arccos(1 - load / r) + 2 degrees, and the
// material near the unreachable places left out): largest engagement
// and where, uncut area against its limit, the tool centre's
// nearest approach to a wall, G00 moves below the stock's top; then the
// length cut and the cycle time on the linuxcnc profile's motion model.
// One line of JSON.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "bezcam/cam/pocket_check.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/machine/planner.hpp"

using namespace bezcam;
using nlohmann::json;

namespace {

constexpr double kSag = 0.001;  // circles as polygons within this (as freecad_adaptive.py)

std::string read_file(const char* path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "pocket_peer: cannot read %s\n", path);
    std::exit(3);
  }
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// The case's loops as bezcam path entities: polygons of lines, circles as
// four rational quadratics (exact).
std::string entities(const json& loops) {
  std::string out;
  for (const json& l : loops) {
    std::string s = R"({"type":"path","closed":true,"segments":[)";
    if (l.is_object()) {
      const double cx = l["circle"][0], cy = l["circle"][1], r = l["circle"][2];
      for (int k = 0; k < 4; ++k) {
        const double a0 = k * std::numbers::pi / 2, a1 = a0 + std::numbers::pi / 2;
        s += std::string(k ? "," : "") + R"({"type":"bezier","points":[[)" + num(cx + r * std::cos(a0)) + "," +
             num(cy + r * std::sin(a0)) + "],[" + num(cx + r * (std::cos(a0) - std::sin(a0))) + "," +
             num(cy + r * (std::sin(a0) + std::cos(a0))) + "],[" + num(cx + r * std::cos(a1)) + "," +
             num(cy + r * std::sin(a1)) + "]],\"weights\":[1," + num(std::sqrt(0.5)) + ",1]}";
      }
    } else {
      for (size_t i = 0; i < l.size(); ++i) {
        const json &a = l[i], &b = l[(i + 1) % l.size()];
        s += std::string(i ? "," : "") + R"({"type":"bezier","points":[[)" + num(a[0]) + "," + num(a[1]) + "],[" +
             num(b[0]) + "," + num(b[1]) + "]]}";
      }
    }
    out += (out.empty() ? "" : ",") + s + "]}";
  }
  return out;
}

PocketLoops walls(const json& loops) {
  PocketLoops out;
  for (const json& l : loops) {
    std::vector<Vec3> w;
    if (l.is_object()) {
      const double cx = l["circle"][0], cy = l["circle"][1], r = l["circle"][2];
      const int n = std::max(8, static_cast<int>(std::ceil(std::numbers::pi / std::acos(1 - kSag / r))));
      for (int k = 0; k < n; ++k)
        w.push_back({cx + r * std::cos(2 * std::numbers::pi * k / n), cy + r * std::sin(2 * std::numbers::pi * k / n)});
    } else {
      for (const json& p : l) w.push_back({p[0].get<double>(), p[1].get<double>()});
    }
    out.push_back(std::move(w));
  }
  return out;
}

int job(const json& doc, const json& c, const std::string& pattern) {
  const double d = c["tool_diameter"];
  std::string keys = R"("tool_diameter":)" + num(d) + R"(,"pattern":")" + pattern + "\"";
  keys += pattern == "adaptive" ? R"(,"load":)" + num(c["load"]) : R"(,"stepover":)" + num(c["stepover"]);
  std::printf(R"({"bezcam":1,"tolerance":%s,"machine":"linuxcnc","job":{"feed":1000,"plunge_feed":300,"safe_z":5,)"
              R"("top_z":0,"clearance":1,"cut_z":%s,"operation":"pocket","region":"p",%s},"entities":[%s]})"
              "\n",
              num(doc["tolerance"]).c_str(), num(doc["cut_z"]).c_str(), keys.c_str(), entities(c["loops"]).c_str());
  return 0;
}

int check(const json& doc, const json& c, const char* program) {
  const std::string text = read_file(program);
  const MachineProfile lcnc = load_machine_profile(std::string(BEZCAM_SOURCE_DIR) + "/machines/linuxcnc.json");
  const std::vector<MotionBlock> blocks = read_gcode(text, &lcnc);
  std::vector<Move> moves;
  double length = 0;
  for (const MotionBlock& b : blocks) {
    Move mv;
    if (b.kind == BlockKind::rapid) {
      mv.what = RapidMove{{b.to, kAxesXYZ, 0}};
    } else if (b.kind == BlockKind::arc_cw || b.kind == BlockKind::arc_ccw) {
      ArcMove a;
      a.to = b.to, a.feed = b.feed, a.center = b.center, a.ccw = b.kind == BlockKind::arc_ccw, a.plane = b.plane;
      mv.what = a;
    } else if (b.kind == BlockKind::linear) {
      mv.what = LineMove{{b.to, kAxesXYZ, b.feed}};
    } else {
      std::fprintf(stderr, "pocket_peer: %s line %d: only G0, G1, G2 and G3 are read\n", program, b.line);
      return 3;
    }
    moves.push_back(mv);
    if (b.kind != BlockKind::rapid) {
      Vec3 p = b.from;
      for (int k = 1; k <= 64; ++k) {
        const Vec3 q = evaluate_block(b, k / 64.0);
        length += std::hypot(q.x - p.x, q.y - p.y);
        p = q;
      }
    }
  }
  if (moves.empty()) {
    std::fprintf(stderr, "pocket_peer: %s has no motion\n", program);
    return 3;
  }
  PocketCheckInput in;
  in.walls = walls(c["loops"]);
  in.wall_bound = kSag;
  in.radius = c["tool_diameter"].get<double>() / 2;
  in.tolerance = doc["tolerance"];
  in.top_z = 0;
  in.levels = {doc["cut_z"].get<double>()};
  in.moves = &moves;
  in.from = 0;
  in.to = moves.size();
  in.start = blocks.front().from;
  // Every program is read with the case's load: the same material near
  // the unreachable places left out, the same bound on the engagement.
  in.load = c["load"];
  const PocketCertificate cert = check_pocket(in);
  Timeline tl;
  tl.blocks = blocks;
  const MotionPlan plan = plan_motion(tl, *lcnc.motion, PlanDetail::summary);
  json out = {{"length_mm", length},
              {"engagement_deg", cert.engagement_deg},
              {"engagement_at", {cert.engagement_at.x, cert.engagement_at.y}},
              {"engagement_bound_deg", cert.engagement_bound},
              {"uncut_mm2", cert.uncut_area},
              {"uncut_limit_mm2", cert.uncut_limit},
              {"unreachable_mm2", cert.unreachable_area},
              {"wall_distance_mm", cert.wall_distance},
              {"wall_distance_needed_mm", in.radius - in.tolerance},
              {"rapids_below_top", cert.rapids_in_material},
              {"cycle_s_linuxcnc", plan.cycle_time_s},
              {"blocks", blocks.size()},
              {"cell_mm", cert.cell}};
  std::printf("%s\n", out.dump().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5 || (std::strcmp(argv[1], "job") != 0 && std::strcmp(argv[1], "check") != 0)) {
    std::fprintf(stderr, "usage: pocket_peer job CASES.json INDEX PATTERN | check CASES.json INDEX PROGRAM.ngc\n");
    return 2;
  }
  const json doc = json::parse(read_file(argv[2]));
  const json& c = doc["cases"].at(static_cast<size_t>(std::atoi(argv[3])));
  try {
    return std::strcmp(argv[1], "job") == 0 ? job(doc, c, argv[4]) : check(doc, c, argv[4]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pocket_peer: %s\n", e.what());
    return 3;
  }
}
