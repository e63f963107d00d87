#pragma once
/// One G-code reader for every dialect bezcam emits: G00/G01, G02/G03 (G17
/// with I/J), the Fanuc-style NURBS block (G06.2 or G06.3 start word, P rank,
/// K knots, R weights), LinuxCNC G5 / G5.1 Bézier moves and G5.2 ... G5.3
/// NURBS. Used by `bezcam lint`, by the round-trip tests, by the simulated
/// controller and by the preview. Parse, validate, then execute (Grbl's
/// structure): a line is checked completely before it changes the state.
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "bezcam/gcode/lint.hpp"  // GcodeFinding, lint_gcode()
#include "bezcam/kernel/arc.hpp"
#include "bezcam/machine/machine_profile.hpp"
#include "bezcam/machine/motion.hpp"

namespace bezcam {

/// Modal state of the interpreter.
/// The modal motion (RS274/NGC group 1), named. The value is the G number
/// times 10 (G06.2 -> 62), as the reader's code tables use.
enum class ModalMotion : int {
  none = -1,          ///< at the start, after G80 and after G5.3
  rapid = 0,          ///< G00
  feed = 10,          ///< G01
  arc_cw = 20,        ///< G02
  arc_ccw = 30,       ///< G03
  cubic = 50,         ///< G5 (LinuxCNC cubic spline)
  quadratic = 51,     ///< G5.1 (LinuxCNC quadratic spline)
  nurbs_g5_2 = 52,    ///< G5.2 (a LinuxCNC NURBS block is open)
  nurbs_g06_2 = 62,   ///< G06.2 (Fanuc NURBS mode)
  nurbs_g06_3 = 63,   ///< G06.3 (the seeds' wording of the Fanuc block)
  chip_break = 730,   ///< G73 (canned cycle: peck drilling, backing off a little)
  drill = 810,        ///< G81 (canned cycle: drilling)
  drill_dwell = 820,  ///< G82 (canned cycle: drilling, dwell at the bottom)
  peck = 830,         ///< G83 (canned cycle: peck drilling, out to R after each peck)
};

/// Whether a modal motion is a canned cycle (G73, G81, G82, G83).
inline bool is_canned_cycle(ModalMotion m) {
  return m == ModalMotion::chip_break || m == ModalMotion::drill || m == ModalMotion::drill_dwell ||
         m == ModalMotion::peck;
}

/// Where a canned cycle leaves the drill after each hole (group 10).
enum class CycleReturn : unsigned char {
  initial_level,  ///< G98: the height where the cycle mode began (or R, if higher)
  r_plane,        ///< G99: the R plane
};

/// Distance mode (group 3): how the X Y Z words of a move are read.
enum class DistanceMode : unsigned char {
  absolute,     ///< G90: the end point
  incremental,  ///< G91: the travel from where the tool is
};

/// Arc centre mode (group 4): how the centre words of G02/G03 are read.
enum class ArcCenterMode : unsigned char {
  incremental,  ///< G91.1 (the default): the centre's offset from the arc's start
  absolute,     ///< G90.1: the centre as a point in program coordinates
};

/// Cutter radius compensation (group 7); the value is the G number.
enum class CutterCompMode : int {
  off = 40,    ///< G40
  left = 41,   ///< G41: the tool left of the path
  right = 42,  ///< G42: the tool right of the path
};

/// Work coordinate system (group 12), G54..G59; the value is the G number.
enum class WorkOffset : int { g54 = 54, g55 = 55, g56 = 56, g57 = 57, g58 = 58, g59 = 59 };

/// Path control mode (group 13); the value is the G number, G61.1 as 611.
enum class PathMode : int {
  unset = 0,         ///< no line has set it: the controller's default applies
  exact_stop = 61,   ///< G61
  exact_path = 611,  ///< G61.1
  blend = 64,        ///< G64 (with its tolerance in path_tolerance)
};

struct MachineState {
  Vec3 pos;
  unsigned known_axes = 0;  ///< X 1, Y 2, Z 4: set once a word gave the axis
  Units units = Units::mm;
  bool units_set = false;
  DistanceMode distance = DistanceMode::absolute;
  ArcCenterMode arc_centers = ArcCenterMode::incremental;
  Plane plane = Plane::xy;  ///< group 2: G17, G18, G19
  ModalMotion motion = ModalMotion::none;
  double feed = 0;
  double spindle_rpm = 0;
  bool spindle_on = false;
  bool spindle_ccw = false;  ///< the spindle was last started with M04 (M03: false)
  int tool = 0;
  bool program_end = false;  ///< M02 / M30 seen
  /// Work coordinate system. The simulated controller's work offsets are
  /// all zero: program and machine coordinates agree.
  WorkOffset coord_system = WorkOffset::g54;
  /// Tool length compensation G43 H- (on, with its H number) or G49 (off).
  /// The offsets are zero in the simulated controller; the state is kept so
  /// that the trace shows what the program asked.
  bool tool_length_comp = false;
  int tool_length_h = 0;
  bool coolant_mist = false;   ///< M07 (M09 stops both)
  bool coolant_flood = false;  ///< M08
  PathMode path_mode = PathMode::unset;
  /// G04 P- dwells and the dwells of canned cycles (G82 P-) so far, in
  /// seconds.
  double dwell_seconds = 0;
  /// G98 / G99; until a program sets it, the dialect's default (LinuxCNC:
  /// G99, Fanuc: G98).
  CycleReturn cycle_return = CycleReturn::initial_level;
  bool cycle_return_set = false;  ///< a G98 or G99 has been given
  /// Path mode: -1 until the program sets one (the controller's default
  /// applies), 0 for exact stop (G61, G61.1), the tolerance P of G64 P-,
  /// infinity for G64 without P (corners as fast as the planner can).
  double path_tolerance = -1;
  int program_stops = 0;  ///< M00 / M01 seen so far (the operator resumes)
  /// Cutter radius compensation, with its D register and the radius it
  /// holds (program units).
  CutterCompMode cutter_comp = CutterCompMode::off;
  int cutter_comp_d = 0;
  double cutter_comp_radius = 0;
};

/// Streaming interpreter: feed it lines in order.
///
/// What it accepts (docs/gcode-dialects.md; every refusal is an
/// InputError "gcode.<what>" at "line N" naming the word and what was
/// expected):
///  - `%` lines, an `O1234` program-number line, `N` line numbers, comments
///    in parentheses and after `;`, upper- or lower-case words, blanks
///    anywhere inside a word (`G 0 1`, `Z   5.0000`, as RS274/NGC);
///  - G00 G01 G02 G03 (G17, G18, G19; centre by the plane's two centre
///    words or radius by R), G04 P dwell, G17 G18 G19, G20/G21 (not changed
///    after the first move), G90/G91 (absolute or incremental X Y Z),
///    G90.1/G91.1 (arc centres absolute or from the start), G94, G40,
///    G41/G42 D- (cutter radius compensation, cutter_comp.hpp: the
///    blocks are the tool centre's; D's diameter from the profile's
///    tool_diameters_mm), G43 H- / G49 (tool length compensation, zero offsets),
///    G54-G59 (zero work offsets), G28 / G30 (rapid through the optional
///    X Y Z point, in the distance mode, to the reference point, machine
///    zero), G53 with G00/G01 in G90 (machine coordinates for that line),
///    G61/G61.1/G64, G80; refused with a reason: G93/G95, anything else;
///  - the canned drilling cycles G81, G82 (P dwell), G83 (Q peck), G73 (Q
///    peck) with X Y Z R L, G98/G99 and G80, in G17, G18 and G19 (the
///    drilling axis is the plane's axis), modal: a later line with axis
///    words drills another hole. They run as the profile's
///    `canned_cycles` dialect runs them (LinuxCNC's interpreter, or
///    Fanuc's; none on Grbl; LinuxCNC's without a profile) and become
///    rapid and feed blocks of their line, a dwell after the block it
///    follows (MotionBlock::dwell_s); docs/gcode-dialects.md lists the
///    differences;
///  - M00 M01 M02 M30 M03 M04 M05 M06 M07 M08 M09, F, S, T;
///  - the Fanuc-style NURBS block: start word G06.2 or G06.3 (with a
///    profile: its start word only), `P` rank 2..4 (default 4; the
///    profile's maximum) on the first block only, the first block's point =
///    the current position, one `K X Y Z R` block per control point (axis
///    words left out keep the previous point's value, R defaults to 1),
///    then exactly P knot-only `K` blocks, after which the block is
///    complete. Knots must not decrease, the first P and the last P must be
///    equal (clamped), no knot may repeat more than P times, weights > 0;
///  - LinuxCNC G5 (I J P Q; I and J may be left out right after another G5:
///    they continue its tangent), G5.1 (I and J), G5.2 P- L- ... X- Y- P-
///    ... G5.3 (order L >= 3, default 3; P on every point; the interpreter's
///    clamped uniform integer knots 0..n-k+2, see linuxcnc_knots()). These
///    move in X and Y only: a Z word is refused.
/// In G91 the end point of every move is its travel from the current
/// position; the control points of a Fanuc block each travel from the one
/// before (the first must be X0 Y0 Z0 or left out), those of a G5.2 block
/// from where the block began (LinuxCNC's interpreter). I J P Q of G5 and
/// G5.1 are always offsets; the centre words of G02/G03 follow G90.1/G91.1.
/// With a profile, the profile's NURBS dialect is enforced (no G5 on a Fanuc,
/// no G06.2 on Grbl), and so are its travel limits (program units, arcs and
/// curves by their true extent), maximum feed and arc tolerance (the
/// centre's distances to start and end may differ by at most
/// arc_tolerance_mm; 0.002 mm without a profile).
class GcodeInterpreter {
 public:
  /// With a profile, travel limits and maximum feed are enforced too. The
  /// profile must outlive the interpreter.
  explicit GcodeInterpreter(const MachineProfile* profile = nullptr);
  ~GcodeInterpreter();
  GcodeInterpreter(const GcodeInterpreter& other);
  GcodeInterpreter& operator=(const GcodeInterpreter& other);
  GcodeInterpreter(GcodeInterpreter&&) noexcept;
  GcodeInterpreter& operator=(GcodeInterpreter&&) noexcept;

