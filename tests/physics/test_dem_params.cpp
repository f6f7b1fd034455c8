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

}  // namespace
}  // namespace sandpic
