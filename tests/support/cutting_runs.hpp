#pragma once
// The cutting runs of a program read back: a run starts with the plunge (a
// feed move after a rapid) and holds the feed moves up to the next rapid.
#include <vector>

#include "bezcam/machine/motion.hpp"

namespace bezcam::test {

inline std::vector<std::vector<MotionBlock>> cutting_runs(const std::vector<MotionBlock>& blocks) {
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

}  // namespace bezcam::test
