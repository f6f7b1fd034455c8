#include <gtest/gtest.h>

#include "physics/dem_params.h"

namespace sandpic {
namespace {

// α follows the friction: the angle a lone grain slides (atan μ) or rolls
// (atan μ_r) at, whichever is lower, plus the margin; a scene's own α wins.
TEST(DemParams, SlopeLimitFollowsFrictionUnlessSet) {
  Scene s;
  s.physics.friction = 0.05;
  s.dem.rolling_resistance = 0.1;
  EXPECT_NEAR(dem_slope_limit_deg(s), 2.862 + 5, 1e-3);
  s.physics.friction = 0.9;  // rolling resistance 0.1 is the lower
  EXPECT_NEAR(dem_slope_limit_deg(s), 5.711 + 5, 1e-3);
  s.dem.slope_margin_deg = 0;
  EXPECT_NEAR(dem_slope_limit_deg(s), 5.711, 1e-3);
  s.dem.slope_limit_deg = 35;
  EXPECT_DOUBLE_EQ(dem_slope_limit_deg(s), 35);
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
