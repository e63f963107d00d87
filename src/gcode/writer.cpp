#include "bezcam/gcode/writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string_view>
#include <unordered_set>

#include "bezcam/cam/program_motion.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/gcode/number_format.hpp"
#include "bezcam/limits.hpp"
#include "bezcam/machine/motion.hpp"
#include "bezcam/machine/planner.hpp"
#include "bezcam/version.hpp"

namespace bezcam {

namespace {

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (size_t i = s.find(from); i != std::string::npos; i = s.find(from, i + to.size())) s.replace(i, from.size(), to);
  return s;
}

// Comment text safe for every controller: no nested parentheses, printable
// ASCII only.
std::string comment(const std::string& text) {
  std::string s;
  // A long id must not make a line longer than a reader takes (limits.hpp).
  const bool cut = text.size() > kMaxCommentBytes;
  for (unsigned char ch : cut ? text.substr(0, kMaxCommentBytes - 3) + "..." : text) {
    if (ch == '(')
      s += '[';
    else if (ch == ')')
      s += ']';
    else if (ch < 32 || ch > 126)
      s += '?';
    else
      s += static_cast<char>(ch);
  }
  return "(" + s + ")";
}

class Writer {
 public:
  // With a sink, the text goes to it in pieces of about kChunk bytes as it
  // is written; without, run() returns it whole.
  Writer(const Program& p, const MachineProfile& m, const GcodeSink* sink = nullptr, const MotionPlan* plan = nullptr)
      : p_(p), m_(m), sink_(sink), plan_(plan) {}

  std::string run() {
    bool numbered = false;
    for (const auto& h : m_.header) {
      numbered = numbered || h.find("{program}") != std::string::npos;
      raw(subst(h));
    }
    const char* u = to_string(p_.units);
    note(std::string("bezcam ") + kVersion + ": " + p_.job_name + ", machine " + m_.name + ", output " +
         output_name(p_));
    // A number the header does not print (no O word on this controller).
    if (p_.program_number && !numbered) note("program " + std::to_string(*p_.program_number));
    // Figures in comments in significant digits, never the coordinate
    // formatter: 5e-07 inch is not "0.".
    const auto sig = [](double v) { return format_significant(v, 4); };
    note("tolerance " + format_significant(p_.tolerance, 6) + " " + u + "; largest deviation measured " +
         measured_text(p_.max_measured, p_.max_bound, p_.tolerance, sig) + " " + u + ", proven bound " +
         format_bound(p_.max_bound, 4) + " " + u + ", rounding included");
    if (m_.comments) {
      tools();
      plunge_feeds();
      registers();
      cycle_time();
    }
    for (const auto& n : p_.notes) note(n);
    line(std::string(p_.units == Units::mm ? "G21" : "G20") + " G90 G17");
    for (const auto& l : m_.preamble) line(subst(l));
    for (const Move& mv : p_.moves) move(mv);
    end_cycles();
    plane(Plane::xy);  // the program ends in G17, as it began
    for (const auto& f : m_.footer) {
      if (!f.empty() && f[0] == '%')
        raw(subst(f));
      else
        line(subst(f));
    }
    if (sink_) {
      (*sink_)(out_);
      out_.clear();
    }
    return std::move(out_);
  }

 private:
  // One style of words in one file: `G4`/`M8` where the profile writes
  // `G0`, `G04`/`M08` where it writes `G00`.
  std::string word(const char* short_form, const char* long_form) const {
    return m_.word_rapid.size() == 2 ? short_form : long_form;
  }

