#include <gtest/gtest.h>

#include <cmath>

#include "src/release.h"

namespace sandpic {
namespace {

TEST(Release, Equation2CarriesTheGrainToTheOutlet) {
  Scene s;
  ReleaseModel m = release_model(s);
  EXPECT_NEAR(m.gravity_px_s2, 9810 / 0.18, 1e-6);
  EXPECT_NEAR(m.outlet_width_px, 15 / 0.18, 1e-9);
  GrainSet g = empty_region(s);
  Unit u;
  u.ellipse = Ellipse{Vec2(500, 200), 300, 100, 0};  // outlet (500, 300)
  Outlet o = outlet(m, u);
  const int32_t id = 100 * 1000 + 380;  // grain at (380.5, 100.5)
  ReleasePath p = release(m, o, g, id);
  double dx = 500 - 380.5, dy = 300 - 100.5;
  EXPECT_NEAR(p.vx, dx * std::sqrt(m.gravity_px_s2 / (2 * dy)), 1e-9);
  // Eq. 1: after t the grain is at the outlet.
  EXPECT_NEAR(p.start.x() + p.vx * p.t, 500, 1e-9);
  EXPECT_NEAR(p.start.y() + m.gravity_px_s2 * p.t * p.t / 2, 300, 1e-9);
  EXPECT_LE(std::abs(p.exit_x - 500), o.width / 2);
}

TEST(Release, DropIsAtLeastOneDiameterAndOutletNoWiderThanTheUnit) {
  Scene s;
  ReleaseModel m = release_model(s);
  GrainSet g = empty_region(s);
  Unit u;
  u.ellipse = Ellipse{Vec2(500, 100), 20, 10, 0};
  Outlet o = outlet(m, u);
  EXPECT_NEAR(o.width, 40, 1e-9);
  ReleasePath p = release(m, o, g, 110 * 1000 + 480);  // below the outlet
  EXPECT_TRUE(std::isfinite(p.vx));
  EXPECT_NEAR(p.t, std::sqrt(2 * m.min_drop_px[g.cls[0]] / m.gravity_px_s2), 1e-12);
  double lo = 1e9, hi = -1e9;
  for (int32_t id = 0; id < 5000; ++id) {
    double x = exit_x(m, o, id);
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  EXPECT_GE(lo, 480);
  EXPECT_LE(hi, 520);
  EXPECT_LT(lo, 481);  // the jitter spans the outlet
  EXPECT_GT(hi, 519);
}

// A unit reaching past a side wall drops its grains from inside the window,
// across the outlet's whole width, not in one file down the wall.
TEST(Release, AnOutletPastAWallIsMovedInside) {
  Scene s;
  ReleaseModel m = release_model(s);
  for (double cx : {-30.0, 1010.0}) {
    Unit u;
    u.ellipse = Ellipse{Vec2(cx, 100), 150, 40, 0};
    Outlet o = outlet(m, u);
    EXPECT_NEAR(o.width, 15 / 0.18, 1e-9);
    for (int32_t id = 0; id < 1000; ++id) {
      double x = exit_x(m, o, id);
      EXPECT_GE(x, 0);
      EXPECT_LE(x, s.window.width);
    }
    EXPECT_NEAR(std::abs(o.centre.x() - s.window.width / 2.0), s.window.width / 2.0 - o.width / 2, 1e-9);
  }
}

}  // namespace
}  // namespace sandpic
