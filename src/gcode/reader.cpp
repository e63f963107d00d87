// The G-code reader: one interpreter for every dialect bezcam emits, in
// Grbl's parse-validate-execute order. A line is parsed into words, checked
// completely on copies of the modal state, and only then committed.
#include "bezcam/gcode/reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>

#include "bezcam/error.hpp"
#include "bezcam/limits.hpp"
#include "bezcam/kernel/knot_vector.hpp"
#include "bezcam/kernel/nurbs_curve.hpp"

namespace bezcam {

namespace {

/// Radius mismatch allowed at the ends of an arc without a profile (mm):
/// the profiles' default, LinuxCNC's order of magnitude.
constexpr double kDefaultArcToleranceMm = 0.002;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Word {
  char letter = 0;
  double value = 0;
  std::string text;  // as printed, e.g. "K0.03118"
};

// A parsed line: its words (N and O apart), G and M codes, and the first
// word of each other letter.
struct Line {
  bool percent = false;
  bool program_number = false;
  std::optional<long> n;
  std::vector<Word> words;
  std::vector<std::pair<int, std::string>> g;  // G code x 10 (G06.2 -> 62), text
  std::vector<std::pair<int, std::string>> m;
  std::array<int, 26> first{};  // 1 + index into words of the first word of a letter, 0 if none

  const Word* get(char c) const {
    const int i = first[static_cast<size_t>(c - 'A')];
    return i ? &words[static_cast<size_t>(i - 1)] : nullptr;
  }
  bool has(char c) const { return get(c) != nullptr; }
  bool empty() const { return words.empty() && g.empty() && m.empty(); }
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string axis_name(int a) { return std::string(1, "XYZ"[a]); }

std::string g_text(int code10) {
  return "G" + std::to_string(code10 / 10) + (code10 % 10 ? "." + std::to_string(code10 % 10) : "");
}

// Modal group of a supported G code (x 10), -1 when unsupported.
int g_group(int c) {
  switch (c) {
    case 0: case 10: case 20: case 30: case 50: case 51: case 52: case 53: case 62: case 63: case 800: return 1;
    case 40: return 0;
    case 170: case 180: case 190: return 2;
    case 900: case 910: return 3;
    case 930: case 940: case 950: return 5;
    case 200: case 210: return 6;
    case 400: case 410: case 420: return 7;
    case 430: case 490: return 8;
    case 540: case 550: case 560: case 570: case 580: case 590: return 12;
    case 610: case 611: case 640: return 13;
    default: return -1;
  }
}

int m_group(int c) {
  switch (c) {
    case 0: case 1: case 2: case 30: return 4;
    case 3: case 4: case 5: return 7;
    case 6: return 6;
    case 7: case 8: case 9: return 8;
    default: return -1;
  }
}

bool is_fanuc(int c) { return c == 62 || c == 63; }
bool is_cutting(BlockKind k) { return k != BlockKind::rapid; }

std::string pt(const Vec3& p) { return "(" + fmt_num(p.x) + ", " + fmt_num(p.y) + ", " + fmt_num(p.z) + ")"; }

// Box of an arc (G17): both ends and every axis extreme the sweep passes.
Box3 arc_box(const MotionBlock& b) {
  Box3 box;
  box.add(b.from);
  box.add(b.to);
  const double sweep = arc_sweep(b);
  const double a0 = std::atan2(b.from.y - b.center.y, b.from.x - b.center.x);
  const bool ccw = b.kind == BlockKind::arc_ccw;
  for (int q = -8; q <= 8; ++q) {
    const double a = q * std::numbers::pi / 2;
    const double d = ccw ? a - a0 : a0 - a;  // angle travelled to reach a
    if (d > 0 && d < sweep) box.add(evaluate_block(b, d / sweep));
  }
  return box;
}

}  // namespace

std::vector<double> linuxcnc_knots(size_t n_points, int order) {
  // knot_vector_creator(n, k) with n = n_points - 1: i < k -> 0,
  // k <= i <= n -> i - k + 1, else n - k + 2.
  const long n = static_cast<long>(n_points) - 1, k = order;
  std::vector<double> U;
  for (long i = 0; i <= n + k; ++i) U.push_back(static_cast<double>(i < k ? 0 : (i <= n ? i - k + 1 : n - k + 2)));
  return U;
}

// ---------------------------------------------------------------------------
// The interpretation of one line, on copies of the state.

struct GcodeInterpreter::Impl {
  const GcodeInterpreter& self;
  MachineState st;
  More mo;
  int line;
  std::vector<MotionBlock> out;
  Line ln;
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
  void save_lists() {
    if (lists_saved) return;
    lists_saved = true;
    // Before this call the line only appended: the first sizes0 elements
    // are the lists as they were.
    saved.ctrl.assign(mo.ctrl.begin(), mo.ctrl.begin() + static_cast<std::ptrdiff_t>(sizes0[0]));
    saved.weights.assign(mo.weights.begin(), mo.weights.begin() + static_cast<std::ptrdiff_t>(sizes0[1]));
    saved.knots.assign(mo.knots.begin(), mo.knots.begin() + static_cast<std::ptrdiff_t>(sizes0[2]));
    saved.knot_lines.assign(mo.knot_lines.begin(), mo.knot_lines.begin() + static_cast<std::ptrdiff_t>(sizes0[3]));
  }

  // A motion code for messages: as written on this line, else canonical.
  std::string wt(int code) const { return word.empty() ? g_text(code) : word; }

  // ---- errors ------------------------------------------------------------
  [[noreturn]] void fail(ErrorId id, const std::string& msg) const {
    throw InputError(id, Place::at_line(line), msg);
  }
  // A problem the line can go on from: thrown by the reader, recorded by lint.
  void soft(ErrorId id, const std::string& msg, int at = 0) const {
    if (!self.findings_) fail(id, msg);
    self.findings_->push_back({at ? at : line, id, msg});
  }
  // Lint only: what a demanding machinist flags but a controller would run.
  void note(ErrorId id, const std::string& msg, int at = 0) const {
    if (self.findings_) self.findings_->push_back({at ? at : line, id, msg});
  }
  bool lint() const { return self.findings_ != nullptr; }

  // ---- units ---------------------------------------------------------------
  const char* unit() const { return st.units == Units::mm ? "mm" : "inch"; }
  double from_mm(double v) const { return v / mm_per_unit(st.units); }
  std::string machine() const { return self.profile_ ? " of machine \"" + self.profile_->name + "\"" : ""; }

