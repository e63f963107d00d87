#include "bezcam/gcode/best_output.hpp"

#include <algorithm>
#include <cmath>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/error.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/gcode/timeline.hpp"
#include "bezcam/gcode/writer.hpp"
#include "convert_plan.hpp"

namespace bezcam {

namespace {

// Whether `a` (time, blocks) beats `b`: shorter by more than a tie, or
// tied with fewer blocks.
bool beats(double ta, size_t ba, double tb, size_t bb) {
  if (std::abs(ta - tb) <= kOutputTie) return ba < bb;
  return ta < tb;
}

// A list of labels for one line: the first few, then a count of the rest.
std::string some_labels(const std::vector<std::string>& labels, size_t most = 4) {
  std::string s;
  for (size_t i = 0; i < labels.size() && i < most; ++i) s += (i ? ", " : "") + labels[i];
  if (labels.size() > most) s += " and " + std::to_string(labels.size() - most) + " more";
  return s;
}

const OutputTiming* timing_of(const OutputChoice& c, OutputMode mode) {
  for (const OutputTiming& t : c.modes)
    if (t.output == mode) return &t;
  return nullptr;
}

// Why NURBS lost on the parts cut at an offset, where it did (one line).
std::string nurbs_note(const OutputChoice& c, const MachineProfile& m) {
  const OutputTiming* nurbs = timing_of(c, OutputMode::nurbs);
  const OutputTiming* arcs = timing_of(c, OutputMode::arcs);
  if (!nurbs || !arcs) return {};
  std::vector<std::string> labels;
  double tn = 0, ta = 0;
  size_t bn = 0, ba = 0;
  for (const EntityChoice& e : c.entities) {
    if (!e.offset || e.output == OutputMode::nurbs) continue;
    labels.push_back(e.label);
    tn += nurbs->entity_time_s[e.entity];
    ta += arcs->entity_time_s[e.entity];
    bn += nurbs->entity_blocks[e.entity];
    ba += arcs->entity_blocks[e.entity];
  }
  if (labels.empty()) return {};
  const std::string parts = std::to_string(labels.size()) + (labels.size() == 1 ? " part" : " parts") +
                            " cut at an offset (" + some_labels(labels) + ")";
  if (m.nurbs == NurbsDialect::linuxcnc && m.arcs)
    return "nurbs: the " + parts +
           " are cut in arcs in nurbs output too: an offset is arcs and lines, and LinuxCNC's exact arc is one "
           "G02/G03 line where G5.2 takes four";
  return "nurbs loses on the " + parts + ": an offset is arcs and lines, and " + m.nurbs_start_word +
         " writes each arc as a rational span of several lines: " + std::to_string(bn) + " blocks against " +
         std::to_string(ba) + " in arcs, " + format_time(tn) + " against " + format_time(ta) + " planned";
}

// The header's line: what each entity got.
std::string best_note(const OutputChoice& c) {
  if (c.whole)
    return std::string("output best: ") + to_string(*c.whole) +
           " for every entity (that mode's program planned whole is shorter than the choice per entity)";
  std::string s = "output best, per entity the mode with the shortest planned time:";
  bool first = true;
  for (OutputMode mode : {OutputMode::lines, OutputMode::arcs, OutputMode::nurbs}) {
    std::vector<std::string> labels;
    for (const EntityChoice& e : c.entities)
      if (e.output == mode && std::find(labels.begin(), labels.end(), e.label) == labels.end())
        labels.push_back(e.label);
    if (labels.empty()) continue;
    s += std::string(first ? " " : "; ") + to_string(mode) + " for " + some_labels(labels, 6);
    first = false;
  }
  return s;
}

// A curve cut as a part on a side of it, at the tool's radius.
bool cut_at_offset(const Job& job, const Entity& e, const MachineProfile& m) {
  if (e.surface || e.curve.pieces.empty()) return false;
  const CutParams cp = cut_params(job, e, m);
  return cp.pocket.operation.value_or(Operation::profile) == Operation::profile && cp.part_cut() &&
         cp.side != CutSide::on;
}

}  // namespace

std::vector<OutputMode> machine_output_modes(const MachineProfile& m) {
  std::vector<OutputMode> modes{OutputMode::lines};
  if (m.arcs) modes.push_back(OutputMode::arcs);
  if (m.nurbs != NurbsDialect::none) modes.push_back(OutputMode::nurbs);
  return modes;
}

OutputTiming time_output(const Job& job, const Program& p, const MachineProfile& m) {
  if (!m.motion) throw std::invalid_argument("time_output: machine " + m.name + " has no motion model");
  OutputTiming t;
  t.output = p.output;
  const size_t n = job.entities.size();
  t.entity_time_s.assign(n, 0);
  t.entity_blocks.assign(n, 0);
  t.entity_moves.assign(n, 0);
  for (const EntityReport& e : p.entities) {
    t.blocks += e.blocks;
    if (e.entity >= 0 && static_cast<size_t>(e.entity) < n) t.entity_blocks[static_cast<size_t>(e.entity)] += e.blocks;
  }
  // The per-block times of the whole program planned (each entity in the
  // context of its neighbours in this mode).
  const MotionPlan plan = plan_motion(program_timeline(p), *m.motion, PlanDetail::full);
  for (size_t b = 0; b < plan.blocks.size() && b < plan.motion.size(); ++b) {
    const int e = plan.motion[b].entity;
    if (e < 0 || static_cast<size_t>(e) >= n) continue;
    t.entity_time_s[static_cast<size_t>(e)] += plan.blocks[b].time_s;
    t.entity_moves[static_cast<size_t>(e)] = 1;
  }
  t.cycle_time_s = program_cycle_time_s(p, m, plan);
  return t;
}

OutputMode OutputChoice::output_of(size_t entity) const {
  if (whole) return *whole;
  for (const EntityChoice& e : entities)
    if (e.entity == entity) return e.output;
  return OutputMode::lines;  // no moves of its own: nothing to choose
}

OutputChoice choose_outputs(const Job& job, const MachineProfile& m, std::vector<OutputTiming> modes) {
  OutputChoice c;
  std::stable_sort(modes.begin(), modes.end(), [](const auto& a, const auto& b) { return a.output < b.output; });
  c.modes = std::move(modes);
  for (const Entity& e : job.entities) {
    const size_t i = e.index;
    const OutputTiming* best = nullptr;
    for (const OutputTiming& t : c.modes) {
      if (i >= t.entity_moves.size() || !t.entity_moves[i]) continue;
      if (!best || beats(t.entity_time_s[i], t.entity_blocks[i], best->entity_time_s[i], best->entity_blocks[i]))
        best = &t;
    }
    if (!best) continue;  // no moves in any mode
    c.entities.push_back({i, e.label(), best->output, cut_at_offset(job, e, m)});
  }
  std::stable_sort(c.entities.begin(), c.entities.end(),
                   [](const auto& a, const auto& b) { return a.entity < b.entity; });
  c.nurbs_note = nurbs_note(c, m);
  return c;
}

BestConversion convert_best(const Job& job, const MachineProfile& m, const ConvertOptions& opt) {
  if (!m.motion)
    throw InputError(errc::usage_output, Place::at_setting("output"),
                     "output best chooses by the planned cycle time, and machine \"" + m.name +
                         "\" has no motion model (key \"motion\", docs/machines.md) to plan it with; choose lines, "
                         "arcs or nurbs");
  const std::vector<OutputMode> modes = machine_output_modes(m);
  // Progress: each mode's build, then the composed program's, as one pass.
  const size_t passes = modes.size() + 1;
  size_t pass = 0;
  const auto progress = [&](ConvertOptions& o) {
    if (!opt.on_entity) return;
    o.on_entity = [&opt, &pass, passes](size_t done, size_t total, const std::string& label) {
      opt.on_entity((pass * total + done) / passes, total, label);
    };
  };
  std::vector<OutputTiming> timed;
  std::vector<std::string> left_out;
  std::optional<InputError> first_refusal;
  // The modes' programs and the composed one share what does not depend
  // on the mode (a pocket's passes in arcs and NURBS, its certificate).
  const std::shared_ptr<ConversionMemo> memo = opt.memo ? opt.memo : make_conversion_memo();
  for (OutputMode mode : modes) {
    ConvertOptions o = opt;
    o.memo = memo;
    o.output = mode;
    o.entity_output.clear();
    o.measure = false;  // its moves only: the composed program is measured
    progress(o);
    try {
      const Program p = build_program(job, m, o);
      timed.push_back(time_output(job, p, m));
    } catch (const InputError& x) {
      if (!first_refusal) first_refusal = x;
      left_out.push_back(std::string(to_string(mode)) + ": " + x.message());
    }
    ++pass;
  }
  if (timed.empty()) throw *first_refusal;
  BestConversion b;
  b.choice = choose_outputs(job, m, std::move(timed));
  b.choice.left_out = std::move(left_out);
  ConvertOptions composed = opt;
  composed.memo = memo;
  composed.entity_output.assign(job.entities.size(), OutputMode::lines);
  for (const EntityChoice& e : b.choice.entities) composed.entity_output[e.entity] = e.output;
  progress(composed);
  b.result = convert_program(job, m, composed);
  b.result.program.best = true;
  const auto cycle_of = [&](const ConvertResult& r) {
    return r.plan ? r.plan->cycle_time_s
                  : program_cycle_time_s(r.program, m, plan_program_summary(r.program, *m.motion));
  };
  b.choice.cycle_time_s = cycle_of(b.result);
  // The choice is per entity; the program is planned whole. Where a single
  // mode's program is shorter still (what the joints between entities
  // cost), every entity gets that mode: best is never slower than one.
  const OutputTiming* fastest = nullptr;
  for (const OutputTiming& t : b.choice.modes)
    if (!fastest || t.cycle_time_s < fastest->cycle_time_s) fastest = &t;
  if (fastest->cycle_time_s < b.choice.cycle_time_s) {
    b.choice.whole = fastest->output;
    composed.entity_output.assign(job.entities.size(), fastest->output);
    b.result = convert_program(job, m, composed);
    b.result.program.best = true;
    b.choice.cycle_time_s = cycle_of(b.result);
  }
  b.result.program.notes.push_back(best_note(b.choice));
  return b;
}

}  // namespace bezcam
