// Every file in tests/bad/ is an input bezcam must refuse, run through the
// real executable the way a user would: the exit status, the first line of
// the message, and that nothing was written (an output file that existed
// keeps its bytes, and no temporary file is left beside it).
//
// Each input has a sidecar:
//   NAME.expect   (this runner's format), lines of `key: value`:
//     # comment                  why the input is bad
//     args: convert {file} -o {out}
//                                the command line (default: that one for
//                                .json, `lint {file} --machine generic` for
//                                .nc); {file} is the input (relative to the
//                                source tree, the working directory), {out}
//                                and {report} existing files that must stay
//                                untouched
//     exit: 2                    the exit status
//     stderr: TEXT               the first line of stderr, exactly
//     stderr-regex: RE           ... or an ECMAScript regex matching all of it
//     stdout: TEXT / stdout-regex: RE   the first line of stdout (lint)
//   NAME.expected (the G-code reader tests' format): one line `line N: MSG`,
//     the reader's refusal; here lint must exit 2 and print `{file}:N: MSG`
//     as its first finding.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <regex>
#include <sstream>

#include "in_process.hpp"
#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kBadDir = fs::path(BEZCAM_SOURCE_DIR) / "tests" / "bad";
const std::string kSentinel = "this file existed before the run and must keep these bytes\n";

std::vector<std::string> bad_inputs() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(kBadDir)) {
    const std::string n = e.path().filename().string();
    if (!e.is_regular_file() || n.ends_with(".expect") || n.ends_with(".expected") || n.starts_with("README") ||
        n.starts_with("."))
      continue;
    names.push_back(n);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (size_t i = s.find(from); i != std::string::npos; i = s.find(from, i + to.size())) s.replace(i, from.size(), to);
  return s;
}

std::string regex_escape(const std::string& s) {
  static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
  return std::regex_replace(s, special, R"(\$&)");
}

struct Expectation {
  std::vector<std::string> args;
  int exit = 2;
  std::map<std::string, std::string> checks;  // stderr, stderr-regex, stdout, stdout-regex, stdout-prefix
};

Expectation read_expectation(const std::string& name) {
  Expectation x;
  const bool gcode = name.ends_with(".nc") || name.ends_with(".ngc") || name.ends_with(".gcode");
  std::string args = gcode ? "lint {file} --machine generic" : "convert {file} -o {out}";
  const fs::path expect = kBadDir / (name + ".expect"), expected = kBadDir / (name + ".expected");
  if (fs::exists(expect)) {
    std::ifstream in(expect);
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      const size_t colon = line.find(": ");
      if (colon == std::string::npos)
        throw std::runtime_error(expect.string() + ": expected `key: value`, found " + line);
      const std::string key = line.substr(0, colon), value = line.substr(colon + 2);
      if (key == "args")
        args = value;
      else if (key == "exit")
        x.exit = std::stoi(value);
      else if (key == "stderr" || key == "stderr-regex" || key == "stdout" || key == "stdout-regex")
        x.checks[key] = value;
      else
        throw std::runtime_error(expect.string() + ": unknown key " + key);
    }
  } else if (fs::exists(expected)) {
    std::ifstream in(expected);
    std::string line;
    std::getline(in, line);
    static const std::regex form(R"(^line ([0-9]+): (.*)$)");
    std::smatch m;
    if (!std::regex_match(line, m, form))
      throw std::runtime_error(expected.string() + ": expected `line N: message`, found " + line);
    x.checks["stdout-prefix"] = "{file}:" + m[1].str() + ": " + m[2].str();
  } else {
    throw std::runtime_error("tests/bad/" + name + " has no .expect file saying what must happen");
  }
  std::istringstream words(args);
  for (std::string w; words >> w;) x.args.push_back(w);
  return x;
}

class BadInput : public ::testing::TestWithParam<std::string> {};

