#include "plan_json.hpp"

#include <cmath>

namespace bezcam::detail {

double round_to(double v, double q) {
  const double r = std::round(v / q) / std::round(1 / q);
  return r == 0 ? 0.0 : r;
}

void put_plan_figures(nlohmann::ordered_json& j, const ProgramReport::Planned& q) {
  j["cycle_time_s"] = round_to(q.cycle_time_s, 1e-6);
  j["cutting_time_s"] = round_to(q.cutting_time_s, 1e-6);
  j["rapid_time_s"] = round_to(q.rapid_time_s, 1e-6);
  j["pause_time_s"] = round_to(q.pause_time_s, 1e-6);
  j["programmed_feed_time_s"] = round_to(q.programmed_feed_time_s, 1e-6);
  j["mean_feed_ratio"] = round_to(q.mean_feed_ratio, 1e-6);
  j["starved_blocks"] = q.starved_blocks;
  j["clamped_blocks"] = q.clamped_blocks;
}

}  // namespace bezcam::detail
