// Every deviation the report gives is a promise kept: for every entity of
// every sample (samples/: jobs and drawings) on the generic, fanuc and
// linuxcnc profiles in lines, arcs and nurbs output, and of every job of
// the fuzz corpus that converts in every output mode, the deviation
// measured is no more than the proven bound, in the JSON report as
// `convert --report` writes it, and as the text report and the program's
// header state them.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "bezcam/error.hpp"
#include "bezcam/gcode/convert.hpp"
#include "bezcam/import/drawing.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/report/report.hpp"
#include "support/drawing_fonts.hpp"
#include "support/sample_job.hpp"

namespace bezcam {
namespace {

namespace fs = std::filesystem;

struct Case {
  std::string name;
  Job job;
};

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The sample jobs and drawings (a drawing as `convert` reads it, with no
// settings).
std::vector<Case> samples() {
  std::vector<Case> out;
  for (const fs::path& dir :
       {fs::path(BEZCAM_SOURCE_DIR "/samples"), fs::path(BEZCAM_SOURCE_DIR "/samples/controller-comp")})
    for (const fs::path& f : files_in(dir)) {
      if (f.extension() == ".json")
        out.push_back({f.filename().string(), test::load_sample(f)});
      else if (import::is_drawing(f))
        out.push_back({f.filename().string(), import::to_job(import::read_drawing(f), test::with_fonts())});
    }
  return out;
}

// The fuzz corpus's jobs that read.
std::vector<Case> corpus() {
  std::vector<Case> out;
  for (const fs::path& f : files_in(BEZCAM_SOURCE_DIR "/tests/fuzz/corpus/job")) {
    std::ifstream in(f, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    try {
      out.push_back({"corpus " + f.filename().string(), parse_job(text.str(), f.filename().string())});
    } catch (const InputError&) {
    }
  }
  return out;
}

struct Run {
  const char* machine;
  OutputMode mode;
};
// Each of these profiles in every mode; lines and arcs are the same on
// each profile but for its rounding, NURBS blocks differ (generic has none).
std::vector<Run> every_mode_on(const char* machine) {
  return {{machine, OutputMode::lines}, {machine, OutputMode::arcs}, {machine, OutputMode::nurbs}};
}
const std::vector<Run> kEveryMode{{"generic", OutputMode::lines},
                                  {"generic", OutputMode::arcs},
                                  {"fanuc", OutputMode::nurbs},
                                  {"linuxcnc", OutputMode::nurbs}};

// Every "deviation <figure> ... proven bound <figure>" the text states
// (the report's lines, the program's header comment): the deviation's
// figure, "below" one included, is never the larger of the two.
void expect_figures_in_order(const std::string& text, const std::string& what) {
  static const std::regex pair(
      R"(deviation (?:measured )?(below )?([-0-9.e+]+) (?:mm|in)[^0-9]*proven bound ([-0-9.e+]+))");
  size_t seen = 0;
  for (std::sregex_iterator it(text.begin(), text.end(), pair), end; it != end; ++it, ++seen)
    EXPECT_LE(std::stod((*it)[2].str()), std::stod((*it)[3].str())) << what << ": " << it->str();
  EXPECT_GT(seen, 0u) << what << ": no deviation stated in\n" << text;
}

// Converts the case as each run asks (a refusal converts nothing); returns
// how many converted.
size_t expect_bound_covers_measured(const Case& c, const std::vector<Run>& runs) {
  size_t converted = 0;
  // As --compare-outputs: the modes share a pocket's passes and certificate.
  const auto memo = make_conversion_memo();
  for (const Run& run : runs) {
    const MachineProfile m = load_machine_profile(run.machine);
    ConvertOptions opt;
    opt.output = run.mode;
    opt.memo = memo;
    ConvertResult r;
    try {
      r = convert(c.job, m, opt);
    } catch (const InputError&) {
      continue;
    }
    ++converted;
    const std::string what = c.name + " on " + run.machine + ", --output " + to_string(run.mode);
    const ProgramReport rep = make_report(r.program, m, r.gcode);
    const auto j = nlohmann::json::parse(report_json(rep));
    for (const auto& x : j["entities"])
      EXPECT_LE(x["measured_deviation"].get<double>(), x["proven_bound"].get<double>())
          << what << ": entity " << x["label"];
    EXPECT_LE(j["max_measured_deviation"].get<double>(), j["max_proven_bound"].get<double>()) << what;
    expect_figures_in_order(report_text(rep, 1000), what + ", report");
    expect_figures_in_order(r.gcode.substr(0, r.gcode.find("proven bound") + 40), what + ", program header");
    // The bound as printed is never below the bound proven.
    static const std::regex printed_bound(R"(proven bound ([-0-9.e+]+))");
    std::smatch pb;
    const std::string head = r.gcode.substr(0, r.gcode.find("proven bound") + 40);
    const bool found = std::regex_search(head, pb, printed_bound);
    EXPECT_TRUE(found) << what;
    if (found) EXPECT_GE(std::stod(pb[1].str()), j["max_proven_bound"].get<double>()) << what << ": " << pb[0];
  }
  return converted;
}

// One test per profile, so that the samples' conversions spread over the
// suite's jobs.
class BoundCoversMeasuredOnProfile : public ::testing::TestWithParam<const char*> {};

TEST_P(BoundCoversMeasuredOnProfile, EverySampleInEveryMode) {
  const auto cases = samples();
  ASSERT_GE(cases.size(), 35u);
  size_t converted = 0;
  for (const Case& c : cases) converted += expect_bound_covers_measured(c, every_mode_on(GetParam()));
  EXPECT_GE(converted, 2 * cases.size());  // every sample converts in lines and arcs, most in NURBS too
}

INSTANTIATE_TEST_SUITE_P(Profiles, BoundCoversMeasuredOnProfile, ::testing::Values("generic", "fanuc", "linuxcnc"));

TEST(BoundCoversMeasured, EveryFuzzCorpusJobThatConverts) {
  const auto cases = corpus();
  ASSERT_GE(cases.size(), 10u);
  size_t converted = 0;
  for (const Case& c : cases) converted += expect_bound_covers_measured(c, kEveryMode);
  EXPECT_GT(converted, 0u);
}

}  // namespace
}  // namespace bezcam
