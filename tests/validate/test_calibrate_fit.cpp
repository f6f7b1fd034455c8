// calibrate's fit against a known truth: a lattice with other rule values
// stands in for the DEM, so the fit must find those values again.
#include <gtest/gtest.h>

#include <filesystem>

#include "lattice/lattice_simulator.h"
#include "validate/calibrate.h"

namespace sandpic {
namespace {

// The lattice with a denser-looking bulk and a surface layer: what the fit
// should recover.
class Truth final : public Simulator {
 public:
  Cost cost(const Scene& s) const override { return lattice_->cost(s); }
  SimResult simulate(const SimInput& in, Progress& progress) override {
    Scene s = in.scene;
    s.lattice.bulk = 1.08;
    s.lattice.surface_px = 3;
    SimInput changed{s, in.grains, in.seg, in.order};
    return lattice_->simulate(changed, progress);
  }

 private:
  std::unique_ptr<Simulator> lattice_ = make_lattice_simulator();
};

SimulatorFactory truth_for_dem() {
  return [](const Scene& s) -> std::unique_ptr<Simulator> {
    if (s.mode == Mode::Dem) return std::make_unique<Truth>();
    return make_lattice_simulator();
  };
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
  class Queuing final : public Simulator {
   public:
    Cost cost(const Scene& s) const override { return lattice_->cost(s); }
    SimResult simulate(const SimInput& in, Progress& progress) override {
      Scene s = in.scene;
      s.lattice = Scene{}.lattice;  // the default rule values
      s.lattice.spot_busy_s = 0.008;
      SimInput changed{s, in.grains, in.seg, in.order};
      return lattice_->simulate(changed, progress);
    }

   private:
    std::unique_ptr<Simulator> lattice_ = make_lattice_simulator();
  };
  SimulatorFactory make = [](const Scene& s) -> std::unique_ptr<Simulator> {
    if (s.mode == Mode::Dem) return std::make_unique<Queuing>();
    return make_lattice_simulator();
  };
  Scene base;
  CalibrateOptions opt;
  opt.grains = {3000};
  opt.scenes = 1;
  opt.spot = true;
  std::vector<std::string> lines;
  Calibration c = calibrate(base, opt, make, [&](const std::string& l) { lines.push_back(l); });
  std::printf("spot: %g s, error %.5f -> %.5f\n", c.spot_busy_s, c.error_before, c.error_after);
  EXPECT_EQ(c.spot_busy_s, 0.008);
  EXPECT_GT(c.error_before, 0.001);
  EXPECT_LT(c.error_after, 0.5 * c.error_before);
  EXPECT_EQ(calibration_json(base, c)["lattice"]["spot_busy_s"].get<double>(), 0.008);
}

// --runs: the "DEM" piles are kept and the second calibration reads them
// back instead of running them, and fits the same values.
TEST(CalibrateFit, KeptPilesAreReusedWhileTheirDigestHolds) {
  const auto dir = std::filesystem::temp_directory_path() / "sandpic-test-calibrate-runs";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
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
