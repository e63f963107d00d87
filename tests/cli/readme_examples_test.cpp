// The README's examples run as written (issue "Safe on the shop floor":
// "the README's examples run as written from a clean clone"): every
// `build/bezcam ...` line of its sh blocks, in order, in a scratch folder
// holding the samples, exits 0. Lines that need what a test cannot give
// them are left out and counted: a placeholder job (JOB.json), a server in
// the background (&) or a controller to talk to (--to, --listen).
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "support/run_process.hpp"
#include "support/shell_words.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<std::string> example_lines() {
  std::ifstream in(std::string(BEZCAM_SOURCE_DIR) + "/README.md");
  std::vector<std::string> out;
  bool sh = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("```", 0) == 0) {
      sh = !sh && line == "```sh";
      continue;
    }
    if (sh && line.rfind("build/bezcam ", 0) == 0) out.push_back(line);
  }
  return out;
}

}  // namespace

TEST(ReadmeExamples, LinesAreSplitAsTheShellSplitsThem) {
  using V = std::vector<std::string>;
  EXPECT_EQ(testproc::shell_words("a  b\tc # note"), (V{"a", "b", "c"}));
  EXPECT_EQ(testproc::shell_words(R"(--set 'k={"a": 1, "b": 2}' x#y)"), (V{"--set", R"(k={"a": 1, "b": 2})", "x#y"}));
  EXPECT_EQ(testproc::shell_words(R"(--set "circle<4:t=\"2\"" a\ b '')"), (V{"--set", R"(circle<4:t="2")", "a b", ""}));
}

TEST(ReadmeExamples, RunAsWritten) {
  const auto lines = example_lines();
  ASSERT_GE(lines.size(), 10u) << "the README's examples were not found";
  testproc::TempDir dir;
  fs::create_directory_symlink(fs::path(BEZCAM_SOURCE_DIR) / "samples", dir / "samples");
  size_t ran = 0, left_out = 0;
  for (const auto& line : lines) {
    if (line.find("JOB.json") != std::string::npos || line.find(" &") != std::string::npos ||
        line.find("--to ") != std::string::npos || line.find("--listen") != std::string::npos) {
      ++left_out;
      continue;
    }
    std::vector<std::string> args = testproc::shell_words(line);
    args.erase(args.begin());  // build/bezcam
    const auto r = testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, dir.path().string());
    EXPECT_EQ(r.status, 0) << line << "\n" << r.err;
    ++ran;
  }
  EXPECT_GE(ran, 10u);
  EXPECT_LE(left_out, 8u);
}
