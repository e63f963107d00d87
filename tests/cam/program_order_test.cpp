// The cut order a program takes by default: inner contours before the
// contour that holds them, one tool at a time where the nesting allows,
// then the shortest rapids; `order: "as-written"` keeps the file's order.
#include <algorithm>
#include <gtest/gtest.h>
#include <string>
#include <vector>

#include "bezcam/cam/program.hpp"
#include "bezcam/job/job_json.hpp"
#include "bezcam/machine/machine_profile.hpp"

namespace bezcam {
namespace {

std::string rect(double x0, double y0, double w, double h, const std::string& extra) {
  auto p = [](double x, double y) { return "[" + std::to_string(x) + "," + std::to_string(y) + "]"; };
  const std::string a = p(x0, y0), b = p(x0 + w, y0), c = p(x0 + w, y0 + h), d = p(x0, y0 + h);
  return R"({"type":"path","closed":true)" + extra + R"(,"segments":[{"type":"bezier","points":[)" + a + "," + b +
         R"(]},{"type":"bezier","points":[)" + b + "," + c + R"(]},{"type":"bezier","points":[)" + c + "," + d +
         R"(]},{"type":"bezier","points":[)" + d + "," + a + "]}]}";
}

Program build(const std::string& entities, const std::string& top = "") {
  const std::string json = R"({"bezcam":1,"tolerance":0.01,)" + top +
                           R"("job":{"feed":600,"plunge_feed":100,"safe_z":5,"tool_diameter":4,"cut_z":-1},)"
                           R"("entities":[)" +
                           entities + "]}";
  return build_program(parse_job(json, "test.json"), load_machine_profile("generic"), ConvertOptions{});
}

std::vector<std::string> labels(const Program& p) {
  std::vector<std::string> out;
  for (const auto& r : p.entities) out.push_back(r.label);
  return out;
}

long at(const std::vector<std::string>& order, const std::string& id) {
  return std::find(order.begin(), order.end(), id) - order.begin();
}

// The plate written first, its holes after it.
const std::string kPlate = rect(0, 0, 100, 60, R"(,"id":"plate","side":"outside")") + "," +
                           rect(80, 40, 10, 10, R"(,"id":"hole-b","side":"inside")") + "," +
                           rect(10, 10, 10, 10, R"(,"id":"hole-a","side":"inside")");

TEST(ProgramOrder, HolesBeforeTheOutlineByDefault) {
  const Program p = build(kPlate);
  const auto order = labels(p);
  EXPECT_LT(at(order, "hole-a"), at(order, "plate"));
  EXPECT_LT(at(order, "hole-b"), at(order, "plate"));
  ASSERT_TRUE(p.order.has_value());
  EXPECT_EQ(p.order->nested, 2u);
  EXPECT_GT(p.order->rapid_as_written, 0);
  EXPECT_NE(p.order_summary.find("as written"), std::string::npos) << p.order_summary;
  EXPECT_NE(std::find(p.notes.begin(), p.notes.end(), p.order_summary), p.notes.end());
}

TEST(ProgramOrder, AsWrittenKeepsTheFilesOrderAndSaysNothing) {
  const Program p = build(kPlate, R"("order":"as-written",)");
  EXPECT_EQ(labels(p), (std::vector<std::string>{"plate", "hole-b", "hole-a"}));
  EXPECT_FALSE(p.order.has_value());
  EXPECT_TRUE(p.order_summary.empty());
}

TEST(ProgramOrder, OneContourHasNothingToOrder) {
  const Program p = build(rect(0, 0, 10, 10, R"(,"id":"only")"));
  EXPECT_FALSE(p.order.has_value());
  EXPECT_TRUE(p.notes.empty());
}

TEST(ProgramOrder, OneToolAtATimeWhereTheNestingAllows) {
  // Holes of tools 1 and 2 written alternately along the plate (tool 1):
  // the tool-2 holes first (they lie in a tool-1 contour), then every
  // tool-1 contour, the plate last: one tool change instead of three.
  std::string ents = rect(0, 0, 200, 60, R"(,"id":"plate","side":"outside")");
  for (int i = 0; i < 4; ++i)
    ents += "," + rect(10 + 45 * i, 20, 10, 10,
                       R"(,"id":"h)" + std::to_string(i) + R"(","side":"inside","tool":)" + std::to_string(1 + i % 2));
  const Program p = build(ents);
  const auto order = labels(p);
  ASSERT_EQ(order.size(), 5u);
  EXPECT_EQ(order.back(), "plate");
  EXPECT_LT(std::max(at(order, "h1"), at(order, "h3")), std::min(at(order, "h0"), at(order, "h2")));
  ASSERT_TRUE(p.order.has_value());
  EXPECT_EQ(p.order->tool_changes_as_written, 3u);
  EXPECT_EQ(p.order->tool_changes_planned, 1u);
  EXPECT_TRUE(p.order->by_tool);
  EXPECT_NE(p.order_summary.find("1 tool change between contours instead of 3"), std::string::npos) << p.order_summary;
}

TEST(ProgramOrder, AToolNestedBothWaysIsPlannedAllTogether) {
  // A tool-2 boss in a tool-1 pocket outline, a tool-1 hole in the boss:
  // tool 1 must go both before and after tool 2; the nesting still holds.
  const std::string ents = rect(0, 0, 100, 100, R"(,"id":"outer","side":"outside")") + "," +
                           rect(20, 20, 60, 60, R"(,"id":"boss","side":"outside","tool":2)") + "," +
                           rect(40, 40, 10, 10, R"(,"id":"hole","side":"inside")");
  const Program p = build(ents);
  EXPECT_EQ(labels(p), (std::vector<std::string>{"hole", "boss", "outer"}));
  ASSERT_TRUE(p.order.has_value());
  EXPECT_FALSE(p.order->by_tool);
}

}  // namespace
}  // namespace bezcam
