#pragma once
/// `--output best`: per entity, the output mode (lines, arcs or NURBS) whose
/// moves take the shortest planned time on the machine's motion model, ties
/// to the fewest blocks, and the program composed of those entities' moves
/// (each exactly as its mode makes them, so each keeps its mode's proven
/// bound), planned whole (docs/cli.md, "Output best").
#include <optional>
#include <string>
#include <vector>

#include "bezcam/gcode/convert.hpp"

namespace bezcam {

/// One output mode's program on the machine's motion model.
struct OutputTiming {
  OutputMode output = OutputMode::lines;
  /// The whole program planned, as its report plans it: its moves, or its
  /// text read back where the profile's tool change lines move the machine
  /// between tools (seconds).
  double cycle_time_s = 0;
  size_t blocks = 0;  ///< cutting blocks (EntityReport::blocks, summed)
  /// Per entity (by Entity::index): the planned time of the blocks it owns
  /// in this program (its approach, cut and retract, with the blend into
  /// the next move), its cutting blocks, and whether it has blocks at all.
  /// Pauses (tool changes, spindle starts, dwells) belong to no entity:
  /// they are the same in every mode.
  std::vector<double> entity_time_s;
  std::vector<size_t> entity_blocks;
  std::vector<char> entity_moves;
};

/// A program of `job` built in one output mode (Program::output), timed on
/// the motion model of `m` (which must have one).
OutputTiming time_output(const Job& job, const Program& p, const MachineProfile& m);

/// Two planned times closer than this (seconds) are a tie, broken by the
/// fewest blocks: the planner's sums agree to far less, and no controller
/// tells a microsecond apart.
inline constexpr double kOutputTie = 1e-6;

struct EntityChoice {
  size_t entity = 0;  ///< Entity::index
  std::string label;
  /// The mode with the shortest planned time for it; within kOutputTie,
  /// the one with fewer blocks; then the first of lines, arcs, nurbs.
  OutputMode output = OutputMode::lines;
  bool offset = false;  ///< a curve cut as a part, at an offset (CutParams::part_cut())
};

struct OutputChoice {
  std::vector<OutputTiming> modes;     ///< in the order lines, arcs, nurbs
  std::vector<EntityChoice> entities;  ///< those with moves, in the job's order
  /// The modes left out, each with the refusal that left it out.
  std::vector<std::string> left_out;
  /// One line, why NURBS lost on the parts cut at an offset (more blocks
  /// than arcs and a longer time; on LinuxCNC, arcs written for G5.2);
  /// empty where it did not lose there or the machine has no NURBS words.
  std::string nurbs_note;
  /// convert_best(): the composed program planned whole (as time_output()
  /// plans it); and where a single mode's program planned whole was
  /// shorter still (the choice lost at the joints between entities), that
  /// mode, given to every entity.
  double cycle_time_s = 0;
  std::optional<OutputMode> whole;
  /// The output mode the composed program gives the entity of index `i`.
  OutputMode output_of(size_t entity) const;
};

/// The output modes a machine takes: lines; arcs where it has them; nurbs
/// where it has a NURBS dialect.
std::vector<OutputMode> machine_output_modes(const MachineProfile& m);

/// Per entity, the shortest of `modes` (programs of `job`, one per mode,
/// timed by time_output()), and the note on NURBS.
OutputChoice choose_outputs(const Job& job, const MachineProfile& m, std::vector<OutputTiming> modes);

struct BestConversion {
  /// The composed program (Program::best, EntityReport::output per
  /// entity), built, measured, validated and planned as convert_program()
  /// does; its header says what each entity got.
  ConvertResult result;
  OutputChoice choice;
};

/// Builds the job in every mode the machine takes (moves only: not
/// measured, never written), chooses per entity (choose_outputs()), then
/// converts the composed program (`opt` with `entity_output` set): every
/// refusal convert_program() makes is made. A mode refused (e.g. NURBS for
/// a controller's compensation) is left out; when every mode is, the
/// first's refusal is thrown. InputError (usage.output) when the machine
/// has no motion model. `opt.on_entity` sees the whole work as one pass.
BestConversion convert_best(const Job& job, const MachineProfile& m, const ConvertOptions& opt);

}  // namespace bezcam
