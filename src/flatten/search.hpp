#pragma once
// One-dimensional searches shared by the flattener, the arc fitter, the
// degree reducer and the deviation measures (private to src/flatten/).
// Each keeps the exact order of evaluations of the loops it replaced, so
// that results are bit-identical.
#include <algorithm>
#include <utility>
#include <vector>

namespace bezcam::flatten_detail {

/// When a branch-and-bound search for a supremum stops.
struct SupStop {
  /// >= 0: stop as soon as the answer against it is certain. A result
  /// <= budget is then a proven upper bound; a result above it a proven
  /// lower bound of the same supremum. < 0: no early exit.
  double budget = -1;
  /// Stop once the upper bound is within max(relative * ub, absolute) of
  /// the lower bound (same unit as the bounds).
  double relative = 1e-3, absolute = 0;
  /// Bound on the nodes split; the best upper bound is returned then.
  int max_splits = 4000;
};

/// The supremum over `root` of a function, by best-first branch and bound:
/// `bound(node)` is an upper bound over a node; `split(node, left, right)`
/// fills the two halves and returns the function's value at a point of the
/// node (a proven lower bound); `lb` is a lower bound known beforehand.
/// Returns an upper bound (or, with a budget, the certain side: see SupStop).
template <class Node, class Bound, class Split>
double sup_branch_and_bound(Node root, double lb, const SupStop& stop, Bound&& bound, Split&& split) {
  struct Entry {
    double ub;
    Node node;
    bool operator<(const Entry& o) const { return ub < o.ub; }
  };
  // A binary max-heap on ub, as std::priority_queue keeps it, but the node
  // taken is moved out rather than copied (a Bézier node owns its points).
  std::vector<Entry> heap;
  const auto push = [&heap](double ub, Node&& n) {
    heap.push_back({ub, std::move(n)});
    std::push_heap(heap.begin(), heap.end());
  };
  const double root_ub = bound(root);
  push(root_ub, std::move(root));
  for (int iter = 0; iter < stop.max_splits; ++iter) {
    const Entry& top = heap.front();
    if (stop.budget >= 0 && top.ub <= stop.budget) return top.ub;  // certainly within
    if (stop.budget >= 0 && lb > stop.budget) return lb;           // certainly over
    if (top.ub - lb <= std::max(stop.relative * top.ub, stop.absolute)) return top.ub;
    std::pop_heap(heap.begin(), heap.end());
    const Node node = std::move(heap.back().node);
    heap.pop_back();
    Node l, r;
    lb = std::max(lb, split(node, l, r));
    const double ul = bound(l), ur = bound(r);
    push(ul, std::move(l));
    push(ur, std::move(r));
  }
  return heap.front().ub;
}

/// Where a golden-section search ended: the bracket [a, b] and the values
/// at its two interior points.
struct GoldenBracket {
  double a, b, f1, f2;
};

/// Golden-section search for a minimum (or, with `maximize`, a maximum) of
/// `f` on [a, b]: at most `iters` steps, fewer once the bracket is no wider
/// than `min_width` (< 0: no width check). Ties keep the right part when
/// minimising and the left when maximising.
template <class F>
GoldenBracket golden_section(double a, double b, F&& f, int iters, double min_width, bool maximize = false) {
  const double g = 0.3819660112501051;  // 2 - golden ratio
  double x1 = a + g * (b - a), x2 = b - g * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < iters && (min_width < 0 || b - a > min_width); ++i) {
    if (maximize ? !(f1 < f2) : f1 < f2) {  // keep [a, x2]
      b = x2, x2 = x1, f2 = f1, x1 = a + g * (b - a), f1 = f(x1);
    } else {  // keep [x1, b]
      a = x1, x1 = x2, f1 = f2, x2 = b - g * (b - a), f2 = f(x2);
    }
  }
  return {a, b, f1, f2};
}

}  // namespace bezcam::flatten_detail
