#include "cut_order_tree.hpp"

#include <algorithm>

namespace bezcam::cut_order_detail {
namespace {

constexpr uint32_t kLeaf = 8;  // contours per leaf at most

}  // namespace

BoxTree::BoxTree(std::span<const Box2> boxes) : leaf_(boxes.size(), 0), active_(boxes.size(), 1) {
  if (boxes.empty()) return;
  std::vector<Vec3> centres(boxes.size());
  order_.resize(boxes.size());
  for (uint32_t u = 0; u < boxes.size(); ++u) {
    centres[u] = boxes[u].center();
    order_[u] = u;
  }
  nodes_.reserve(2 * boxes.size() / kLeaf + 2);
  nodes_.push_back({});
  nodes_[0].hi = static_cast<uint32_t>(boxes.size());
  build(0, boxes, centres);
}

void BoxTree::build(uint32_t node, std::span<const Box2> boxes, const std::vector<Vec3>& centres) {
  const uint32_t lo = nodes_[node].lo, hi = nodes_[node].hi;
  Box2 b, c;
  for (uint32_t i = lo; i < hi; ++i) {
    const Box2& x = boxes[order_[i]];
    b.add({x.lx, x.ly});
    b.add({x.hx, x.hy});
    c.add(centres[order_[i]]);
  }
  nodes_[node].boxes = b;
  nodes_[node].centres = c;
  nodes_[node].active = hi - lo;
  if (hi - lo <= kLeaf) {
    for (uint32_t i = lo; i < hi; ++i) leaf_[order_[i]] = node;
    return;
  }
  const bool by_x = c.hx - c.lx >= c.hy - c.ly;
  const uint32_t mid = lo + (hi - lo) / 2;
  std::nth_element(order_.begin() + lo, order_.begin() + mid, order_.begin() + hi, [&](uint32_t p, uint32_t q) {
    const double a = by_x ? centres[p].x : centres[p].y, d = by_x ? centres[q].x : centres[q].y;
    return a != d ? a < d : p < q;
  });
  const uint32_t left = static_cast<uint32_t>(nodes_.size());
  nodes_[node].left = left;
  nodes_.push_back({});
  nodes_.push_back({});
  nodes_[left].lo = lo, nodes_[left].hi = mid, nodes_[left].parent = node;
  nodes_[left + 1].lo = mid, nodes_[left + 1].hi = hi, nodes_[left + 1].parent = node;
  build(left, boxes, centres);
  build(left + 1, boxes, centres);
}

void BoxTree::set_active(uint32_t u, bool active) {
  if ((active_[u] != 0) == active) return;
  active_[u] = active ? 1 : 0;
  for (uint32_t n = leaf_[u];; n = nodes_[n].parent) {
    nodes_[n].active = active ? nodes_[n].active + 1 : nodes_[n].active - 1;
    if (n == 0) break;
  }
}

}  // namespace bezcam::cut_order_detail
