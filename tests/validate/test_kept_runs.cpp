#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "lattice/lattice_simulator.h"
#include "tests/test_folder.h"
#include "validate/kept_runs.h"

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

}  // namespace
}  // namespace sandpic
