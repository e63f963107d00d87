// `preview --deviation` of parts cut beside their curves, through the
// executable: every block of the path (not its leads) is coloured by its
// distance from the exact offset, and the largest reading of each part
// agrees with what convert's summary prints for it and never exceeds its
// proven bound.
#include <gtest/gtest.h>
#include <map>
#include <regex>

#include "support/mini_xml.hpp"
#include "support/run_process.hpp"

namespace {

namespace fs = std::filesystem;

testproc::Result bezcam(const std::vector<std::string>& args) {
  return testproc::run(BEZCAM_EXE, args, {{"BEZCAM_PROGRESS", "off"}}, BEZCAM_SOURCE_DIR);
}

struct Summary {
  double measured = 0, bound = 0;
};

// convert's summary lines: "  bore: path, ..., deviation 0.00989 mm (proven
// bound 0.00997 mm)", by label.
std::map<std::string, Summary> summary_of(const std::string& err) {
  static const std::regex re(R"(\n  (\S+): path, .*, deviation ([0-9.e-]+) mm \(proven bound ([0-9.e-]+) mm\))");
  std::map<std::string, Summary> out;
  for (auto it = std::sregex_iterator(err.begin(), err.end(), re); it != std::sregex_iterator(); ++it)
    out[(*it)[1]] = {std::stod((*it)[2]), std::stod((*it)[3])};
  return out;
}

void check_part(const std::vector<std::string>& job) {
  testproc::TempDir dir;
  std::vector<std::string> conv{"convert"};
  conv.insert(conv.end(), job.begin(), job.end());
  conv.insert(conv.end(), {"-o", (dir / "p.nc").string()});
  const auto c = bezcam(conv);
  ASSERT_EQ(c.status, 0) << c.err;
  const auto summary = summary_of(c.err);
  ASSERT_FALSE(summary.empty()) << c.err;

  std::vector<std::string> prev{"preview"};
  prev.insert(prev.end(), job.begin(), job.end());
  prev.insert(prev.end(), {"--deviation", "-o", (dir / "p.svg").string(), "-q"});
  const auto p = bezcam(prev);
  ASSERT_EQ(p.status, 0) << p.err;
  const auto root = testxml::parse(testproc::slurp(dir / "p.svg"));
  std::map<std::string, std::string> label;  // data-entity -> id
  for (const auto* g : root.by_class("entity")) label[g->attr("data-entity")] = g->attr("data-id");
  std::map<std::string, double> largest;
  std::map<std::string, size_t> measured, blocks;
  size_t parts = 0;
  for (const auto* f : root.by_class("feed")) {
    const std::string e = f->attr("data-entity");
    ++blocks[e];
    if (!f->has("data-deviation")) continue;
    ++measured[e];
    largest[e] = std::max(largest[e], std::stod(f->attr("data-deviation")));
  }
  for (const auto& [entity, id] : label) {
    SCOPED_TRACE("entity " + id);
    const auto s = summary.find(id);
    if (s == summary.end()) continue;  // not a path (a pocket)
    ++parts;
    // The path is measured, its leads (a few blocks a pass) are not.
    EXPECT_GE(double(measured[entity]), 0.8 * double(blocks[entity])) << blocks[entity] << " blocks";
    // A distance to the exact offset: within the proven bound, and the
    // program's own reading (which also counts the material left) agrees.
    EXPECT_LE(largest[entity], s->second.bound);
    EXPECT_LE(largest[entity], s->second.measured * 1.02);
    EXPECT_GE(largest[entity], s->second.measured * 0.5);
  }
  EXPECT_GT(parts, 0u);
}

TEST(PreviewDeviation, OffsetPathsAreColouredByTheirDistanceFromTheExactOffset) {
  {
    SCOPED_TRACE("part-flange-tools");
    check_part({"samples/part-flange-tools.json"});
  }
  {
    SCOPED_TRACE("part-plate");
    check_part({"samples/part-plate.json"});
  }
  {
    SCOPED_TRACE("plate-layer0.dxf");
    check_part({"samples/plate-layer0.dxf", "--set", "side=outside", "--set", "tool_diameter=2", "--set", "cut_z=-1"});
  }
}

}  // namespace
