// DXF TEXT and MTEXT as a drawing's texts: the string with its codes
// resolved, the capitals' height, the alignment point and the angle, the
// style's font (TABLES, STYLE). What a text entity cannot be (a width
// factor, an oblique angle, mirrored, fitted between two points, several
// lines) is refused, naming the entity and where it is.
#include <algorithm>
#include <cctype>

#include "bezcam/format.hpp"
#include "dxf_reader_impl.hpp"

namespace bezcam::import::dxf {

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

void append_utf8(std::string& out, unsigned c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

bool valid_utf8(const std::string& s) {
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (size_t k = 1; k < n; ++k)
      if ((static_cast<unsigned char>(s[i + k]) >> 6) != 0x2) return false;
    i += n;
  }
  return true;
}

// A DXF string as UTF-8: files of AutoCAD 2007 and later are UTF-8; older
// ones are in their code page, read here as Latin-1 when not valid UTF-8.
std::string to_utf8(const std::string& s) {
  if (valid_utf8(s)) return s;
  std::string out;
  for (const char c : s) append_utf8(out, static_cast<unsigned char>(c));
  return out;
}

// `n` hexadecimal digits at `at` of `s`, or nothing.
std::optional<unsigned> hex(const std::string& s, size_t at, size_t n) {
  if (at + n > s.size()) return std::nullopt;
  unsigned v = 0;
  const auto r = std::from_chars(s.data() + at, s.data() + at + n, v, 16);
  if (r.ec != std::errc() || r.ptr != s.data() + at + n) return std::nullopt;
  return v;
}

// A style's font file names a stroke font (no outlines): AutoCAD's SHX,
// LibreCAD's LFF, QCAD's CXF, or a name without extension (AutoCAD adds
// .shx: `txt`, `simplex`).
bool stroke_font(const std::string& file) {
  const std::string l = lower(file);
  if (l.empty()) return false;
  const size_t dot = l.rfind('.');
  if (dot == std::string::npos) return true;
  const std::string ext = l.substr(dot);
  return ext == ".shx" || ext == ".lff" || ext == ".cxf";
}

std::string trimmed(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

}  // namespace

std::string percent_codes(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%' || i + 2 >= s.size() || s[i + 1] != '%') {
      out += s[i];
      continue;
    }
    const char k = static_cast<char>(std::tolower(static_cast<unsigned char>(s[i + 2])));
    if (k == 'c')
      append_utf8(out, 0xD8);  // the diameter sign as CAD fonts draw it: Ø
    else if (k == 'd')
      append_utf8(out, 0xB0);
    else if (k == 'p')
      append_utf8(out, 0xB1);
    else if (k == '%')
      out += '%';
    else if (k == 'u' || k == 'o' || k == 'k')
      ;  // underline, overline, strike-through: not letters
    else if (std::isdigit(static_cast<unsigned char>(k)) && i + 4 < s.size() &&
             std::isdigit(static_cast<unsigned char>(s[i + 3])) && std::isdigit(static_cast<unsigned char>(s[i + 4]))) {
      append_utf8(out, static_cast<unsigned>(std::stoi(s.substr(i + 2, 3))));
      i += 2;
    } else {
      out += s.substr(i, 3);
    }
    i += 2;
  }
  return out;
}