  std::string subst(const std::string& s) const {
    char pn[24];
    std::snprintf(pn, sizeof pn, "%04ld", p_.program_number.value_or(m_.program_number));
    return replace_all(replace_all(s, "{safe_z}", format_number(p_.safe_z, p_.decimals)), "{program}", pn);
  }
  void note(const std::string& text) {
    if (m_.comments) line(comment(text));
  }
  // The tools in the order they are loaded, each with its diameter and
  // shape where the job gives them (`T1: 6 mm flat end mill: outline,
  // bore`; a table's bull, vee or drill with its corner radius or angle,
  // and flutes: `[bull D6 r0.5 flutes 2.5]`) and the entities it cuts: the
  // operator loads them from this. A flat or ball end reads the same with
  // a table as with `tool_diameter`.
  void tools() {
    // Each label once per tool: the contours of one glyph share its label
    // (the labels seen, per tool, in a set: a job of many entities).
    std::vector<std::pair<int, std::vector<std::string>>> cuts;
    std::vector<std::unordered_set<std::string_view>> seen;
    for (const EntityReport& e : p_.entities) {
      auto it = std::find_if(cuts.begin(), cuts.end(), [&](const auto& t) { return t.first == e.tool; });
      if (it == cuts.end()) {
        cuts.push_back({e.tool, {e.label}});
        seen.push_back({e.label});
      } else if (seen[static_cast<size_t>(it - cuts.begin())].insert(e.label).second) {
        it->second.push_back(e.label);
      }
    }
    std::vector<std::pair<int, std::string>> list;
    for (const auto& [tool, labels] : cuts) {
      std::string joined;
      for (const std::string& l : labels) joined += (joined.empty() ? "" : ", ") + l;
      list.push_back({tool, joined});
    }
    if (list.empty() || (list.size() == 1 && list.front().first < 0)) return;
    for (const auto& [tool, labels] : list) {
      std::string what;
      const auto t = std::find_if(p_.tools.begin(), p_.tools.end(), [&](const JobTool& j) { return j.number == tool; });
      if (t != p_.tools.end() && t->diameter)
        what = format_significant(*t->diameter, 6) + (p_.units == Units::inch ? " in " : " mm ") + to_string(t->shape) +
               (t->entry && t->entry->shape != ToolType::flat && t->entry->shape != ToolType::ball
                    ? " [" + t->entry->description() + "]"
                    : "") +
               ": ";
      note("T" + std::to_string(tool) + ": " + what + labels);
    }
  }
  // The plunge feed of each tool (`T2 plunge feed 200 mm/min`), per entity
  // where a tool's entities differ (`T1 plunge feed 150 mm/min: outline`):
  // a resume plunges at the job's feed, not the profile's (resume.hpp).
  void plunge_feeds() {
    std::vector<std::pair<int, std::vector<std::pair<double, std::string>>>> by_tool;  // tool -> (feed, labels)
    for (const EntityReport& e : p_.entities) {
      if (!(e.plunge_feed > 0)) continue;
      auto t = std::find_if(by_tool.begin(), by_tool.end(), [&](const auto& x) { return x.first == e.tool; });
      if (t == by_tool.end()) t = by_tool.insert(by_tool.end(), {e.tool, {}});
      auto f =
          std::find_if(t->second.begin(), t->second.end(), [&](const auto& x) { return x.first == e.plunge_feed; });
      if (f == t->second.end())
        t->second.push_back({e.plunge_feed, e.label});
      else
        f->second += ", " + e.label;
    }
    const std::string u = p_.units == Units::inch ? " in/min" : " mm/min";
    for (const auto& [tool, feeds] : by_tool)
      for (const auto& [feed, labels] : feeds)
        note((tool >= 0 ? "T" + std::to_string(tool) + " " : std::string()) + "plunge feed " +
             format_significant(feed, 6) + u + (feeds.size() > 1 ? ": " + labels : std::string()));
  }
  // Under the controller's compensation (G41/G42 D-), what each D register
  // must hold, next to the tools: the operator sets the tool table from it.
  void registers() {
    std::vector<std::pair<int, double>> regs;  // D, radius, in the order first used
    for (const Move& mv : p_.moves)
      if (const auto* cc = std::get_if<CompensationMove>(&mv.what);
          cc && cc->side != 0 &&
          std::none_of(regs.begin(), regs.end(), [&](const auto& r) { return r.first == cc->d; }))
        regs.push_back({cc->d, cc->radius});
    const char* unit = p_.units == Units::inch ? " in" : " mm";
    for (const auto& [d, r] : regs) {
      char b[128];
      std::snprintf(b, sizeof b, "D%d: tool radius %s%s (diameter %s%s) for G41/G42", d,
                    format_significant(r, 6).c_str(), unit, format_significant(2 * r, 6).c_str(), unit);
      note(b);
    }
  }
  // The cycle time the report gives: the program planned on the machine's
  // motion model when the profile has one (machine/planner.hpp), else feeds and
  // rapids at their rates.
  void cycle_time() {
    if (m_.motion) {
      const MotionPlan own = plan_ ? MotionPlan{} : plan_motion(program_timeline(p_), *m_.motion, PlanDetail::summary);
      const MotionPlan& plan = plan_ ? *plan_ : own;
      // Given, the plan is the program's (program_plan()); planned here,
      // the moves' with the text's time where they differ.
      note(cycle_time_words(m_, plan_ ? plan.cycle_time_s : program_cycle_time_s(p_, m_, own), p_.units));
      path_bound(plan.path_time_s);
      return;
    }
    const double rapid = m_.max_feed_mm_min / mm_per_unit(p_.units);
    const auto motion = program_motion(p_);
    const double s = motion_totals(motion, rapid).time_s();
    note(cycle_time_words(m_, s, p_.units));
  }
  // The cutting along curves beside the time-optimal bound of their exact
  // path (machine/path_bound.hpp), when the program has such cuts.
  void path_bound(double path) {
    const double bound = exact_path_bound_s(p_);
    if (!(bound > 0) || !(path > 0)) return;
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.3f", path / bound);
    note("cutting along the curves " + format_time(path) + "; the exact path's bound on this machine " +
         format_time(bound, true) + " (x" + ratio + "; rapids, plunges and pauses not counted)");
  }
  void raw(std::string_view s) {
    out_ += s;
    out_ += '\n';
    flush();
  }
  void line(std::string_view s) {
    if (m_.line_numbers) {
      char b[16];
      out_ += 'N';
      out_.append(b, std::to_chars(b, b + sizeof b, n_).ptr);
      out_ += ' ';
      n_ += m_.line_step;
    }
    raw(s);
  }
  // Hands the text written so far to the sink once it is a chunk.
  void flush() {
    if (sink_ && out_.size() >= kChunk) {
      (*sink_)(out_);
      out_.clear();
    }
  }
  std::string num(double v) const { return format_number(v, p_.decimals); }

