// The command line as an object (src/cli/command_line.hpp): each
// subcommand's options land in its arguments struct, CLI11's refusals come
// before anything runs, and a command line run in-process prints what the
// executable prints and ends with the same status.
#include "cli/command_line.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "in_process.hpp"
#include "support/run_process.hpp"

namespace {

using bezcam::test::run_cli;

/// The arguments a command line is parsed into (CLI::ParseError when
/// CLI11 refuses it), without running the command.
bezcam::cli::Arguments parse_cli(const std::vector<std::string>& args) {
  bezcam::cli::CommandLine command_line;
  std::vector<std::string> argv{"bezcam"};
  argv.insert(argv.end(), args.begin(), args.end());
  command_line.parse(argv);
  return command_line.args();
}

const std::string kSemicircle = std::string(BEZCAM_SOURCE_DIR) + "/samples/curve-semicircle.json";

TEST(CliParse, EachSubcommandBindsItsArguments) {
  auto a = parse_cli({"convert", "job.json", "-o", "out.nc", "--tolerance", "0.05", "--output", "arcs", "--precision",
                      "4", "--origin", "center", "--compare-outputs", "-q"});
  EXPECT_EQ(a.convert.job, "job.json");
  EXPECT_EQ(a.convert.out, "out.nc");
  EXPECT_DOUBLE_EQ(a.convert.conv.tolerance, 0.05);
  EXPECT_EQ(a.convert.conv.output, "arcs");
  EXPECT_EQ(a.convert.post.precision, 4);
  EXPECT_EQ(a.convert.post.origin, "center");
  EXPECT_TRUE(a.convert.compare);
  EXPECT_TRUE(a.convert.quiet);
  EXPECT_EQ(a.check.job, "");  // the other subcommands keep their defaults

  a = parse_cli({"check", "part.dxf", "--set", "feed=600", "--set", "cut_z=-1", "--layer", "HOLES"});
  EXPECT_EQ(a.check.conv.sets, (std::vector<std::string>{"feed=600", "cut_z=-1"}));
  EXPECT_EQ(a.check.conv.layers, std::vector<std::string>{"HOLES"});
  EXPECT_EQ(a.check.conv.output, "lines");
  EXPECT_EQ(a.check.post.precision, -1);

  a = parse_cli({"lint", "p.nc", "--tool-diameter", "1=6"});
  EXPECT_EQ(a.lint.machine, "");  // the machine the program names, else generic
  EXPECT_EQ(a.lint.tool_diameters, std::vector<std::string>{"1=6"});

  a = parse_cli({"stream", "p.nc", "--to", "127.0.0.1:5020", "--retries", "3", "--from-line", "120", "--safe-z", "12"});
  EXPECT_EQ(a.stream.to, "127.0.0.1:5020");
  EXPECT_EQ(a.stream.retries, 3);
  EXPECT_DOUBLE_EQ(a.stream.timeout, 2);
  EXPECT_EQ(a.stream.resume.from_line, 120);
  EXPECT_EQ(a.stream.resume.safe_z, 12.0);
  EXPECT_FALSE(a.stream.resume.plunge_feed);

  a = parse_cli(
      {"simulate", "--listen", "127.0.0.1:0", "--fault", "drop-after:3", "--fault", "corrupt:5", "--buffer", "8192"});
  EXPECT_EQ(a.simulate.faults, (std::vector<std::string>{"drop-after:3", "corrupt:5"}));
  EXPECT_EQ(a.simulate.buffer, 8192u);
  EXPECT_EQ(a.simulate.time_scale, "1");

  a = parse_cli({"status", "--to", "host:502", "--timeout", "5"});
  EXPECT_DOUBLE_EQ(a.status.timeout, 5);
  a = parse_cli({"import", "d.svg", "-o", "j.json", "--layer", "A"});
  EXPECT_EQ(a.import_drawing.drawing, "d.svg");
  EXPECT_EQ(a.import_drawing.conv.layers, std::vector<std::string>{"A"});
}

TEST(CliParse, PreviewKnowsWhetherOutputWasGiven) {
  // --output has a default (lines) but does not apply to --program: the
  // run must know whether the user gave it.
  auto a = parse_cli({"preview", "--program", "p.nc", "-o", "p.svg"});
  EXPECT_FALSE(a.preview.output_given);
  EXPECT_EQ(a.preview.conv.output, "lines");
  a = parse_cli({"preview", "--program", "p.nc", "-o", "p.svg", "--output", "lines"});
  EXPECT_TRUE(a.preview.output_given);
}

TEST(CliParse, RefusesBadOptionsBeforeAnythingRuns) {
  EXPECT_THROW(parse_cli({"convert", "j.json", "--tolerance", "-1"}), CLI::ValidationError);
  EXPECT_THROW(parse_cli({"convert", "j.json", "--output", "out.nc"}), CLI::ValidationError);
  EXPECT_THROW(parse_cli({"convert", "j.json", "--origin", "center", "--offset", "1,2"}), CLI::ExcludesError);
  EXPECT_THROW(parse_cli({"stream", "p.nc", "--to", "h:1", "--safe-z", "5"}), CLI::RequiresError);
  EXPECT_THROW(parse_cli({"simulate", "--listen", "h:1", "--program", "p.nc"}), CLI::ExcludesError);
  EXPECT_THROW(parse_cli({"convert"}), CLI::RequiredError);
  EXPECT_THROW(parse_cli({}), CLI::RequiredError);
  EXPECT_THROW(parse_cli({"frobnicate"}), CLI::ParseError);
  EXPECT_THROW(parse_cli({"convert", "j.json", "--tol", "0.1"}), CLI::ExtrasError);
}

TEST(CliParse, ChosenIsTheSubcommandParsed) {
  bezcam::cli::CommandLine command_line;
  EXPECT_EQ(command_line.chosen(), nullptr);
  command_line.parse({"bezcam", "lint", "p.nc"});
  ASSERT_NE(command_line.chosen(), nullptr);
  EXPECT_EQ(command_line.chosen()->get_name(), "lint");
}

// Help text with the option lists after "Excludes:" and "Needs:" sorted:
// CLI11 lists them in the order of the options' addresses, which differ
// from one process to another.
std::string with_sorted_lists(const std::string& help) {
  static const std::regex list(R"((Excludes|Needs): ((?:--[\w-]+ ?)+))");
  std::string out;
  std::istringstream in(help);
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    if (std::regex_search(line, m, list)) {
      std::istringstream words(m[2].str());
      std::vector<std::string> opts{std::istream_iterator<std::string>(words), {}};
      std::sort(opts.begin(), opts.end());
      std::string sorted;
      for (const auto& o : opts) sorted += o + " ";
      line = m.prefix().str() + m[1].str() + ": " + sorted + m.suffix().str();
    }
    out += line + "\n";
  }
  return out;
}

