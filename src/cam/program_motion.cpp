#include "bezcam/cam/program_motion.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>

#include "bezcam/machine/cutter_comp.hpp"

namespace bezcam {

std::vector<MotionBlock> program_motion(const Program& p, std::vector<size_t>& source) {
  std::vector<MotionBlock> out;
  // A block per motion (compensation may add a few): no reallocation
  // moving every block of a long program.
  const auto motions = static_cast<size_t>(
      std::count_if(p.moves.begin(), p.moves.end(), [](const Move& mv) { return motion_of(mv) != nullptr; }));
  out.reserve(motions);
  source.clear();
  source.reserve(motions);
  for_each_motion_block(p, [&](MotionBlock& b, size_t at) {
    out.push_back(std::move(b));
    source.push_back(at);
  });
  return out;
}

std::vector<MotionBlock> program_motion(const Program& p) {
  std::vector<size_t> source;
  return program_motion(p, source);
}

void for_each_motion_block(const Program& p, const std::function<void(MotionBlock&, size_t)>& each) {
  Vec3 pos;
  unsigned known = 0;
  // G41/G42: the blocks are where the tool's centre goes (cutter_comp.hpp).
  CutterComp comp;
  size_t at = 0;  // the move being read
  auto add = [&](std::vector<MotionBlock> blocks) {
    for (auto& b : blocks) each(b, at);
  };
  for (; at < p.moves.size(); ++at) {
    const Move& mv = p.moves[at];
    if (const auto* cc = std::get_if<CompensationMove>(&mv.what)) {
      try {
        if (cc->side == 0)
          add(comp.off());
        else
          comp.on(cc->side, cc->radius);
      } catch (const CompensationError& e) {
        throw std::logic_error(std::string("built program: ") + e.what());
      }
      continue;
    }
    const Motion* mo = motion_of(mv);
    if (!mo) continue;  // no motion
    MotionBlock b;
    b.entity = mv.entity;
    b.kind = BlockKind::linear;
    if (is_rapid(mv)) b.kind = BlockKind::rapid;
    if (const auto* arc = std::get_if<ArcMove>(&mv.what)) {
      b.kind = arc->ccw ? BlockKind::arc_ccw : BlockKind::arc_cw;
      b.center = arc->center;
      b.plane = arc->plane;
    }
    if (const auto* cv = std::get_if<CurveMove>(&mv.what)) {
      b.kind = cv->shape->form == CurveMove::Form::bezier ? BlockKind::bezier : BlockKind::nurbs;
      b.ctrl = cv->shape->ctrl;
      b.weights = cv->shape->weights;
      b.knots = cv->shape->knots;
      b.order =
          cv->shape->form == CurveMove::Form::bezier ? static_cast<int>(cv->shape->ctrl.size()) : cv->shape->order;
    }
    Vec3 to = pos;
    for (int a = 0; a < 3; ++a)
      if (mo->axes & (1u << a)) to[a] = mo->to[a];
    Vec3 from = pos;
    for (int a = 0; a < 3; ++a)
      if (!(known & (1u << a))) from[a] = to[a];
    b.from = from;
    // The axes not set yet start where the machine stands (the planner
    // takes them from Timeline::start), as the reader marks them.
    b.from_known = known & 7u;
    b.to = to;
    b.feed = b.kind == BlockKind::rapid ? 0 : mo->feed;
    pos = to;
    known |= mo->axes;
    if (comp.idle()) {  // no compensation: the block as it is
      each(b, at);
      continue;
    }
    try {
      add(comp.push(b));
    } catch (const CompensationError& e) {
      throw std::logic_error(std::string("built program: ") + e.what());
    }
  }
  at = p.moves.empty() ? 0 : p.moves.size() - 1;
  add(comp.finish());
}

namespace {

// Which moves of `p` cut along an entity's curve with a time-optimal bound;
// empty when none does.
std::vector<char> moves_on_path(const Program& p) {
  std::vector<char> cut;
  for (const EntityReport& e : p.entities) {
    if (!(e.time_bound_s > 0) || e.cut_end > p.moves.size()) continue;
    cut.resize(p.moves.size(), 0);
    for (size_t i = e.cut_first; i < e.cut_end; ++i) cut[i] = 1;
  }
  return cut;
}

// A built program's pauses: tool changes, spindle starts and dwells.
void add_pauses(const Program& p, Timeline& tl) {
  size_t motions = 0;
  for (const Move& mv : p.moves) {
    if (motion_of(mv)) {
      ++motions;
      continue;
    }
    if (const auto* d = std::get_if<Dwell>(&mv.what))
      tl.pauses.push_back({PlanPause::Kind::dwell, d->seconds, 0, motions});
    else if (std::get_if<ToolChange>(&mv.what))
      tl.pauses.push_back({PlanPause::Kind::tool_change, 0, 0, motions});
    else if (const auto* s = std::get_if<SpindleMove>(&mv.what); s && s->rpm > 0)
      tl.pauses.push_back({PlanPause::Kind::spindle_start, 0, 0, motions});
    else if (std::get_if<ProgramStop>(&mv.what))
      tl.pauses.push_back({PlanPause::Kind::program_stop, 0, 0, motions});
  }
}

}  // namespace

Timeline program_timeline(const Program& p) {
  Timeline tl;
  tl.units = p.units;
  std::vector<size_t> source;
  tl.blocks = program_motion(p, source);
  tl.path_tolerance.assign(tl.blocks.size(), -1);
  if (const std::vector<char> cut = moves_on_path(p); !cut.empty()) {
    tl.on_path.resize(tl.blocks.size());
    for (size_t i = 0; i < tl.blocks.size(); ++i) tl.on_path[i] = cut[source[i]];
  }
  add_pauses(p, tl);
  return tl;
}

double exact_path_bound_s(const Program& p) {
  double t = 0;
  for (const EntityReport& e : p.entities) t += e.time_bound_s;
  return t;
}

MotionPlan plan_program_summary(const Program& p, const MotionModel& model) {
  // No path tolerance: as program_timeline()'s -1 for every block.
  Timeline tl;
  tl.units = p.units;
  add_pauses(p, tl);
  if (const std::vector<char> cut = moves_on_path(p); !cut.empty())
    for_each_motion_block(p, [&](MotionBlock&, size_t at) { tl.on_path.push_back(cut[at]); });
  return plan_motion_summary(
      std::move(tl),
      [&](const std::function<void(MotionBlock&)>& each) {
        for_each_motion_block(p, [&](MotionBlock& b, size_t) { each(b); });
      },
      model);
}

}  // namespace bezcam
