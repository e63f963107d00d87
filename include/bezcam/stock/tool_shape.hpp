#pragma once
/// The cutting shape of a tool, for sweeping it through the stock.
///
/// A tool is a solid of revolution about a vertical axis. Its programmed
/// position is its tip (the lowest point on the axis); its cutting surface
/// rises from the tip to the height h(R) at its radius R, and above that the
/// tool is a cylinder of radius R. The height profile h(rho), 0 <= rho <= R,
/// is convex and nondecreasing for every shape here, which is what makes the
/// machined floors exact (docs/verify.md).
///
///   flat   h = 0
///   ball   h = R - sqrt(R^2 - rho^2)
///   bull   h = 0 up to R - rc, then the quarter torus of radius rc
///   vee    h = rho / tan(angle / 2)          (included angle, sharp tip)
///   drill  h = rho / tan(point_angle / 2)    (the point of a twist drill)
///
/// Lengths are in the caller's unit (the verifier works in millimetres),
/// angles in degrees.
#include <string>

namespace bezcam {

enum class ToolShapeKind { flat, ball, bull, vee, drill };

/// The name of a shape as the tools table spells it: "flat", "ball", ...
const char* to_string(ToolShapeKind k);

class ToolShape {
 public:
  /// Each factory refuses, with InputError `tool.shape` naming the setting
  /// (`diameter`, `corner_radius`, `angle`, `point_angle`), a diameter that
  /// is not a finite number > 0, a corner radius outside 0 < rc <= radius,
  /// and an angle outside 0 < angle < 180 degrees.
  static ToolShape flat(double diameter);
  static ToolShape ball(double diameter);
  static ToolShape bull(double diameter, double corner_radius);
  static ToolShape vee(double diameter, double angle_deg);
  static ToolShape drill(double diameter, double point_angle_deg);

  ToolShapeKind kind() const { return kind_; }
  double diameter() const { return 2 * radius_; }
  double radius() const { return radius_; }
  /// bull: the corner radius; ball: the radius; otherwise 0.
  double corner_radius() const { return corner_; }
  /// vee: the included angle; drill: the point angle (degrees); otherwise 0.
  double angle_deg() const { return angle_deg_; }
  /// vee and drill: the slope of the cone, 1 / tan(angle / 2); otherwise 0.
  double cone_slope() const { return slope_; }

  /// Height of the cutting surface above the tip at radial distance rho
  /// (clamped to [0, R]).
  double height(double rho) const;
  /// h(R): the height where the cutting surface meets the cylinder.
  double cutting_height() const { return height(radius_); }
  /// "ball D6", "bull D10 r1", "vee D6 60deg": for messages and reports.
  std::string describe() const;

 private:
  ToolShape(ToolShapeKind k, double r, double corner, double angle_deg);
  ToolShapeKind kind_ = ToolShapeKind::flat;
  double radius_ = 0, corner_ = 0, angle_deg_ = 0, slope_ = 0;
};

}  // namespace bezcam
