#pragma once
/// The stated limits (bezcam/limits.hpp, docs/limits.md) that concern a
/// whole entity or a whole program, checked by build_program() so that a job
/// that would exceed them is refused before the work, not after it:
///  * the tolerance double precision can honour at the entity's magnitude;
///  * the segments a curve entity needs at that tolerance (estimated, see
///    estimate_segments() in flatten_curve.hpp);
///  * the lines of the program as it grows.
#include <cstddef>
#include <string>

#include "bezcam/cam/program.hpp"
#include "bezcam/error.hpp"

namespace bezcam {

/// Largest absolute coordinate of an entity's exact geometry (curve pieces'
/// or surface cells' control points), plus the tool radius for surfaces.
double entity_magnitude(const Entity& e, double tool_radius);

/// Refuses an entity before it is cut (InputError, place `tolerance_place`,
/// the message naming the entity):
///  * "limit.tolerance-precision" when tolerance < kMinRelativeTolerance x
///    its magnitude;
///  * "limit.segments" when a curve entity needs about more than
///    kMaxProgramLines segments at `tolerance` less the rounding to
///    `decimals`.
void check_entity_limits(const Job& job, const Entity& e, double tolerance, int decimals, double tool_radius,
                         const Place& tolerance_place);

/// Lines the G-code writer prints for moves[first, end): one per move, and
/// for an exact-curve block one per control point and per knot-only block.
std::size_t program_lines(const Program& p, std::size_t first = 0);

/// Counts a program's lines as build_program() adds entities, and refuses
/// it (InputError "limit.program-length", naming the entity that crosses
/// the limit) once they exceed kMaxProgramLines.
class ProgramLength {
 public:
  void after_entity(const Program& p, const Job& job, const Entity& e);
  std::size_t lines() const { return lines_; }

 private:
  std::size_t moves_ = 0, lines_ = 0;
};

}  // namespace bezcam
