#pragma once
// The reader's private parts, private to src/gcode: what it keeps between
// lines (GcodeInterpreter::Impl) and the interpretation of one line
// (GcodeInterpreter::LineRun). A line is lexed into words (lexer.hpp),
// checked completely on copies of the state and only then committed by
// feed_line(). The interpretation lives in one file per concept:
//   reader.cpp           the line's order, plain motions (G00-G03), the
//                        multi-line block machinery, feed_line(), read_gcode()
//   modal_state.cpp      modal groups, the non-motion words (F S T M G17 G21 ...)
//   fanuc_nurbs.cpp      the Fanuc-style G06.2 / G06.3 NURBS block
//   linuxcnc_curves.cpp  LinuxCNC G5, G5.1 and G5.2 ... G5.3
//   canned_cycles.cpp    G73, G81, G82, G83 (LinuxCNC's and Fanuc's)
//   lint.cpp             lint_gcode() and the checks only lint makes
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bezcam/error.hpp"
#include "bezcam/gcode/reader.hpp"
#include "bezcam/machine/cutter_comp.hpp"
#include "diagnostics.hpp"
#include "lexer.hpp"

namespace bezcam {

namespace gcode {

/// Radius mismatch allowed at the ends of an arc without a profile (mm):
/// the profiles' default, LinuxCNC's order of magnitude.
inline constexpr double kDefaultArcToleranceMm = 0.002;

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

inline std::string axis_name(int a) { return std::string(1, "XYZ"[a]); }

/// A G code given x 10 as written canonically (62 -> "G6.2").
inline std::string g_text(int code10) {
  return "G" + std::to_string(code10 / 10) + (code10 % 10 ? "." + std::to_string(code10 % 10) : "");
}

/// The plane a G17 / G18 / G19 code (x 10) selects.
inline Plane plane_of(int code10) { return code10 == 170 ? Plane::xy : code10 == 180 ? Plane::zx : Plane::yz; }

inline bool is_fanuc(int c) { return c == 62 || c == 63; }
inline bool is_cutting(BlockKind k) { return k != BlockKind::rapid; }

/// A point for messages: "(x, y, z)".
inline std::string pt(const Vec3& p) { return "(" + fmt_num(p.x) + ", " + fmt_num(p.y) + ", " + fmt_num(p.z) + ")"; }

/// The whole text's limit (limits.hpp): a finding when `text` is too large;
/// the lines' count and length are checked line by line by feed_line().
std::optional<GcodeFinding> too_large(std::string_view text);
/// The same for a program of `bytes` bytes (read as it is written).
std::optional<GcodeFinding> too_large(size_t bytes);

}  // namespace gcode

// Everything the reader keeps between lines.
struct GcodeInterpreter::Impl {
  // Everything beyond MachineState that later lines depend on. A line is
  // interpreted on copies of `state` and `more`, committed only when accepted.
  struct More {
    ModalMotion open = ModalMotion::none;  // open multi-line block: none, a Fanuc one, G5.2
    int open_line = 0;                     // where it started
    int order = 0;                         // its rank / order
    double open_feed = 0;                  // the feed it runs at
    std::vector<Vec3> ctrl;
    std::vector<double> weights, knots;  // Fanuc knots; NaN where lint recovered a missing K
    std::vector<int> knot_lines;
    int knot_only = 0;        // Fanuc: knot-only blocks so far
    int knot_only_line = 0;   // the first of them
    int nurbs_mode_line = 0;  // where the Fanuc NURBS mode was entered
    int selected_tool = -1;   // last T word (-1: none)
    bool g5_chain = false;    // the previous motion was a G5: I and J may be left out
    Vec3 g5_next_ij;          // ... and then default to minus its P and Q
    bool moved = false;       // a move has been made (units may no longer change)
    bool distance_set = false, plane_set = false;
    int end_line = 0;   // M02 / M30 seen there
    long last_n = -1;   // last N word
    int last_line = 0;  // last line fed
    // Lint-only bookkeeping: findings already reported once.
    bool noted_modes = false, noted_position = false, noted_spindle = false;
    double feed_reported = -1;  // the excessive feed last reported
    CutterComp comp;            // G41/G42: the tool-centre path, one move behind
    // Canned cycles: the initial level (the drilling axis's position where
    // the cycle mode began) and the words later holes take over.
    struct Cycle {
      bool in = false;  // in canned cycle mode since line `line`
      int line = 0;
      double initial = 0;
      std::optional<double> r, z, q, p;  // as written (G91: increments)
    } cycle;
  };

