#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <tbb/global_control.h>

#include "src/pipeline.h"
#include "src/scene_file.h"

namespace sandpic {
namespace {

RunResult run(const Scene& s, int threads = 0) {
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0) limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  return run_pipeline(s, *make_simulator(s), RunOptions{true, false});
}

Scene preview() {
  Scene s;
  apply_scale(s, 0.25);
  return s;
}

TEST(Pipeline, DefaultSceneAtQuarterScaleAccountsForEveryGrain) {
  RunResult r = run(preview());
  EXPECT_EQ(r.picture.cols, 250);
  EXPECT_EQ(r.picture.rows, 175);
  EXPECT_EQ(r.stats["grains"]["total"].get<int64_t>(), 250 * 88);
  EXPECT_EQ(r.stats["grains"]["in_picture"], r.stats["grains"]["total"]);
  EXPECT_EQ(r.stats["grains"]["released"], r.stats["grains"]["total"]);
  for (const char* k : {"init_s", "segment_s", "simulate_s", "render_s", "total_s"})
    EXPECT_TRUE(r.stats["timing"].contains(k)) << k;
  EXPECT_EQ(r.stages.size(), 5u);
}

// Same scene + same seed = same bytes at any thread count (STYLE.md, Jolt).
TEST(Pipeline, SameSeedSameBytesAtAnyThreadCount) {
  RunResult one = run(preview(), 1), two = run(preview(), 2);
  EXPECT_EQ(one.png, two.png);
  for (size_t i = 0; i < one.stages.size(); ++i)
    EXPECT_EQ(cv::norm(one.stages[i].second, two.stages[i].second, cv::NORM_INF), 0) << one.stages[i].first;
  Scene other = preview();
  other.seed = 2;
  EXPECT_NE(run(other).png, one.png);
}

TEST(Pipeline, PhysicsSeedAloneKeepsTheComposition) {
  Scene s = preview();
  RunResult a = run(s);
  s.physics_seed = 42;
  RunResult b = run(s);
  EXPECT_EQ(a.stats["grains"]["per_class"], b.stats["grains"]["per_class"]);
  EXPECT_EQ(cv::norm(a.stages[1].second, b.stages[1].second, cv::NORM_INF), 0);  // same filled cells
  EXPECT_NE(a.png, b.png);  // another fall
}

TEST(Pipeline, HalftoneAndCellUnitsRunEndToEnd) {
  std::string path = testing::TempDir() + "/pipeline_in.png";
  cv::Mat img(88, 250, CV_8UC3);
  for (int y = 0; y < img.rows; ++y)
    for (int x = 0; x < img.cols; ++x) img.at<cv::Vec3b>(y, x) = cv::Vec3b(uint8_t(x), uint8_t(y * 2), 128);
  cv::imwrite(path, img);
  Scene s = preview();
  s.init.method = InitMethod::Halftone;
  s.init.image = path;
  RunResult r = run(s);
  EXPECT_EQ(r.stats["grains"]["in_picture"], r.stats["grains"]["total"]);
  s = preview();
  s.segment.method = SegmentMethod::Cells;
  r = run(s);
  EXPECT_EQ(r.stats["grains"]["in_picture"], r.stats["grains"]["total"]);
  EXPECT_GT(r.stats["units"].get<int>(), 20);
}

TEST(Pipeline, BackgroundFillsTheEmptiedUpperPart) {
  std::string path = testing::TempDir() + "/pipeline_bg.png";
  cv::imwrite(path, cv::Mat(10, 10, CV_8UC3, cv::Scalar(0, 0, 255)));
  Scene s = preview();
  s.render.background = path;
  RunResult r = run(s);
  EXPECT_EQ(r.picture.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 255));
}

}  // namespace
}  // namespace sandpic
