// Every command's --help ends with examples, and they run as written: in
// a scratch folder holding the samples, in the order --help lists the
// commands (later examples use the programs earlier ones wrote). Examples
// that need a controller (--to) or start a server (--listen) are parsed,
// not run.
#include "cli/help_examples.hpp"

#include <filesystem>
#include <gtest/gtest.h>
#include <sstream>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "support/run_process.hpp"
#include "support/shell_words.hpp"

namespace fs = std::filesystem;

TEST(HelpExamples, EveryCommandsHelpEndsWithExamples) {
  bezcam::cli::CommandLine cl;
  for (const CLI::App* sub : cl.app().get_subcommands({})) {
    const std::string help = sub->help();
    const size_t at = help.find("Examples:\n  bezcam " + sub->get_name() + " ");
    EXPECT_NE(at, std::string::npos) << sub->get_name() << " --help has no examples";
  }
  EXPECT_NE(cl.app().help().find("man bezcam"), std::string::npos);
}

TEST(HelpExamples, RunAsWritten) {
  testproc::TempDir dir;
  fs::create_directory_symlink(fs::path(BEZCAM_SOURCE_DIR) / "samples", dir / "samples");
  size_t ran = 0;
  for (const auto& [command, lines] : bezcam::cli::help_examples()) {
    for (const auto& line : lines) {
      std::vector<std::string> args = testproc::shell_words(line);
      ASSERT_GE(args.size(), 2u);
      EXPECT_EQ(args[0], "bezcam") << line;
      EXPECT_EQ(args[1], command) << line;
      args.erase(args.begin());
      if (line.find("--listen") != std::string::npos || line.find("--to ") != std::string::npos) {
        bezcam::cli::CommandLine cl;
        std::vector<std::string> argv = {"bezcam"};
        argv.insert(argv.end(), args.begin(), args.end());
        EXPECT_NO_THROW(cl.parse(argv)) << line;
        continue;
      }
      const auto r = testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, dir.path().string());
      EXPECT_EQ(r.status, 0) << line << "\n" << r.err;
      ++ran;
    }
  }
  EXPECT_GE(ran, 10u);
}
