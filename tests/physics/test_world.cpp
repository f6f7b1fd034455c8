#include <gtest/gtest.h>

#include <algorithm>
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

// The position correction pushes apart only what overlaps past the resting
// overlap, and every other touching contact resists the push past its own
// resting overlap: a column of three small grains, no gravity, the top pair
// overlapping by 5.5% of a diameter and the bottom pair by 0.5%. The push
// apart of the top pair used to drive the middle grain into the bottom one
// unresisted (its overlap 0.5% -> 1.2%, pushed again at the next step: a
// heap's load pumped down through it).
TEST(GrainWorld, APushStopsAtTheNeighboursRestingOverlap) {
  Scene s;
  const auto radius = dem_radii(s);
  const int cls = int(std::min_element(radius.begin(), radius.end()) - radius.begin());
  const double d = 2 * radius[size_t(cls)], rest = kRestOverlap * d;
  GrainWorld world(100, 100, radius, dem_masses(s), GrainMaterial{s.physics.friction, 0, 0.3, 10, 1e9});
  const int a = world.add_body(cls, Vec2(50, 50), Vec2(0, 0));
  const int b = world.add_body(cls, Vec2(50, 50 + d - 0.005 * d), Vec2(0, 0));
  const int c = world.add_body(cls, Vec2(50, 50 + 2 * d - 0.055 * d), Vec2(0, 0));
  double ab = 0;  // the bottom pair's deepest overlap
  for (int i = 0; i < 40; ++i) {  // each step pushes out m_erp2 (0.2) of the excess
    world.step(dem_time_step(s));
    ab = std::max(ab, d - (world.position(b) - world.position(a)).norm());
  }
  const double bc = d - (world.position(c) - world.position(b)).norm();
  EXPECT_LE(ab, rest * 1.001) << "bottom pair's deepest overlap / d: " << ab / d;
  EXPECT_LE(bc, rest * 1.05) << "top pair overlap / d: " << bc / d;
  EXPECT_LT(bc, 0.02 * d) << "the top pair is pushed out";
}

}  // namespace
}  // namespace sandpic