  // ---- parsing -------------------------------------------------------------
  void parse(std::string_view text) {
    while (!text.empty() && (text.back() == '\r' || text.back() == '\n')) text.remove_suffix(1);
    size_t i = 0;
    const size_t n = text.size();
    auto skip_comment = [&] {
      const size_t close = text.find(')', i + 1);
      if (close == std::string_view::npos)
        fail(errc::gcode_syntax, "a comment opened with '(' is not closed on this line: add ')'");
      if (text.substr(i + 1, close - i - 1).find('(') != std::string_view::npos)
        fail(errc::gcode_syntax, "a comment may not contain '(' (no nested comments)");
      i = close + 1;
    };
    while (i < n && is_space(text[i])) ++i;
    if (i < n && text[i] == '%') {
      ln.percent = true;
      ++i;
      while (i < n) {
        if (is_space(text[i])) ++i;
        else if (text[i] == '(') skip_comment();
        else if (text[i] == ';') break;
        else fail(errc::gcode_syntax, "a '%' line may hold nothing but comments, found '" + std::string(1, text[i]) + "'");
      }
      return;
    }
    if (i < n && text[i] == '/') fail(errc::gcode_unsupported, "block delete ('/' at the start of a line) is not supported: remove it or the line");
    while (i < n) {
      const char c = text[i];
      if (is_space(c)) { ++i; continue; }
      if (c == '(') { skip_comment(); continue; }
      if (c == ';') break;
      if (!std::isalpha(static_cast<unsigned char>(c)))
        fail(errc::gcode_syntax, "unexpected character '" + std::string(1, c) + "': expected a word (a letter and a number)");
      const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      ++i;
      const size_t start = i;
      if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
      size_t digits = 0;
      while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) ++i, ++digits;
      if (i < n && text[i] == '.') {
        ++i;
        while (i < n && std::isdigit(static_cast<unsigned char>(text[i]))) ++i, ++digits;
      }
      std::string num(text.substr(start, i - start));
      if (digits == 0) {
        size_t e = i;
        while (e < n && !is_space(text[e]) && text[e] != '(' && text[e] != ';') ++e;
        const std::string found(text.substr(start, std::max(e, i) - start));
        fail(errc::gcode_syntax, std::string("expected a number after '") + letter + "', found " +
                           (found.empty() ? std::string("nothing") : "'" + found + "'"));
      }
      Word w;
      w.letter = letter;
      w.text = std::string(1, letter) + num;
      const std::string digits_only = num[0] == '+' ? num.substr(1) : num;
      const auto fc = std::from_chars(digits_only.data(), digits_only.data() + digits_only.size(), w.value);
      // A number too large for a double must not read as 0 (from_chars
      // leaves the value alone then): that would be a different program.
      if (fc.ec != std::errc() || !std::isfinite(w.value))
        fail(errc::gcode_number, std::string("the number after '") + letter + "' is too large to read (" +
                           std::to_string(num.size()) + " digits): expected at most about 1e308");
      add(std::move(w));
    }
    for (size_t k = 0; k < ln.words.size(); ++k) {
      int& f = ln.first[static_cast<size_t>(ln.words[k].letter - 'A')];
      if (!f) f = static_cast<int>(k) + 1;
    }
  }

  void add(Word w) {
    const bool first_word = ln.words.empty() && ln.g.empty() && ln.m.empty() && !ln.n && !ln.program_number;
    if (w.letter == 'N') {
      if (!first_word) fail(errc::gcode_syntax, "the line number " + w.text + " must be the first word of the line");
      if (w.value < 0 || w.value != std::floor(w.value) || w.value > 1e9)
        fail(errc::gcode_syntax, "expected a whole line number after N, found " + w.text);
      ln.n = static_cast<long>(w.value);
      return;
    }
    if (ln.program_number) fail(errc::gcode_syntax, "a program-number line (O...) may hold nothing but comments, found " + w.text);
    if (w.letter == 'O') {
      if (!first_word || ln.n) fail(errc::gcode_unsupported, "O words (" + w.text + ") are only understood as a program number alone on its line");
      if (w.value < 0 || w.value != std::floor(w.value)) fail(errc::gcode_syntax, "expected a whole program number after O, found " + w.text);
      ln.program_number = true;
      return;
    }
    if (w.letter == 'G') {
      const double x10 = w.value * 10;
      const double r = std::nearbyint(x10);
      if (w.value < 0 || std::abs(x10 - r) > 1e-9 || r > 10000)
        fail(errc::gcode_unsupported, "G-code " + w.text + " is not supported by this reader");
      ln.g.push_back({static_cast<int>(r), w.text});
      return;
    }
    if (w.letter == 'M') {
      if (w.value < 0 || w.value != std::floor(w.value) || w.value > 1000)
        fail(errc::gcode_unsupported, "M-code " + w.text + " is not supported by this reader");
      ln.m.push_back({static_cast<int>(w.value), w.text});
      return;
    }
    for (const Word& o : ln.words)
      if (o.letter == w.letter) {
        // Controllers differ (LinuxCNC and Grbl refuse, others keep the
        // last): refuse. Lint goes on with the first one.
        soft(errc::gcode_repeated_word, std::string(1, w.letter) + " appears twice on the line (" + o.text + " and " + w.text +
                                  "); a block gives each address once");
        return;
      }
    ln.words.push_back(std::move(w));
  }

  // ---- helpers ----------------------------------------------------------
  double val(char c) const { return ln.get(c)->value; }
  std::string txt(char c) const { return ln.get(c)->text; }

  // Target of a move: the current position with the given axis words.
  std::pair<Vec3, unsigned> target() const {
    Vec3 t = st.pos;
    unsigned axes = 0;
    for (int a = 0; a < 3; ++a)
      if (const Word* w = ln.get("XYZ"[a])) {
        t[a] = w->value;
        axes |= 1u << a;
      }
    return {t, axes};
  }

  // Start point of a move: unknown axes take the end's value.
  Vec3 start_for(const Vec3& to) const {
    Vec3 f = st.pos;
    for (int a = 0; a < 3; ++a)
      if (!(st.known_axes & (1u << a))) f[a] = to[a];
    return f;
  }

  void require_xy_known(const std::string& what) const {
    if ((st.known_axes & 3) != 3)
      fail(errc::gcode_position_unknown, what + " cannot start from an unknown position: no earlier move has set " +
                                   ((st.known_axes & 1) ? std::string("Y") : (st.known_axes & 2) ? "X" : "X and Y"));
  }

  void require_feed(const std::string& what) const {
    if (!(st.feed > 0))
      soft(errc::gcode_no_feed, what + " needs a feed rate, and no F word has set one (F is in " + unit() + "/min)");
  }

  // Travel limits of the profile, for the axes given by `axes`.
  void check_travel(const Box3& b, unsigned axes) const {
    if (!self.profile_ || b.empty()) return;
    const auto& m = *self.profile_;
    for (int a = 0; a < 3; ++a) {
      if (!(axes & (1u << a))) continue;
      const double lo = from_mm(m.travel_mm[a][0]), hi = from_mm(m.travel_mm[a][1]);
      if (b.lo[a] < lo || b.hi[a] > hi) {
        const double v = b.lo[a] < lo ? b.lo[a] : b.hi[a];
        soft(errc::gcode_travel, "the move reaches " + axis_name(a) + " = " + fmt_num(v) + " " + unit() +
                           ", outside the travel of machine \"" + m.name + "\" (" + axis_name(a) + " from " +
                           fmt_num(lo) + " to " + fmt_num(hi) + " " + unit() + ")");
      }
    }
  }