  /// Interprets one line (`line_no` is 1-based). Returns the motion blocks
  /// the line completes (a NURBS block completes on the line that ends it).
  /// Throws InputError("gcode.*", "line N", ...) on any error; the state is
  /// unchanged by a refused line.
  std::vector<MotionBlock> feed_line(std::string_view text, int line_no);
  /// End of input: throws if a multi-line block is still open.
  std::vector<MotionBlock> finish();

  const MachineState& state() const;

  /// The D registers for cutter compensation (diameters in mm), added to
  /// the profile's tool_diameters_mm (a reader without a profile has none).
  void set_tool_diameters_mm(const std::map<int, double>& d);

  /// What the next line depends on besides state(): the multi-line block
  /// it may be inside and the words earlier lines left for it. Used to
  /// resume a program part-way (bezcam/gcode/resume.hpp).
  struct Continuation {
    ModalMotion open_block = ModalMotion::none;  ///< the open multi-line block (G06.2/G06.3, G5.2), none when none is
    int open_line = 0;                           ///< the line that opened it
    bool g5_chain = false;                       ///< the last motion was a G5: a G5 without I and J takes its tangent
    int selected_tool = -1;                      ///< the last T word (-1: none); M06 puts it in the spindle
    int end_line = 0;                            ///< the M02 / M30 line, 0 before it
  };
  Continuation continuation() const;

 private:
  struct Impl;     // what the reader keeps between lines (src/gcode/interpreter_impl.hpp)
  struct LineRun;  // the interpretation of one line (src/gcode/interpreter_impl.hpp)
  friend std::vector<GcodeFinding> lint_gcode(std::string_view text, const MachineProfile& profile);

  std::unique_ptr<Impl> impl_;
};

/// Reads a whole program; throws at the first error (InputError, "line N").
std::vector<MotionBlock> read_gcode(std::string_view text, const MachineProfile* profile = nullptr);

/// LinuxCNC's knot vector for a G5.2 block of `n_points` control points and
/// order k (its interpreter, knot_vector_creator() in
/// nurbs_additional_functions.cc): k zeros, then 1, 2, ..., n_points - k,
/// then k times n_points - k + 1.
std::vector<double> linuxcnc_knots(size_t n_points, int order);

}  // namespace bezcam
