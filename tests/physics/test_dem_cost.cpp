// The DEM's cost estimate follows what makes a run slow: the stress
// catalogue's quick scene took 27x as long with grains 100x and 1.05x as
// dense as the water, and 5.9x as long at restitution 1 as at 0.
#include <gtest/gtest.h>

#include "physics/dem_cost.h"

namespace sandpic {
namespace {

TEST(DemCost, DenseAndLightGrainsAndBouncesCostMore) {
  Scene s;
  s.mode = Mode::Dem;
  const double base = dem_cost(s).seconds;
  Scene dense = s;
  dense.grains.density_g_cm3 = {1.05, 1.05, 100, 100};
  const double density = dem_cost(dense).seconds / base;
  EXPECT_GT(density, 27 / 3.0);
  EXPECT_LT(density, 27 * 3.0);
  Scene bouncy = s, dead = s;
  bouncy.physics.restitution = 1;
  dead.physics.restitution = 0;
  const double bounce = dem_cost(bouncy).seconds / dem_cost(dead).seconds;
  EXPECT_GT(bounce, 5.9 / 3);
  EXPECT_LT(bounce, 5.9 * 3);
  Scene fine = s;
  fine.dem.step_diameters = s.dem.step_diameters / 2;
  EXPECT_NEAR(dem_cost(fine).seconds / base, 2, 1e-9);  // twice the steps
  // A band of static bodies is solved with the flow (1.4-1.5x the time of
  // immovable static grains at --scale 0.2); all-dynamic has no band.
  Scene bodies = s, immovable = s;
  bodies.dem.static_bodies = true;
  immovable.dem.static_bodies = false;
  EXPECT_GT(dem_cost(bodies).seconds, 1.3 * dem_cost(immovable).seconds);
  Scene all = bodies, all_immovable = immovable;
  all.dem.layers = all_immovable.dem.layers = Layers::AllDynamic;
  EXPECT_EQ(dem_cost(all).seconds, dem_cost(all_immovable).seconds);
}

}  // namespace
}  // namespace sandpic
