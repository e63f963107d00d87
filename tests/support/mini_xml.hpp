#pragma once
// A strict little XML reader for tests: enough of XML 1.0 to check that a
// generated document (the preview's SVG) is well-formed and to look at its
// elements. Elements, attributes (quoted, unique per element), character
// data with the five predefined and numeric character references, comments,
// the XML declaration and CDATA; DOCTYPE and processing instructions other
// than the declaration are refused (the writer never emits them). Throws
// std::runtime_error naming the byte offset of the first fault.
#include <cctype>
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace testxml {

struct Element {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::vector<Element> children;
  std::string text;  ///< character data directly inside, concatenated

  bool has(const std::string& a) const { return attrs.count(a) != 0; }
  std::string attr(const std::string& a) const {
    auto it = attrs.find(a);
    return it == attrs.end() ? std::string() : it->second;
  }
  /// Whether the class attribute holds `cls` as one of its words.
  bool has_class(const std::string& cls) const {
    const std::string c = " " + attr("class") + " ";
    return c.find(" " + cls + " ") != std::string::npos;
  }
  /// Every descendant (not this element) matching `pred`, in document order.
  std::vector<const Element*> find_all(const std::function<bool(const Element&)>& pred) const {
    std::vector<const Element*> out;
    walk(pred, out);
    return out;
  }
  std::vector<const Element*> by_class(const std::string& cls) const {
    return find_all([&](const Element& e) { return e.has_class(cls); });
  }
  std::vector<const Element*> by_name(const std::string& n) const {
    return find_all([&](const Element& e) { return e.name == n; });
  }
  const Element* by_id(const std::string& id) const {
    auto v = find_all([&](const Element& e) { return e.attr("id") == id; });
    return v.empty() ? nullptr : v.front();
  }

 private:
  void walk(const std::function<bool(const Element&)>& pred, std::vector<const Element*>& out) const {
    for (const auto& c : children) {
      if (pred(c)) out.push_back(&c);
      c.walk(pred, out);
    }
  }
};

class Parser {
 public:
  explicit Parser(std::string_view s) : s_(s) {}

  Element document() {
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") i_ = 3;  // byte order mark
    if (s_.substr(i_, 5) == "<?xml") {
      const size_t e = s_.find("?>", i_);
      if (e == std::string_view::npos) fail("unterminated XML declaration");
      i_ = e + 2;
    }
    misc();
    if (i_ >= s_.size() || s_[i_] != '<') fail("expected the root element");
    Element root = element();
    misc();
    if (i_ != s_.size()) fail("content after the root element");
    return root;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("XML not well-formed at byte " + std::to_string(i_) + ": " + what);
  }
  static bool name_start(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_' || c == ':' || static_cast<unsigned char>(c) >= 0x80;
  }
  static bool name_char(char c) {
    return name_start(c) || std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '.';
  }
  void ws() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t' || s_[i_] == '\n' || s_[i_] == '\r')) ++i_;
  }
  // Whitespace and comments outside the root.
  void misc() {
    for (;;) {
      ws();
      if (s_.substr(i_, 4) == "<!--")
        comment();
      else if (s_.substr(i_, 2) == "<?" || s_.substr(i_, 2) == "<!")
        fail("unexpected declaration");
      else
        return;
    }
  }
  void comment() {
    const size_t e = s_.find("-->", i_ + 4);
    if (e == std::string_view::npos) fail("unterminated comment");
    if (s_.substr(i_ + 4, e - i_ - 4).find("--") != std::string_view::npos) fail("'--' inside a comment");
    i_ = e + 3;
  }
  std::string name() {
    if (i_ >= s_.size() || !name_start(s_[i_])) fail("expected a name");
    const size_t b = i_;
    while (i_ < s_.size() && name_char(s_[i_])) ++i_;
    return std::string(s_.substr(b, i_ - b));
  }
  static void append_utf8(std::string& o, uint32_t cp) {
    if (cp < 0x80)
      o += char(cp);
    else if (cp < 0x800)
      o += char(0xC0 | (cp >> 6)), o += char(0x80 | (cp & 0x3F));
    else if (cp < 0x10000)
      o += char(0xE0 | (cp >> 12)), o += char(0x80 | ((cp >> 6) & 0x3F)), o += char(0x80 | (cp & 0x3F));
    else
      o += char(0xF0 | (cp >> 18)), o += char(0x80 | ((cp >> 12) & 0x3F)), o += char(0x80 | ((cp >> 6) & 0x3F)),
          o += char(0x80 | (cp & 0x3F));
  }
  // Character data up to `stop` (exclusive), references expanded.
  std::string chars(char stop, bool in_attr) {
    std::string o;
    while (i_ < s_.size() && s_[i_] != stop) {
      const char c = s_[i_];
      if (c == '<') {
        if (in_attr) fail("'<' in an attribute value");
        break;
      }
      if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') fail("control character");
      if (c != '&') {
        o += c;
        ++i_;
        continue;
      }
      const size_t e = s_.find(';', i_);
      if (e == std::string_view::npos || e - i_ > 12) fail("unterminated reference");
      const std::string_view ref = s_.substr(i_ + 1, e - i_ - 1);
      if (ref == "amp")
        o += '&';
      else if (ref == "lt")
        o += '<';
      else if (ref == "gt")
        o += '>';
      else if (ref == "quot")
        o += '"';
      else if (ref == "apos")
        o += '\'';
      else if (ref.size() > 1 && ref[0] == '#') {
        const bool hex = ref[1] == 'x';
        const std::string digits(ref.substr(hex ? 2 : 1));
        if (digits.empty()) fail("empty character reference");
        size_t used = 0;
        const unsigned long cp = std::stoul(digits, &used, hex ? 16 : 10);
        if (used != digits.size() || cp == 0 || cp > 0x10FFFF) fail("bad character reference");
        append_utf8(o, static_cast<uint32_t>(cp));
      } else {
        fail("unknown entity &" + std::string(ref) + ";");
      }
      i_ = e + 1;
    }
    return o;
  }
  Element element() {
    ++i_;  // '<'
    Element el;
    el.name = name();
    for (;;) {
      const size_t before = i_;
      ws();
      if (i_ >= s_.size()) fail("unterminated start tag");
      if (s_.substr(i_, 2) == "/>") {
        i_ += 2;
        return el;
      }
      if (s_[i_] == '>') {
        ++i_;
        break;
      }
      if (i_ == before) fail("expected whitespace before an attribute");
      const std::string a = name();
      ws();
      if (i_ >= s_.size() || s_[i_] != '=') fail("expected '=' after attribute " + a);
      ++i_;
      ws();
      if (i_ >= s_.size() || (s_[i_] != '"' && s_[i_] != '\'')) fail("attribute value must be quoted");
      const char q = s_[i_++];
      std::string v = chars(q, true);
      if (i_ >= s_.size()) fail("unterminated attribute value");
      ++i_;
      if (!el.attrs.emplace(a, std::move(v)).second) fail("duplicate attribute " + a);
    }
    for (;;) {
      el.text += chars('<', false);
      if (i_ >= s_.size()) fail("unterminated element " + el.name);
      if (s_.substr(i_, 4) == "<!--") {
        comment();
      } else if (s_.substr(i_, 9) == "<![CDATA[") {
        const size_t e = s_.find("]]>", i_);
        if (e == std::string_view::npos) fail("unterminated CDATA");
        el.text += std::string(s_.substr(i_ + 9, e - i_ - 9));
        i_ = e + 3;
      } else if (s_.substr(i_, 2) == "</") {
        i_ += 2;
        if (name() != el.name) fail("end tag does not match <" + el.name + ">");
        ws();
        if (i_ >= s_.size() || s_[i_] != '>') fail("expected '>'");
        ++i_;
        return el;
      } else if (s_.substr(i_, 2) == "<?" || s_.substr(i_, 2) == "<!") {
        fail("unexpected declaration inside an element");
      } else {
        el.children.push_back(element());
      }
    }
  }

  std::string_view s_;
  size_t i_ = 0;
};

inline Element parse(std::string_view s) { return Parser(s).document(); }

}  // namespace testxml