  const MachineProfile* profile = nullptr;
  std::map<int, double> tool_diameters_mm;
  MachineState state;
  More more;
  // lint_gcode(): recoverable problems are recorded here (and the line goes
  // on with the values as given) instead of thrown.
  std::vector<GcodeFinding>* findings = nullptr;
};

// The interpretation of one line, on copies of the reader's state.
struct GcodeInterpreter::LineRun {
  const Impl& self;
  MachineState st;
  Impl::More mo;
  int line;
  std::vector<MotionBlock> out;
  gcode::Line ln;
  std::string word;  // the line's motion word as written (G06.3, G1, ...), if any
  // The open block's lists as they were before this line (see feed_line()):
  // their sizes, and a copy once the line clears or replaces them.
  struct Lists {
    std::vector<Vec3> ctrl;
    std::vector<double> weights, knots;
    std::vector<int> knot_lines;
  };
  std::array<size_t, 4> sizes0{};
  bool lists_saved = false;
  Lists saved{};

  // ---- errors: through gcode::Diagnostics (diagnostics.cpp)
  gcode::Diagnostics diag() const { return {line, self.findings}; }
  [[noreturn]] void fail(ErrorId id, const std::string& msg) const { diag().fail(id, msg); }
  void soft(ErrorId id, const std::string& msg, int at = 0) const { diag().soft(id, msg, at); }
  void note(ErrorId id, const std::string& msg, int at = 0) const { diag().note(id, msg, at); }
  bool lint() const { return self.findings != nullptr; }

  // ---- words and units
  // A motion code for messages: as written on this line, else canonical.
  std::string wt(int code) const { return word.empty() ? gcode::g_text(code) : word; }
  const char* unit() const { return st.units == Units::mm ? "mm" : "inch"; }
  double from_mm(double v) const { return v / mm_per_unit(st.units); }
  std::string machine() const { return self.profile ? " of machine \"" + self.profile->name + "\"" : ""; }
  double val(char c) const { return ln.get(c)->value; }
  std::string txt(char c) const { return ln.get(c)->text; }

  // ---- the line (reader.cpp)
  void run(std::string_view text);
  void motion_line(int code, bool explicit_motion);
  void check_dialect(int code) const;
  static int start_code(const std::string& word);

  // ---- helpers (reader.cpp)
  /// The coordinate an axis word programs: the word in G90, `from` plus
  /// the word in G91 (`from`: the axis's current position for a move, the
  /// previous control point inside a Fanuc NURBS block).
  double coordinate(const gcode::Word& w, double from) const;
  /// Whether an axis word on axis `a` (X 0, Y 1, Z 2) gives a coordinate:
  /// always in G90 or once a move has set the axis; in G91 on an axis no
  /// move has set, a word of 0 (no travel) does not, any other is refused.
  bool gives_coordinate(int a, const gcode::Word& w) const;
  /// Target of a move: the current position with the line's X Y Z words
  /// (coordinate()), and the axes whose value is known afterwards (a G91
  /// word of 0 leaves an axis no move has set unknown; any other G91 word
  /// on such an axis is refused).
  std::pair<Vec3, unsigned> target() const;
  /// The axes the line names with X Y Z words (X 1, Y 2, Z 4).
  unsigned named_axes() const;
  // Start point of a move: unknown axes take the end's value.
  Vec3 start_for(const Vec3& to) const;
  void require_xy_known(const std::string& what) const { require_known(what, 3); }
  /// Fails unless every axis of `mask` (X 1, Y 2, Z 4) has been set.
  void require_known(const std::string& what, unsigned mask) const;
  void require_feed(const std::string& what) const;
  // Travel limits of the profile, for the axes given by `axes`.
  void check_travel(const Box3& b, unsigned axes) const;
  void check_feed_limit(double feed);
  MotionBlock block(BlockKind k, const Vec3& to) const;
  void commit_move(const MotionBlock& b, unsigned axes);
  // Hands a programmed block to cutter compensation; its output to `out`.
  void emit(const MotionBlock& b);
  void emit_all(std::vector<MotionBlock> blocks);
  void comp_off();  // G40 or the program's end: the move compensation holds
  void cutter_comp(int code);

