// job_json family: `bspline` segments and `interpolate` entities.
#include "job_json_detail.hpp"

namespace bezcam::detail {

void parse_bspline_segment(const JsonCtx& ctx, const json&, const std::string& path, int*, std::vector<Bezier>&,
                           CurveSegment&) {
  ctx.fail(path + ".type", "job.unsupported", "B-spline curves are not supported by this build yet");
}

void parse_interpolate_entity(const JsonCtx& ctx, const json&, const std::string& path, Entity&) {
  ctx.fail(path + ".type", "job.unsupported", "interpolating splines are not supported by this build yet");
}

}  // namespace bezcam::detail
