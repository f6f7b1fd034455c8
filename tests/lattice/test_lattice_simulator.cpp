#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lattice/lattice_simulator.h"
#include "src/errors.h"
#include "src/frames.h"
#include "src/init/init.h"
#include "src/pipeline.h"
#include "tests/test_util.h"

namespace sandpic {
namespace {

double pile_angle(const Scene& s) {
  SimResult r = test::simulate_scene(s, *make_lattice_simulator());
  return test::heap_angle_deg(test::column_heights(r.class_map));
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

// Where the time went: the stages in their order, within the simulate time
// (the frames apart from the landings they interrupt).
TEST(LatticeSimulator, StatsSayWhereTheTimeWent) {
  Scene s = test::one_ellipse_scene();
  auto sim = make_lattice_simulator();
  RunResult r = run_pipeline(s, *sim, RunOptions{});
  std::vector<std::string> names;
  double sum = 0;
  for (const auto& [name, seconds] : r.stats["backend"]["stages_s"].items()) {
    names.push_back(name);
    EXPECT_TRUE(std::isfinite(seconds.get<double>()) && seconds.get<double>() >= 0) << name;
    sum += seconds.get<double>();
  }
  EXPECT_EQ(names, (std::vector<std::string>{"land", "frames", "draw"}));
  EXPECT_GT(r.stats["backend"]["stages_s"]["land"].get<double>(), 0);
  EXPECT_LE(sum, r.stats["timing"]["simulate_s"].get<double>());
}

// A lattice run of the scene with `count` frames of its fall kept.
struct FramedRun {
  Initialization init;
  FallingOrder order;
  std::vector<cv::Mat> frames;
  SimResult result;
};
FramedRun framed_run(const Scene& s, int count) {
  FramedRun run;
  run.init = initialize(s);
  Segmentation seg = segment(s, run.init.tessellation);
  run.order = falling_order(seg, run.init.grains, s.layout());
  SimInput in{s, run.init.grains, seg, run.order};
  in.frames = {count, [&](const cv::Mat& m) { run.frames.push_back(m.clone()); }};
  Progress quiet(false);
  run.result = make_lattice_simulator()->simulate(in, quiet);
  return run;
}

// paper Fig. 14c-d: in every frame each grain is either waiting at its
// pixel in the region or part of the pile: the region holds exactly the
// grains not yet released, and the pile the area of those released (to a
// pixel per column: the class map samples pixel centres).
TEST(LatticeSimulator, FramesAccountForEveryGrain) {
  Scene s = test::one_ellipse_scene();
  s.lattice.arrival = LatticeArrival::Release;  // landings in falling order: each frame's pile is known
  const FramedRun run = framed_run(s, 9);
  const std::vector<cv::Mat>& frames = run.frames;
  ASSERT_EQ(frames.size(), 9u);
  EXPECT_EQ(cv::norm(frames.back(), run.result.class_map, cv::NORM_INF), 0);
  const int64_t total = run.init.grains.size();
  const cv::Rect region(0, 0, s.window.width, s.region.height);
  const cv::Rect below(0, s.region.height, s.window.width, s.window.height - s.region.height);
  double area = 0;
  int64_t released = 0;
  for (int k = 0; k < 9; ++k) {
    for (int64_t end = frame_released(total, 9, k); released < end; ++released)
      area += lattice_area_px(s, run.init.grains.cls[size_t(run.order.grain[size_t(released)])]);
    const cv::Mat& f = frames[size_t(k)];
    EXPECT_EQ(cv::countNonZero(f(region) != kNoSand), total - released) << "frame " << k;
    EXPECT_NEAR(cv::countNonZero(f(below) != kNoSand), area, s.window.width) << "frame " << k;
  }
}

// How much higher the small grains (S3, S4) lie than the big ones: the
// difference of their mean heights over the mean height of all.
double small_above_big(const Scene& s, const FramedRun& run) {
  double sum[2] = {0, 0}, n[2] = {0, 0};
  for (size_t i = 0; i < run.result.y.size(); ++i) {
    const int small = run.init.grains.cls[i] >= 2;
    sum[small] += s.window.height - run.result.y[i], n[small] += 1;
  }
  return (sum[1] / n[1] - sum[0] / n[0]) / ((sum[0] + sum[1]) / (n[0] + n[1]));
}
double small_above_big(const Scene& s) { return small_above_big(s, framed_run(s, 0)); }

// paper §7 in water: a unit's small grains sink at a quarter of the big ones'
// speed, so they land last and cap its pile, as in the DEM.
TEST(LatticeSimulator, SmallGrainsLandLastAndCapThePile) {
  Scene s = test::one_ellipse_scene();
  s.lattice.arrival = LatticeArrival::Release;
  const double in_order = small_above_big(s);
  s.lattice.arrival = LatticeArrival::Settling;
  const double settling = small_above_big(s);
  std::printf("small grains' mean height over big grains': %+.2f in falling order, %+.2f settling\n", in_order,
              settling);
  EXPECT_LT(std::abs(in_order), 0.05);
  EXPECT_GT(settling, in_order + 0.1);
}

// Landings that never overlap (no water: grains drop in a tenth of a
// second; one grain a second) are the falling order itself: the same bytes
// as lattice.arrival = release.
TEST(LatticeSimulator, SettlingWithNoOverlapIsTheFallingOrder) {
  Scene s = test::one_ellipse_scene(200, 150, 40);
  s.dem.water = false;
  s.dem.release_rate = 1;
  SimResult a = test::simulate_scene(s, *make_lattice_simulator());
  s.lattice.arrival = LatticeArrival::Release;
  SimResult b = test::simulate_scene(s, *make_lattice_simulator());
  EXPECT_EQ(cv::norm(a.class_map, b.class_map, cv::NORM_INF), 0);
  s.dem.release_rate = 4000;  // and they do overlap at the default rate
  s.lattice.arrival = LatticeArrival::Settling;
  SimResult c = test::simulate_scene(s, *make_lattice_simulator());
  EXPECT_GT(cv::norm(c.class_map, b.class_map, cv::NORM_L1), 0);
}

// The DEM puts a grain in above the pile only where no other is in its way,
// so one outlet fed faster than it can take grains makes them queue
// (lattice.spot_busy_s): they land later, fewer small ones cap the pile
// because big and small queue together, and every grain still lands.
TEST(LatticeSimulator, ABusyOutletsGrainsQueueAndLandMixed) {
  Scene s = test::one_ellipse_scene();
  const FramedRun free_run = framed_run(s, 0);
  EXPECT_EQ(free_run.result.stats["grains_waited"].get<int64_t>(), 0);
  const double free_cap = small_above_big(s, free_run);
  s.lattice.spot_busy_s = 0.02;  // a 5.6 px outlet takes about 280 grains/s of the 4000 released
  const FramedRun busy = framed_run(s, 0);
  const double busy_cap = small_above_big(s, busy);
  const int64_t total = busy.init.grains.size();
  const int64_t waited = busy.result.stats["grains_waited"].get<int64_t>();
  const double last = busy.result.stats["last_landing_s"].get<double>();
  std::printf("%lld of %lld grains waited; last landing %.2f s (%.2f s free); small over big %+.2f (%+.2f free)\n",
              (long long)waited, (long long)total, last, free_run.result.stats["last_landing_s"].get<double>(),
              busy_cap, free_cap);
  EXPECT_GT(waited, total / 2);
  EXPECT_GT(last, 2 * free_run.result.stats["last_landing_s"].get<double>());
  EXPECT_LT(busy_cap, free_cap - 0.05);
  for (size_t i = 0; i < busy.result.x.size(); ++i) ASSERT_TRUE(std::isfinite(busy.result.y[i])) << "grain " << i;
  // In falling order there are no landing times to queue by: the key does nothing.
  s.lattice.arrival = LatticeArrival::Release;
  SimResult a = test::simulate_scene(s, *make_lattice_simulator());
  s.lattice.spot_busy_s = 0;
  SimResult b = test::simulate_scene(s, *make_lattice_simulator());
  EXPECT_EQ(cv::norm(a.class_map, b.class_map, cv::NORM_INF), 0);
}

// Frames of a settling run: the region empties as grains leave and the last
// frame is the picture; grains on their way down are in neither.
TEST(LatticeSimulator, SettlingFramesEmptyTheRegionInOrder) {
  const Scene s = test::one_ellipse_scene();
  const FramedRun run = framed_run(s, 9);
  const std::vector<cv::Mat>& frames = run.frames;
  ASSERT_EQ(frames.size(), 9u);
  EXPECT_EQ(cv::norm(frames.back(), run.result.class_map, cv::NORM_INF), 0);
  const int64_t total = run.init.grains.size();
  const cv::Rect region(0, 0, s.window.width, s.region.height);
  int64_t last = total + 1;
  for (int k = 0; k < 9; ++k) {
    const int64_t waiting = cv::countNonZero(frames[size_t(k)](region) != kNoSand);
    EXPECT_LE(waiting, total - frame_released(total, 9, k)) << "frame " << k;  // landed ones have left
    EXPECT_LE(waiting, last) << "frame " << k;
    last = waiting;
  }
  EXPECT_EQ(last, 0);
}

}  // namespace
}  // namespace sandpic
