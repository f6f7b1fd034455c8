#include <gtest/gtest.h>

#include <cstdio>

#include "lattice/lattice_simulator.h"
#include "src/pipeline.h"
#include "tests/test_util.h"

namespace sandpic {
namespace {

double pile_angle(const Scene& s) {
  SimResult r = test::simulate_scene(s, *make_lattice_simulator());
  return test::flank_angle_deg(test::column_heights(r.class_map));
}

// paper §7, Fig. 9: piles grow steeper with friction.
TEST(LatticeSimulator, PileSlopeGrowsWithFriction) {
  double last = 0;
  for (double mu : {0.1, 0.4, 0.9}) {
    Scene s = test::one_ellipse_scene();
    s.physics.friction = mu;
    double angle = pile_angle(s);
    std::printf("friction %.1f: rule %.1f°, pile %.1f°\n", mu, repose_angle_deg(s, 0), angle);
    EXPECT_GT(angle, last + 5) << "friction " << mu;
    EXPECT_NEAR(angle, repose_angle_deg(s, 0), 6) << "friction " << mu;
    last = angle;
  }
}

// paper §7: "bigger sand grains may result in steeper sand piles".
TEST(LatticeSimulator, BigGrainsPileSteeper) {
  Scene s = test::one_ellipse_scene();
  s.init.dominant_share = 1;
  s.grains.proportions = {1, 0, 0, 0};
  double big = pile_angle(s);
  s.grains.proportions = {0, 0, 1, 0};
  double small = pile_angle(s);
  std::printf("S1 only: %.1f°, S3 only: %.1f°\n", big, small);
  EXPECT_GT(big, small + 2);
}

TEST(LatticeSimulator, EveryGrainSettlesInThePicture) {
  Scene s = test::one_ellipse_scene();
  auto sim = make_lattice_simulator();
  RunResult r = run_pipeline(s, *sim, RunOptions{});
  EXPECT_EQ(r.stats["grains"]["in_picture"], r.stats["grains"]["total"]);
  EXPECT_EQ(r.stats["grains"]["total"].get<int64_t>(), 400 * 80);
}

}  // namespace
}  // namespace sandpic
