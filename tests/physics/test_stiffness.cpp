// The DEM watches its own stiffness and sub-steps by itself.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/dem_simulator.h"
#include "physics/stiffness.h"
#include "src/errors.h"
#include "src/pipeline.h"
#include "tests/test_util.h"

namespace sandpic {
namespace {

using Verdict = StiffnessWatch::Verdict;

// A target overlap of 0.05 and a hard limit of 1 (px).
StiffnessReading reading(double overlap_px, double kinetic = 0.1) {
  return StiffnessReading{overlap_px, kinetic, /*settling=*/1.0, /*budget=*/100.0};
}

TEST(StiffnessWatch, CalmRunsKeepOneSubStep) {
  StiffnessWatch w(0.05, 1.0, 16);
  for (int i = 0; i < 500; ++i) EXPECT_EQ(w.judge(reading(0.04, 1.0), i, i), Verdict::Calm);
  EXPECT_EQ(w.substeps(), 1);
  EXPECT_TRUE(w.changes().empty());
}

TEST(StiffnessWatch, SoftLevelDoublesUpToTheMost) {
  StiffnessWatch w(0.05, 1.0, 10);
  for (int want : {2, 4, 8, 10}) {
    EXPECT_EQ(w.judge(reading(0.6), 0, 0), Verdict::Changed);
    EXPECT_EQ(w.substeps(), want);
  }
  EXPECT_EQ(w.judge(reading(0.6), 0, 0), Verdict::Calm);  // at the most: only the hard limit decides
  EXPECT_EQ(w.judge(reading(0.1, 5.0), 0, 0), Verdict::Calm);
  EXPECT_EQ(w.judge(reading(1.2), 0, 0), Verdict::Diverged);
  EXPECT_NE(w.reason().find("dem.max_overlap"), std::string::npos);
  EXPECT_EQ(w.changes().size(), 4u);
}

TEST(StiffnessWatch, EnergyGrowthIsSoftAndBeyondTheBudgetHard) {
  StiffnessWatch w(0.05, 1.0, 4);
  EXPECT_EQ(w.judge(reading(0.0, 5.0), 0, 0), Verdict::Changed);  // rms speed over twice settling
  EXPECT_EQ(w.substeps(), 2);
  EXPECT_EQ(w.judge(reading(0.0, 200.0), 0, 0), Verdict::Changed);  // past the budget below the most: the most
  EXPECT_EQ(w.substeps(), 4);
  EXPECT_EQ(w.judge(reading(0.0, 200.0), 0, 0), Verdict::Diverged);
  EXPECT_NE(w.reason().find("kinetic energy"), std::string::npos);
}

TEST(StiffnessWatch, OneSubStepAtMostDivergesAtTheHardLimit) {
  StiffnessWatch w(0.05, 1.0, 1);
  EXPECT_EQ(w.judge(reading(0.9), 0, 0), Verdict::Calm);
  EXPECT_EQ(w.judge(reading(1.1), 0, 0), Verdict::Diverged);
}

TEST(StiffnessWatch, LongCalmHalvesTheSubSteps) {
  StiffnessWatch w(0.05, 1.0, 16);
  w.judge(reading(0.6), 0, 0);
  w.judge(reading(0.6), 0, 0);
  ASSERT_EQ(w.substeps(), 4);
  int cycles = 0;
  while (w.substeps() == 4 && cycles < 1000) {
    ++cycles;
    w.judge(reading(0.01), cycles, cycles);
  }
  EXPECT_EQ(w.substeps(), 2);
  EXPECT_EQ(cycles, 100);
  EXPECT_EQ(w.most_substeps(), 4);
}

// A small DEM scene (about 300 grains) with a time step twenty times the
// default (a grain falls a small grain's diameter per step) and perfectly
// elastic grains: they sink about 0.2 small diameters into each other, past
// a divergence limit of a tenth of a diameter (the default step: about 0.01).
Scene stiff_scene(int max_substeps) {
  Scene s = test::one_ellipse_scene(100, 90, 3);
  s.release.outlet_width_mm = 4;
  s.mode = Mode::Dem;
  s.dem.patience_cycles = 3;
  s.dem.step_diameters = 1;
  s.dem.max_overlap = 0.1;
  s.physics.restitution = 1;
  s.dem.max_substeps = max_substeps;
  return s;
}

RunResult run(const Scene& s) { return run_pipeline(s, *make_dem_simulator(), RunOptions{true, false}); }

TEST(DemStiffness, AStiffSceneDivergesWithoutSubStepsAndFinishesWithThem) {
  EXPECT_THROW(run(stiff_scene(1)), SimulationError);
  RunResult r = run(stiff_scene(16));
  EXPECT_EQ(r.stats["grains"]["in_picture"], r.stats["grains"]["released"]);
  const auto& b = r.stats["backend"];
  EXPECT_GT(b["substeps"].get<int>(), 1);
  ASSERT_FALSE(b["substep_changes"].empty());

  for (const auto& c : b["substep_changes"]) {
    EXPECT_TRUE(std::isfinite(c["t_s"].get<double>()));
    EXPECT_GT(c["step"].get<int64_t>(), 0);
    EXPECT_GT(c["substeps"].get<int>(), 0);
    EXPECT_FALSE(c["reason"].get<std::string>().empty());
  }
}

// At ten times the default step (restitution and limits at their defaults)
// no grain comes near the divergence limit, but contacts overlap past
// dem.target_overlap: the run sub-steps on that alone.
TEST(DemStiffness, AnOverlapPastTheTargetSubSteps) {
  Scene s = stiff_scene(16);
  s.dem.step_diameters = 0.5;
  s.physics.restitution = Scene{}.physics.restitution;
  s.dem.max_overlap = Scene{}.dem.max_overlap;
  RunResult r = run(s);
  const auto& changes = r.stats["backend"]["substep_changes"];
  ASSERT_FALSE(changes.empty());
  EXPECT_EQ(changes.front()["substeps"].get<int>(), 2);
  EXPECT_NE(changes.front()["reason"].get<std::string>().find("dem.target_overlap"), std::string::npos)
      << changes.front()["reason"];
}

TEST(DemStiffness, StatsAreFinite) {
  Scene s = stiff_scene(16);
  s.dem.step_diameters = Scene{}.dem.step_diameters;
  s.physics.restitution = Scene{}.physics.restitution;
  RunResult r = run(s);
  const auto& b = r.stats["backend"];
  EXPECT_EQ(b["substeps"].get<int>(), 1);
  EXPECT_TRUE(b["substep_changes"].empty());
  for (const char* key : {"deepest_overlap_px", "deepest_overlap_diameters", "kinetic_energy_end_J"}) {
    const double v = b[key].get<double>();
    EXPECT_TRUE(std::isfinite(v)) << key;
    EXPECT_GE(v, 0) << key;
  }
  EXPECT_LT(b["deepest_overlap_diameters"].get<double>(), 0.5);
}

TEST(DemStiffness, GrainsNoDenserThanTheWaterAreASceneError) {
  Scene s = stiff_scene(16);
  s.grains.density_g_cm3 = {1.0, 1.0, 2.7, 2.7};
  try {
    run(s);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grains.density_g_cm3["), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sandpic
