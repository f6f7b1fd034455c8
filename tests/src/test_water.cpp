#include <gtest/gtest.h>

#include <cmath>

#include "src/water.h"

namespace sandpic {
namespace {

TEST(Water, SlowSmallSpheresFollowStokes) {
  // d = 10 µm quartz in water: Re ≪ 1, so the Stokes speed holds.
  double d = 1e-5, rho = 2650, g = 9.81;
  double stokes = (rho - 1000) * g * d * d / (18 * 1e-3);
  EXPECT_NEAR(settling_speed(d, rho, 1000, 1e-3, g), stokes, stokes * 0.01);
}

TEST(Water, BuoyancyAndSettlingPerClass) {
  Scene s;
  Water w = water_model(s);
  const double px_per_m = 1000 / 0.18;
  EXPECT_NEAR(w.gravity_px_s2[0], 9.81 * (1 - 1 / 3.2) * px_per_m, 1e-6);
  EXPECT_NEAR(w.gravity_px_s2[2], 9.81 * (1 - 1 / 2.7) * px_per_m, 1e-6);
  // Heavy, big S1 settles faster than light, small S3: the classes sort.
  EXPECT_GT(w.terminal_px_s[0], 2 * w.terminal_px_s[2]);
  // A 0.2 mm grain of 3.2 g/cm³ settles at a few cm/s (Re ≈ 6).
  EXPECT_GT(w.terminal_px_s[0] / px_per_m, 0.02);
  EXPECT_LT(w.terminal_px_s[0] / px_per_m, 0.05);
  for (int k = 0; k < kClasses; ++k) EXPECT_NEAR(w.drag_per_s[k] * w.terminal_px_s[k], w.gravity_px_s2[k], 1e-6);
  s.dem.water = false;
  w = water_model(s);
  EXPECT_EQ(w.drag_per_s[0], 0);
  EXPECT_NEAR(w.gravity_px_s2[0], 9.81 * px_per_m, 1e-6);
}

}  // namespace
}  // namespace sandpic
