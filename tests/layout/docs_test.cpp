// The users' documentation (README.md, CONTRIBUTING.md, docs/*.md) read
// mechanically against the tree and the program: every relative link
// reaches a file (and a heading, where it names one), every path of the
// repository a doc cites exists, every option a doc gives `bezcam` is one
// the program's --help lists, and no doc points at what a user of a clone
// does not have.
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/files.hpp"

namespace fs = std::filesystem;

namespace {

using bezcam::test::slurp;

const fs::path kRoot = BEZCAM_SOURCE_DIR;

struct Line {
  int number = 0;
  std::string text;
  bool in_code = false;  ///< inside a ``` fenced block
};

struct Doc {
  fs::path path;  ///< relative to the root
  std::vector<Line> lines;
};

Doc read_doc(const fs::path& rel) {
  Doc d{rel, {}};
  std::istringstream in(slurp(kRoot / rel));
  std::string text;
  bool code = false;
  for (int n = 1; std::getline(in, text); ++n) {
    const bool fence = text.rfind("```", 0) == 0;
    d.lines.push_back({n, text, code || fence});
    if (fence) code = !code;
  }
  return d;
}

std::vector<Doc> all_docs() {
  std::vector<Doc> out{read_doc("README.md"), read_doc("CONTRIBUTING.md")};
  std::set<fs::path> names;
  for (const auto& e : fs::directory_iterator(kRoot / "docs"))
    if (e.path().extension() == ".md") names.insert(fs::relative(e.path(), kRoot));
  for (const auto& n : names) out.push_back(read_doc(n));
  return out;
}

std::string where(const Doc& d, const Line& l) { return d.path.string() + ":" + std::to_string(l.number); }

// The anchors GitHub gives a document's headings: lower case, everything
// but letters, digits, spaces, '-' and '_' dropped, spaces as '-', and
// "-1", "-2" after a repeated one.
std::set<std::string> anchors_of(const Doc& d) {
  std::set<std::string> out;
  std::map<std::string, int> seen;
  for (const Line& l : d.lines) {
    if (l.in_code || l.text.empty() || l.text[0] != '#') continue;
    const size_t start = l.text.find_first_not_of('#');
    if (start == std::string::npos || l.text[start] != ' ') continue;
    std::string slug;
    for (size_t i = start + 1; i < l.text.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(l.text[i]);
      if (c >= 0x80 || std::isalnum(c) || c == '-' || c == '_')
        slug += static_cast<char>(std::tolower(c));
      else if (c == ' ')
        slug += '-';
    }
    while (!slug.empty() && slug.back() == '-') slug.pop_back();
    const int n = seen[slug]++;
    out.insert(n == 0 ? slug : slug + "-" + std::to_string(n));
  }
  return out;
}

// What `bezcam ARGS` prints on stdout.
std::string run_bezcam(const std::string& args) {
  const std::string cmd = std::string("\"") + BEZCAM_EXE + "\" " + args + " 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
  std::string out;
  if (!p) return out;
  std::array<char, 4096> buf{};
  for (size_t n; (n = fread(buf.data(), 1, buf.size(), p.get())) > 0;) out.append(buf.data(), n);
  return out;
}

// The long options each command's --help lists ("" for bezcam itself).
const std::map<std::string, std::set<std::string>>& help_options() {
  static const std::map<std::string, std::set<std::string>> options = [] {
    std::map<std::string, std::set<std::string>> m;
    const std::regex option(R"((^|[\s,])(--[a-z][a-z0-9-]*))");
    const auto options_in = [&](const std::string& help) {
      std::set<std::string> s;
      for (std::sregex_iterator it(help.begin(), help.end(), option), end; it != end; ++it) s.insert((*it)[2]);
      return s;
    };
    const std::string top = run_bezcam("--help");
    m[""] = options_in(top);
    std::istringstream in(top.substr(std::min(top.size(), top.find("Subcommands:"))));
    std::string line;
    std::getline(in, line);
    const std::regex command(R"(^  ([a-z]+)\s)");
    std::smatch sm;
    while (std::getline(in, line))
      if (std::regex_search(line, sm, command)) m[sm[1]] = options_in(run_bezcam(sm[1].str() + " --help"));
    return m;
  }();
  return options;
}

}  // namespace

