// Limits of a whole entity and of a whole program (program_limits.hpp).
#include "bezcam/cam/program_limits.hpp"

#include <algorithm>
#include <cmath>

#include "bezcam/error.hpp"
#include "bezcam/flatten/flatten_curve.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/limits.hpp"

namespace bezcam {

double entity_magnitude(const Entity& e, double tool_radius) {
  double m = 0;
  for (const auto& b : e.curve.pieces)
    for (const auto& p : b.points) m = std::max(m, max_abs(p));
  if (e.surface) {
    for (const auto& cell : e.surface->grid.cells)
      for (const auto& p : cell.points) m = std::max(m, max_abs(p));
    m += std::abs(tool_radius);
  }
  return m;
}

void check_entity_limits(const Job& job, const Entity& e, double tolerance, int decimals, double tool_radius,
                         const Place& tolerance_place) {
  const double magnitude = entity_magnitude(e, tool_radius);
  const double least = kMinRelativeTolerance * magnitude;
  if (tolerance < least)
    throw InputError(errc::limit_tolerance_precision, tolerance_place,
                     "tolerance " + fmt_num(tolerance) + " is too small for " + e.label() + " (" + job.source + ": " +
                         e.json_path() + "), whose coordinates reach " + fmt_num(magnitude) +
                         ": double precision cannot honour less than " + fmt_num(kMinRelativeTolerance) +
                         " times the magnitude (docs/limits.md); use a tolerance of at least " + fmt_num(least) +
                         " or move the geometry nearer the origin");
  if (e.curve.pieces.empty()) return;
  // The flattener also checks (estimate first, then the count itself); here
  // the refusal can name the entity. Arcs and exact blocks need no more
  // segments than lines do, so one estimate serves every output mode.
  const double budget = tolerance - max_rounding_displacement(decimals, e.curve.dim);
  if (!(budget > 0)) return;  // the flattener refuses that, naming the decimals
  const double n = estimate_segments(e.curve.pieces, budget);
  if (n > static_cast<double>(kMaxProgramLines))
    throw InputError(
        errc::limit_segments, Place::in_json(job.source, e.json_path()),
        e.label() + " needs about " + (std::isfinite(n) ? fmt_num(std::round(n)) : std::string("infinitely many")) +
            " segments within tolerance " + fmt_num(tolerance) + ", more than the " + std::to_string(kMaxProgramLines) +
            " lines a program may hold (docs/limits.md); raise the tolerance or split the curve");
}

std::size_t program_lines(const Program& p, std::size_t first) {
  std::size_t n = 0;
  for (std::size_t i = first; i < p.moves.size(); ++i) {
    // Fanuc: a block per control point, then `order` knot-only blocks;
    // LinuxCNC G5.2: a line per point and G5.3.
    const auto* cv = std::get_if<CurveMove>(&p.moves[i].what);
    n += cv && cv->shape->form == CurveMove::Form::nurbs
             ? cv->shape->ctrl.size() + static_cast<std::size_t>(std::max(cv->shape->order, 1))
             : 1;
  }
  return n;
}

void ProgramLength::after_entity(const Program& p, const Job& job, const Entity& e) {
  lines_ += program_lines(p, moves_);
  moves_ = p.moves.size();
  if (lines_ > kMaxProgramLines)
    throw InputError(errc::limit_program_length, Place::in_json(job.source, e.json_path()),
                     "with " + e.label() + " the program reaches " + std::to_string(lines_) + " lines, more than the " +
                         std::to_string(kMaxProgramLines) +
                         " a program may hold (docs/limits.md); split the job or raise the tolerance");
}

}  // namespace bezcam