  // Appends a word to s: a space first unless s is empty.
  static void word_to(std::string& s, char letter, std::string_view v) {
    if (!s.empty()) s += ' ';
    if (letter) s += letter;
    s += v;
  }
  // Appends the axis words whose printed value changes; updates the modal
  // state. Numbers are printed into a buffer on the stack, not a string each.
  void axes_to(std::string& s, const Vec3& to, unsigned mask) {
    static const char names[3] = {'X', 'Y', 'Z'};
    for (int a = 0; a < 3; ++a) {
      if (!(mask & (1u << a))) continue;
      char b[kNumberChars];
      const std::string_view v(b, static_cast<size_t>(format_number_to(b, to[a], p_.decimals) - b));
      if (v != axis_[a]) {
        word_to(s, names[a], v);
        axis_[a].assign(v);
      }
    }
  }
  std::string axes(const Vec3& to, unsigned mask) {
    std::string s;
    axes_to(s, to, mask);
    return s;
  }
  // Appends the feed word when its printed value changes.
  void feed_to(std::string& s, double f) {
    char b[kNumberChars];
    const std::string_view v(b, static_cast<size_t>(format_number_to(b, f, m_.feed_decimals) - b));
    if (v == feed_) return;
    feed_.assign(v);
    word_to(s, 'F', v);
  }
  std::string feed(double f) {
    std::string s;
    feed_to(s, f);
    return s;
  }
  static std::string join(std::initializer_list<std::string> parts) {
    std::string s;
    for (const auto& x : parts)
      if (!x.empty()) s += (s.empty() ? "" : " ") + x;
    return s;
  }

  // Selects the arc plane when it changes (a line of its own).
  void plane(Plane pl) {
    if (pl == plane_) return;
    plane_ = pl;
    line("G" + std::to_string(g_number(pl)));
  }

