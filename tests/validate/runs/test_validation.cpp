#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "lattice/lattice_simulator.h"
#include "src/errors.h"
#include "tests/test_folder.h"
#include "validate/report/report_html.h"
#include "validate/runs/validation.h"

namespace sandpic {
namespace {

// The plumbing of validate with the lattice standing in for the DEM (its
// physics seed only breaks ties, so its "noise floor" is small but not 0):
// quick, and it needs no Bullet. The real DEM runs in the CLI test.
SimulatorFactory lattice_for_all() {
  return [](const Scene&) { return make_lattice_simulator(); };
}

Scene small_scene() {
  Scene s;
  apply_scale(s, 0.0845);
  return s;
}

TEST(Validation, MeanComparisonAveragesPsnrThroughTheMeanSquaredError) {
  Comparison a, b;
  a.psnr_db = 20, b.psnr_db = 30;  // MSE 650.25 and 65.025
  a.ssim = 0.2, b.ssim = 0.4;
  a.composition = {0.1, 0.3}, b.composition = {0.3, 0.5};
  Comparison m = mean_comparison({a, b});
  EXPECT_NEAR(m.psnr_db, 10 * std::log10(255.0 * 255 / ((650.25 + 65.025) / 2)), 1e-9);
  EXPECT_NEAR(m.ssim, 0.3, 1e-12);
  EXPECT_NEAR(m.composition[1], 0.4, 1e-12);
  b.psnr_db = INFINITY;  // identical pictures add no error
  EXPECT_NEAR(mean_comparison({a, b}).psnr_db, 20 + 10 * std::log10(2.0), 1e-9);
}

TEST(Validation, RunsTheEnsembleKeepsItAndReportsEveryMetric) {
  const std::string dir = test::fresh_folder();
  ValidateOptions opt;
  opt.cache_dir = dir;
  opt.sweep_dem = true;
  opt.all_dynamic_max = 0;  // the all-dynamic point is skipped, and says why
  opt.lattice_timing_runs = 1;
  const Scene s = small_scene();
  Validation v = run_validation(s, opt, lattice_for_all(), [](const std::string&) {});
  ASSERT_EQ(v.dem.size(), 5u);
  EXPECT_EQ(v.dem[0].physics_seed, s.physics_rng());
  EXPECT_EQ(v.dem[4].physics_seed, s.physics_rng() + 4);
  ASSERT_EQ(v.metrics.size(), 5u);
  EXPECT_EQ(v.metrics[0].name, "silhouette_error");
  for (const MetricRow& m : v.metrics) EXPECT_TRUE(std::isfinite(m.lattice)) << m.name;
  bool skipped_all_dynamic = false;
  int lattice_points = 0;
  for (const ValidationRun& r : v.sweep) {
    if (r.setting == "dem.layers=all-dynamic") skipped_all_dynamic = !r.skipped.empty();
    lattice_points += r.group == "sweep-lattice";
  }
  EXPECT_TRUE(skipped_all_dynamic);
  EXPECT_GE(lattice_points, 8);
  auto swept = [&](const std::string& setting) {
    return std::any_of(v.sweep.begin(), v.sweep.end(), [&](const ValidationRun& r) { return r.setting == setting; });
  };
  // The registry's sweep points (Field::sweep), around this scene's values.
  for (const char* setting :
       {"lattice.resolution=0.5", "lattice.resolution=2", "lattice.repose_deg-5", "lattice.repose_deg+5",
        "lattice.runout_px=0", "lattice.runout_px*2+2", "lattice.bulk=0.95", "lattice.bulk=1.05",
        "lattice.surface_px=2", "lattice.spot_busy_s=0.01", "lattice.picture_share=1,1,1.5,1.5",
        "lattice.arrival=release", "dem.layers=bcre", "dem.layers=all-dynamic", "dem.step_diameters=0.1",
        "dem.step_diameters=0.025", "dem.solver_iterations=5", "dem.solver_iterations=20", "dem.release_rate=2000",
        "dem.release_rate=8000", "dem.static_thickness_diameters=5", "dem.static_thickness_diameters=20"})
    EXPECT_TRUE(swept(setting)) << setting;
  EXPECT_FALSE(v.heat_map.empty());
  for (const ValidationRun& d : v.dem) EXPECT_FALSE(d.cached);

  // Again: every DEM run comes from the folder, with the same picture.
  Validation again = run_validation(s, opt, lattice_for_all(), [](const std::string&) {});
  for (size_t i = 0; i < v.dem.size(); ++i) {
    EXPECT_TRUE(again.dem[i].cached);
    EXPECT_EQ(cv::norm(again.dem[i].picture, v.dem[i].picture, cv::NORM_INF), 0);
  }
  EXPECT_DOUBLE_EQ(again.metrics[0].floor, v.metrics[0].floor);
  // A changed DEM value is a new scene: not reused.
  Scene changed = s;
  changed.dem.solver_iterations = 7;
  opt.sweep_dem = opt.sweep_lattice = false;
  Validation other = run_validation(changed, opt, lattice_for_all(), [](const std::string&) {});
  for (const ValidationRun& d : other.dem) EXPECT_FALSE(d.cached);

  const ordered_json j = validation_json(v, "test");
  EXPECT_TRUE(j["headline"].contains("silhouette_error_ratio"));
  EXPECT_TRUE(j["headline"].contains("time_ratio"));
  EXPECT_EQ(j["runs"].size(), 6u);
  const std::string html = validation_html(v, "test");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// --lattice-seeds: the lattice's figures are the mean over every lattice seed
// and DEM run, and its seed-to-seed spread is the mean over lattice pairs.
TEST(Validation, ScoresTheLatticeOverSeveralSeeds) {
  ValidateOptions opt;
  opt.sweep_dem = opt.sweep_lattice = false;
  opt.lattice_timing_runs = 1;
  opt.lattice_seeds = 3;
  const Scene s = small_scene();
  Validation v = run_validation(s, opt, lattice_for_all(), [](const std::string&) {});
  ASSERT_EQ(v.lattice_seeds.size(), 2u);
  EXPECT_EQ(v.lattice.physics_seed, s.physics_rng());
  EXPECT_EQ(v.lattice_seeds[1].physics_seed, s.physics_rng() + 2);
  std::vector<const ValidationRun*> lats{&v.lattice, &v.lattice_seeds[0], &v.lattice_seeds[1]};
  // The seeds give different piles (else the spread would be 0 by construction).
  EXPECT_GT(cv::norm(v.lattice.picture, v.lattice_seeds[0].picture, cv::NORM_INF), 0);
  double sil = 0, spread = 0;
  for (const ValidationRun* l : lats)
    for (const ValidationRun& d : v.dem)
      sil += compare_pictures(l->picture, d.picture, s.grains.colors, opt.bands, opt.blur_sigma_px).silhouette_error / 15;
  for (size_t a = 0; a < 3; ++a)
    for (size_t b = a + 1; b < 3; ++b)
      spread += compare_pictures(lats[a]->picture, lats[b]->picture, s.grains.colors, opt.bands, opt.blur_sigma_px)
                    .silhouette_error / 3;
  EXPECT_NEAR(v.metrics[0].lattice, sil, 1e-12);
  EXPECT_NEAR(v.metrics[0].spread, spread, 1e-12);
  EXPECT_GT(spread, 0);
  const ordered_json j = validation_json(v, "test");
  EXPECT_EQ(j["headline"]["lattice_seeds"], 3);
  EXPECT_TRUE(j["metrics"][0].contains("lattice_seed_to_seed"));
  EXPECT_EQ(j["runs"].size(), 8u);  // 3 lattice + 5 DEM
  EXPECT_NE(validation_html(v, "test").find("lattice seed to seed"), std::string::npos);

  // One seed: no spread, and the report says none.
  opt.lattice_seeds = 1;
  Validation one = run_validation(s, opt, lattice_for_all(), [](const std::string&) {});
  EXPECT_TRUE(one.lattice_seeds.empty());
  EXPECT_TRUE(std::isnan(one.metrics[0].spread));
  EXPECT_FALSE(validation_json(one, "test")["metrics"][0].contains("lattice_seed_to_seed"));
  opt.lattice_seeds = 0;
  EXPECT_THROW(run_validation(s, opt, lattice_for_all(), [](const std::string&) {}), InputError);
}

TEST(Validation, NeedsFiveDemRuns) {
  ValidateOptions opt;
  opt.extra_seeds = 3;
  EXPECT_THROW(run_validation(small_scene(), opt, lattice_for_all(), [](const std::string&) {}), InputError);
}

TEST(Validation, Base64AsRfc4648) {
  auto b = [](std::string s) { return base64(std::vector<unsigned char>(s.begin(), s.end())); };
  EXPECT_EQ(b(""), "");
  EXPECT_EQ(b("f"), "Zg==");
  EXPECT_EQ(b("fo"), "Zm8=");
  EXPECT_EQ(b("foo"), "Zm9v");
  EXPECT_EQ(b("foobar"), "Zm9vYmFy");
}

}  // namespace
}  // namespace sandpic
