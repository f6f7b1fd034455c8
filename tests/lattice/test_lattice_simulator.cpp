#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "lattice/lattice_simulator.h"
#include "src/errors.h"
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

// At friction 0 the look-ahead is as wide as allowed (the ratio once
// overflowed an int and fell to one column: 45° piles).
TEST(LatticeSimulator, FrictionZeroLooksAsFarAsAllowed) {
  EXPECT_EQ(make_slope_rule(0, 1.18, 1.0).window, HeightField::kMaxWindow);
  Scene s = test::one_ellipse_scene();
  s.physics.friction = 0;
  std::vector<double> h = test::column_heights(test::simulate_scene(s, *make_lattice_simulator()).class_map);
  auto [lo, hi] = std::minmax_element(h.begin(), h.end());
  EXPECT_LT(*hi - *lo, 4);  // the sand lies flat from wall to wall
  EXPECT_GT(*lo, 40);
}

TEST(LatticeSimulator, AGridTooFineForTheWindowIsABadScene) {
  Scene s;
  s.window.width = s.window.height = 8;
  s.region.height = 1;
  s.lattice.resolution = 8;  // one big grain raises a column 9.4 px: more than the window
  try {
    run_pipeline(s, *make_lattice_simulator(), RunOptions{});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lattice.resolution"), std::string::npos);
  }
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
