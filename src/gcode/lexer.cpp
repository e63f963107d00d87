#include "lexer.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace bezcam::gcode {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Files a word into the line: N, O, G and M apart, the others by letter.
void add(Line& ln, Word w, const Diagnostics& d) {
  const bool first_word = ln.words.empty() && ln.g.empty() && ln.m.empty() && !ln.n && !ln.program_number;
  if (w.letter == 'N') {
    if (!first_word) d.fail(errc::gcode_syntax, "the line number " + w.text + " must be the first word of the line");
    if (w.value < 0 || w.value != std::floor(w.value) || w.value > 1e9)
      d.fail(errc::gcode_syntax, "expected a whole line number after N, found " + w.text);
    ln.n = static_cast<long>(w.value);
    return;
  }
  if (ln.program_number)
    d.fail(errc::gcode_syntax, "a program-number line (O...) may hold nothing but comments, found " + w.text);
  if (w.letter == 'O') {
    if (!first_word || ln.n)
      d.fail(errc::gcode_unsupported,
             "O words (" + w.text + ") are only understood as a program number alone on its line");
    if (w.value < 0 || w.value != std::floor(w.value))
      d.fail(errc::gcode_syntax, "expected a whole program number after O, found " + w.text);
    ln.program_number = true;
    return;
  }
  if (w.letter == 'G') {
    const double x10 = w.value * 10;
    const double r = std::nearbyint(x10);
    if (w.value < 0 || std::abs(x10 - r) > 1e-9 || r > 10000)
      d.fail(errc::gcode_unsupported, "G-code " + w.text + " is not supported by this reader");
    ln.g.push_back({static_cast<int>(r), w.text});
    return;
  }
  if (w.letter == 'M') {
    if (w.value < 0 || w.value != std::floor(w.value) || w.value > 1000)
      d.fail(errc::gcode_unsupported, "M-code " + w.text + " is not supported by this reader");
    ln.m.push_back({static_cast<int>(w.value), w.text});
    return;
  }
  for (const Word& o : ln.words)
    if (o.letter == w.letter) {
      // Controllers differ (LinuxCNC and Grbl refuse, others keep the
      // last): refuse. Lint goes on with the first one.
      d.soft(errc::gcode_repeated_word, std::string(1, w.letter) + " appears twice on the line (" + o.text + " and " +
                                            w.text + "); a block gives each address once");
      return;
    }
  ln.words.push_back(std::move(w));
}

}  // namespace

Line lex_line(std::string_view text, const Diagnostics& d) {
  Line ln;
  while (!text.empty() && (text.back() == '\r' || text.back() == '\n')) text.remove_suffix(1);
  size_t i = 0;
  const size_t n = text.size();
  auto skip_comment = [&] {
    const size_t close = text.find(')', i + 1);
    if (close == std::string_view::npos)
      d.fail(errc::gcode_syntax, "a comment opened with '(' is not closed on this line: add ')'");
    if (text.substr(i + 1, close - i - 1).find('(') != std::string_view::npos)
      d.fail(errc::gcode_syntax, "a comment may not contain '(' (no nested comments)");
    i = close + 1;
  };
  while (i < n && is_space(text[i])) ++i;
  if (i < n && text[i] == '%') {
    ln.percent = true;
    ++i;
    while (i < n) {
      if (is_space(text[i]))
        ++i;
      else if (text[i] == '(')
        skip_comment();
      else if (text[i] == ';')
        break;
      else
        d.fail(errc::gcode_syntax, "a '%' line may hold nothing but comments, found '" + std::string(1, text[i]) + "'");
    }
    return ln;
  }
  if (i < n && text[i] == '/')
    d.fail(errc::gcode_unsupported,
           "block delete ('/' at the start of a line) is not supported: remove it or the line");
  while (i < n) {
    const char c = text[i];
    if (is_space(c)) {
      ++i;
      continue;
    }
    if (c == '(') {
      skip_comment();
      continue;
    }
    if (c == ';') break;
    if (!std::isalpha(static_cast<unsigned char>(c)))
      d.fail(errc::gcode_syntax,
             "unexpected character '" + std::string(1, c) + "': expected a word (a letter and a number)");
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    ++i;
    // RS274/NGC reads a line with its blanks taken out (comments aside), so
    // a blank may stand anywhere inside a word: "G 0 1", "X - 1 . 5" and
    // "Z   5.0000" are G01, X-1.5 and Z5. A blank before a digit (or before
    // the number's one decimal point) goes on with the number; before
    // anything else it ends it.
    auto skip_blanks = [&] {
      while (i < n && is_space(text[i])) ++i;
    };
    skip_blanks();
    const size_t start = i;
    std::string num;
    if (i < n && (text[i] == '+' || text[i] == '-')) {
      num += text[i++];
      skip_blanks();
    }
    size_t digits = 0;
    bool point = false;
    while (i < n) {
      const char ch = text[i];
      if (std::isdigit(static_cast<unsigned char>(ch))) {
        num += ch;
        ++digits;
        ++i;
      } else if (ch == '.' && !point) {
        num += ch;
        point = true;
        ++i;
      } else if (is_space(ch)) {
        size_t j = i;
        while (j < n && is_space(text[j])) ++j;
        if (j < n && (std::isdigit(static_cast<unsigned char>(text[j])) || (text[j] == '.' && !point)))
          i = j;
        else
          break;
      } else {
        break;
      }
    }
    if (digits == 0) {
      size_t e = start;
      while (e < n && !is_space(text[e]) && text[e] != '(' && text[e] != ';') ++e;
      const std::string found(text.substr(start, e - start));
      d.fail(errc::gcode_syntax, std::string("expected a number after '") + letter + "', found " +
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
      d.fail(errc::gcode_number, std::string("the number after '") + letter + "' is too large to read (" +
                                     std::to_string(num.size()) + " digits): expected at most about 1e308");
    add(ln, std::move(w), d);
  }
  for (size_t k = 0; k < ln.words.size(); ++k) {
    int& f = ln.first[static_cast<size_t>(ln.words[k].letter - 'A')];
    if (!f) f = static_cast<int>(k) + 1;
  }
  return ln;
}

}  // namespace bezcam::gcode