// The in-process run is the executable's: the same help, byte for byte
// but for the order of CLI11's option lists, and for refusals the same
// status and messages.
TEST(CliInProcess, HelpIsTheExecutables) {
  for (const std::string cmd : {"", "check", "convert", "import", "lint", "preview", "simulate", "status", "stream"}) {
    std::vector<std::string> args;
    if (!cmd.empty()) args.push_back(cmd);
    args.push_back("--help");
    const auto exe = testproc::run(BEZCAM_EXE, args);
    const auto in = run_cli(args, BEZCAM_EXE);
    EXPECT_EQ(in.status, 0) << cmd;
    EXPECT_EQ(in.status, exe.status) << cmd;
    EXPECT_EQ(with_sorted_lists(in.out), with_sorted_lists(exe.out)) << cmd;
    EXPECT_EQ(in.err, "") << cmd;
  }
  const auto version = run_cli({"--version"});
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out, testproc::run(BEZCAM_EXE, {"--version"}).out);
}

TEST(CliInProcess, RefusalsAreTheExecutables) {
  const std::vector<std::vector<std::string>> lines = {
      {},                                                                            // no subcommand: usage, 2
      {"convert", kSemicircle, "--tol", "0.1"},                                      // a misspelt option, 2
      {"convert", kSemicircle, "--machine", "nosuch"},                               // an unknown profile, 2
      {"convert", std::string(BEZCAM_SOURCE_DIR) + "/no-such.json"},                 // a missing file, 3
      {"check", std::string(BEZCAM_SOURCE_DIR) + "/tests/bad/path-joint-gap.json"},  // a bad job, 2
      {"simulate"},  // neither --listen nor --program, 2
  };
  for (const auto& args : lines) {
    const auto exe = testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}});
    const auto in = run_cli(args);
    EXPECT_NE(in.status, 0);
    EXPECT_EQ(in.status, exe.status) << exe.err;
    EXPECT_EQ(in.err, exe.err);
    EXPECT_EQ(in.out, exe.out);
  }
}

TEST(CliInProcess, AnUnknownCommandIsNamedWithTheOneMeant) {
  const auto typo = run_cli({"convrt", kSemicircle});
  EXPECT_EQ(typo.status, 2);
  EXPECT_EQ(typo.err,
            "bezcam: error: there is no command convrt: did you mean convert?\n  (bezcam --help lists the "
            "commands)\n");
  const auto other = run_cli({"engrave", "x.json"});
  EXPECT_EQ(other.status, 2);
  EXPECT_EQ(other.err, "bezcam: error: there is no command engrave\n  (bezcam --help lists the commands)\n");
  // The executable says the same.
  EXPECT_EQ(testproc::run(BEZCAM_EXE, {"engrave", "x.json"}).err, other.err);
}

TEST(CliInProcess, ARunPrintsOnTheStreamsItWasGiven) {
  const auto r = run_cli({"convert", kSemicircle, "--machine", "fanuc"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, testproc::run(BEZCAM_EXE, {"convert", kSemicircle, "--machine", "fanuc", "-q"}).out);
  EXPECT_EQ(r.err.rfind("bezcam: 1 entity, ", 0), 0u) << r.err;  // the summary, on stderr only
  EXPECT_EQ(r.out.find("bezcam: "), std::string::npos);
}

}  // namespace
