#pragma once
// A command line as the shell splits it, for the tests that run the
// examples of the README and of `--help` as written: words apart at
// blanks, 'single' and "double" quotes kept together (the quotes removed),
// a backslash taking the next character, and a comment from a `#` that
// starts a word.
#include <string>
#include <vector>

namespace testproc {

inline std::vector<std::string> shell_words(const std::string& line) {
  std::vector<std::string> out;
  std::string w;
  bool in_word = false;
  char quote = 0;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote)
        quote = 0;
      else if (quote == '"' && c == '\\' && i + 1 < line.size())
        w += line[++i];
      else
        w += c;
      continue;
    }
    if (c == ' ' || c == '\t') {
      if (in_word) out.push_back(w), w.clear(), in_word = false;
      continue;
    }
    if (c == '#' && !in_word) break;
    in_word = true;
    if (c == '\'' || c == '"')
      quote = c;
    else if (c == '\\' && i + 1 < line.size())
      w += line[++i];
    else
      w += c;
  }
  if (in_word) out.push_back(w);
  return out;
}

}  // namespace testproc
