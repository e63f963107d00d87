// Golden files for the drawing samples (samples/logo.svg, samples/part.dxf):
// the job each is read as (tests/golden/import/<sample>.json, what
// `bezcam import` writes) and its programs in every output mode
// (tests/golden/import/<sample>.<profile>[.<mode>].nc), byte for byte.
// Regenerate with BEZCAM_UPDATE_GOLDEN=1 ctest --test-dir build -R Golden.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

#include "bezcam/gcode/convert.hpp"
#include "bezcam/import/read_drawing.hpp"
#include "support/drawing_fonts.hpp"

namespace bezcam::import {
namespace {

namespace fs = std::filesystem;
const fs::path kRoot = BEZCAM_SOURCE_DIR;

void check_golden(const fs::path& golden, const std::string& actual) {
  if (const char* u = std::getenv("BEZCAM_UPDATE_GOLDEN"); u && std::string(u) == "1") {
    fs::create_directories(golden.parent_path());
    std::ofstream(golden, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing; regenerate with BEZCAM_UPDATE_GOLDEN=1";
  std::ifstream in(golden, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  EXPECT_TRUE(s.str() == actual) << golden << " differs; regenerate with BEZCAM_UPDATE_GOLDEN=1 and review the diff";
}

TEST(GoldenImport, DrawingSamplesTheirJobsAndPrograms) {
  for (const char* sample : {"logo.svg", "part.dxf"}) {
    SCOPED_TRACE(sample);
    const Drawing d = read_drawing(kRoot / "samples" / sample);
    const std::string stem = fs::path(sample).stem().string();
    check_golden(kRoot / "tests/golden/import" / (stem + ".json"), job_json(d, test::with_fonts()));
    const Job job = to_job(d, test::with_fonts());
    for (const auto& [machine, mode] :
         {std::pair{"generic", "lines"}, std::pair{"generic", "arcs"}, std::pair{"fanuc", "lines"},
          std::pair{"fanuc", "nurbs"}, std::pair{"linuxcnc", "nurbs"}}) {
      ConvertOptions opt;
      opt.output = parse_output_mode(mode);
      const ConvertResult r = convert(job, load_machine_profile(machine), opt);
      EXPECT_LE(r.program.max_measured, job.tolerance);
      check_golden(kRoot / "tests/golden/import" /
                       (stem + "." + machine + (std::string(mode) == "lines" ? "" : std::string(".") + mode) + ".nc"),
                   r.gcode);
    }
  }
}

}  // namespace
}  // namespace bezcam::import
