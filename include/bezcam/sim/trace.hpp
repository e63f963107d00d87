#pragma once
/// The simulated controller's trace: the executed blocks with their end
/// positions, arcs and curves sampled, modal changes, and how the program
/// ended. Deterministic by construction: no times, addresses or session
/// ids; every number printed with kTraceDecimals fixed decimals (no "-0"),
/// so the same program gives the same bytes whether it was run from a file
/// or streamed. Golden files are compared token by token, numbers within
/// kTraceTolerance (compare_traces).
///
/// Records, one per line (docs/modbus-register-map.md, "Trace"):
///   bezcam-trace 1 machine NAME
///   line N KIND to X Y Z [center X Y Z] [order K points P] [feed F]
///     at T X Y Z            (samples of arcs and curves, T in (0,1))
///   line N units mm|inch | distance absolute|incremental | tool T |
///          spindle on RPM | spindle off | program end
///   alarm line N CODE ID: MESSAGE
///   done lines L blocks B at X Y Z
///   stock hash H removed V deepest Z at X Y   (with a stock, after the
///     final record; millimetres)
/// A block spanning several lines is written "lines A-B".
#include <optional>
#include <string>
#include <string_view>

#include "bezcam/gcode/reader.hpp"
#include "bezcam/stock/dexel_grid.hpp"

namespace bezcam::sim {

/// Decimals of every coordinate, parameter and feed in a trace.
inline constexpr int kTraceDecimals = 6;
/// Golden comparison: numbers may differ by this much (program units). The
/// programs print at most 4 decimals, so any real change is far larger,
/// while floating-point differences between compilers (around 1e-12,
/// which can flip the 6th printed decimal) are absorbed.
inline constexpr double kTraceTolerance = 1e-5;
/// Samples per arc and per Bézier move; NURBS get this many per non-empty
/// knot span. Fixed counts (not length-based) so a sample count never
/// depends on a rounding of the geometry.
inline constexpr int kArcSamples = 32;
inline constexpr int kSpanSamples = 16;

/// First record of every trace.
std::string trace_header(std::string_view machine);
/// A motion block and its samples (several lines of text).
std::string trace_block(const MotionBlock& b);
/// Modal changes made by program line `line` (empty when nothing changed).
std::string trace_state(int line, const MachineState& before, const MachineState& after);
/// The alarm that stopped the program.
std::string trace_alarm(int line, std::string_view code, std::string_view id, std::string_view message);
/// Last record of a complete program.
std::string trace_done(long lines, long blocks, const Vec3& pos);
/// The machined stock after a program: the hash of its floors (16
/// hexadecimal digits, as `bezcam verify --hash` prints it), the removed
/// volume (mm^3) and the deepest floor (z, then the column's x y; mm).
std::string trace_stock(const DexelGrid& g);
/// How many points trace_block() samples on a block (0 for lines/rapids).
int trace_sample_count(const MotionBlock& b);
/// A number as the trace prints it.
std::string trace_number(double v);

/// First difference between two traces.
struct TraceMismatch {
  std::size_t line = 0;  ///< 1-based line of the traces
  std::string expected, actual, why;
};
/// Compares token by token: tokens that both read as numbers may differ by
/// `tolerance`, every other token and the line structure must be equal. The
/// token after `hash` is a word whatever its digits.
std::optional<TraceMismatch> compare_traces(std::string_view expected, std::string_view actual,
                                            double tolerance = kTraceTolerance);

}  // namespace bezcam::sim
