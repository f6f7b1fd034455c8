#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "physics/dem_simulator.h"
#include "lattice/lattice_simulator.h"
#include "src/errors.h"
#include "src/init/init.h"
#include "tests/test_folder.h"
#include "validate/runs/calibrate.h"

namespace sandpic {
namespace {

SimulatorFactory backends() {
  return [](const Scene& s) { return s.mode == Mode::Dem ? make_dem_simulator() : make_lattice_simulator(); };
}

TEST(Calibrate, ScenesAreOtherLayoutsOfTheSamePhysics) {
  Scene base;
  base.physics.friction = 0.7;
  CalibrateOptions opt;
  opt.grains = {3000};
  auto scenes = calibration_scenes(base, opt);
  ASSERT_EQ(scenes.size(), 3u);
  for (const Scene& s : scenes) {
    EXPECT_NE(s.layout(), base.layout());
    EXPECT_EQ(s.physics.friction, 0.7);
    const double n = double(initialize(s).grains.size());
    EXPECT_NEAR(n, 3000, 3000 * 0.1);
  }
  EXPECT_EQ(scenes[1].init.tessellation, TessellationKind::Uniform);
  EXPECT_EQ(scenes[2].init.tessellation, TessellationKind::Strips);
  opt.grains = {3000, 12000};  // each variant at each size
  scenes = calibration_scenes(base, opt);
  ASSERT_EQ(scenes.size(), 6u);
  EXPECT_EQ(scenes[4].layout(), scenes[1].layout());
  EXPECT_NEAR(double(initialize(scenes[4]).grains.size()), 12000, 1200);
}

// A small fit end to end: the fitted lattice is closer to the DEM's piles
// than the default one, and the file it writes is one a scene can name.
TEST(Calibrate, FitLowersTheSilhouetteErrorAndAppliesThroughTheScene) {
  Scene base;
  CalibrateOptions opt;
  opt.grains = {2600};
  opt.scenes = 1;
  opt.physics_seeds = {1, 2};
  Calibration c = calibrate(base, opt, backends(), [](const std::string&) {});
  std::printf("calibration: error %.5f -> %.5f (DEM seed to seed %.5f), bulk %.3f, repose %.1f/%.1f\n", c.error_before,
              c.error_after, c.noise_floor, c.bulk, c.repose_deg[0], c.repose_deg[2]);
  EXPECT_LT(c.error_after, c.error_before);
  EXPECT_GT(c.noise_floor, 0);
  EXPECT_EQ(c.repose_deg[0], c.repose_deg[1]);  // S1 and S2: one diameter and density, one value
  EXPECT_EQ(c.repose_deg[2], c.repose_deg[3]);
  EXPECT_GT(c.bulk, 1.0);  // the DEM's piles pack looser than units.packing

  const auto path = std::filesystem::path(test::fresh_folder()) / "calibration.json";
  std::ofstream(path) << calibration_json(base, c).dump(2);
  Scene s;
  s.lattice.calibration = path.string();
  Scene applied = with_calibration(s);
  ASSERT_TRUE(applied.lattice.repose_deg.has_value());
  EXPECT_DOUBLE_EQ((*applied.lattice.repose_deg)[2], c.repose_deg[2]);
  EXPECT_DOUBLE_EQ(applied.lattice.bulk, c.bulk);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace sandpic