  void check_feed_limit(double feed) {
    if (!self.profile_) return;
    const double max = from_mm(self.profile_->max_feed_mm_min);
    if (feed > max && feed != mo.feed_reported) {
      mo.feed_reported = feed;  // lint: once per feed value, not on every move at it
      soft(errc::gcode_feed, "feed F" + fmt_num(feed) + " (" + unit() + "/min) exceeds the maximum feed" + machine() + ", " +
                       fmt_num(max) + " " + unit() + "/min");
    }
  }

  // Lint checks shared by every motion.
  void lint_motion(BlockKind kind, const Vec3& from, const Vec3& to, unsigned axes) {
    if (!lint()) return;
    if (!mo.noted_modes && (!st.units_set || !mo.distance_set || !mo.plane_set)) {
      std::vector<std::string> missing;
      if (!st.units_set) missing.push_back("G21/G20 (units)");
      if (!mo.distance_set) missing.push_back("G90 (absolute)");
      if (!mo.plane_set) missing.push_back("G17 (XY plane)");
      std::string list = missing[0];
      for (size_t k = 1; k < missing.size(); ++k) list += (k + 1 == missing.size() ? " and " : ", ") + missing[k];
      note(errc::gcode_modes_unset, "the first move comes before " + list + (missing.size() == 1 ? " is" : " are") +
                              " set: the machine would use whatever the last program left; start with a safety "
                              "line such as G21 G90 G17");
      mo.noted_modes = true;
    }
    if (is_cutting(kind)) {
      if (!mo.noted_position && (st.known_axes & 7) != 7) {
        note(errc::gcode_position_unknown, "this cutting move starts from an unknown position (no earlier move set " +
                                     std::string((st.known_axes & 1) ? "" : "X ") + ((st.known_axes & 2) ? "" : "Y ") +
                                     ((st.known_axes & 4) ? "" : "Z ") +
                                     "): position the tool with G00 first");
        mo.noted_position = true;
      }
      if (!st.spindle_on && !mo.noted_spindle) {
        note(errc::gcode_spindle_off, "cutting move with the spindle stopped: no M03/M04 is in effect");
        mo.noted_spindle = true;
      }
    } else if ((axes & 3) && (axes & 4) && to.z < from.z && (to.x != from.x || to.y != from.y)) {
      note(errc::gcode_rapid_plunge, "a rapid move lowers Z while moving in X/Y: plunge separately (G00 over the point, then "
                           "G01 down)");
    }
  }

  MotionBlock block(BlockKind k, const Vec3& to) const {
    MotionBlock b;
    b.kind = k;
    b.line = b.first_line = line;
    b.to = to;
    b.from = start_for(to);
    b.from_known = st.known_axes & 7;
    b.feed = k == BlockKind::rapid ? 0 : st.feed;
    return b;
  }

  void commit_move(const MotionBlock& b, unsigned axes) {
    st.pos = b.to;
    st.known_axes |= axes;
    mo.moved = true;
    out.push_back(b);
  }

  // ---- the line ------------------------------------------------------------
  void run(std::string_view text) {
    parse(text);
    if (ln.percent || ln.program_number) return;
    if (ln.empty()) {
      if (ln.n) check_n();
      return;
    }
    if (mo.end_line)
      fail(errc::gcode_after_end, "the program ended at line " + std::to_string(mo.end_line) +
                            " (M02/M30): nothing after it runs; remove this line or move the end");
    if (ln.n) check_n();
    if (mo.open) {
      if (continue_block()) return;
    }
    run_modal();
  }

  void check_n() {
    if (mo.last_n >= 0 && *ln.n <= mo.last_n)
      note(errc::gcode_line_number_order, "line number N" + std::to_string(*ln.n) + " does not increase (the previous was N" +
                                    std::to_string(mo.last_n) + ")");
    mo.last_n = *ln.n;
  }

  // Lines inside an open multi-line block. Returns true when consumed.
  bool continue_block() {
    if (mo.open == 52) return continue_g52();
    // Fanuc: "K- [X- Y- Z- R-]" until the P-th knot-only block.
    const bool only_block_words = ln.g.empty() && ln.m.empty() &&
                                  std::all_of(ln.words.begin(), ln.words.end(), [](const Word& w) {
                                    return std::string_view("KXYZR").find(w.letter) != std::string_view::npos;
                                  });
    if (!ln.has('K') || !only_block_words) {
      if (ln.has('K') && ln.g.empty() && ln.m.empty()) {
        if (ln.has('P')) fail(errc::gcode_nurbs_word, "P (the rank) is only given on the first block of a NURBS block, found " + txt('P'));
        if (ln.has('F')) fail(errc::gcode_nurbs_word, "F is only given on the first block of a NURBS block, found " + txt('F'));
      }
      const std::string msg = "the NURBS block opened at line " + std::to_string(mo.open_line) +
                              " is incomplete: it has " + std::to_string(mo.ctrl.size()) + " control points and " +
                              std::to_string(mo.knot_only) + " of its " + std::to_string(mo.order) +
                              " knot-only blocks; until the last knot every line must be 'K- [X- Y- Z- R-]'";
      if (!lint()) fail(errc::gcode_nurbs_open, msg);
      soft(errc::gcode_nurbs_open, msg);
      abandon_block();
      return false;  // lint reads the line on its own
    }
    const Word& k = *ln.get('K');
    const bool knot_only = ln.words.size() == 1;
    if (!knot_only) {
      if (mo.knot_only > 0)
        fail(errc::gcode_knot_count, "a control point after the knot-only blocks that began at line " +
                               std::to_string(mo.knot_only_line) + ": a NURBS block lists every control point first, "
                               "then exactly P (" + std::to_string(mo.order) + ") knot-only K blocks");
      Vec3 p = mo.ctrl.back();
      for (int a = 0; a < 3; ++a)
        if (const Word* w = ln.get("XYZ"[a])) p[a] = w->value;
      double w = 1;
      if (ln.has('R')) w = weight(*ln.get('R'));
      mo.ctrl.push_back(p);
      mo.weights.push_back(w);
    } else {
      if (mo.knot_only == 0) mo.knot_only_line = line;
      ++mo.knot_only;
    }
    add_knot(k, knot_only);
    if (mo.knot_only == mo.order) complete_fanuc();
    return true;
  }

  double weight(const Word& r) const {
    if (!(r.value > 0)) soft(errc::gcode_weight, "weight " + r.text + ": expected a weight R > 0");
    return r.value;
  }

