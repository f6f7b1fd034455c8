#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/dem_simulator.h"
#include "validate/bench/friction_bench.h"

namespace sandpic {
namespace {

TEST(FrictionBench, EveryFrictionSeedAndModelWithAnglesAndErrors) {
  Scene s = pile_scene();
  apply_scale(s, 0.3);  // 90×36 px, about 320 grains
  // A pile this low lies inside the default band of static bodies (ten
  // grains): three-layer's run would be all-dynamic's byte for byte (an
  // error of 0, which this test rejects). One grain of band it is not.
  s.dem.static_thickness_diameters = 1;
  FrictionBenchOptions opt;
  opt.friction = {0.1, 0.9};
  opt.seeds = {1};
  opt.layers = {Layers::Three, Layers::AllDynamic};
  auto dem = make_dem_simulator();
  int heard = 0;
  auto rows = run_friction_bench(s, opt, *dem, [&](const FrictionBenchRow&) { ++heard; });
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(heard, 4);
  for (const FrictionBenchRow& r : rows) {
    EXPECT_GT(r.grains, 250);
    EXPECT_TRUE(std::isfinite(r.angle_deg)) << r.layers << " " << r.friction;
    EXPECT_GT(r.slope_deg, 0) << r.layers << " " << r.friction;
    EXPECT_GT(r.simulate_s, 0);
    EXPECT_EQ(r.picture.size(), cv::Size(90, 36));
    if (r.layers == "all-dynamic") {
      EXPECT_EQ(r.silhouette_error, 0);
    } else {
      EXPECT_GT(r.silhouette_error, 0);  // against all-dynamic, same friction and seed
    }
  }
  std::string table = friction_bench_table(rows);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 7);  // header, 2 models × (2 rows + verdict)
  EXPECT_NE(table.find("all-dynamic: the mean angle"), std::string::npos);
  std::string csv = friction_bench_csv(rows);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
}

// A picture of many mountains has no heap angle: the verdict is then the
// scene slope's, not a "does not grow" from NaN angles.
TEST(FrictionBench, WithoutAHeapTheVerdictIsTheSceneSlopes) {
  auto rows = [](std::vector<double> slopes, double angle) {
    std::vector<FrictionBenchRow> out;
    for (size_t i = 0; i < slopes.size(); ++i) {
      FrictionBenchRow r;
      r.layers = "three";
      r.friction = 0.1 + 0.4 * double(i);
      r.angle_deg = angle;
      r.slope_deg = slopes[i];
      out.push_back(r);
    }
    return out;
  };
  const auto has = [](const std::string& table, const std::string& s) { return table.find(s) != std::string::npos; };
  EXPECT_TRUE(has(friction_bench_table(rows({9.5, 12.1, 13.0}, NAN)), "the mean scene slope grows with friction"));
  EXPECT_TRUE(has(friction_bench_table(rows({9.5, 12.1, 12.0}, NAN)), "the mean scene slope does NOT grow"));
  EXPECT_TRUE(has(friction_bench_table(rows({9.5, 12.1, 12.0}, 30)), "the mean angle does NOT grow"));
}

}  // namespace
}  // namespace sandpic