  // ---- motions (reader.cpp)
  void linear(bool rapid);
  // G28 (code 280) / G30 (300): rapid through the line's X Y Z (if any,
  // in the distance mode) to the reference point, with axis words for
  // those axes only, else for all.
  void go_home(int code);
  // The reference point of G28 / G30 (program coordinates): machine zero,
  // LinuxCNC's #5161-#5163 and #5181-#5183 as a new parameter file has
  // them; the simulated controller's offsets are zero.
  Vec3 reference_point(int code) const;
  double arc_tolerance() const;
  void arc(bool cw);

  // ---- multi-line NURBS blocks, shared by both dialects (reader.cpp)
  void save_lists();
  double weight(const gcode::Word& r) const;
  // Travel and lint checks of a completed NURBS block, then the move.
  // The NURBS block collected since line mo.open_line (Fanuc G06.2 or
  // LinuxCNC G5.2), ending at this line, with these knots.
  void finish_nurbs_block(std::vector<double> knots);
  void finish_curve_block(MotionBlock& b);
  void clear_block();
  void abandon_block();

  // ---- canned cycles (canned_cycles.cpp)
  // A G73 / G81 / G82 / G83 line (`code` x 10).
  void canned_cycle(int code, bool explicit_motion);
  // Leaving canned cycle mode (G80 or another motion).
  void end_cycles();
  // One straight move of a cycle, in the plane's coordinates (a, b, axis);
  // a rapid that would not move is left out.
  void cycle_move(bool rapid, const Vec3& plane_to, double dwell = 0);

  // ---- modal groups and non-motion words (modal_state.cpp)
  // What a line's G codes ask.
  struct Codes {
    int motion = -999;           // the motion code (group 1) x 10, -999 for none
    std::optional<Plane> plane;  // the line's own G17 / G18 / G19
    int home = 0;                // G28 280, G30 300: to a reference point
    int comp = 0;                // G40 400, G41 410, G42 420
    bool dwell = false, machine_coords = false, length_comp = false, blend = false, comp_d = false;
  };
  void run_modal();
  Codes gather_codes();
  // The motion the line's words belong to: -999 none, -1 G80, else its code.
  int active_motion(const Codes& k) const;
  void check_combinations(const Codes& k, int active);
  void set_feed_speed_tool();
  void run_m_codes();
  void dwell();
  void set_mode(int code, const std::string& text);
  void blend();
  void tool_length_on();
  // Every word must mean something on this line.
  // `extra`: letters the line's non-motion codes take (G04 P, G43 H, G28 XYZ).
  /// `plane`: the plane the line's arc is in (the line's own G17/G18/G19
  /// if it has one).
  void check_letters(int active, const std::string& extra, bool explicit_motion, Plane plane);

  // ---- Fanuc G06.2 / G06.3 blocks (fanuc_nurbs.cpp)
  // Lines inside an open multi-line block. Returns true when consumed.
  bool continue_block();
  // Knot rules of the Fanuc block (alarms PS1004-PS1009 cover the same).
  void add_knot(const gcode::Word& k, bool knot_only);
  void complete_fanuc();
  void fanuc_start(int code);

  // ---- LinuxCNC G5, G5.1, G5.2 ... G5.3 (linuxcnc_curves.cpp)
  void g5();
  void g51();
  void curve_move(MotionBlock& b, unsigned axes);
  void g52();
  // G5.2 block lines: "X- Y- P-" until G5.3.
  bool continue_g52();
  void g52_point();
  void g53();

  // ---- lint-only checks (lint.cpp)
  // Lint checks shared by every motion.
  void lint_motion(BlockKind kind, const Vec3& from, const Vec3& to, unsigned axes);
  // An interior knot of multiplicity = order lets the curve jump from
  // ctrl[i-1] to ctrl[i]; the reader accepts it (the dialect allows it),
  // lint flags it when the two points differ.
  void lint_jumps(const MotionBlock& b);
  void check_n();
};

}  // namespace bezcam
