#pragma once
// The modal groups of the G and M codes the reader supports (RS274/NGC's
// table, with its numbers), so that one line gives at most one code of a
// group. Private to src/gcode.

namespace bezcam::gcode {

/// Modal group of a G code.
enum class GGroup : int {
  unsupported = -1,   ///< not a code this reader takes
  non_modal = 0,      ///< G04 dwell, G28, G30, G53
  motion = 1,         ///< G00-G03, G5, G5.1, G5.2, G5.3, G06.2, G06.3, G73, G80-G83
  plane = 2,          ///< G17, G18, G19
  distance = 3,       ///< G90, G91
  arc_distance = 4,   ///< G90.1, G91.1 (arc centres absolute or from the start)
  feed_mode = 5,      ///< G93, G94, G95
  units = 6,          ///< G20, G21
  cutter_comp = 7,    ///< G40, G41, G42
  tool_length = 8,    ///< G43, G49
  cycle_return = 10,  ///< G98, G99
  coord_system = 12,  ///< G54-G59
  path_mode = 13,     ///< G61, G61.1, G64
};

/// Modal group of an M code.
enum class MGroup : int {
  unsupported = -1,
  stopping = 4,     ///< M00, M01, M02, M30
  tool_change = 6,  ///< M06
  spindle = 7,      ///< M03, M04, M05
  coolant = 8,      ///< M07, M08, M09
};

/// One more than the largest group number: the size of a per-group table.
inline constexpr int kModalGroups = 16;

/// Group of a G code given x 10 (G06.2 -> 62, G80 -> 800).
GGroup g_group(int code10);
/// Group of an M code.
MGroup m_group(int code);

}  // namespace bezcam::gcode
