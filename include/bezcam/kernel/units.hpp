#pragma once
/// Length units of a job, a profile and a program.

namespace bezcam {

enum class Units { mm, inch };
inline const char* to_string(Units u) { return u == Units::mm ? "mm" : "inch"; }
/// Millimetres per unit.
inline double mm_per_unit(Units u) { return u == Units::mm ? 1.0 : 25.4; }

/// The chord tolerance when a job, or a caller of the flattener, gives none
/// (mm; in a job's own units, kDefaultToleranceMm / mm_per_unit(units)).
inline constexpr double kDefaultToleranceMm = 0.01;

}  // namespace bezcam
