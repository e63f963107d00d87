#include "bezcam/post/gcode_writer.hpp"

#include <cmath>

#include "bezcam/post/number_format.hpp"

#ifndef BEZCAM_VERSION
#define BEZCAM_VERSION "0"
#endif

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
  for (unsigned char ch : text) {
    if (ch == '(') s += '[';
    else if (ch == ')') s += ']';
    else if (ch < 32 || ch > 126) s += '?';
    else s += static_cast<char>(ch);
  }
  return "(" + s + ")";
}

class Writer {
 public:
  Writer(const Program& p, const MachineProfile& m) : p_(p), m_(m) {}

  std::string run() {
    for (const auto& h : m_.header) raw(subst(h));
    const char* u = to_string(p_.units);
    line(comment(std::string("bezcam ") + BEZCAM_VERSION + ": " + p_.job_name + ", machine " + m_.name +
                 ", output " + to_string(p_.output)));
    line(comment("tolerance " + format_number(p_.tolerance, 6) + " " + u + "; largest deviation measured " +
                 format_number(p_.max_measured, 6) + " " + u + ", proven bound " + format_number(p_.max_bound, 6) +
                 " " + u + ", rounding included"));
    line(std::string(p_.units == Units::mm ? "G21" : "G20") + " G90 G17");
    for (const Move& mv : p_.moves) move(mv);
    for (const auto& f : m_.footer) {
      if (!f.empty() && f[0] == '%') raw(subst(f));
      else line(subst(f));
    }
    return out_;
  }

 private:
  std::string subst(const std::string& s) const {
    return replace_all(s, "{safe_z}", format_number(p_.safe_z, p_.decimals));
  }
  void raw(const std::string& s) { out_ += s + "\n"; }
  void line(const std::string& s) {
    if (m_.line_numbers) {
      out_ += "N" + std::to_string(n_) + " ";
      n_ += m_.line_step;
    }
    out_ += s + "\n";
  }
  std::string num(double v) const { return format_number(v, p_.decimals); }

  // Axis words whose printed value changes; updates the modal state.
  std::string axes(const Vec3& to, unsigned mask) {
    std::string s;
    static const char names[3] = {'X', 'Y', 'Z'};
    for (int a = 0; a < 3; ++a) {
      if (!(mask & (1u << a))) continue;
      const std::string v = num(to[a]);
      if (v != axis_[a]) {
        s += std::string(s.empty() ? "" : " ") + names[a] + v;
        axis_[a] = v;
      }
    }
    return s;
  }
  std::string motion(const std::string& word) {
    if (word == motion_) return "";
    motion_ = word;
    return word;
  }
  std::string feed(double f) {
    const std::string v = format_number(f, m_.feed_decimals);
    if (v == feed_) return "";
    feed_ = v;
    return "F" + v;
  }
  static std::string join(std::initializer_list<std::string> parts) {
    std::string s;
    for (const auto& x : parts)
      if (!x.empty()) s += (s.empty() ? "" : " ") + x;
    return s;
  }

  void move(const Move& mv) {
    switch (mv.kind) {
      case MoveKind::comment: line(comment(mv.text)); break;
      case MoveKind::tool_change: line(replace_all(m_.tool_change, "{tool}", std::to_string(mv.tool))); break;
      case MoveKind::spindle_on: line(replace_all(m_.spindle_on, "{rpm}", std::to_string(std::llround(mv.rpm)))); break;
      case MoveKind::spindle_off: line(m_.spindle_off); break;
      case MoveKind::rapid:
      case MoveKind::linear: {
        const std::string a = axes(mv.to, mv.axes);
        for (int k = 0; k < 3; ++k)
          if (mv.axes & (1u << k)) pos_[k] = mv.to[k];
        if (a.empty()) return;  // no motion once printed: nothing to say
        const bool rapid = mv.kind == MoveKind::rapid;
        const std::string g = motion(rapid ? m_.word_rapid : m_.word_feed);
        line(join({g, a, rapid ? "" : feed(mv.feed)}));
        break;
      }
      case MoveKind::arc_cw:
      case MoveKind::arc_ccw: {
        const Vec3 from = pos_;
        const std::string g = motion(mv.kind == MoveKind::arc_cw ? m_.word_cw : m_.word_ccw);
        // Arcs always print both end words (some controllers require them).
        axis_[0].clear();
        axis_[1].clear();
        const std::string a = axes(mv.to, mv.axes);
        line(join({g, a, "I" + num(mv.center.x - from.x), "J" + num(mv.center.y - from.y), feed(mv.feed)}));
        motion_.clear();  // arcs are always written with their word
        pos_ = mv.to;
        break;
      }
      case MoveKind::nurbs:
      case MoveKind::bezier:
        throw std::logic_error("exact-curve moves need the NURBS writer");
    }
  }

  const Program& p_;
  const MachineProfile& m_;
  std::string out_;
  int n_ = m_.line_start;
  std::string axis_[3], motion_, feed_;
  Vec3 pos_;  // current position as printed
};

}  // namespace

std::string write_gcode(const Program& p, const MachineProfile& m) { return Writer(p, m).run(); }

}  // namespace bezcam