TEST_P(BadInput, IsRefusedWithItsMessageAndWritesNothing) {
  const std::string name = GetParam();
  const Expectation x = read_expectation(name);
  testproc::TempDir dir;
  // Without an extension: every command writes it (preview refuses a name
  // of another format than SVG).
  const fs::path out = dir / "out", report = dir / "report.json";
  testproc::write_file(out, kSentinel);
  testproc::write_file(report, kSentinel);
  const std::string file = "tests/bad/" + name;
  std::vector<std::string> args;
  for (const auto& a : x.args)
    args.push_back(
        replace_all(replace_all(replace_all(a, "{file}", file), "{out}", out.string()), "{report}", report.string()));
  // No progress lines before the message, whatever the machine's load.
  const auto r = testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, BEZCAM_SOURCE_DIR);

  EXPECT_EQ(r.status, x.exit) << "stderr:\n" << r.err;
  auto expand = [&](const std::string& s, bool regex) {
    return replace_all(replace_all(s, "{file}", regex ? regex_escape(file) : file), "{out}",
                       regex ? regex_escape(out.string()) : out.string());
  };
  for (const auto& [key, value] : x.checks) {
    const std::string got = key.starts_with("stderr") ? r.err_first_line() : r.out_first_line();
    if (key.ends_with("-regex")) {
      EXPECT_TRUE(std::regex_match(got, std::regex(expand(value, true)))) << key << ": " << value << "\ngot: " << got;
    } else if (key == "stdout-prefix") {
      EXPECT_EQ(got.substr(0, expand(value, false).size()), expand(value, false)) << "stdout:\n" << r.out;
    } else {
      EXPECT_EQ(got, expand(value, false)) << key;
    }
  }
  // A refusal names itself as an error (or, for lint, lists findings).
  if (x.exit != 0 && !x.args.empty() && x.args[0] != "lint") {
    EXPECT_EQ(r.err_first_line().rfind("bezcam: error: ", 0), 0u) << r.err;
  }
  // Nothing written: the existing files keep their bytes, nothing was added.
  EXPECT_EQ(testproc::slurp(out), kSentinel);
  EXPECT_EQ(testproc::slurp(report), kSentinel);
  EXPECT_EQ(dir.files(), (std::vector<std::string>{"out", "report.json"}));
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string s;
  for (char c : info.param) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(TestsBad, BadInput, ::testing::ValuesIn(bad_inputs()), test_name);

// `check` runs every validation `convert` runs (issue "Safe on the shop
// floor", bug 2): every job convert refuses, check refuses with the same
// status and the same message, with the same --machine, --tolerance and
// --output. Both run in-process: the executable's refusals are checked
// above.
class CheckLikeConvert : public ::testing::TestWithParam<std::string> {};

TEST_P(CheckLikeConvert, RefusesWhatConvertRefuses) {
  const std::string name = GetParam();
  const Expectation x = read_expectation(name);
  if (x.args.empty() || x.args[0] != "convert" || x.exit == 0) GTEST_SKIP() << "not a convert refusal";
  if (std::find(x.args.begin(), x.args.end(), "--report") != x.args.end())
    GTEST_SKIP() << "a usage refusal of convert's";
  const std::string file = "tests/bad/" + name;
  std::vector<std::string> args{"check", file};
  // Every option convert was given, but where its program goes.
  for (size_t i = 2; i < x.args.size(); ++i) {
    if (x.args[i] == "-o") {
      ++i;
      continue;
    }
    args.push_back(x.args[i]);
  }
  const auto c = bezcam::test::run_cli(args);
  testproc::TempDir dir;
  std::vector<std::string> conv{"convert", file, "-o", (dir / "out.nc").string()};
  conv.insert(conv.end(), args.begin() + 2, args.end());
  const auto v = bezcam::test::run_cli(conv);
  EXPECT_EQ(c.status, v.status) << "check:\n" << c.out << c.err << "convert:\n" << v.err;
  EXPECT_EQ(c.err_first_line(), v.err_first_line());
}

INSTANTIATE_TEST_SUITE_P(TestsBad, CheckLikeConvert, ::testing::ValuesIn([] {
                           std::vector<std::string> jobs;
                           for (const auto& n : bad_inputs())
                             if (n.ends_with(".json") || n.ends_with(".svg") || n.ends_with(".dxf")) jobs.push_back(n);
                           return jobs;
                         }()),
                         test_name);

// The runner itself: the directory holds both kinds of input and every one
// has its sidecar (a new file without one fails above, loudly).
TEST(BadInputs, CoverJobsAndGcode) {
  const auto names = bad_inputs();
  size_t json = 0, nc = 0;
  for (const auto& n : names) json += n.ends_with(".json"), nc += n.ends_with(".nc");
  EXPECT_GE(json, 30u);
  EXPECT_GE(nc, 1u);
}

}  // namespace