std::string mtext_plain(const std::string& s) {
  std::string out;
  const auto skip_to_semicolon = [&](size_t from) {
    const size_t e = s.find(';', from);
    return e == std::string::npos ? s.size() : e + 1;
  };
  for (size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (c == '{' || c == '}') {
      ++i;
      continue;
    }
    if (c != '\\' || i + 1 >= s.size()) {
      out += c;
      ++i;
      continue;
    }
    const char k = s[i + 1];
    switch (k) {
      case 'P':
      case 'X':
        out += '\n';
        i += 2;
        break;
      case '~':
        out += ' ';
        i += 2;
        break;
      case '\\':
      case '{':
      case '}':
        out += k;
        i += 2;
        break;
      case 'U':
        if (i + 2 < s.size() && s[i + 2] == '+') {
          if (const std::optional<unsigned> v = hex(s, i + 3, 4)) {
            append_utf8(out, *v);
            i += 7;
            break;
          }
        }
        i += 2;
        break;
      case 'M':  // \M+nXXXX: a double-byte character of code page n
        i += (i + 2 < s.size() && s[i + 2] == '+') ? 8 : 2;
        break;
      case 'S': {  // stacked text \Sa^b; \Sa/b; \Sa#b;: written a/b
        const size_t e = skip_to_semicolon(i + 2);
        std::string st = s.substr(i + 2, e - (i + 2));
        if (!st.empty() && st.back() == ';') st.pop_back();
        for (char& ch : st)
          if (ch == '^' || ch == '#') ch = '/';
        out += st;
        i = e;
        break;
      }
      case 'L':
      case 'l':
      case 'O':
      case 'o':
      case 'K':
      case 'k':
      case 'N':
        i += 2;  // underline, overline, strike-through, new column: not letters
        break;
      default:  // \f \F \H \C \c \Q \T \W \A \p: a change of font, height, ... up to ';'
        i = skip_to_semicolon(i + 2);
        break;
    }
  }
  return out;
}

void Reader::tables() {
  while (at_ < groups_.size() && !at(0, "ENDSEC")) {
    if (!at(0, "STYLE")) {
      ++at_;
      continue;
    }
    const Entity st = entity();
    std::string name;
    Style style;
    bool acad = false;
    for (const Group& g : st.groups) {
      if (g.code == 2) name = g.value;
      if (g.code == 3) style.file = trimmed(g.value);
      if (g.code == 1001) acad = g.value == "ACAD";
      if (g.code == 1000 && acad && style.family.empty()) style.family = trimmed(g.value);
    }
    if (!name.empty()) styles_[upper(name)] = style;
  }
}

void Reader::fail_text(const Entity& e, const std::string& layer, const Vec3& at, const std::string& what) const {
  const std::string h = e.handle();
  throw InputError(errc::import_text, Place::at_file(source_),
                   "layer \"" + layer + "\", " + e.type +
                       (h.empty() ? " on line " + std::to_string(e.line) : " (handle " + h + ")") + " at (" +
                       format_significant(at.x, 6) + ", " + format_significant(at.y, 6) + "): " + what);
}

