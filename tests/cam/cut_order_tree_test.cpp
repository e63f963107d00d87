// The cut-order planner's tree of boxes (src/cam/cut_order_tree.hpp): its
// searches give what comparing every box gives, on boxes spread very
// unevenly (a dense cluster, a sparse field, a few boxes as wide as the
// whole), with contours switched off and on again.
#include "cam/cut_order_tree.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <utility>
#include <vector>

using namespace bezcam;
using cut_order_detail::Box2;
using cut_order_detail::BoxTree;

namespace {

std::vector<Box2> uneven_boxes(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> cluster(0, 20);
  std::uniform_real_distribution<double> field(-1000, 1000), size(0, 60), u01(0, 1);
  std::vector<Box2> out;
  for (size_t i = 0; i < n; ++i) {
    const bool dense = u01(rng) < 0.8;
    const double x = dense ? cluster(rng) : field(rng), y = dense ? cluster(rng) : field(rng);
    const double w = i % 97 == 0 ? 1500 : size(rng), h = i % 89 == 0 ? 1200 : size(rng);
    Box2 b;
    b.add({x, y});
    b.add({x + w, y + h});
    out.push_back(b);
  }
  return out;
}

double centre_gap(const Vec3& a, const Vec3& b) { return std::hypot(a.x - b.x, a.y - b.y); }

TEST(CutOrderTree, KNearestBoxesEqualComparingEveryPair) {
  const std::vector<Box2> boxes = uneven_boxes(3000, 7);
  const BoxTree tree(boxes);
  using Key = std::pair<double, double>;
  struct Cand {
    double gap, cd;
    uint32_t v;
    bool operator<(const Cand& o) const { return gap != o.gap ? gap < o.gap : cd != o.cd ? cd < o.cd : v < o.v; }
  };
  constexpr size_t K = 10;
  for (uint32_t u = 0; u < boxes.size(); u += 7) {
    const Vec3 cu = boxes[u].center();
    std::vector<Cand> best;
    tree.search<Key>(
        [&](const Box2& b, const Box2& c) {
          return Key{boxes[u].gap(b), c.gap(cu)};
        },
        [&](uint32_t v) {
          if (v == u) return;
          best.push_back({boxes[u].gap(boxes[v]), centre_gap(cu, boxes[v].center()), v});
          std::sort(best.begin(), best.end());
          if (best.size() > K) best.pop_back();
        },
        [&](const Key& lower) {
          return best.size() == K && Key{best.back().gap, best.back().cd} < lower;
        });
    std::vector<Cand> all;
    for (uint32_t v = 0; v < boxes.size(); ++v)
      if (v != u) all.push_back({boxes[u].gap(boxes[v]), centre_gap(cu, boxes[v].center()), v});
    std::sort(all.begin(), all.end());
    all.resize(K);
    ASSERT_EQ(best.size(), K);
    for (size_t k = 0; k < K; ++k) EXPECT_EQ(best[k].v, all[k].v) << "box " << u << ", neighbour " << k;
  }
}

TEST(CutOrderTree, NearestActiveBoxEqualsComparingEveryBox) {
  const std::vector<Box2> boxes = uneven_boxes(2000, 11);
  BoxTree tree(boxes);
  std::vector<char> active(boxes.size(), 1);
  std::mt19937 rng(3);
  std::uniform_int_distribution<uint32_t> pick(0, static_cast<uint32_t>(boxes.size() - 1));
  std::normal_distribution<double> near(0, 50);
  size_t visited_total = 0;
  for (int q = 0; q < 1500; ++q) {
    // switch a few off, and now and then one back on
    for (int k = 0; k < 2; ++k) {
      const uint32_t u = pick(rng);
      tree.set_active(u, false);
      active[u] = 0;
    }
    if (q % 5 == 0) {
      const uint32_t u = pick(rng);
      tree.set_active(u, true);
      active[u] = 1;
    }
    const Vec3 p{near(rng), near(rng)};
    double best = HUGE_VAL;
    uint32_t bu = UINT32_MAX;
    size_t visited = 0;
    tree.search<double>([&](const Box2& b, const Box2&) { return b.gap(p); },
                        [&](uint32_t u) {
                          ++visited;
                          EXPECT_TRUE(active[u]) << "an inactive box was searched";
                          const double d = boxes[u].gap(p);
                          if (d < best || (d == best && u < bu)) best = d, bu = u;
                        },
                        [&](double lower) { return lower > best; });
    double want = HUGE_VAL;
    uint32_t wu = UINT32_MAX;
    for (uint32_t u = 0; u < boxes.size(); ++u)
      if (active[u] && boxes[u].gap(p) < want) want = boxes[u].gap(p), wu = u;
    ASSERT_EQ(bu, wu) << "query " << q;
    visited_total += visited;
  }
  // The search looks at the boxes near p, not at every box.
  EXPECT_LT(visited_total, 1500u * boxes.size() / 4);
}

}  // namespace
