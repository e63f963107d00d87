// The size rule (CONTRIBUTING.md): no source file of the library or the
// program over 800 lines and no function over 150, so that each piece can
// be checked by reading it. The scanner blanks comments and literals, then
// follows braces: a brace block that opens after a parameter list, at
// namespace or class scope, is a function body (lambdas and blocks inside
// it count as part of it).
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

constexpr int kMaxFileLines = 800;
constexpr int kMaxFunctionLines = 150;

// Files and functions still over the limit ("path" or "path:function").
// The list may only shrink.
const std::vector<std::string> kAllowed = {};

// The text with comments, string and character literals replaced by blanks
// (newlines kept, so that line numbers stay).
std::string blank_comments_and_literals(const std::string& s) {
  std::string out = s;
  size_t i = 0;
  const size_t n = s.size();
  auto blank = [&](size_t from, size_t to) {
    for (size_t k = from; k < to && k < n; ++k)
      if (out[k] != '\n') out[k] = ' ';
  };
  while (i < n) {
    if (s.compare(i, 2, "//") == 0) {
      size_t j = s.find('\n', i);
      if (j == std::string::npos) j = n;
      blank(i, j);
      i = j;
    } else if (s.compare(i, 2, "/*") == 0) {
      size_t j = s.find("*/", i + 2);
      j = j == std::string::npos ? n : j + 2;
      blank(i, j);
      i = j;
    } else if (s.compare(i, 2, "R\"") == 0 && (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1])))) {
      const size_t open = s.find('(', i);
      const std::string delim = ")" + s.substr(i + 2, open - i - 2) + "\"";
      size_t j = s.find(delim, open);
      j = j == std::string::npos ? n : j + delim.size();
      blank(i + 2, j - 1);
      i = j;
    } else if (s[i] == '"' || (s[i] == '\'' && (i == 0 || !std::isxdigit(static_cast<unsigned char>(s[i - 1]))))) {
      const char q = s[i];
      size_t j = i + 1;
      while (j < n && s[j] != q && s[j] != '\n') j += s[j] == '\\' ? 2 : 1;
      blank(i + 1, j);
      i = j + 1;
    } else {
      ++i;
    }
  }
  return out;
}

struct Function {
  std::string name;
  int first_line = 0, lines = 0;
};

// What precedes an opening brace decides what the brace opens.
enum class Block { kNamespace, kClass, kFunction, kOther };

Block classify(const std::string& before) {
  static const std::regex ns(R"((namespace|extern\s+"\s*")[^;{}]*$)");
  static const std::regex cls(R"(\b(struct|class|union|enum)\b[^;{}()]*$)");
  static const std::regex fn(R"(\)\s*(const|noexcept|override|final|mutable|&|&&|->[^{};]*|\s)*$)");
  static const std::regex ctor(R"(\)\s*:[^;{}]*$)");
  if (std::regex_search(before, ns)) return Block::kNamespace;
  if (std::regex_search(before, cls)) return Block::kClass;
  if (std::regex_search(before, fn) || std::regex_search(before, ctor)) return Block::kFunction;
  return Block::kOther;
}

std::string function_name(const std::string& before) {
  const size_t paren = before.rfind(')');
  if (paren == std::string::npos) return "?";
  int depth = 0;
  size_t k = paren + 1;
  while (k-- > 0) {
    if (before[k] == ')') ++depth;
    if (before[k] == '(' && --depth == 0) break;
  }
  size_t end = k;
  while (end > 0 && std::isspace(static_cast<unsigned char>(before[end - 1]))) --end;
  size_t start = end;
  while (start > 0 && (std::isalnum(static_cast<unsigned char>(before[start - 1])) || before[start - 1] == '_' ||
                       before[start - 1] == ':' || before[start - 1] == '~'))
    --start;
  return start < end ? before.substr(start, end - start) : "?";
}