  // Knot rules of the Fanuc block (alarms PS1004-PS1009 cover the same).
  void add_knot(const Word& k, bool knot_only) {
    const double v = k.value;
    const int rank = mo.order;
    size_t prev = mo.knots.size();
    while (prev > 0 && std::isnan(mo.knots[prev - 1])) --prev;
    bool reported = false;
    if (prev > 0 && v < mo.knots[prev - 1]) {
      soft(errc::gcode_knot_order, k.text + ": expected a knot >= " + fmt_num(mo.knots[prev - 1]) +
                             " (knots must not decrease; the previous knot is on line " +
                             std::to_string(mo.knot_lines[prev - 1]) + "), found " + fmt_num(v));
      reported = true;
    }
    const size_t idx = mo.knots.size();  // this knot's index
    // Clamped start: the first `rank` knots are equal.
    if (!reported && idx < static_cast<size_t>(rank)) {
      for (size_t j = 0; j < idx; ++j)
        if (!std::isnan(mo.knots[j]) && mo.knots[j] != v) {
          soft(errc::gcode_knot_clamped, k.text + " is knot " + std::to_string(idx + 1) + " of the block: the first P (" +
                                   std::to_string(rank) + ") knots must be equal (a clamped start: the curve starts "
                                   "at the current position), but the first is " + fmt_num(mo.knots[j]) +
                                   " (line " + std::to_string(mo.knot_lines[j]) + ")");
          reported = true;
          break;
        }
    }
    // Clamped end: the knot-only blocks (the last `rank` knots) are equal.
    if (!reported && knot_only && mo.knot_only > 1) {
      const size_t first_end = mo.knots.size() - static_cast<size_t>(mo.knot_only - 1);
      if (mo.knots[first_end] != v) {
        soft(errc::gcode_knot_clamped, k.text + ": the last P (" + std::to_string(rank) + ") knots, the knot-only blocks, must "
                                 "be equal (a clamped end: the curve ends at its last control point), but the first "
                                 "of them is " + fmt_num(mo.knots[first_end]) + " (line " +
                                 std::to_string(mo.knot_lines[first_end]) + ")");
        reported = true;
      }
    }
    // Multiplicity: no knot repeated more than `rank` times.
    if (!reported) {
      size_t run = 1;
      for (size_t j = idx; j > 0 && mo.knots[j - 1] == v; --j) ++run;
      if (run == static_cast<size_t>(rank) + 1)
        soft(errc::gcode_knot_multiplicity, k.text + ": knot " + fmt_num(v) + " now appears " + std::to_string(run) +
                                      " times (from line " + std::to_string(mo.knot_lines[idx + 1 - run]) +
                                      "); no knot may repeat more than the rank P (" + std::to_string(rank) +
                                      ") times");
    }
    mo.knots.push_back(v);
    mo.knot_lines.push_back(line);
  }

  void complete_fanuc() {
    if (mo.ctrl.size() < static_cast<size_t>(mo.order)) {
      const std::string msg = "the NURBS block opened at line " + std::to_string(mo.open_line) + " has " +
                              std::to_string(mo.ctrl.size()) + " control points; a block of rank P" +
                              std::to_string(mo.order) + " needs at least " + std::to_string(mo.order);
      if (!lint()) fail(errc::gcode_knot_count, msg);
      soft(errc::gcode_knot_count, msg);  // lint: the block is dropped and reading goes on
      abandon_block();
      return;
    }
    finish_nurbs_block(mo.knots);
    st.motion = mo.open;  // NURBS mode goes on until G00..G03
    clear_block();
  }

  // Travel and lint checks of a completed NURBS block, then the move.
  // The NURBS block collected since line mo.open_line (Fanuc G06.2 or
  // LinuxCNC G5.2), ending at this line, with these knots.
  void finish_nurbs_block(std::vector<double> knots) {
    MotionBlock b;
    b.kind = BlockKind::nurbs;
    b.first_line = mo.open_line;
    b.line = line;
    b.from = mo.ctrl.front();
    b.to = mo.ctrl.back();
    b.feed = mo.open_feed;
    b.order = mo.order;
    b.ctrl = mo.ctrl;
    b.weights = mo.weights;
    b.knots = std::move(knots);
    finish_curve_block(b);
  }

  void finish_curve_block(MotionBlock& b) {
    const bool valid = std::none_of(b.knots.begin(), b.knots.end(), [](double k) { return std::isnan(k); });
    Box3 box;
    bool exact = false;
    if (valid) {
      try {
        for (const auto& z : block_to_bezier(b)) box.add(bounds(z));
        exact = true;
      } catch (const std::invalid_argument&) {
      }
    }
    if (!exact)
      for (const auto& p : b.ctrl) box.add(p);  // the hull contains the curve
    check_travel(box, 7);
    check_feed_limit(b.feed);
    if (lint() && valid) lint_jumps(b);
    st.pos = b.to;
    st.known_axes = 7;
    mo.moved = true;
    out.push_back(b);
  }

  // An interior knot of multiplicity = order lets the curve jump from
  // ctrl[i-1] to ctrl[i]; the reader accepts it (the dialect allows it),
  // lint flags it when the two points differ.
  void lint_jumps(const MotionBlock& b) {
    const auto& U = b.knots;
    const size_t k = static_cast<size_t>(b.order);
    for (size_t i = k; i + k < U.size();) {
      size_t j = i;
      while (j + 1 < U.size() && U[j + 1] == U[i]) ++j;
      if (j - i + 1 >= k && i < b.ctrl.size() && b.ctrl[i - 1] != b.ctrl[i])
        note(errc::gcode_nurbs_jump, "knot " + fmt_num(U[i]) + " repeats " + std::to_string(j - i + 1) +
                               " times inside the NURBS block of line " + std::to_string(b.first_line) +
                               ": the curve jumps from " + pt(b.ctrl[i - 1]) + " to " + pt(b.ctrl[i]),
             b.line);
      i = j + 1;
    }
  }

  void clear_block() {
    save_lists();
    mo.open = 0;
    mo.ctrl.clear();
    mo.weights.clear();
    mo.knots.clear();
    mo.knot_lines.clear();
    mo.knot_only = 0;
    mo.knot_only_line = 0;
  }
  void abandon_block() {
    clear_block();
    st.motion = -1;
  }

  // G5.2 block lines: "X- Y- P-" until G5.3.
  bool continue_g52() {
    const bool closes = ln.g.size() == 1 && ln.g[0].first == 53;
    if (closes) return false;  // run_modal() handles G5.3
    const bool only_points = ln.g.empty() && ln.m.empty() &&
                             std::all_of(ln.words.begin(), ln.words.end(), [](const Word& w) {
                               return std::string_view("XYP").find(w.letter) != std::string_view::npos;
                             });
    if (!only_points) {
      std::string msg = "the G5.2 block opened at line " + std::to_string(mo.open_line) +
                        " is still open: only control points 'X- Y- P-' may follow until G5.3";
      if (ln.has('Z')) msg = "G5.2 blocks move in X and Y only: a Z word is not allowed (" + txt('Z') + ")";
      if (!lint()) fail(errc::gcode_nurbs_open, msg);
      soft(errc::gcode_nurbs_open, msg);
      abandon_block();
      return false;
    }
    g52_point();
    return true;
  }

