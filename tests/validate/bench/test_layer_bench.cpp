#include <gtest/gtest.h>

#include <cmath>

#include "physics/dem_simulator.h"
#include "tests/test_util.h"
#include "validate/bench/layer_bench.h"

namespace sandpic {
namespace {

TEST(LayerBench, EveryModelAtEveryCountWithItsErrorAgainstAllDynamic) {
  Scene s = test::one_ellipse_scene(140, 90, 5);
  s.release.outlet_width_mm = 4;
  s.dem.patience_cycles = 3;  // the faster setting: see tests/physics/test_dem_simulator.cpp
  // Immovable static grains: a pile of 150 grains lies wholly inside the
  // default band of static bodies (ten grains), and three-layer's run would be
  // all-dynamic's byte for byte (an error of 0, which this test rejects).
  s.dem.static_bodies = false;
  LayerBenchOptions opt;
  opt.grains = {150, 400};
  opt.seeds = {1, 2};
  opt.all_dynamic_max = 150;
  auto dem = make_dem_simulator();
  int heard = 0;
  auto rows = run_layer_bench(s, opt, *dem, [&](const LayerBenchRow&) { ++heard; });
  // 150: all-dynamic ×2, its spread ×1, three ×2, bcre ×2; 400: three ×2, bcre ×2.
  ASSERT_EQ(rows.size(), 11u);
  EXPECT_EQ(heard, 11);
  for (const LayerBenchRow& r : rows) {
    EXPECT_NEAR(double(r.grains), double(r.target), 0.2 * double(r.target)) << r.layers;
    if (r.layers == "all-dynamic-spread") {
      EXPECT_GT(r.silhouette_error, 0);  // two seeds, two piles
      continue;
    }
    EXPECT_GT(r.simulate_s, 0);
    EXPECT_GT(r.steps, 0);
    if (r.layers == "all-dynamic") {
      EXPECT_EQ(r.silhouette_error, 0);
    }
    if (r.layers != "all-dynamic" && r.target == 150) {
      EXPECT_GT(r.silhouette_error, 0);
      EXPECT_LT(r.silhouette_error, 0.2);
    }
    if (r.target == 400) {
      EXPECT_TRUE(std::isnan(r.silhouette_error));  // no reference ran
    }
  }
  std::string csv = layer_bench_csv(rows);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 12);
  EXPECT_EQ(csv.rfind("layers,target_grains,grains,", 0), 0u);
  std::string table = layer_bench_table(rows);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 3);  // header and two counts
  cv::Mat plot = layer_bench_plot(rows);
  EXPECT_EQ(plot.size(), cv::Size(800, 520));
  EXPECT_LT(cv::countNonZero(plot.reshape(1) != 255), int(plot.total() * 3));  // something drawn, not all ink
  EXPECT_GT(cv::countNonZero(plot.reshape(1) != 255), 1000);
}

}  // namespace
}  // namespace sandpic