void Reader::emit_text(const Entity& e, const Affine& m, const std::string& layer, const std::string& prefix,
                       const Vec3& ext) {
  const bool mtext = e.type == "MTEXT";
  const Vec3 first = vec(e, 10);
  const Vec3 shown = m.apply(first) * unit_;  // where messages say it is
  const auto fail = [&](const std::string& what) { fail_text(e, layer, shown, what); };
  DrawingText t;
  t.layer = layer;
  t.id = layer + ":" + prefix + (e.handle().empty() ? "line" + std::to_string(e.line) : e.handle());
  t.element = e.type + (e.handle().empty() ? " on line " + std::to_string(e.line) : " (handle " + e.handle() + ")");
  // The string: an MTEXT's chunks (group 3) before its last (group 1).
  std::string raw;
  for (const Group& g : e.groups)
    if (g.code == 3 && mtext) raw += g.value;
  for (const Group& g : e.groups)
    if (g.code == 1) {
      raw += g.value;
      break;
    }
  t.text = percent_codes(mtext ? mtext_plain(to_utf8(raw)) : to_utf8(raw));
  while (!t.text.empty() && (t.text.back() == '\n' || t.text.back() == ' ')) t.text.pop_back();
  if (t.text.find_first_not_of(' ') == std::string::npos) {
    d_.layers[layer].skipped[e.type + " without letters"] += 1;
    return;
  }
  if (t.text.find('\n') != std::string::npos)
    fail(
        "expected one line of text, found several (\\P in the MTEXT); bezcam cuts one line per text: split it "
        "into one text per line in the CAD program");
  // The style and its font.
  std::string style = "Standard";
  for (const Group& g : e.groups)
    if (g.code == 7) style = g.value;
  t.style = style;
  if (const auto it = styles_.find(upper(style)); it != styles_.end()) {
    t.font = it->second.family.empty() ? it->second.file : it->second.family;
    t.stroke_font = it->second.family.empty() && stroke_font(it->second.file);
  }
  // What a text entity cannot be.
  if (!(ext.x == 0 && ext.y == 0 && ext.z > 0))
    fail("expected text in the drawing's XY plane (extrusion direction 0, 0, 1), found the direction " +
         format_significant(ext.x, 6) + ", " + format_significant(ext.y, 6) + ", " + format_significant(ext.z, 6) +
         " (mirrored or tilted text); draw it unmirrored in the XY plane");
  if (!mtext) {
    if (const double w = num(e, 41, 1); std::abs(w - 1) > 1e-9)
      fail("a width factor of " + format_significant(w, 6) +
           " (group code 41) is not cut: bezcam cuts the font's letters at their own width; set the width factor "
           "to 1");
    if (const double o = num(e, 51, 0); o != 0)
      fail("an oblique angle of " + format_significant(o, 6) +
           " degrees (group code 51) is not cut: bezcam cuts the font's letters as drawn; set it to 0, or use an "
           "italic font");
    if ((integer(e, 71, 0) & 6) != 0)
      fail("mirrored text (group code 71: backward or upside down) is not cut; draw it unmirrored");
  }
  double height = num(e, 40, 0);
  if (!(height > 0)) fail("expected a text height > 0 (group code 40), found " + format_significant(height, 6));
  // Where it is, in the OCS (the XY plane here) before the INSERTs.
  Vec3 at = first;
  std::optional<Vec3> to;
  double angle = num(e, 50, 0);
  if (mtext) {
    if (has(e, 11)) {
      const Vec3 dir = vec(e, 11);
      if (dir.x != 0 || dir.y != 0) angle = std::atan2(dir.y, dir.x) / kDegree;
    }
    const int attach = integer(e, 71, 1, 1, 9);
    t.along = ((attach - 1) % 3) * 0.5;
    const int row = (attach - 1) / 3;
    t.vertical = row == 0   ? DrawingText::Vertical::top
                 : row == 1 ? DrawingText::Vertical::middle
                            : DrawingText::Vertical::bottom;
  } else {
    const int h = integer(e, 72, 0, 0, 5), v = integer(e, 73, 0, 0, 3);
    if (h == 5)
      fail(
          "text fitted between two points (group code 72 = 5, \"fit\") is stretched sideways, which bezcam does "
          "not cut; use \"aligned\" (72 = 3) or a left, centre or right alignment");
    if ((h != 0 || v != 0) && has(e, 11)) at = vec(e, 11);
    if (h == 3) {
      at = first;
      to = vec(e, 11);
      if (to->x == at.x && to->y == at.y)
        fail("an aligned text (group code 72 = 3) needs two different points (group codes 10 and 11)");
    } else {
      t.along = h == 1 || h == 4 ? 0.5 : h == 2 ? 1 : 0;
      t.vertical = h == 4   ? DrawingText::Vertical::middle
                   : v == 1 ? DrawingText::Vertical::bottom
                   : v == 2 ? DrawingText::Vertical::middle
                   : v == 3 ? DrawingText::Vertical::top
                            : DrawingText::Vertical::baseline;
    }
  }
  // Through the INSERTs: a turn and a uniform scale keep the letters.
  const double s = std::hypot(m.a, m.b);
  if (!(s > 0) || std::abs(m.a - m.d) > 1e-9 * s || std::abs(m.b + m.c) > 1e-9 * s)
    fail(
        "the text is inserted through a block with unequal x and y scales or a mirror, which would distort its "
        "letters; insert the block with one scale for x and y, unmirrored");
  t.at = m.apply(at) * unit_;
  t.at.z = 0;
  if (to) {
    t.to = m.apply(*to) * unit_;
    t.to->z = 0;
  }
  t.height = height * s * unit_;
  t.angle = angle + std::atan2(m.b, m.a) / kDegree;
  d_.layers[layer].read[e.type] += 1;
  d_.texts.push_back(std::move(t));
}

}  // namespace bezcam::import::dxf
