#pragma once
// Internal to the post layer: the per-mode emitters of cutting moves. Each
// starts with the tool at the entity's first point at cutting depth and
// appends the moves that cut the entity, filling the report's blocks,
// measured deviation and bound.
#include "bezcam/post/toolpath.hpp"

namespace bezcam::detail {

struct CutContext {
  const Job& job;
  const Entity& entity;
  const MachineProfile& machine;
  const CutParams& params;
  int decimals;      // coordinate decimals of the program's units
  double tolerance;  // job units
  bool measure;
  Program& program;
};

/// The point the tool cuts at for a curve point (2D curves at cut_z).
Vec3 cut_point(const CutContext& c, const Vec3& p);

/// G01 polyline within the tolerance after rounding (flatten_curve.hpp).
void emit_lines(CutContext& c, EntityReport& r);

}  // namespace bezcam::detail