  void move(const Move& mv) {
    const bool canned = m_.cycles.dialect != CannedCycles::Dialect::none;
    if (mv.in_cycle && canned) {  // printed as the cycle's line: where it takes the drill
      if (const Motion* mo = motion_of(mv))
        for (int k = 0; k < 3; ++k)
          if (mo->axes & (1u << k)) {
            pos_[k] = mo->to[k];
            axis_[k] = num(mo->to[k]);
          }
      return;
    }
    if (!std::holds_alternative<Comment>(mv.what) && !std::holds_alternative<CannedCycle>(mv.what)) end_cycles();
    // Back to G17 before what assumes it: compensation, curve blocks (G5.x
    // are XY moves), the operator's and the job's lines, tool changes. Lines,
    // rapids, comments, spindle, coolant and dwells do not depend on it.
    if (plane_ != Plane::xy &&
        !(std::holds_alternative<ArcMove>(mv.what) || std::holds_alternative<LineMove>(mv.what) ||
          std::holds_alternative<RapidMove>(mv.what) || std::holds_alternative<Comment>(mv.what) ||
          std::holds_alternative<SpindleMove>(mv.what) || std::holds_alternative<CoolantMove>(mv.what) ||
          std::holds_alternative<Dwell>(mv.what)))
      plane(Plane::xy);
    if (const auto* c = std::get_if<Comment>(&mv.what)) {
      note(c->text);
    } else if (const auto* v = std::get_if<Verbatim>(&mv.what)) {
      line(v->text);
    } else if (std::holds_alternative<ToolChangePosition>(mv.what)) {
      for (const auto& l : m_.tool_change_position) line(l);
      axis_[2].clear();  // Z is where the machine went: say it again next time
      motion_.clear();
    } else if (const auto* t = std::get_if<ToolChange>(&mv.what)) {
      line(replace_all(m_.tool_change, "{tool}", std::to_string(t->tool)));
      if (!m_.tool_length.empty()) line(replace_all(m_.tool_length, "{tool}", std::to_string(t->tool)));
    } else if (const auto* sp = std::get_if<SpindleMove>(&mv.what)) {
      line(sp->rpm > 0 ? replace_all(m_.spindle_on, "{rpm}", std::to_string(std::llround(sp->rpm))) : m_.spindle_off);
    } else if (const auto* d = std::get_if<Dwell>(&mv.what)) {
      line(word("G4", "G04") + " P" + format_number(d->seconds, 3));
    } else if (const auto* cl = std::get_if<CoolantMove>(&mv.what)) {
      line(cl->mode == Coolant::flood  ? word("M8", "M08")
           : cl->mode == Coolant::mist ? word("M7", "M07")
                                       : word("M9", "M09"));
    } else if (const auto* st = std::get_if<ProgramStop>(&mv.what)) {
      line(word("M0", "M00") + " " + comment(st->message));  // the operator's message, even without comments
    } else if (const auto* cc = std::get_if<CompensationMove>(&mv.what)) {
      line(cc->side == 0 ? std::string("G40") : (cc->side > 0 ? "G41 D" : "G42 D") + std::to_string(cc->d));
    } else if (const auto* cy = std::get_if<CannedCycle>(&mv.what)) {
      if (canned) cycle(*cy);  // else its moves follow as they are
    } else if (const auto* a = std::get_if<ArcMove>(&mv.what)) {
      arc(*a);
    } else if (const auto* cv = std::get_if<CurveMove>(&mv.what)) {
      curve(*cv);
    } else {
      straight(*motion_of(mv), is_rapid(mv));
    }
  }

  // A canned drilling cycle: the whole line (G98/G99, the cycle, the hole,
  // its bottom, R, Q or P, F) where the cycle mode begins or its words
  // change, the hole's X and Y alone for the next hole of the same cycle.
  void cycle(const CannedCycle& cy) {
    const bool same = cycle_on_ && cy.code == cycle_.code && cy.r == cycle_.r && cy.z == cycle_.z && cy.q == cycle_.q &&
                      cy.p == cycle_.p && cy.feed == cycle_.feed && cy.to_r == cycle_.to_r;
    std::string s;
    if (!same) s = std::string(cy.to_r ? "G99" : "G98") + " G" + std::to_string(cy.code);
    word_to(s, 'X', num(cy.at.x));
    word_to(s, 'Y', num(cy.at.y));
    if (!same) {
      word_to(s, 'Z', num(cy.z));
      word_to(s, 'R', num(cy.r));
      if (cy.code == 73 || cy.code == 83) word_to(s, 'Q', num(cy.q));
      if (cy.code == 82) word_to(s, 'P', format_number(cy.p, 3));
      feed_.clear();  // F on the line that enters the cycle, always
      feed_to(s, cy.feed);
    }
    line(s);
    cycle_on_ = true;
    cycle_ = cy;
  }
  // G80 when a cycle mode is on: what follows is no hole.
  void end_cycles() {
    if (!cycle_on_) return;
    line("G80");
    cycle_on_ = false;
    motion_.clear();  // G80 leaves no motion mode: the next move says G00 or G01
  }

