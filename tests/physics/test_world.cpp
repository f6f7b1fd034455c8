#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/dem_params.h"
#include "src/water.h"
#include "physics/ground.h"
#include "physics/world.h"

namespace sandpic {
namespace {

// How far a big grain rolls in one simulated second on a static slope, with
// the DEM mode's own radii, masses and time step.
double rolled_px(double slope_deg, double rolling_resistance) {
  Scene s;
  s.dem.rolling_resistance = rolling_resistance;
  const Water w = water_model(s);
  const double dt = dem_time_step(s), g = w.gravity_px_s2[0];
  GrainWorld world(200, 200, dem_radii(s), dem_masses(s),
                   GrainMaterial{s.physics.friction, s.physics.restitution, rolling_resistance, 10, 1e9});
  const double t = std::tan(slope_deg * std::numbers::pi / 180), r = dem_radii(s)[0];
  for (double x = 0; x <= 200; x += 1.0 / kGroundPerPx) world.raise_ground(Vec2(x, 10 + t * x), 0);
  const Vec2 start(100, 10 + t * 100 + r / std::cos(slope_deg * std::numbers::pi / 180));
  const int slot = world.add_body(0, start, Vec2(0, 0));
  for (double time = 0; time < 1; time += dt) {
    Vec2 v = world.velocity(slot);
    v.y() -= g * dt;
    world.set_velocity(slot, v);
    world.step(dt);
  }
  return (world.position(slot) - start).norm();
}

// Rolling resistance μ_r·R holds a sphere on slopes up to atan(μ_r). Bullet
// caps the rolling impulse at μ_r itself (as if the normal impulse were at
// most 1), so this holds only with the DEM's scaled masses: with masses in
// g·px³/cm³ the sphere rolled down 10° at μ_r = 0.5.
TEST(GrainWorld, RollingResistanceHoldsASphereUpToItsAngle) {
  // Friction 0.4: above 21.8° the sphere slides whatever its rolling resistance.
  EXPECT_LT(rolled_px(10, 0.5), 0.5);
  EXPECT_LT(rolled_px(19, 0.5), 0.5);
  EXPECT_GT(rolled_px(19, 0.2), 10);  // atan 0.2 = 11.3°
  EXPECT_GT(rolled_px(10, 0.0), 10);  // no resistance: a sphere rolls
}

}  // namespace
}  // namespace sandpic