TEST(Docs, RelativeLinksReachAFileAndAHeading) {
  const std::vector<Doc> docs = all_docs();
  std::map<fs::path, std::set<std::string>> anchors;
  for (const Doc& d : docs) anchors[fs::weakly_canonical(kRoot / d.path)] = anchors_of(d);
  const std::regex link(R"(\]\(([^)\s]+)\))");
  int links = 0;
  for (const Doc& d : docs)
    for (const Line& l : d.lines) {
      if (l.in_code) continue;
      for (std::sregex_iterator it(l.text.begin(), l.text.end(), link), end; it != end; ++it) {
        const std::string target = (*it)[1];
        if (std::regex_search(target, std::regex("^[a-z]+:"))) continue;  // https:, mailto:
        ++links;
        const size_t hash = target.find('#');
        const std::string file = target.substr(0, hash),
                          anchor = hash == std::string::npos ? "" : target.substr(hash + 1);
        const fs::path p = file.empty() ? kRoot / d.path : fs::weakly_canonical(kRoot / d.path.parent_path() / file);
        if (!fs::exists(p)) {
          ADD_FAILURE() << where(d, l) << ": the link " << target << " names no file of the repository";
          continue;
        }
        if (anchor.empty() || p.extension() != ".md") continue;
        const fs::path key = fs::weakly_canonical(p);
        if (!anchors.count(key)) anchors[key] = anchors_of(read_doc(fs::relative(key, kRoot)));
        EXPECT_TRUE(anchors[key].count(anchor))
            << where(d, l) << ": the link " << target << " names no heading of " << fs::relative(key, kRoot).string();
      }
    }
  EXPECT_GT(links, 50) << "the docs' links were not found";
}

TEST(Docs, PathsOfTheRepositoryTheyCiteExist) {
  // A path starting with a folder of the repository, as the docs write
  // them in backquotes: `tests/bad/`, `include/bezcam/error_ids.hpp`.
  const std::regex cited(
      R"(`((?:\.ci|bench|cmake|docs|examples|include|machines|samples|src|tests)/[A-Za-z0-9_./-]*)`)");
  int paths = 0;
  for (const Doc& d : all_docs())
    for (const Line& l : d.lines)
      for (std::sregex_iterator it(l.text.begin(), l.text.end(), cited), end; it != end; ++it) {
        std::string p = (*it)[1];
        if (p.find("..") != std::string::npos) continue;
        ++paths;
        EXPECT_TRUE(fs::exists(kRoot / p)) << where(d, l) << ": `" << p << "` is not in the repository";
      }
  EXPECT_GT(paths, 20) << "the docs' paths were not found";
}

TEST(Docs, EveryOptionOfCliMdIsOneTheProgramTakes) {
  const auto& help = help_options();
  ASSERT_GT(help.size(), 5u) << "bezcam --help lists no commands (" << BEZCAM_EXE << ")";
  std::set<std::string> any;
  for (const auto& [command, options] : help) any.insert(options.begin(), options.end());
  const std::regex option(R"((^|[^A-Za-z0-9_-])(--[a-z][a-z0-9-]*))");
  int seen = 0;
  const Doc cli = read_doc("docs/cli.md");
  for (const Line& l : cli.lines)
    for (std::sregex_iterator it(l.text.begin(), l.text.end(), option), end; it != end; ++it) {
      ++seen;
      EXPECT_TRUE(any.count((*it)[2])) << where(cli, l) << ": " << (*it)[2] << " is an option of no bezcam command";
    }
  EXPECT_GT(seen, 100) << "docs/cli.md names no options";
}

TEST(Docs, CommandLinesTheyShowUseTheCommandsOptions) {
  // A command line in a code block, `bezcam CMD ...`, `build/bezcam CMD
  // ...` or `$ bezcam CMD ...`: each of its --options is one CMD's --help
  // lists.
  const auto& help = help_options();
  ASSERT_GT(help.size(), 5u);
  const std::regex command(R"(^(?:\$ )?(?:build/)?bezcam ([a-z]+)\b(.*)$)");
  const std::regex option(R"((^|\s)(--[a-z][a-z0-9-]*))");
  int lines = 0;
  for (const Doc& d : all_docs())
    for (const Line& l : d.lines) {
      std::smatch m;
      if (!l.in_code || !std::regex_search(l.text, m, command)) continue;
      const auto it = help.find(m[1]);
      if (it == help.end()) {
        ADD_FAILURE() << where(d, l) << ": bezcam has no command " << m[1];
        continue;
      }
      ++lines;
      std::string rest = m[2];
      rest = rest.substr(0, rest.find('#'));  // a shell comment after the command
      for (std::sregex_iterator o(rest.begin(), rest.end(), option), end; o != end; ++o)
        EXPECT_TRUE(it->second.count((*o)[2])) << where(d, l) << ": bezcam " << m[1] << " has no option " << (*o)[2];
    }
  EXPECT_GT(lines, 20) << "the docs show no bezcam command lines";
}

TEST(Docs, NameNothingAUserOfACloneLacks) {
  // Issue numbers, the brief and folders outside the repository mean
  // nothing to someone who has only the clone.
  const std::regex outside(R"(\bissues? #?[0-9]|\bthe brief\b|\.\./shared|/work/|shared/spec)", std::regex::icase);
  for (const Doc& d : all_docs())
    for (const Line& l : d.lines)
      if (std::smatch m; std::regex_search(l.text, m, outside))
        ADD_FAILURE() << where(d, l) << ": \"" << m[0] << "\" names what a user of a clone does not have";
}
