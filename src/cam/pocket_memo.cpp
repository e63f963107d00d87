#include "pocket_memo.hpp"

#include <algorithm>
#include <mutex>
#include <utility>
#include <vector>

namespace bezcam {

namespace {

// A certificate's input with the moves it read held by value.
struct CheckKey {
  PocketCheckInput in;
  std::vector<Move> moves;
};

CheckKey key_of(const PocketCheckInput& in) {
  CheckKey k{in, {}};
  if (in.moves)
    k.moves.assign(in.moves->begin() + static_cast<long>(in.from), in.moves->begin() + static_cast<long>(in.to));
  k.in.moves = nullptr;
  k.in.from = k.in.to = 0;
  return k;
}

bool same(const CheckKey& a, const CheckKey& b) {
  const PocketCheckInput &p = a.in, &q = b.in;
  return p.walls == q.walls && p.wall_bound == q.wall_bound && p.radius == q.radius && p.stock == q.stock &&
         p.tolerance == q.tolerance && p.top_z == q.top_z && p.levels == q.levels && p.start == q.start &&
         p.cell == q.cell && p.max_cells == q.max_cells && p.engagement == q.engagement &&
         p.cleared_before == q.cleared_before && p.load == q.load && a.moves == b.moves;
}

}  // namespace

struct ConversionMemo {
  std::mutex lock;
  std::vector<std::pair<detail::PocketPlanInput, detail::PocketPlan>> plans;
  std::vector<std::pair<CheckKey, PocketCertificate>> checks;
};

std::shared_ptr<ConversionMemo> make_conversion_memo() { return std::make_shared<ConversionMemo>(); }

namespace detail {

PocketPlan memo_plan(ConversionMemo* memo, const PocketPlanInput& in) {
  if (!memo) return plan_pocket(in);
  {
    const std::lock_guard<std::mutex> hold(memo->lock);
    for (const auto& [k, plan] : memo->plans)
      if (k == in) return plan;
  }
  PocketPlan plan = plan_pocket(in);
  const std::lock_guard<std::mutex> hold(memo->lock);
  memo->plans.emplace_back(in, plan);
  return plan;
}

PocketCertificate memo_check(ConversionMemo* memo, const PocketCheckInput& in) {
  if (!memo) return check_pocket(in);
  CheckKey key = key_of(in);
  {
    const std::lock_guard<std::mutex> hold(memo->lock);
    for (const auto& [k, cert] : memo->checks)
      if (same(k, key)) return cert;
  }
  PocketCertificate cert = check_pocket(in);
  const std::lock_guard<std::mutex> hold(memo->lock);
  memo->checks.emplace_back(std::move(key), cert);
  return cert;
}

}  // namespace detail
}  // namespace bezcam
