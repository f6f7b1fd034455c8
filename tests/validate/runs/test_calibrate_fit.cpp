// calibrate's fit against a known truth: a lattice with other rule values
// stands in for the DEM, so the fit must find those values again.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>

#include "lattice/lattice_simulator.h"
#include "tests/test_folder.h"
#include "validate/runs/calibrate.h"

namespace sandpic {
namespace {

// A lattice whose scene `change` alters stands in for the DEM: the values
// the fit should recover.
class StandIn final : public Simulator {
 public:
  explicit StandIn(std::function<void(Scene&)> change) : change_(std::move(change)) {}
  Cost cost(const Scene& s) const override { return lattice_->cost(s); }
  SimResult simulate(const SimInput& in, Progress& progress) override {
    Scene s = in.scene;
    change_(s);
    SimInput changed{s, in.grains, in.seg, in.order};
    return lattice_->simulate(changed, progress);
  }

 private:
  std::function<void(Scene&)> change_;
  std::unique_ptr<Simulator> lattice_ = make_lattice_simulator();
};

SimulatorFactory dem_as(std::function<void(Scene&)> change) {
  return [change](const Scene& s) -> std::unique_ptr<Simulator> {
    if (s.mode == Mode::Dem) return std::make_unique<StandIn>(change);
    return make_lattice_simulator();
  };
}

// A denser-looking bulk and a surface layer.
SimulatorFactory truth_for_dem() {
  return dem_as([](Scene& s) {
    s.lattice.bulk = 1.08;
    s.lattice.surface_px = 3;
  });
}

// Two pile sizes tell a surface layer from the bulk; one size cannot, so
// the bulk takes it all.
TEST(CalibrateFit, TwoSizesRecoverTheBulkAndTheSurfaceLayer) {
  Scene base;
  CalibrateOptions opt;
  opt.grains = {3000, 12000};
  opt.scenes = 1;
  std::vector<std::string> lines;
  Calibration c = calibrate(base, opt, truth_for_dem(), [&](const std::string& l) { lines.push_back(l); });
  std::printf("two sizes: bulk %.4f, surface %.2f px, error %.5f -> %.5f\n", c.bulk, c.surface_px, c.error_before,
              c.error_after);
  EXPECT_NEAR(c.bulk, 1.08, 0.02);
  EXPECT_NEAR(c.surface_px, 3, 0.75);
  EXPECT_LT(c.error_after, c.error_before);

  opt.grains = {3000};
  Calibration one = calibrate(base, opt, truth_for_dem(), [](const std::string&) {});
  std::printf("one size: bulk %.4f, surface %.2f px\n", one.bulk, one.surface_px);
  EXPECT_EQ(one.surface_px, 0);
  EXPECT_GT(one.bulk, 1.1);  // the 3 px layer read as bulk on a low pile
}

// A "DEM" whose outlets are busy (lattice.spot_busy_s) lands grains in
// another order; calibrate --spot must find the time again among its grid,
// the other rule values refitted for each candidate.
TEST(CalibrateFit, SpotFindsTheBusyTimeOfAQueuingTruth) {
  SimulatorFactory make = dem_as([](Scene& s) {
    s.lattice = Scene{}.lattice;  // the default rule values
    s.lattice.spot_busy_s = 0.008;
  });
  Scene base;
  CalibrateOptions opt;
  opt.grains = {3000};
  opt.scenes = 1;
  opt.fit = {"lattice.spot_busy_s"};
  std::vector<std::string> lines;
  Calibration c = calibrate(base, opt, make, [&](const std::string& l) { lines.push_back(l); });
  std::printf("spot: %g s, error %.5f -> %.5f\n", c.grid["lattice.spot_busy_s"].get<double>(), c.error_before, c.error_after);
  EXPECT_EQ(c.grid["lattice.spot_busy_s"], 0.008);
  EXPECT_GT(c.error_before, 0.001);
  EXPECT_LT(c.error_after, 0.5 * c.error_before);
  EXPECT_EQ(calibration_json(base, c)["lattice"]["spot_busy_s"].get<double>(), 0.008);
}

// calibrate --fit takes exactly the keys the registry gives a fit grid, and
// the calibration file holds every one of them.
TEST(CalibrateFit, FitKeysAreTheRegistrysGridKeys) {
  std::vector<std::string> grid;
  for (const Field& f : scene_fields())
    if (!f.fit_grid.empty()) grid.push_back(f.path);
  for (const char* key : {"lattice.trap_rate", "lattice.trap_deg", "lattice.spot_busy_s"})  // and any a key adds
    EXPECT_NE(std::find(grid.begin(), grid.end(), key), grid.end()) << key;
  EXPECT_NO_THROW(check_fit_keys(grid));
  for (const std::string bad : {"lattice.bulk", "lattice.nope"}) {
    try {
      check_fit_keys({bad});
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("lattice.spot_busy_s"), std::string::npos) << e.what();
    }
  }
}

// A "DEM" whose picture shows small grains at twice their area where they
// mix with big ones (lattice.picture_share 2): the shares are fitted to the
// composition error and found again; the silhouette fit does not see them.
TEST(CalibrateFit, PictureSharesAreFittedToTheComposition) {
  SimulatorFactory make = dem_as([](Scene& s) {
    s.lattice = Scene{}.lattice;
    s.lattice.picture_share = {1, 1, 2, 2};
  });
  Scene base;
  CalibrateOptions opt;
  opt.grains = {3000};
  opt.scenes = 1;
  Calibration off = calibrate(base, opt, make, [](const std::string&) {});
  EXPECT_EQ(off.picture_share[2], 1);  // fitted only when asked
  opt.shares = true;
  Calibration c = calibrate(base, opt, make, [](const std::string&) {});
  EXPECT_EQ(c.composition_before, off.composition_before);
  std::printf("picture shares %.3f %.3f %.3f %.3f, composition %.5f -> %.5f, silhouette %.5f -> %.5f\n",
              c.picture_share[0], c.picture_share[1], c.picture_share[2], c.picture_share[3], c.composition_before,
              c.composition_after, c.error_before, c.error_after);
  EXPECT_EQ(c.picture_share[0], 1);
  EXPECT_EQ(c.picture_share[1], 1);
  EXPECT_NEAR(c.picture_share[2], 2, 0.2);
  EXPECT_EQ(c.picture_share[3], c.picture_share[2]);  // one group: S3 and S4 share a diameter and density
  EXPECT_GT(c.composition_before, 0.002);
  EXPECT_LT(c.composition_after, 0.25 * c.composition_before);
  EXPECT_LT(c.composition_after, 0.25 * off.composition_after);  // the rule values alone do not do it
  EXPECT_GT(c.composition_floor, 0);  // two physics seeds of the stand-in differ
  const ordered_json j = calibration_json(base, c);
  EXPECT_NEAR(j["lattice"]["picture_share"][2].get<double>(), c.picture_share[2], 1e-12);
  EXPECT_TRUE(j["fit"].contains("dem_composition_floor"));
}

// --runs: the "DEM" piles are kept and the second calibration reads them
// back instead of running them, and fits the same values.
TEST(CalibrateFit, KeptPilesAreReusedWhileTheirDigestHolds) {
  const std::filesystem::path dir = test::fresh_folder();
  Scene base;
  CalibrateOptions opt;
  opt.grains = {3000};
  opt.scenes = 1;
  opt.runs_dir = dir.string();
  auto count_kept = [](const std::vector<std::string>& lines) {
    int n = 0;
    for (const std::string& l : lines) n += l.find("kept from an earlier run") != std::string::npos;
    return n;
  };
  std::vector<std::string> first, second, third;
  Calibration a = calibrate(base, opt, truth_for_dem(), [&](const std::string& l) { first.push_back(l); });
  Calibration b = calibrate(base, opt, truth_for_dem(), [&](const std::string& l) { second.push_back(l); });
  EXPECT_EQ(count_kept(first), 0);
  EXPECT_EQ(count_kept(second), 2);
  EXPECT_DOUBLE_EQ(a.bulk, b.bulk);
  EXPECT_EQ(a.repose_deg, b.repose_deg);
  base.physics.friction = 0.5;  // another scene for the DEM: run again
  calibrate(base, opt, truth_for_dem(), [&](const std::string& l) { third.push_back(l); });
  EXPECT_EQ(count_kept(third), 0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sandpic
