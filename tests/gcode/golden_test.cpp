// Golden G-code: every sample converted for the reference profiles must equal
// tests/golden/<sample>.<profile>.nc byte for byte (lines output), and
// tests/golden/<sample>.<profile>.<mode>.nc for the other output modes where
// such a file exists.
//
// After an intended change of the output, regenerate with
//   BEZCAM_UPDATE_GOLDEN=1 ctest --test-dir build -R Golden
// and review the diff (git diff tests/golden) before committing it.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

#include "bezcam/gcode/convert.hpp"
#include "bezcam/job/job_json.hpp"
#include "support/sample_job.hpp"

using namespace bezcam;
namespace fs = std::filesystem;

namespace {

const fs::path kRoot = BEZCAM_SOURCE_DIR;

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> samples() {
  std::vector<fs::path> v;
  for (const auto& e : fs::directory_iterator(kRoot / "samples"))
    if (e.path().extension() == ".json") v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

// Compares (or, with BEZCAM_UPDATE_GOLDEN=1, rewrites) one golden file.
void check_golden(const fs::path& golden, const std::string& actual) {
  if (const char* u = std::getenv("BEZCAM_UPDATE_GOLDEN"); u && std::string(u) == "1") {
    std::ofstream(golden, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing; regenerate with BEZCAM_UPDATE_GOLDEN=1";
  const std::string expected = read(golden);
  if (expected == actual) return;
  // Name the first differing line to make the failure readable.
  std::istringstream a(expected), b(actual);
  std::string la, lb;
  int line = 0;
  while (true) {
    ++line;
    const bool ga = static_cast<bool>(std::getline(a, la)), gb = static_cast<bool>(std::getline(b, lb));
    if (!ga || !gb || la != lb) {
      FAIL() << golden.filename() << " differs at line " << line << ":\n  golden: " << (ga ? la : "<end>")
             << "\n  actual: " << (gb ? lb : "<end>");
    }
  }
}

}  // namespace

TEST(Golden, EverySampleForGenericAndFanucInLinesMode) {
  for (const auto& s : samples()) {
    const Job job = test::load_sample(s);
    for (const char* machine : {"generic", "fanuc"}) {
      SCOPED_TRACE(s.filename().string() + " / " + machine);
      const MachineProfile m = load_machine_profile(machine);
      const ConvertResult r = convert(job, m, {});
      check_golden(kRoot / "tests/golden" / (s.stem().string() + "." + machine + ".nc"), r.gcode);
    }
  }
}

TEST(Golden, OtherModesAndProfilesWhereAGoldenExists) {
  // Files named <sample>.<profile>.<mode>.nc pin the arcs and nurbs output.
  int checked = 0;
  for (const auto& e : fs::directory_iterator(kRoot / "tests/golden")) {
    const std::string name = e.path().filename().string();
    if (e.path().extension() != ".nc") continue;
    const std::string stem = e.path().stem().string();  // sample.profile[.mode]
    const auto d1 = stem.find('.');
    if (d1 == std::string::npos) continue;
    const auto d2 = stem.find('.', d1 + 1);
    if (d2 == std::string::npos) continue;  // lines mode: the test above
    const std::string sample = stem.substr(0, d1), machine = stem.substr(d1 + 1, d2 - d1 - 1),
                      mode = stem.substr(d2 + 1);
    SCOPED_TRACE(name);
    ConvertOptions opt;
    opt.output = parse_output_mode(mode);
    const ConvertResult r =
        convert(test::load_sample(kRoot / "samples" / (sample + ".json")), load_machine_profile(machine), opt);
    check_golden(e.path(), r.gcode);
    ++checked;
  }
  RecordProperty("checked", checked);
}