std::vector<Function> functions_of(const std::string& text) {
  const std::string s = blank_comments_and_literals(text);
  struct Open {
    Block kind;
    int line;
    std::string name;
  };
  std::vector<Open> stack;
  std::vector<Function> out;
  int line = 1;
  size_t stmt_start = 0;  // after the last ';', '{' or '}' at this level
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
    } else if (c == '{') {
      bool in_function = false;
      for (const Open& o : stack) in_function |= o.kind == Block::kFunction;
      Block kind = Block::kOther;
      std::string name;
      if (!in_function) {
        std::string before = s.substr(stmt_start, i - stmt_start);
        // a preprocessor line is not part of the declaration
        std::string kept;
        std::istringstream lines(before);
        for (std::string l; std::getline(lines, l);)
          if (l.find_first_not_of(" \t") == std::string::npos || l[l.find_first_not_of(" \t")] != '#') kept += l + " ";
        // braced initializers of a constructor's members read as ()
        static const std::regex braced(R"(\{[^{}]*\})");
        for (std::string prev_kept; prev_kept != kept;) {
          prev_kept = kept;
          kept = std::regex_replace(kept, braced, "()");
        }
        kind = classify(kept);
        static const std::regex member(R"(\)\s*:[^;{}]*[\w>]\s*$)");
        if (kind == Block::kFunction && std::regex_search(kept, member)) {
          // `v{1}` in a constructor's initializer list: skip it whole
          int depth = 0;
          for (; i < s.size(); ++i) {
            if (s[i] == '\n') ++line;
            if (s[i] == '{') ++depth;
            if (s[i] == '}' && --depth == 0) break;
          }
          continue;
        }
        if (kind == Block::kFunction) {
          // a constructor's name stands before its initializer list
          static const std::regex init_list(R"(\)\s*:(?!:))");
          std::smatch m;
          name = function_name(std::regex_search(kept, m, init_list) ? kept.substr(0, m.position(0) + 1) : kept);
        }
      }
      stack.push_back({kind, line, name});
      stmt_start = i + 1;
    } else if (c == '}') {
      if (!stack.empty()) {
        const Open o = stack.back();
        stack.pop_back();
        if (o.kind == Block::kFunction) out.push_back({o.name, o.line, line - o.line + 1});
      }
      stmt_start = i + 1;
    } else if (c == ';') {
      stmt_start = i + 1;
    }
  }
  return out;
}

bool allowed(const std::string& key) {
  for (const std::string& a : kAllowed)
    if (a == key) return true;
  return false;
}

std::vector<fs::path> sources() {
  std::vector<fs::path> out;
  const fs::path root = BEZCAM_SOURCE_DIR;
  for (const char* top : {"include/bezcam", "src"})
    for (const auto& e : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = e.path().extension().string();
      if (e.is_regular_file() && (ext == ".cpp" || ext == ".hpp")) out.push_back(e.path());
    }
  return out;
}

}  // namespace

TEST(SizeRule, ScannerFindsFunctionsAndTheirLengths) {
  const std::string code =
      "namespace a {\n"
      "struct S {\n"
      "  int f() const { return 1; }\n"
      "};\n"
      "// void g() {\n"
      "int g(int x) {\n"
      "  auto l = [&](int y) {\n"
      "    return y + \"}\"[0];\n"
      "  };\n"
      "  return l(x);\n"
      "}\n"
      "S::S() : v{1} {\n"
      "}\n"
      "}  // namespace a\n";
  const auto f = functions_of(code);
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0].name, "f");
  EXPECT_EQ(f[0].lines, 1);
  EXPECT_EQ(f[1].name, "g");
  EXPECT_EQ(f[1].first_line, 6);
  EXPECT_EQ(f[1].lines, 6);
  EXPECT_EQ(f[2].name, "S::S");
  EXPECT_EQ(f[2].lines, 2);
}

TEST(SizeRule, NoFileOver800LinesAndNoFunctionOver150) {
  const fs::path root = BEZCAM_SOURCE_DIR;
  std::vector<std::string> over;
  for (const fs::path& p : sources()) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    const std::string rel = fs::relative(p, root).generic_string();
    const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    if (lines > kMaxFileLines && !allowed(rel))
      over.push_back(rel + ": " + std::to_string(lines) + " lines (at most " + std::to_string(kMaxFileLines) + ")");
    for (const Function& f : functions_of(text)) {
      if (f.lines > kMaxFunctionLines && !allowed(rel + ":" + f.name))
        over.push_back(rel + ":" + std::to_string(f.first_line) + ": " + f.name + "() is " + std::to_string(f.lines) +
                       " lines (at most " + std::to_string(kMaxFunctionLines) + ")");
    }
  }
  std::string all;
  for (const auto& o : over) all += o + "\n";
  EXPECT_TRUE(over.empty()) << "split by concept (CONTRIBUTING.md, \"Size\"):\n" << all;
}

TEST(SizeRule, TheAllowListOnlyNamesWhatIsStillOver) {
  // An entry that no longer needs its place must leave the list.
  const fs::path root = BEZCAM_SOURCE_DIR;
  for (const std::string& a : kAllowed) {
    const size_t colon = a.find(':');
    const std::string file = a.substr(0, colon);
    std::ifstream in(root / file);
    ASSERT_TRUE(in) << a << ": no such file";
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    bool still_over = false;
    if (colon == std::string::npos) {
      still_over = std::count(text.begin(), text.end(), '\n') > kMaxFileLines;
    } else {
      for (const Function& f : functions_of(text))
        still_over |= f.name == a.substr(colon + 1) && f.lines > kMaxFunctionLines;
    }
    EXPECT_TRUE(still_over) << a << " is within the rule now: remove it from kAllowed";
  }
}
