#include <cmath>

#include <gtest/gtest.h>

#include "physics/dem_params.h"

namespace sandpic {
namespace {

// α is the angle the grains' piles stand at when every grain is a body (a
// table measured by friction and rolling resistance) plus the margin; a
// scene's own α wins.
TEST(DemParams, SlopeLimitIsThePilesAngleUnlessSet) {
  Scene s;
  s.physics.friction = 0.4;
  s.dem.rolling_resistance = 0.1;
  const double heap = all_dynamic_heap_angle_deg(0.4, 0.1);
  EXPECT_DOUBLE_EQ(dem_slope_limit_deg(s), heap + s.dem.slope_margin_deg);
  s.dem.slope_margin_deg = 3;
  EXPECT_DOUBLE_EQ(dem_slope_limit_deg(s), heap + 3);
  s.dem.slope_limit_deg = 35;
  EXPECT_DOUBLE_EQ(dem_slope_limit_deg(s), 35);
}

// The table's angle grows with sliding friction and with rolling
// resistance, continuously, is 0 without friction, and holds its last
// value beyond the table.
TEST(DemParams, ThePilesAngleGrowsWithFrictionAndRollingResistance) {
  EXPECT_DOUBLE_EQ(all_dynamic_heap_angle_deg(0, 0.3), 0);
  double last_mu = -1;
  for (double mu = 0; mu <= 1.2; mu += 0.01) {
    double last_mr = -1;
    for (double mr = 0; mr <= 0.5; mr += 0.01) {
      const double a = all_dynamic_heap_angle_deg(mu, mr);
      EXPECT_GE(a, last_mr - 1e-9) << "friction " << mu << ", rolling resistance " << mr;
      EXPECT_LT(std::abs(a - all_dynamic_heap_angle_deg(mu, mr + 0.001)), 0.2) << mu << ", " << mr;
      EXPECT_LT(std::abs(a - all_dynamic_heap_angle_deg(mu + 0.001, mr)), 0.2) << mu << ", " << mr;
      last_mr = a;
    }
    const double at_default = all_dynamic_heap_angle_deg(mu, 0.1);
    EXPECT_GE(at_default, last_mu - 1e-9) << "friction " << mu;
    last_mu = at_default;
  }
  EXPECT_DOUBLE_EQ(all_dynamic_heap_angle_deg(5, 5), all_dynamic_heap_angle_deg(kHeapFriction.back(), kHeapRolling.back()));
  EXPECT_GT(all_dynamic_heap_angle_deg(kHeapFriction.back(), kHeapRolling.back()), all_dynamic_heap_angle_deg(0.1, 0));
}

// One step moves the fastest grain dem.step_diameters small diameters.
TEST(DemParams, TimeStepFromTheFastestGrain) {
  Scene s;
  const Water w = water_model(s);
  double fastest = 0, smallest = 1e9;
  for (int k = 0; k < kClasses; ++k) {
    fastest = std::max(fastest, w.terminal_px_s[k]);
    smallest = std::min(smallest, 2 * dem_radii(s)[k]);
  }
  EXPECT_NEAR(dem_time_step(s) * fastest, s.dem.step_diameters * smallest, 1e-12);
  s.dem.step_diameters *= 2;
  EXPECT_NEAR(dem_time_step(s) * fastest, s.dem.step_diameters * smallest, 1e-12);
}

// Classes without grains do not set the step: heavy S3 and S4 that are not
// in the run would shorten it for the light S1 and S2 that are.
TEST(DemParams, TimeStepFromThePresentClassesOnly) {
  Scene s;
  s.grains.density_g_cm3 = {1.05, 1.05, 100, 100};
  const Water w = water_model(s);
  const ClassSet light{true, true, false, false};
  const double fastest = std::max(w.terminal_px_s[0], w.terminal_px_s[1]);
  const double smallest = std::min(2 * dem_radii(s)[0], 2 * dem_radii(s)[1]);
  EXPECT_NEAR(dem_time_step(s, light) * fastest, s.dem.step_diameters * smallest, 1e-12);
  EXPECT_GT(dem_time_step(s, light), 3 * dem_time_step(s));
  EXPECT_DOUBLE_EQ(dem_time_step(s, kAllClasses), dem_time_step(s));
  EXPECT_DOUBLE_EQ(dem_time_step(s, ClassSet{}), dem_time_step(s));  // no grains: every class
  EXPECT_EQ(dem_masses(s, ClassSet{}), dem_masses(s));
  // The masses' unit follows: the heaviest present grain's weight a step is 1e-5.
  const auto m = dem_masses(s, light);
  const double dt = dem_time_step(s, light);
  EXPECT_NEAR(std::max(m[0] * w.gravity_px_s2[0], m[1] * w.gravity_px_s2[1]) * dt, 1e-5, 1e-12);
}

}  // namespace
}  // namespace sandpic
