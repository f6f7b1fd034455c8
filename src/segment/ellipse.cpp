#include "src/segment/ellipse.h"

#include <cmath>
#include <numbers>

namespace sandpic {

Ellipse Ellipse::from(const EllipseSpec& e) {
  return Ellipse{Vec2(e.cx, e.cy), e.a, e.b, e.angle_deg * std::numbers::pi / 180};
}

double Ellipse::level(const Vec2& p) const {
  Vec2 d = p - c;
  double cs = std::cos(theta), sn = std::sin(theta);
  double X = cs * d.x() + sn * d.y(), Y = -sn * d.x() + cs * d.y();
  return X * X / (a * a) + Y * Y / (b * b);
}

// With u = x - cx and v = y - cy fixed, the level is A u² + B u + C' and the
// span is where A u² + B u + C' - 1 <= 0.
bool Ellipse::row_span(double y, double& x0, double& x1) const {
  double cs = std::cos(theta), sn = std::sin(theta), v = y - c.y();
  double ia = 1 / (a * a), ib = 1 / (b * b);
  double A = cs * cs * ia + sn * sn * ib;
  double B = 2 * v * sn * cs * (ia - ib);
  double C = v * v * (sn * sn * ia + cs * cs * ib) - 1;
  double disc = B * B - 4 * A * C;
  if (disc < 0) return false;
  double r = std::sqrt(disc);
  x0 = c.x() + (-B - r) / (2 * A);
  x1 = c.x() + (-B + r) / (2 * A);
  return true;
}

double Ellipse::half_height() const {
  double cs = std::cos(theta), sn = std::sin(theta);
  return std::sqrt(a * a * sn * sn + b * b * cs * cs);
}

Vec2 Ellipse::lowest() const {
  // On p(t) = c + a cos t (cos θ, sin θ) + b sin t (-sin θ, cos θ), y is
  // largest where tan t = b cos θ / (a sin θ).
  double cs = std::cos(theta), sn = std::sin(theta);
  double t = std::atan2(b * cs, a * sn);
  return c + a * std::cos(t) * Vec2(cs, sn) + b * std::sin(t) * Vec2(-sn, cs);
}

double Ellipse::distance_outside(const Vec2& p) const {
  double q = level(p);
  if (q <= 1) return 0;
  return (p - c).norm() * (1 - 1 / std::sqrt(q));
}

}  // namespace sandpic
