#pragma once
/// The tools a job cuts with: per tool number, the diameter and shape its
/// entities are cut for. One tool number is one tool: the operator loads
/// one cutter for it, so a job that offsets some entities for a 3 mm tool
/// and others for a 6 mm tool under the same number is refused.
#include <optional>
#include <string>
#include <vector>

#include "bezcam/job/job.hpp"

namespace bezcam {

/// The shape of a tool's end.
enum class ToolEnd { flat, ball };
/// "flat end mill" or "ball end mill".
const char* to_string(ToolEnd s);

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
  /// A ball end where a surface is cut with `tool_radius` > 0; otherwise a
  /// flat end mill.
  ToolEnd shape = ToolEnd::flat;
  std::vector<size_t> entities;  ///< the entities it cuts (indices, in the job's order)
};

/// The job's tools in the order first used. Each entity's tool number,
/// `tool_diameter` and `tool_radius` are its own, else the job's, else
/// `defaults`' (the machine profile's, in job units; a default without a
/// tool number groups the entities that give none as tool -1).
/// Throws InputError (errc::job_tool, at the later entity) when two
/// entities give one tool number two diameters or two shapes, naming both
/// entities, both diameters and where each is set.
std::vector<JobTool> job_tools(const Job& job, const JobParams& defaults = {});

}  // namespace bezcam