  // G00 / G01: only the axes that change (modal), no line at all when none does.
  // (The line is put together in a string kept from line to line.)
  void straight(const Motion& mv, bool rapid) {
    std::string& s = line_;
    s.clear();
    axes_to(s, mv.to, mv.axes);
    for (int k = 0; k < 3; ++k)
      if (mv.axes & (1u << k)) pos_[k] = mv.to[k];
    if (s.empty()) return;  // no motion once printed: nothing to say
    const std::string& g = rapid ? m_.word_rapid : m_.word_feed;
    if (g != motion_) {
      motion_ = g;
      if (!g.empty()) s.insert(0, g + ' ');
    }
    if (!rapid) feed_to(s, mv.feed);
    line(s);
  }

  void curve(const CurveMove& mv) {
    if (mv.shape->form == CurveMove::Form::bezier) {
      if (m_.nurbs != NurbsDialect::linuxcnc) throw std::logic_error("a G5/G5.1 move for a machine without them");
      g5(mv);
    } else if (m_.nurbs == NurbsDialect::fanuc) {
      fanuc_block(mv);
    } else if (m_.nurbs == NurbsDialect::linuxcnc) {
      g52_block(mv);
    } else {
      throw std::logic_error("a NURBS move for a machine without a NURBS dialect");
    }
  }

  // Every digit, as the seeds' listing prints NURBS blocks (never "-0.000").
  static std::string fixed(double v, int decimals) {
    std::string s = format_number(v, decimals);
    const size_t dot = s.find('.');
    s.append(static_cast<size_t>(decimals) - (s.size() - dot - 1), '0');
    return s;
  }
  void arrived(const Vec3& to) {
    for (int a = 0; a < 3; ++a) axis_[a] = num(to[a]);
    pos_ = to;
  }

  // G02/G03 in the arc's plane (G17, G18 or G19 on a line of its own when
  // it changes): both end words of the plane always (some controllers
  // require them), the centre relative to the start in the plane's words
  // only (I J, K I, J K: some controllers reject the third), the plane's
  // axis only if it changes (a helix). The word is always printed.
  void arc(const ArcMove& mv) {
    plane(mv.plane);
    const Vec3 from = pos_;
    const std::string g = mv.ccw ? m_.word_ccw : m_.word_cw;
    const int h = world_axis(mv.plane, 2);
    std::string centre[3];
    for (int k = 0; k < 3; ++k)
      if (k != h) {
        axis_[k].clear();
        centre[k] = std::string(1, "IJK"[k]) + num(mv.center[k] - from[k]);
      }
    const std::string a = axes(mv.to, mv.axes);
    line(join({g, a, centre[0], centre[1], centre[2], feed(mv.feed)}));
    motion_ = g;
    for (int k = 0; k < 3; ++k)
      if (mv.axes & (1u << k)) pos_[k] = mv.to[k];
  }

  // Fanuc-style block (docs/gcode-dialects.md): start word, P rank and the first
  // control point (the current position) with its knot and weight, one
  // K X Y Z R block per further point, then the remaining knots alone.
  void fanuc_block(const CurveMove& mv) {
    const bool fx = m_.nurbs_fixed_decimals;
    auto coord = [&](double v) { return fx ? fixed(v, p_.decimals) : num(v); };
    auto knot = [&](double k) { return "K" + (fx ? fixed(k, m_.knot_decimals) : format_number(k, m_.knot_decimals)); };
    auto point = [&](size_t i) {
      const Vec3& p = mv.shape->ctrl[i];
      const double w = mv.shape->weights.empty() ? 1.0 : mv.shape->weights[i];
      std::string xyz[3] = {"X" + coord(p.x), "Y" + coord(p.y), "Z" + coord(p.z)};
      std::string r = "R" + (fx ? fixed(w, m_.weight_decimals) : format_number(w, m_.weight_decimals));
      if (m_.modal && i > 0) {
        // Modal words: a coordinate equal to the previous point's, and a
        // weight of 1 (the default when R is omitted), are left out.
        for (int a = 0; a < 3; ++a)
          if (coord(p[a]) == coord(mv.shape->ctrl[i - 1][a])) xyz[a].clear();
        if (format_number(w, m_.weight_decimals) == "1.") r.clear();
      }
      return join({knot(mv.shape->knots[i]), xyz[0], xyz[1], xyz[2], r});
    };
    line(join({m_.nurbs_start_word, "P" + std::to_string(mv.shape->order), point(0), feed(mv.feed)}));
    for (size_t i = 1; i < mv.shape->ctrl.size(); ++i) line(point(i));
    for (size_t j = mv.shape->ctrl.size(); j < mv.shape->knots.size(); ++j) line(knot(mv.shape->knots[j]));
    motion_.clear();  // the next G00/G01/G02/G03 must say so: it ends the mode
    arrived(mv.shape->ctrl.back());
  }

