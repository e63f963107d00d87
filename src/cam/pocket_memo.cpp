#include "pocket_memo.hpp"

#include <mutex>
#include <utility>
#include <vector>

namespace bezcam {

namespace {

// A certificate's input with the moves it reads held by value, not
// where they lie in their program.
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

// Every field of the inputs (the keys' `moves` are null), then the moves.
bool same(const CheckKey& a, const CheckKey& b) { return a.in == b.in && a.moves == b.moves; }

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
