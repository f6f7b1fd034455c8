#pragma once
// Ellipse geometry for segmentation (paper §5): rotated ellipses in window
// pixels, x right and y down.
#include "src/grains.h"

namespace sandpic {

struct Ellipse {
  Vec2 c{0, 0};
  double a = 1, b = 1;  // semi-axes along the rotated x and y
  double theta = 0;     // rotation, radians

  static Ellipse from(const EllipseSpec& e);
  // (X/a)² + (Y/b)² in the ellipse's own frame: <= 1 inside.
  double level(const Vec2& p) const;
  // The span [x0, x1] of the horizontal line at y inside the ellipse.
  bool row_span(double y, double& x0, double& x1) const;
  double half_height() const;  // vertical extent from the centre
  Vec2 lowest() const;         // the point of largest y
  // Distance from p (outside) to the boundary along the ray from the centre.
  double distance_outside(const Vec2& p) const;
};

}  // namespace sandpic
