// Round trip: every sample, converted for every shipped profile, is read
// back by the G-code reader and measured against its source geometry with
// the independent deviation measure. Lines mode here (the arcs and NURBS
// output modes extend it).
#include <gtest/gtest.h>

#include <filesystem>

#include "bezcam/error.hpp"
#include "bezcam/flatten/deviation.hpp"
#include "bezcam/flatten/tolerance.hpp"
#include "bezcam/post/convert.hpp"
#include "bezcam/post/gcode_reader.hpp"

using namespace bezcam;
namespace fs = std::filesystem;

namespace {

const char* const kProfiles[] = {"generic", "fanuc", "fanuc-g063", "linuxcnc", "grbl", "unisurf"};

std::vector<fs::path> samples() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(BEZCAM_SOURCE_DIR "/samples"))
    if (e.path().extension() == ".json") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The cutting runs of a program read back: each run starts with the plunge
// (a feed move after a rapid) and holds the feed moves up to the next rapid.
std::vector<std::vector<MotionBlock>> cutting_runs(const std::vector<MotionBlock>& blocks) {
  std::vector<std::vector<MotionBlock>> runs;
  bool in_run = false;
  for (const auto& b : blocks) {
    if (b.kind == BlockKind::rapid) {
      in_run = false;
      continue;
    }
    if (!in_run) runs.emplace_back();
    in_run = true;
    runs.back().push_back(b);
  }
  return runs;
}

}  // namespace

TEST(RoundTrip, LinesModeProgramsReadBackWithinTolerance) {
  int programs = 0, skipped = 0;
  for (const auto& file : samples()) {
    const Job job = load_job(file);
    // Surfaces cut in many runs; surface_emitter_test.cpp reads them back.
    if (std::any_of(job.entities.begin(), job.entities.end(), [](const Entity& e) { return e.surface != nullptr; }))
      continue;
    for (const char* name : kProfiles) {
      SCOPED_TRACE(file.filename().string() + " for " + name);
      const MachineProfile m = load_machine_profile(name);
      ConvertResult r;
      try {
        r = convert(job, m, ConvertOptions{});
      } catch (const InputError& e) {
        // A machine may legitimately refuse a job (travel, feed, too few
        // decimals for the tolerance: UNISURF prints 2); nothing else.
        ASSERT_TRUE(e.id() == "program.travel" || e.id() == "program.feed" ||
                    e.id() == "flatten.tolerance-below-rounding")
            << e.what();
        ++skipped;
        continue;
      }
      ++programs;
      std::vector<MotionBlock> blocks;
      ASSERT_NO_THROW(blocks = read_gcode(r.gcode, &m)) << r.gcode;
      EXPECT_TRUE(lint_gcode(r.gcode, m).empty());
      const auto runs = cutting_runs(blocks);
      std::vector<const Entity*> cut;
      for (const auto& e : job.entities)
        if (!e.curve.pieces.empty()) cut.push_back(&e);
      ASSERT_EQ(runs.size(), cut.size());
      for (size_t i = 0; i < cut.size(); ++i) {
        const Entity& e = *cut[i];
        const auto& run = runs[i];
        const CutParams cp = cut_params(job, e, m);
        // The plunge is vertical, at the plunge feed; then only G01 at the feed.
        ASSERT_GE(run.size(), 2u);
        EXPECT_EQ(run[0].kind, BlockKind::linear);
        EXPECT_EQ(run[0].from.x, run[0].to.x);
        EXPECT_EQ(run[0].from.y, run[0].to.y);
        EXPECT_EQ(run[0].feed, quantize(cp.plunge_feed, m.feed_decimals));
        EXPECT_EQ(run.size() - 1, r.program.entities[i].blocks);
        std::vector<Vec3> poly;
        for (size_t k = 0; k < run.size(); ++k) {
          const MotionBlock& b = run[k];
          if (k > 0) {
            EXPECT_EQ(b.kind, BlockKind::linear);
            EXPECT_EQ(b.feed, quantize(cp.feed, m.feed_decimals));
          }
          Vec3 p = b.to;
          if (e.curve.dim == 2) {
            EXPECT_EQ(p.z, quantize(cp.cut_z, m.decimals(job.units)));
            p.z = 0;  // 2D curves are cut at cut_z: compare in the plane
          }
          poly.push_back(p);
        }
        const Deviation d = measure_deviation(e.curve.pieces, poly, job.tolerance);
        EXPECT_LE(d.max(), job.tolerance) << e.label() << ": curve to path " << d.curve_to_path << ", path to curve "
                                          << d.path_to_curve;
      }
    }
  }
  EXPECT_GT(programs, 6 * 10);  // most combinations convert
  RecordProperty("programs", programs);
  RecordProperty("refused_by_machine_limits", skipped);
}
