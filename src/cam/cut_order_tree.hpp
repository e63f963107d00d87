#pragma once
// A tree of the contours' boxes for the cut-order planner's nearest
// searches (cut_order.cpp): the boxes split at the median of their centres,
// each node holding the union of its boxes and the box of its centres, and
// how many of its contours are still active. A search goes down the nearer
// child first and skips a node whose lower bound cannot beat the best found,
// so its result equals that of comparing every contour, at a cost that
// follows how many contours are near, however unevenly they are spread.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "cut_order_nesting.hpp"

namespace bezcam::cut_order_detail {

class BoxTree {
 public:
  /// The tree of these boxes, every one active.
  explicit BoxTree(std::span<const Box2> boxes);

  /// Marks contour u inactive (searches skip it) or active again.
  void set_active(uint32_t u, bool active);

  /// Depth-first search over the active contours. key(node_boxes,
  /// node_centres) is a lower bound of item(u)'s figure for every contour
  /// under the node; a node is skipped when beaten(key) says the best found
  /// is already better than that bound; item(u) is called for each active
  /// contour not skipped.
  template <class Key, class KeyFn, class ItemFn, class BeatenFn>
  void search(KeyFn&& key, ItemFn&& item, BeatenFn&& beaten) const {
    if (nodes_.empty() || nodes_[0].active == 0) return;
    struct Open {
      uint32_t node;
      Key k;
    };
    std::vector<Open> stack;
    stack.reserve(64);
    stack.push_back({0, key(nodes_[0].boxes, nodes_[0].centres)});
    while (!stack.empty()) {
      const Open o = stack.back();
      stack.pop_back();
      if (beaten(o.k)) continue;
      const Node& n = nodes_[o.node];
      if (n.left == 0) {
        for (uint32_t i = n.lo; i < n.hi; ++i)
          if (active_[order_[i]]) item(order_[i]);
        continue;
      }
      const Node& a = nodes_[n.left];
      const Node& b = nodes_[n.left + 1];
      const bool use_a = a.active != 0, use_b = b.active != 0;
      if (use_a && use_b) {
        Key ka = key(a.boxes, a.centres), kb = key(b.boxes, b.centres);
        if (kb < ka) {  // the nearer child on top
          stack.push_back({n.left, ka});
          stack.push_back({n.left + 1, kb});
        } else {
          stack.push_back({n.left + 1, kb});
          stack.push_back({n.left, ka});
        }
      } else if (use_a) {
        stack.push_back({n.left, key(a.boxes, a.centres)});
      } else if (use_b) {
        stack.push_back({n.left + 1, key(b.boxes, b.centres)});
      }
    }
  }

 private:
  struct Node {
    Box2 boxes, centres;
    uint32_t lo = 0, hi = 0;  // the contours order_[lo, hi)
    uint32_t left = 0;        // the children are left and left + 1; 0 for a leaf
    uint32_t parent = 0;
    uint32_t active = 0;
  };
  void build(uint32_t node, std::span<const Box2> boxes, const std::vector<Vec3>& centres);

  std::vector<Node> nodes_;
  std::vector<uint32_t> order_, leaf_;  // leaf_[u]: the leaf holding u
  std::vector<char> active_;
};

}  // namespace bezcam::cut_order_detail
