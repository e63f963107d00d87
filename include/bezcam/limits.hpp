#pragma once
/// bezcam's stated limits (docs/limits.md): what it accepts, and what it
/// refuses with an InputError naming the place, so that no input, however
/// large or pathological, makes it hang, exhaust memory or write a program
/// other than the one it states. Every value here is enforced where the
/// input enters (the job reader, the G-code reader, the post-processor, the
/// flattener, the simulated controller) and documented in docs/limits.md;
/// tests/*/limits_test.cpp show each one refused quickly.
///
/// The maximum degree of a curve or patch is kMaxBezierDegree
/// (kernel/bezier.hpp): 64.
#include <cstddef>
#include <filesystem>
#include <string>

namespace bezcam {

/// Job files: at most this many bytes (32 MiB). Read whole, then parsed:
/// the JSON tree takes several times the file's size in memory.
inline constexpr std::size_t kMaxJobBytes = std::size_t{32} << 20;
/// Entities in one job.
inline constexpr std::size_t kMaxEntities = 10'000;
/// Control points (or through points) of one entity: a curve, all segments
/// of a path, a patch's grid, a Coons patch's four boundaries.
inline constexpr std::size_t kMaxEntityPoints = 100'000;
/// Control points of all entities of a job together.
inline constexpr std::size_t kMaxJobPoints = 1'000'000;
/// Exact Bézier cells of one patch (a Coons patch of B-spline boundaries is
/// a grid of cells, one per pair of knot spans across).
inline constexpr std::size_t kMaxPatchCells = 10'000;
/// Passes planned on one patch.
inline constexpr std::size_t kMaxPassesPerPatch = 10'000;

/// Programs bezcam writes: at most this many lines (a NURBS block counts one
/// line per control point and per knot-only block); also the vertices one
/// flattening, or all the passes of one patch, may produce. Every program
/// written is measured against the geometry (about 50 us per segment), so
/// this also bounds the time a job may take: about a minute.
inline constexpr std::size_t kMaxProgramLines = 1'000'000;
/// Programs bezcam reads (the G-code reader, lint, the simulated
/// controller): at most this many lines, twice what it writes.
inline constexpr std::size_t kMaxReadLines = 2'000'000;
/// Bytes of a program file the reader, lint, preview and stream accept
/// (128 MiB).
inline constexpr std::size_t kMaxProgramBytes = std::size_t{128} << 20;
/// Bytes of one program line, end of line excluded. The simulated
/// controller also refuses a line longer than its receive buffer.
inline constexpr std::size_t kMaxLineBytes = 4096;
/// Moves one canned cycle line (G73, G81-G83, its L repeats and pecks
/// included) may expand into.
inline constexpr std::size_t kMaxCycleMoves = 100'000;
/// Text of one comment the G-code writer prints (longer ids are cut).
inline constexpr std::size_t kMaxCommentBytes = 200;

/// Smallest tolerance relative to the largest coordinate magnitude of the
/// geometry: below tolerance = 1e-12 x magnitude, the error of double
/// arithmetic (about 1e-16 x magnitude per operation, times the operations
/// of evaluation, subdivision and root finding) is no longer a negligible
/// share of the tolerance, so no bound could be trusted. (The flattener's
/// own, finer check keeps 5 % of the tolerance for it: 1280 eps x magnitude.)
inline constexpr double kMinRelativeTolerance = 1e-12;

/// Reads a whole file of at most `max_bytes` bytes. Throws IoError
/// ("io.read", the path) when it cannot be read, InputError
/// ("limit.file-size", the path) naming the size and the limit when it is
/// larger, before reading it. `what` names the file's kind in messages
/// ("job file", "program").
std::string read_bounded(const std::filesystem::path& file, std::size_t max_bytes, const std::string& what);

}  // namespace bezcam