  void g52_point() {
    if (ln.has('X') != ln.has('Y'))
      fail(errc::gcode_nurbs_point, std::string("a G5.2 control point needs both X and Y, found only ") + (ln.has('X') ? txt('X') : txt('Y')));
    if (!ln.has('X')) fail(errc::gcode_nurbs_point, "a G5.2 control point line needs X, Y and P (its weight)");
    double w = 1;
    if (!ln.has('P')) soft(errc::gcode_weight, "a G5.2 control point needs its weight P (LinuxCNC refuses a point without it)");
    else w = weight(*ln.get('P'));
    mo.ctrl.push_back({val('X'), val('Y'), st.pos.z});
    mo.weights.push_back(w);
  }

  // ---- modal groups and non-motion words --------------------------------
  void run_modal() {
    // One code per modal group.
    std::array<std::string, 16> seen_g{};
    int motion = -999;
    bool dwell = false;
    for (const auto& [c, t] : ln.g) {
      const int grp = g_group(c);
      if (grp < 0) fail(errc::gcode_unsupported, "G-code " + t + " is not supported by this reader");
      if (grp > 0) {
        if (!seen_g[static_cast<size_t>(grp)].empty())
          fail(errc::gcode_modal_group, seen_g[static_cast<size_t>(grp)] + " and " + t + " are in the same modal group: give one");
        seen_g[static_cast<size_t>(grp)] = t;
      }
      switch (c) {
        case 180: case 190:
          fail(errc::gcode_plane, t + " selects the " + std::string(c == 180 ? "XZ" : "YZ") +
                            " plane: this reader supports G17 (XY) only");
        case 910: fail(errc::gcode_incremental, "G91 (incremental distances) is not supported by this reader: use G90 absolute coordinates");
        case 930: case 950:
          fail(errc::gcode_unsupported, t + std::string(c == 930 ? " (inverse-time feed)" : " (feed per revolution)") +
                                  " is not supported by this reader: use G94 (units per minute)");
        case 410: case 420:
          fail(errc::gcode_unsupported, t + " (cutter radius compensation) is not supported by this reader: the program must "
                                  "describe the tool centre");
        case 430: fail(errc::gcode_unsupported, "G43 (tool length compensation) is not supported by this reader");
        case 40: dwell = true; break;
        default: break;
      }
      if (grp == 1) {
        motion = c;
        word = t;
      }
    }
    std::array<std::string, 16> seen_m{};
    for (const auto& [c, t] : ln.m) {
      const int grp = m_group(c);
      if (grp < 0) fail(errc::gcode_unsupported, "M-code " + t + " is not supported by this reader");
      if (!seen_m[static_cast<size_t>(grp)].empty())
        fail(errc::gcode_modal_group, seen_m[static_cast<size_t>(grp)] + " and " + t + " are in the same modal group: give one");
      seen_m[static_cast<size_t>(grp)] = t;
    }
    if (mo.open == 52 && motion != 53)
      fail(errc::gcode_nurbs_open, "the G5.2 block opened at line " + std::to_string(mo.open_line) + " is still open: close it with G5.3");

    // Which motion the line's words belong to (-999: none; -1: G80).
    const bool has_axes = ln.has('X') || ln.has('Y') || ln.has('Z');
    bool motion_words = has_axes;
    for (char c : std::string_view(dwell ? "IJKRQL" : "IJKRQLP")) motion_words = motion_words || ln.has(c);
    int active = -999;
    if (motion == 800) active = -1;
    else if (motion != -999) active = motion;
    else if (motion_words) active = st.motion >= 0 && st.motion <= 3 ? st.motion * 10 : st.motion;
    if (dwell && (has_axes || motion != -999))
      fail(errc::gcode_modal_group, "G04 (dwell) cannot share a line with a motion: put it on its own line");
    check_letters(active, dwell, motion != -999);

    // Execution order (RS274/NGC): F, S, T, M06, spindle, coolant, dwell,
    // plane, units, distance mode, motion, program end.
    if (ln.has('F')) {
      if (val('F') < 0) fail(errc::gcode_feed, "expected a feed rate F >= 0, found " + txt('F'));
      st.feed = val('F');
    }
    if (ln.has('S')) {
      if (val('S') < 0) fail(errc::gcode_spindle, "expected a spindle speed S >= 0, found " + txt('S'));
      st.spindle_rpm = val('S');
    }
    if (ln.has('T')) {
      // (Bounded before the conversion: T1e20 as an int is undefined; found by fuzzing.)
      if (val('T') < 0 || val('T') != std::floor(val('T')) || val('T') > 1e9)
        fail(errc::gcode_tool, "expected a whole tool number T from 0 to 1000000000, found " + txt('T'));
      mo.selected_tool = static_cast<int>(val('T'));
    }
    for (const auto& [c, t] : ln.m) {
      if (c == 6) {
        if (mo.selected_tool < 0) note(errc::gcode_tool_unset, "M06 changes the tool, but no T word has selected one");
        st.tool = std::max(mo.selected_tool, 0);
      }
      if (c == 3 || c == 4) {
        st.spindle_on = true;
        mo.noted_spindle = false;
      }
      if (c == 5) st.spindle_on = false;
    }
    if (dwell) {
      if (!ln.has('P') || val('P') < 0) fail(errc::gcode_dwell, "G04 needs its duration P (seconds) >= 0");
    }
    for (const auto& [c, t] : ln.g) {
      if (c == 170) {
        st.plane = 17;
        mo.plane_set = true;
      } else if (c == 200 || c == 210) {
        const Units u = c == 200 ? Units::inch : Units::mm;
        if (mo.moved && u != st.units)
          fail(errc::gcode_units_change, t + " changes the units after the first move: positions would change meaning; set "
                                   "the units once, before any move");
        st.units = u;
        st.units_set = true;
      } else if (c == 900) {
        st.absolute = true;
        mo.distance_set = true;
      }
    }
    if (active != -999) motion_line(active, motion != -999);
    for (const auto& [c, t] : ln.m)
      if (c == 2 || c == 30) {
        st.program_end = true;
        mo.end_line = line;
      }
  }

