#pragma once
/// Length units of a job, a profile and a program.

namespace bezcam {

enum class Units { mm, inch };
inline const char* to_string(Units u) { return u == Units::mm ? "mm" : "inch"; }
/// Millimetres per unit.
inline double mm_per_unit(Units u) { return u == Units::mm ? 1.0 : 25.4; }

}  // namespace bezcam
