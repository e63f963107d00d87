#pragma once
/// The tools a job cuts with: per tool number, the diameter and shape its
/// entities are cut for. One tool number is one tool: the operator loads
/// one cutter for it, so a job that offsets some entities for a 3 mm tool
/// and others for a 6 mm tool under the same number is refused. A job
/// with a tool table (Job::tools) takes each tool from it.
#include <optional>
#include <string>
#include <vector>

#include "bezcam/job/job.hpp"

namespace bezcam {

/// One tool of a job.
struct JobTool {
  /// The tool number (`tool`); -1 for entities that give none when
  /// job_tools() was given no default (the machine's default tool).
  int number = -1;
  /// The diameter its entities are cut for (job units): `tool_diameter`
  /// for curves, twice `tool_radius` for surfaces cut with a ball end.
  /// Nothing when no entity gives one (a curve cut on its line, a surface
  /// followed by the tool's tip).
  std::optional<double> diameter;
  /// The table's shape; without a table, a ball end where a surface is
  /// cut with `tool_radius` > 0, otherwise a flat end mill.
  ToolType shape = ToolType::flat;
  /// The job's tool table entry for this number (job units), when the job
  /// has a table.
  std::optional<ToolEntry> entry;
  std::vector<size_t> entities;  ///< the entities it cuts (indices, in the job's order)
};

/// An entity's cutting parameters: its own over the job's, with its tool
/// table entry applied, over `defaults` (the machine profile's, in job
/// units). When the job has a tool table, the entity's tool (its own
/// `tool`, the job's, else `defaults.tool`) must be in it; the entry's
/// diameter becomes the curve's `tool_diameter`, and a ball entry's radius
/// a surface's `tool_radius` (unless the entity or job gives 0: the tip
/// follows the surface); a surface cut with any other shape is followed
/// by the tip. Throws InputError:
/// - errc::job_tool, at the `tool` key (or the entity when the number is
///   the defaults'), when the table lacks the tool, naming the numbers it
///   has;
/// - errc::job_tool, at `tool_diameter` or `tool_radius`, when the entity
///   or the job gives a value that differs from the entry's (beyond 1e-9
///   relative), naming both places;
/// - errc::job_cut, at `step_down`, when a curve's step_down is deeper
///   than the tool's flute length, naming both.
/// Without a table: e.params.over(job.params.over(defaults)).
JobParams entity_params(const Job& job, const Entity& e, const JobParams& defaults = {});
/// The table entry of the tool that cuts the entity (its own `tool`, the
/// job's, else `defaults.tool`); nullptr when the job has no table or no
/// number is given anywhere. Unchecked: entity_params() refuses what is
/// wrong.
const ToolEntry* entity_tool_entry(const Job& job, const Entity& e, const JobParams& defaults = {});

/// The job's tools in the order first used. Each entity's tool number,
/// `tool_diameter` and `tool_radius` are its own, else the job's, else
/// `defaults`' (the machine profile's, in job units; a default without a
/// tool number groups the entities that give none as tool -1).
/// Throws InputError (errc::job_tool, at the later entity) when two
/// entities give one tool number two diameters or two shapes, naming both
/// entities, both diameters and where each is set.
std::vector<JobTool> job_tools(const Job& job, const JobParams& defaults = {});

}  // namespace bezcam