  // Every word must mean something on this line.
  void check_letters(int active, bool dwell, bool explicit_motion) {
    std::string allowed = "FST";
    switch (active) {
      case 0: case 10: allowed += "XYZ"; break;
      case 20: case 30: allowed += "XYZIJR"; break;
      case 50: allowed += "XYIJPQ"; break;
      case 51: allowed += "XYIJ"; break;
      case 52: allowed += "XYPL"; break;
      case 62: case 63: allowed += explicit_motion ? "XYZKRP" : ""; break;
      default: break;
    }
    if (dwell) allowed += "P";
    for (const Word& w : ln.words) {
      if (allowed.find(w.letter) != std::string::npos) continue;
      if (std::string_view("ABCUVW").find(w.letter) != std::string_view::npos)
        fail(errc::gcode_unsupported, "axis " + std::string(1, w.letter) + " (" + w.text + ") is not supported by this reader: X, Y and Z only");
      if (w.letter == 'K' && (active == 20 || active == 30))
        fail(errc::gcode_arc, w.text + ": K is not a centre word in the G17 plane (some controllers refuse even K0): give I and J only");
      if (w.letter == 'Z' && (active == 50 || active == 51 || active == 52))
        fail(errc::gcode_bezier, wt(active) + " moves in X and Y only: a Z word (" + w.text + ") is not allowed");
      if ((active == 62 || active == 63) && !explicit_motion) {
        if (w.letter == 'K')
          fail(errc::gcode_nurbs_start, "K word outside a NURBS block (the last one ended at line " +
                                  std::to_string(mo.nurbs_mode_line) + "): a block starts with " + g_text(active) +
                                  " P- K- X- Y- Z-");
        fail(errc::gcode_nurbs_mode, w.text + " in NURBS mode (" + g_text(active) + " since line " +
                               std::to_string(mo.nurbs_mode_line) + ") outside a block: start a new block with " +
                               g_text(active) + ", or leave the mode with G00 or G01");
      }
      if (std::string_view("XYZ").find(w.letter) != std::string_view::npos)
        fail(errc::gcode_no_motion, w.text + ": axis words without a motion mode (none is active): give G00 or G01");
      if (w.letter == 'K') fail(errc::gcode_nurbs_start, "K word outside a NURBS block: a block starts with G06.2 P- K- X- Y- Z-");
      fail(errc::gcode_unexpected_word, "word " + w.text + " has no meaning on this line" +
                                  (active >= 0 ? " (" + wt(active) + ")" : std::string()) + ": remove it");
    }
  }

  // ---- motions ---------------------------------------------------------------
  void motion_line(int code, bool explicit_motion) {
    if (code == -1) {  // G80 or no motion words
      st.motion = -1;
      mo.g5_chain = false;
      return;
    }
    if (self.profile_ && explicit_motion) check_dialect(code);
    switch (code) {
      case 0: case 10: linear(code == 0); break;
      case 20: case 30: arc(code == 20); break;
      case 50: g5(); break;
      case 51: g51(); break;
      case 52: g52(); break;
      case 53: g53(); break;
      case 62: case 63:
        if (!explicit_motion) break;  // K lines are handled by continue_block()
        fanuc_start(code);
        break;
      default: break;
    }
  }

  void check_dialect(int code) const {
    const auto& m = *self.profile_;
    if ((code == 20 || code == 30) && !m.arcs)
      fail(errc::gcode_dialect, "machine \"" + m.name + "\" does not take arcs (" + wt(code) + "): use G01");
    if (code >= 50 && code <= 53 && m.nurbs != NurbsDialect::linuxcnc)
      fail(errc::gcode_dialect, wt(code) + " is a LinuxCNC word; machine \"" + m.name + "\" does not take it");
    if (is_fanuc(code)) {
      if (m.nurbs != NurbsDialect::fanuc)
        fail(errc::gcode_dialect, "machine \"" + m.name + "\" does not take Fanuc-style NURBS blocks (" + wt(code) + ")");
      if (code != start_code(m.nurbs_start_word))
        fail(errc::gcode_dialect, "machine \"" + m.name + "\" starts a NURBS block with " + m.nurbs_start_word + ", not " +
                            wt(code));
    }
  }
  static int start_code(const std::string& word) {
    double v = 0;
    if (word.size() > 1) std::from_chars(word.data() + 1, word.data() + word.size(), v);
    return static_cast<int>(std::nearbyint(v * 10));
  }

  void linear(bool rapid) {
    st.motion = rapid ? 0 : 1;
    mo.g5_chain = false;
    const auto [to, axes] = target();
    if (!axes) return;
    if (!rapid) require_feed("G01");
    MotionBlock b = block(rapid ? BlockKind::rapid : BlockKind::linear, to);
    lint_motion(b.kind, b.from, to, axes);
    Box3 box;
    box.add(to);
    check_travel(box, axes | st.known_axes);
    if (!rapid) check_feed_limit(st.feed);
    commit_move(b, axes);
  }

  double arc_tolerance() const {
    return from_mm(self.profile_ ? self.profile_->arc_tolerance_mm : kDefaultArcToleranceMm);
  }

  void arc(bool cw) {
    st.motion = cw ? 2 : 3;
    mo.g5_chain = false;
    const std::string g = cw ? "G02" : "G03";
    const bool ij = ln.has('I') || ln.has('J'), r = ln.has('R');
    if (ij && r) fail(errc::gcode_arc, g + ": give either I and J (the centre) or R (the radius), not both");
    if (!ij && !r) fail(errc::gcode_arc, g + " needs the centre offsets I and J (or a radius R)");
    require_xy_known(g);
    require_feed(g);
    const auto [to, axes] = target();
    const Vec3 from = st.pos;
    Vec3 c{from.x, from.y, from.z};
    if (ij) {
      c.x += ln.has('I') ? val('I') : 0;
      c.y += ln.has('J') ? val('J') : 0;
    } else {
      if (!(axes & 3)) fail(errc::gcode_arc, g + " with R needs an end point X or Y (a full circle needs I and J)");
      const double dx = to.x - from.x, dy = to.y - from.y, d = std::hypot(dx, dy);
      const double R = val('R');
      if (d == 0) fail(errc::gcode_arc, g + " with R: the end point equals the start point; give a full circle with I and J");
      const double tol = arc_tolerance();
      if (std::abs(R) < d / 2 - tol)
        fail(errc::gcode_arc, txt('R') + " is too small for the chord of " + fmt_num(d) + " " + unit() +
                        " between start and end (the radius must be at least half of it)");
      const double h = std::sqrt(std::max(0.0, R * R - d * d / 4));
      // Centre left of the chord for a minor CCW arc or a major CW one.
      const double side = ((!cw) == (R > 0)) ? 1.0 : -1.0;
      c.x = (from.x + to.x) / 2 - side * h * dy / d;
      c.y = (from.y + to.y) / 2 + side * h * dx / d;
    }
    const double r0 = std::hypot(from.x - c.x, from.y - c.y), r1 = std::hypot(to.x - c.x, to.y - c.y);
    if (r0 == 0) fail(errc::gcode_arc, g + ": the centre coincides with the start point (I and J are both 0)");
    const double tol = arc_tolerance();
    const double slack = 1e-12 * std::max({1.0, max_abs(from), max_abs(to), max_abs(c)});
    if (std::abs(r0 - r1) > tol + slack)
      soft(errc::gcode_arc_radius, g + ": the centre (" + fmt_num(c.x) + ", " + fmt_num(c.y) + ") is " + fmt_num(r0) +
                             " from the start and " + fmt_num(r1) + " from the end; they differ by " +
                             fmt_num(std::abs(r0 - r1)) + " " + unit() + ", more than the arc tolerance" + machine() +
                             " (" + fmt_num(tol) + " " + unit() + "): the end point or the centre is wrong");
    MotionBlock b = block(cw ? BlockKind::arc_cw : BlockKind::arc_ccw, to);
    b.center = {c.x, c.y, from.z};
    lint_motion(b.kind, b.from, to, axes);
    check_travel(arc_box(b), 7);
    check_feed_limit(st.feed);
    commit_move(b, axes);
  }

