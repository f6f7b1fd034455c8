#include <gtest/gtest.h>

#include <functional>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <tbb/global_control.h>

#include "src/pipeline.h"
#include "src/render.h"
#include "tests/test_util.h"
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
  // The stages are disjoint parts of the whole (frames_s is a part of simulate_s).
  double sum = 0;
  for (const auto& [k, v] : r.stats["timing"].items())
    if (k != "total_s" && k != "frames_s") sum += v.get<double>();
  EXPECT_LE(sum, r.stats["timing"]["total_s"].get<double>() + 1e-9);
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

// The layout key follows what the stages before the simulation read: not
// the physics or the backends' keys; a run that reuses an
// earlier run's layout makes the bytes a fresh run makes.
TEST(Pipeline, AReusedLayoutMakesTheSamePicture) {
  const Scene base = preview();
  Scene physics = base;
  physics.physics.friction = 0.9;
  physics.lattice.runout_px = {0, 0, 1, 1};
  EXPECT_EQ(layout_key(physics), layout_key(base));
  for (auto change : std::vector<std::function<void(Scene&)>>{
           [](Scene& s) { s.segment.semi_major_min += 5; }, [](Scene& s) { s.init.dominant_share = 0.7; },
           [](Scene& s) { s.layout_seed = 3; }, [](Scene& s) { s.window.width += 10; },
           [](Scene& s) { s.grains.proportions[0] += 0.1; }}) {
    Scene other = base;
    change(other);
    EXPECT_NE(layout_key(other), layout_key(base));
  }
  RunResult first = run(base);
  RunOptions opt;
  opt.prepared = first.prepared;
  RunResult again = run_pipeline(physics, *make_simulator(physics), opt);
  EXPECT_EQ(again.png, run(physics).png);
  EXPECT_EQ(again.stats["timing"]["layout_reused"], true);
  EXPECT_FALSE(first.stats["timing"].contains("layout_reused"));
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

// paper Fig. 14c-d: frames of the fall, drawn as the picture is.
struct Fall {
  RunResult run;
  std::vector<cv::Mat> frames;
};
Fall fall(const Scene& s, int count) {
  Fall f;
  RunOptions opt;
  opt.frames = count;
  opt.frame = [&](const cv::Mat& picture) { f.frames.push_back(picture.clone()); };
  f.run = run_pipeline(s, *make_simulator(s), opt);
  return f;
}

TEST(PipelineFrames, FromAFullRegionToThePicture) {
  const Scene s = preview();
  Fall f = fall(s, 7);
  ASSERT_EQ(f.frames.size(), 7u);
  EXPECT_EQ(f.run.stats["frames"], 7);
  const auto [region_blank, floor_sand] = test::first_frame_counts(s, f.frames.front());
  EXPECT_EQ(region_blank, 0);  // every grain at its place
  EXPECT_EQ(floor_sand, 0);    // nothing fallen yet
  EXPECT_EQ(cv::norm(f.frames.back(), f.run.picture, cv::NORM_INF), 0);
  for (size_t i = 1; i + 1 < f.frames.size(); ++i) EXPECT_GT(cv::norm(f.frames[i], f.frames[i - 1], cv::NORM_L1), 0) << i;
}

TEST(PipelineFrames, SameSeedSameFramesAndTheSamePicture) {
  const Scene s = preview();
  Fall a = fall(s, 5), b = fall(s, 5);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (size_t i = 0; i < a.frames.size(); ++i) EXPECT_EQ(cv::norm(a.frames[i], b.frames[i], cv::NORM_INF), 0) << i;
  EXPECT_EQ(a.run.png, run(s).png);  // frames never change the picture
}

TEST(PipelineFrames, ASymmetricScenesLastFrameIsItsMirroredPicture) {
  Scene s = preview();
  s.render.symmetric = true;
  Fall f = fall(s, 4);
  ASSERT_EQ(f.frames.size(), 4u);
  EXPECT_EQ(cv::norm(f.frames.back(), f.run.picture, cv::NORM_INF), 0);
  // The picture is mirror-symmetric about its mirror row.
  const int axis = f.run.stats["symmetric"]["mirror_row"];
  ASSERT_GT(axis, 0);
  ASSERT_LT(axis, s.window.height);
  for (int i = 0; axis - 1 - i >= 0 && axis + i < s.window.height; ++i)
    ASSERT_EQ(cv::norm(f.run.picture.row(axis - 1 - i), f.run.picture.row(axis + i), cv::NORM_INF), 0) << i;
}

TEST(PipelineFrames, NoneUnlessAsked) {
  Fall f = fall(preview(), 0);
  EXPECT_TRUE(f.frames.empty());
  EXPECT_EQ(f.run.stats["frames"], 0);
}

// The studio's cancel button: a run asked to stop throws Cancelled at the
// backend's next progress update, in either mode, and returns nothing.
TEST(PipelineCancel, AStoppedRunThrowsCancelledInEitherMode) {
  const std::atomic<bool> stop{true};
  for (const Mode mode : {Mode::Lattice, Mode::Dem}) {
    Scene s = preview();
    s.mode = mode;
#if !SANDPIC_WITH_BULLET
    if (mode == Mode::Dem) continue;
#endif
    RunOptions opt;
    opt.cancel = &stop;
    EXPECT_THROW(run_pipeline(s, *make_simulator(s), opt), Cancelled) << int(mode);
  }
  // Not set: the run goes to the end.
  const std::atomic<bool> go{false};
  RunOptions opt;
  opt.cancel = &go;
  const Scene s = preview();
  EXPECT_EQ(run_pipeline(s, *make_simulator(s), opt).stats["grains"]["in_picture"], 250 * 88);
}

}  // namespace
}  // namespace sandpic
