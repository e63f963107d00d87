#include "bezcam/stock/tool_shape.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bezcam/error.hpp"

namespace bezcam {

namespace {

void check_diameter(double d) {
  if (!std::isfinite(d) || d <= 0)
    throw InputError(errc::tool_shape, Place::at_setting("diameter"),
                     "a tool's diameter must be a finite number > 0, not " + fmt_num(d));
}

void check_angle(double a, const char* setting) {
  if (!std::isfinite(a) || a <= 0 || a >= 180)
    throw InputError(
        errc::tool_shape, Place::at_setting(setting),
        std::string("a tool's ") + setting + " must lie strictly between 0 and 180 degrees, not " + fmt_num(a));
}

}  // namespace

const char* to_string(ToolShapeKind k) {
  switch (k) {
    case ToolShapeKind::flat: return "flat";
    case ToolShapeKind::ball: return "ball";
    case ToolShapeKind::bull: return "bull";
    case ToolShapeKind::vee: return "vee";
    case ToolShapeKind::drill: return "drill";
  }
  return "?";
}

ToolShape::ToolShape(ToolShapeKind k, double r, double corner, double angle_deg)
    : kind_(k), radius_(r), corner_(corner), angle_deg_(angle_deg) {
  if (k == ToolShapeKind::vee || k == ToolShapeKind::drill) slope_ = 1 / std::tan(angle_deg * std::numbers::pi / 360);
}

ToolShape ToolShape::flat(double diameter) {
  check_diameter(diameter);
  return ToolShape(ToolShapeKind::flat, diameter / 2, 0, 0);
}

ToolShape ToolShape::ball(double diameter) {
  check_diameter(diameter);
  return ToolShape(ToolShapeKind::ball, diameter / 2, diameter / 2, 0);
}

ToolShape ToolShape::bull(double diameter, double corner_radius) {
  check_diameter(diameter);
  if (!std::isfinite(corner_radius) || corner_radius <= 0 || corner_radius > diameter / 2)
    throw InputError(errc::tool_shape, Place::at_setting("corner_radius"),
                     "a bull tool's corner radius must be > 0 and at most its radius " + fmt_num(diameter / 2) +
                         ", not " + fmt_num(corner_radius));
  return ToolShape(ToolShapeKind::bull, diameter / 2, corner_radius, 0);
}

ToolShape ToolShape::vee(double diameter, double angle_deg) {
  check_diameter(diameter);
  check_angle(angle_deg, "angle");
  return ToolShape(ToolShapeKind::vee, diameter / 2, 0, angle_deg);
}

ToolShape ToolShape::drill(double diameter, double point_angle_deg) {
  check_diameter(diameter);
  check_angle(point_angle_deg, "point_angle");
  return ToolShape(ToolShapeKind::drill, diameter / 2, 0, point_angle_deg);
}

double ToolShape::height(double rho) const {
  rho = std::clamp(rho, 0.0, radius_);
  switch (kind_) {
    case ToolShapeKind::flat: return 0;
    case ToolShapeKind::ball: return radius_ - std::sqrt((radius_ - rho) * (radius_ + rho));
    case ToolShapeKind::bull: {
      const double x = rho - (radius_ - corner_);
      if (x <= 0) return 0;
      return corner_ - std::sqrt((corner_ - x) * (corner_ + x));
    }
    case ToolShapeKind::vee:
    case ToolShapeKind::drill: return rho * slope_;
  }
  return 0;
}

std::string ToolShape::describe() const {
  std::string s = std::string(to_string(kind_)) + " D" + fmt_num(diameter());
  if (kind_ == ToolShapeKind::bull) s += " r" + fmt_num(corner_);
  if (kind_ == ToolShapeKind::vee || kind_ == ToolShapeKind::drill) s += " " + fmt_num(angle_deg_) + "deg";
  return s;
}

}  // namespace bezcam