  void g5() {
    st.motion = 50;
    require_xy_known("G5");
    require_feed("G5");
    if (ln.has('I') != ln.has('J')) fail(errc::gcode_bezier, "G5 needs both I and J, or neither");
    if (!ln.has('P') || !ln.has('Q'))
      fail(errc::gcode_bezier, "G5 needs both P and Q (the second control point's offset from the end point)");
    Vec3 ij;
    if (ln.has('I')) ij = {val('I'), val('J'), 0};
    else if (mo.g5_chain) ij = mo.g5_next_ij;
    else fail(errc::gcode_bezier, "G5 without I and J continues the tangent of a G5 just before it, and there is none: give I and J");
    const auto [to, axes] = target();
    const Vec3 from = st.pos;
    MotionBlock b = block(BlockKind::bezier, to);
    b.order = 4;
    b.ctrl = {from, from + ij, to + Vec3{val('P'), val('Q'), 0}, to};
    curve_move(b, axes);
    mo.g5_chain = true;
    mo.g5_next_ij = {-val('P'), -val('Q'), 0};
  }

  void g51() {
    st.motion = 51;
    mo.g5_chain = false;
    require_xy_known("G5.1");
    require_feed("G5.1");
    if (!ln.has('I') || !ln.has('J')) fail(errc::gcode_bezier, "G5.1 needs both I and J (the middle control point's offset from the start)");
    const auto [to, axes] = target();
    MotionBlock b = block(BlockKind::bezier, to);
    b.order = 3;
    b.ctrl = {st.pos, st.pos + Vec3{val('I'), val('J'), 0}, to};
    curve_move(b, axes);
  }

  void curve_move(MotionBlock& b, unsigned axes) {
    lint_motion(b.kind, b.from, b.to, axes);
    Box3 box;
    for (const auto& z : block_to_bezier(b)) box.add(bounds(z));
    check_travel(box, 7);
    check_feed_limit(st.feed);
    commit_move(b, axes);
  }

  void g52() {
    if (mo.open == 52)
      fail(errc::gcode_nurbs_open, "a G5.2 block is already open since line " + std::to_string(mo.open_line) + ": close it with G5.3 first");
    require_xy_known("G5.2");
    require_feed("G5.2");
    mo.g5_chain = false;
    int order = 3;
    if (ln.has('L')) {
      const double L = val('L');
      if (L != std::floor(L) || L < 3)
        soft(errc::gcode_rank, "G5.2 order " + txt('L') + ": LinuxCNC ignores an order below 3 (it then uses 3); give L3 or more");
      // Any order above the largest is refused below; one past it keeps a
      // huge L from overflowing the int (found by fuzzing).
      else order = static_cast<int>(std::min(L, static_cast<double>(kMaxBezierDegree) + 2));
    }
    const int max = self.profile_ ? self.profile_->nurbs_max_rank : kMaxBezierDegree + 1;
    if (order > max) {
      soft(errc::gcode_rank, "G5.2 order " + txt('L') + " exceeds the largest order" + machine() + ", " + std::to_string(max));
    }
    mo.open = 52;
    mo.open_line = line;
    mo.order = order;
    mo.open_feed = st.feed;
    save_lists();
    mo.ctrl = {st.pos};
    mo.weights = {1};
    if (ln.has('X') || ln.has('Y')) {
      // LinuxCNC: the current position gets weight 1, the point its P.
      g52_point();
    } else if (!ln.has('P')) {
      soft(errc::gcode_weight, "the G5.2 line needs P, the weight of its first control point (the current position): "
                     "without it the weight differs between LinuxCNC versions");
    } else {
      mo.weights[0] = weight(*ln.get('P'));
    }
    st.motion = 52;
    lint_motion(BlockKind::nurbs, st.pos, st.pos, 0);
  }

  void g53() {
    if (mo.open != 52) fail(errc::gcode_nurbs_start, "G5.3 ends a G5.2 block, and none is open");
    if (!ln.words.empty()) fail(errc::gcode_unexpected_word, "G5.3 takes no words, found " + ln.words.front().text);
    if (mo.ctrl.size() < static_cast<size_t>(mo.order)) {
      const std::string msg = "the G5.2 block opened at line " + std::to_string(mo.open_line) + " has " +
                              std::to_string(mo.ctrl.size()) + " control points; order L" + std::to_string(mo.order) +
                              " needs at least " + std::to_string(mo.order);
      if (!lint()) fail(errc::gcode_knot_count, msg);
      soft(errc::gcode_knot_count, msg);
      abandon_block();
      return;
    }
    finish_nurbs_block(linuxcnc_knots(mo.ctrl.size(), mo.order));
    clear_block();
    st.motion = -1;  // as LinuxCNC does after G5.3
  }

