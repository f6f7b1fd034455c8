#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lattice/lattice_simulator.h"
#include "tests/test_folder.h"
#include "validate/runs/kept_runs.h"

namespace sandpic {
namespace {

Scene small() {
  Scene s;
  apply_scale(s, 0.1);
  return s;
}

TEST(KeptRuns, AKeptRunComesBackWithItsPictureAndClassMap) {
  const std::string dir = test::fresh_folder();
  const Scene s = small();
  RunResult r = run_pipeline(s, *make_lattice_simulator(), RunOptions{});
  keep_run(dir, "a", r);
  std::optional<KeptRun> k = load_kept(dir, "a", s);
  ASSERT_TRUE(k.has_value());
  EXPECT_EQ(cv::norm(k->picture, r.picture, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(k->class_map, r.class_map, cv::NORM_INF), 0);
  EXPECT_EQ(k->stats["grains"]["total"], r.stats["grains"]["total"]);
  EXPECT_FALSE(load_kept("", "a", s).has_value());     // no folder: nothing kept
  EXPECT_FALSE(load_kept(dir, "b", s).has_value());    // another label
  std::filesystem::remove_all(dir);
}

TEST(KeptRuns, AnotherSceneOrABrokenFileIsNotReused) {
  const std::string dir = test::fresh_folder();
  const Scene s = small();
  keep_run(dir, "a", run_pipeline(s, *make_lattice_simulator(), RunOptions{}));
  Scene other = s;
  other.lattice.bulk = 1.1;  // a value the lattice reads: another digest
  EXPECT_FALSE(load_kept(dir, "a", other).has_value());
  // An older folder without class maps: the picture is still good.
  std::filesystem::remove(dir + "/a.classes.png");
  std::optional<KeptRun> k = load_kept(dir, "a", s);
  ASSERT_TRUE(k.has_value());
  EXPECT_TRUE(k->class_map.empty());
  std::ofstream(dir + "/a.json") << "{ not json";
  EXPECT_FALSE(load_kept(dir, "a", s).has_value());
  std::filesystem::remove_all(dir);
}

// validate's and calibrate's one way to a run: kept if it holds, else run and kept.
TEST(KeptRuns, RunOrReuseRunsOnceAndThenReuses) {
  const std::string dir = test::fresh_folder();
  const Scene s = small();
  int made = 0;
  const SimulatorFactory make = [&](const Scene&) {
    ++made;
    return make_lattice_simulator();
  };
  const ReusedRun first = run_or_reuse(dir, "a", s, make);
  EXPECT_FALSE(first.kept);
  const ReusedRun again = run_or_reuse(dir, "a", s, make);
  EXPECT_TRUE(again.kept);
  EXPECT_EQ(made, 1);
  EXPECT_EQ(cv::norm(again.run.picture, first.run.picture, cv::NORM_INF), 0);
  EXPECT_EQ(cv::norm(again.run.class_map, first.run.class_map, cv::NORM_INF), 0);
  // Kept without a class map: reused for its picture, run again when the map is needed.
  std::filesystem::remove(dir + "/a.classes.png");
  EXPECT_TRUE(run_or_reuse(dir, "a", s, make).kept);
  EXPECT_FALSE(run_or_reuse(dir, "a", s, make, /*need_class_map=*/true).kept);
  EXPECT_EQ(made, 2);
  EXPECT_FALSE(run_or_reuse("", "a", s, make).kept);  // no folder: run, nothing kept
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sandpic