  // LinuxCNC G5.2 ... G5.3: the current position is the first point; its
  // weight and the order on the G5.2 line; X Y P per further point (P
  // always: older versions do not default it to 1).
  void g52_block(const CurveMove& mv) {
    auto w = [&](size_t i) {
      return "P" + format_number(mv.shape->weights.empty() ? 1.0 : mv.shape->weights[i], m_.weight_decimals);
    };
    line(join({"G5.2", w(0), "L" + std::to_string(mv.shape->order), feed(mv.feed)}));
    for (size_t i = 1; i < mv.shape->ctrl.size(); ++i)
      line(join({"X" + num(mv.shape->ctrl[i].x), "Y" + num(mv.shape->ctrl[i].y), w(i)}));
    line("G5.3");
    motion_.clear();
    arrived({mv.shape->ctrl.back().x, mv.shape->ctrl.back().y, pos_.z});
  }

  // LinuxCNC G5 (cubic: I J = P1 - P0, P Q = P2 - P3) and G5.1 (quadratic:
  // I J = P1 - P0), X and Y always, Z never.
  void g5(const CurveMove& mv) {
    const auto& c = mv.shape->ctrl;
    const Vec3& to = c.back();
    std::string s = std::string(c.size() == 4 ? "G5" : "G5.1") + " X" + num(to.x) + " Y" + num(to.y) + " I" +
                    num(c[1].x - c[0].x) + " J" + num(c[1].y - c[0].y);
    if (c.size() == 4) s += " P" + num(c[2].x - c[3].x) + " Q" + num(c[2].y - c[3].y);
    line(join({s, feed(mv.feed)}));
    motion_.clear();
    arrived({to.x, to.y, pos_.z});
  }

  static constexpr size_t kChunk = size_t{1} << 16;
  const Program& p_;
  const MachineProfile& m_;
  const GcodeSink* sink_;
  const MotionPlan* plan_;
  std::string out_, line_;
  int n_ = m_.line_start;
  std::string axis_[3], motion_, feed_;
  Vec3 pos_;                 // current position as printed
  Plane plane_ = Plane::xy;  // the arc plane in force (the units line sets G17)
  bool cycle_on_ = false;    // in a canned cycle mode (cycle_'s), until G80
  CannedCycle cycle_;
};

}  // namespace

std::string cycle_time_words(const MachineProfile& m, double seconds, Units units) {
  if (m.motion)
    return "estimated cycle time " + format_clock(seconds) + " on the motion model of machine " + m.name +
           " (acceleration, corners, tool changes)";
  return "estimated cycle time " + format_clock(seconds) + ": feeds as programmed, rapids at " +
         format_significant(m.max_feed_mm_min / mm_per_unit(units), 6) + " " + to_string(units) +
         "/min, no acceleration, tool changes not counted";
}

std::string write_gcode(const Program& p, const MachineProfile& m) { return Writer(p, m).run(); }

std::string write_gcode(const Program& p, const MachineProfile& m, const MotionPlan* plan) {
  return Writer(p, m, nullptr, plan).run();
}

void write_gcode(const Program& p, const MachineProfile& m, const GcodeSink& sink) { Writer(p, m, &sink).run(); }

void write_gcode(const Program& p, const MachineProfile& m, const MotionPlan* plan, const GcodeSink& sink) {
  Writer(p, m, &sink, plan).run();
}

}  // namespace bezcam