  void fanuc_start(int code) {
    st.motion = code;
    mo.g5_chain = false;
    mo.nurbs_mode_line = line;
    const int max = self.profile_ ? self.profile_->nurbs_max_rank : 4;
    int rank = 4;
    if (ln.has('P')) {
      const double P = val('P');
      if (P != std::floor(P) || P < 2 || P > max) {
        soft(errc::gcode_rank, "rank " + txt('P') + ": expected P from 2 to " + std::to_string(max) + " (order = degree + 1)" +
                         machine());
        rank = static_cast<int>(std::clamp(std::floor(P), 2.0, static_cast<double>(max)));
      } else {
        rank = static_cast<int>(P);
      }
    }
    require_feed(wt(code));
    // The first control point is the current position.
    Vec3 p0 = st.pos;
    for (int a = 0; a < 3; ++a) {
      const Word* w = ln.get("XYZ"[a]);
      if (!w) continue;
      if (st.known_axes & (1u << a)) {
        const double slack = 1e-12 * std::max(1.0, std::abs(st.pos[a]));
        if (std::abs(w->value - st.pos[a]) > slack)
          soft(errc::gcode_nurbs_start, w->text + ": the first control point of a NURBS block must be the current position (" +
                                  axis_name(a) + " = " + fmt_num(st.pos[a]) + ")");
      }
      p0[a] = w->value;
    }
    if ((st.known_axes & 7) != 7 && lint() && !mo.noted_position) {
      // Axes neither known nor given: lint goes on with 0.
      note(errc::gcode_position_unknown, "the NURBS block starts from a position this program has not set (its first "
                               "control point must be the current position): position the tool with G00 first");
      mo.noted_position = true;
    }
    double w = 1;
    if (ln.has('R')) w = weight(*ln.get('R'));
    mo.open = code;
    mo.open_line = line;
    mo.order = rank;
    mo.open_feed = st.feed;
    save_lists();
    mo.ctrl = {p0};
    mo.weights = {w};
    mo.knots.clear();
    mo.knot_lines.clear();
    mo.knot_only = 0;
    if (!ln.has('K')) {
      soft(errc::gcode_knot_missing, "the first block of a NURBS block needs its knot K (K- X- Y- Z- R-)");
      mo.knots.push_back(kNaN);
      mo.knot_lines.push_back(line);
    } else {
      add_knot(*ln.get('K'), false);
    }
    lint_motion(BlockKind::nurbs, p0, p0, 0);
    // The position is defined from here on (the block starts there).
    st.pos = p0;
    st.known_axes = 7;
  }
};

// ---------------------------------------------------------------------------

GcodeInterpreter::GcodeInterpreter(const MachineProfile* profile) : profile_(profile) {}

std::vector<MotionBlock> GcodeInterpreter::feed_line(std::string_view text, int line_no) {
  more_.last_line = line_no;  // bookkeeping for finish(), even if the line is refused
  // Stated limits (limits.hpp), checked before the line is looked at.
  if (static_cast<size_t>(line_no) > kMaxReadLines)
    throw InputError(errc::gcode_program_too_long, Place::at_line(line_no),
                     "the program has more than " + std::to_string(kMaxReadLines) +
                         " lines, the most bezcam reads (docs/limits.md); split it into several programs");
  while (!text.empty() && (text.back() == '\r' || text.back() == '\n')) text.remove_suffix(1);
  if (text.size() > kMaxLineBytes)
    throw InputError(errc::gcode_line_too_long, Place::at_line(line_no),
                     "the line has " + std::to_string(text.size()) + " characters, more than the " +
                         std::to_string(kMaxLineBytes) + " bezcam reads in one line (docs/limits.md)");
  // The line runs on copies of the state, committed only when it is
  // accepted. The open NURBS block's lists are moved in, not copied (a copy
  // per line made a block of n control points cost n^2): until a line
  // clears or replaces them (Impl::save_lists() keeps them then) it only
  // appends, so a refused line is undone by cutting them back.
  const std::array<size_t, 4> sizes{more_.ctrl.size(), more_.weights.size(), more_.knots.size(),
                                    more_.knot_lines.size()};
  Impl im{*this, state_, std::move(more_), line_no, {}, {}, {}};
  im.sizes0 = sizes;
  try {
    im.run(text);
  } catch (...) {
    // more_ kept every scalar (moving copies them); give the lists back.
    Impl::Lists& back = im.saved;
    if (!im.lists_saved) {
      back.ctrl = std::move(im.mo.ctrl);
      back.weights = std::move(im.mo.weights);
      back.knots = std::move(im.mo.knots);
      back.knot_lines = std::move(im.mo.knot_lines);
      back.ctrl.resize(sizes[0]);
      back.weights.resize(sizes[1]);
      back.knots.resize(sizes[2]);
      back.knot_lines.resize(sizes[3]);
    }
    more_.ctrl = std::move(back.ctrl);
    more_.weights = std::move(back.weights);
    more_.knots = std::move(back.knots);
    more_.knot_lines = std::move(back.knot_lines);
    throw;
  }
  state_ = im.st;
  more_ = std::move(im.mo);
  return std::move(im.out);
}

std::vector<MotionBlock> GcodeInterpreter::finish() {
  if (more_.open) {
    const bool fanuc = more_.open != 52;
    const std::string msg =
        fanuc ? "the program ends inside the NURBS block opened at line " + std::to_string(more_.open_line) + ": it has " +
                    std::to_string(more_.ctrl.size()) + " control points and " + std::to_string(more_.knot_only) +
                    " of its " + std::to_string(more_.order) + " knot-only K blocks"
              : "the program ends inside the G5.2 block opened at line " + std::to_string(more_.open_line) +
                    ": close it with G5.3";
    throw InputError(errc::gcode_nurbs_open, Place::at_line(std::max(more_.last_line, 1)), msg);
  }
  return {};
}

namespace {

// The whole text's limit (limits.hpp); the lines' count and length are
// checked line by line by feed_line().
std::optional<GcodeFinding> too_large(std::string_view text) {
  if (text.size() <= kMaxProgramBytes) return std::nullopt;
  return GcodeFinding{1, errc::gcode_program_too_large,
                      "the program is " + std::to_string(text.size() >> 20) + " MiB, more than the " +
                          std::to_string(kMaxProgramBytes >> 20) +
                          " MiB bezcam reads (docs/limits.md); split it into several programs"};
}

}  // namespace

std::vector<MotionBlock> read_gcode(std::string_view text, const MachineProfile* profile) {
  if (const auto f = too_large(text)) throw InputError(f->id, "line 1", f->message);
  GcodeInterpreter in(profile);
  std::vector<MotionBlock> out;
  int no = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    auto blocks = in.feed_line(text.substr(pos, end - pos), ++no);
    out.insert(out.end(), std::make_move_iterator(blocks.begin()), std::make_move_iterator(blocks.end()));
    pos = end + 1;
  }
  in.finish();
  return out;
}

std::vector<GcodeFinding> lint_gcode(std::string_view text, const MachineProfile& profile) {
  if (const auto f = too_large(text)) return {*f};
  std::vector<GcodeFinding> findings;
  GcodeInterpreter in(&profile);
  in.findings_ = &findings;
  int no = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    ++no;
    try {
      in.feed_line(text.substr(pos, end - pos), no);
    } catch (const InputError& e) {
      findings.push_back({no, e.id(), e.message()});  // the line is skipped
      if (e.id() == errc::gcode_program_too_long) {  // and so is the rest: one finding, not millions
        std::stable_sort(findings.begin(), findings.end(), [](const auto& a, const auto& b) { return a.line < b.line; });
        return findings;
      }
    }
    pos = end + 1;
  }
  try {
    in.finish();
  } catch (const InputError& e) {
    findings.push_back({std::max(no, 1), e.id(), e.message()});
  }
  if (!in.state().program_end)
    findings.push_back({std::max(no, 1), errc::gcode_no_program_end,
                        "the program has no end (M02 or M30): the controller may wait or run on"});
  std::stable_sort(findings.begin(), findings.end(), [](const auto& a, const auto& b) { return a.line < b.line; });
  return findings;
}

}  // namespace bezcam
