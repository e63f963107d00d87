#pragma once
// The G-code lexer: one line of text into its words. Private to src/gcode.
//
// Number syntax: an optional sign, digits, an optional '.' and digits (at
// least one digit in all); no exponent. Blanks may stand anywhere inside a
// word, as RS274/NGC reads it ("X - 1 . 5" is ). Comments are '( ... )' (not nested,
// closed on the line) and everything after ';'. Letters are upper-cased.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "diagnostics.hpp"

namespace bezcam::gcode {

/// One address word: a letter and its number.
struct Word {
  char letter = 0;
  double value = 0;
  std::string text;  ///< as printed without its blanks, e.g. "K0.03118"
};

/// A parsed line: its words (N and O apart), G and M codes, and the first
/// word of each other letter.
struct Line {
  bool percent = false;                        ///< a '%' line (tape start / end)
  bool program_number = false;                 ///< an O1234 line
  std::optional<long> n;                       ///< the N word
  std::vector<Word> words;                     ///< every word but N, O, G and M
  std::vector<std::pair<int, std::string>> g;  ///< G code x 10 (G06.2 -> 62), text
  std::vector<std::pair<int, std::string>> m;  ///< M code, text
  std::array<int, 26> first{};                 ///< 1 + index into words of the first word of a letter, 0 if none

  const Word* get(char c) const {
    const int i = first[static_cast<size_t>(c - 'A')];
    return i ? &words[static_cast<size_t>(i - 1)] : nullptr;
  }
  bool has(char c) const { return get(c) != nullptr; }
  bool empty() const { return words.empty() && g.empty() && m.empty(); }
};

/// Splits `text` (one line, its end of line optional) into words. Syntax
/// errors are refused through `d`; a letter given twice is a soft problem
/// (lint goes on with the first word).
Line lex_line(std::string_view text, const Diagnostics& d);

}  // namespace bezcam::gcode
