// The folders are the architecture (docs/architecture.md): each folder of
// include/bezcam/ and src/ may include only the folders below it. This test
// reads every #include of the library's headers and sources and fails on
// one that crosses the graph the wrong way, naming the file and line.
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <set>
#include <string>

namespace fs = std::filesystem;

namespace {

// Which folders each folder may include (besides itself and the top-level
// headers error.hpp, limits.hpp, version.hpp, which belong to `base`).
const std::map<std::string, std::set<std::string>>& allowed() {
  static const std::map<std::string, std::set<std::string>> g = {
      {"base", {}},
      {"kernel", {"base"}},
      {"flatten", {"base", "kernel"}},
      {"stock", {"base", "kernel", "flatten"}},
      {"job", {"base", "kernel"}},
      {"machine", {"base", "kernel", "flatten", "job"}},
      {"cam", {"base", "kernel", "flatten", "job", "machine"}},
      {"gcode", {"base", "kernel", "flatten", "job", "machine", "cam"}},
      {"report", {"base", "kernel", "flatten", "job", "machine", "cam", "gcode"}},
      {"verify", {"base", "kernel", "flatten", "stock", "job", "machine", "cam", "gcode"}},
      {"link", {"base"}},
      {"sim", {"base", "kernel", "flatten", "stock", "job", "machine", "gcode", "verify", "link"}},
      {"import", {"base", "kernel", "flatten", "job"}},
      {"text", {"base", "kernel", "flatten", "job"}},
      {"cli",
       {"base", "kernel", "flatten", "stock", "job", "machine", "cam", "gcode", "report", "verify", "link", "sim",
        "import", "text", "cli"}},
  };
  return g;
}

// The folder a "bezcam/..." include names.
std::string folder_of(const std::string& inc) {
  const std::string rest = inc.substr(std::string("bezcam/").size());
  const auto slash = rest.find('/');
  if (slash == std::string::npos) return rest == "bezcam.hpp" ? "facade" : "base";
  return rest.substr(0, slash);
}

std::vector<std::string> violations() {
  std::vector<std::string> out;
  const fs::path root = BEZCAM_SOURCE_DIR;
  const std::regex inc_re(R"(^\s*#\s*include\s*[<"](bezcam/[^">]+)[">])");
  for (const char* top : {"include/bezcam", "src"}) {
    for (const auto& e : fs::recursive_directory_iterator(root / top)) {
      if (!e.is_regular_file()) continue;
      const fs::path rel = fs::relative(e.path(), root / top);
      if (rel.begin() == rel.end() || std::next(rel.begin()) == rel.end()) continue;  // top-level headers
      const std::string folder = rel.begin()->string();
      const auto rule = allowed().find(folder);
      if (rule == allowed().end()) {
        out.push_back(std::string(top) + "/" + rel.string() + ": folder \"" + folder + "\" is not in the graph");
        continue;
      }
      std::ifstream in(e.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        std::smatch m;
        if (!std::regex_search(line, m, inc_re)) continue;
        const std::string to = folder_of(m[1]);
        if (to == folder || rule->second.count(to)) continue;
        out.push_back(std::string(top) + "/" + rel.string() + ":" + std::to_string(n) + ": " + folder +
                      " must not include " + m[1].str());
      }
    }
  }
  return out;
}

}  // namespace

TEST(Layout, IncludesFollowTheFolderGraph) {
  const auto v = violations();
  std::string all;
  for (const auto& s : v) all += s + "\n";
  EXPECT_TRUE(v.empty()) << all;
}

TEST(Layout, EveryFolderOfSrcHasItsHeaders) {
  // One concept per header: every library folder of src/ has its public
  // headers under include/bezcam/<folder>/ (cli is the program, not a library).
  const fs::path root = BEZCAM_SOURCE_DIR;
  for (const auto& e : fs::directory_iterator(root / "src")) {
    if (!e.is_directory()) continue;
    const std::string f = e.path().filename().string();
    EXPECT_TRUE(allowed().count(f)) << "src/" << f << " is not in the folder graph";
    if (f == "cli" || f == "base") continue;
    EXPECT_TRUE(fs::is_directory(root / "include/bezcam" / f)) << "src/" << f << " has no include/bezcam/" << f;
  }
}

TEST(Layout, TheLibraryNamesNoOptionOfTheProgram) {
  // The library names settings (Place::setting: "output", "tolerance"); the
  // CLI shows them as its options. A "--flag" in a string literal of the
  // library (anything but src/cli) would tie it to one program's options.
  const fs::path root = BEZCAM_SOURCE_DIR;
  const std::regex flag_re(R"re("[^"\n]*--[a-z][a-z-]*)re");
  std::string all;
  for (const char* top : {"include/bezcam", "src"}) {
    for (const auto& e : fs::recursive_directory_iterator(root / top)) {
      if (!e.is_regular_file()) continue;
      const fs::path rel = fs::relative(e.path(), root / top);
      if (rel.begin()->string() == "cli") continue;
      std::ifstream in(e.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        const auto code = line.substr(0, line.find("//"));
        if (std::regex_search(code, flag_re))
          all += std::string(top) + "/" + rel.string() + ":" + std::to_string(n) + ": " + line + "\n";
      }
    }
  }
  EXPECT_TRUE(all.empty()) << all;
}
