#include <gtest/gtest.h>

#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "src/errors.h"
#include "src/render.h"
#include "src/scene_file.h"
#include "src/simulator.h"

namespace sandpic {
namespace {

// A 60x40 window, sand of class S3 in its lower half.
Scene small_scene() {
  Scene s;
  s.window.width = 60;
  s.window.height = 40;
  s.region.height = 10;
  return s;
}

cv::Mat half_sand(const Scene& s) {
  cv::Mat m(s.window.height, s.window.width, CV_8U, cv::Scalar(kNoSand));
  m.rowRange(s.window.height / 2, s.window.height).setTo(2);
  return m;
}

TEST(Render, SandOnAFigureIsC1OrC2AtSevenToThree) {
  Scene s = small_scene();
  // A polygon over columns 10-49, rows 10-39: half of it on no sand.
  s.render.figures = {Figure{"", 0, 0, 1, {{10, 10}, {50, 10}, {50, 40}, {10, 40}}}};
  const cv::Mat figures = load_figures(s);
  ASSERT_EQ(cv::countNonZero(figures), 40 * 30);
  const cv::Mat img = render(s, half_sand(s), {}, figures);
  const cv::Vec3b c1 = bgr(s.grains.colors[0]), c2 = bgr(s.grains.colors[1]), c3 = bgr(s.grains.colors[2]);
  const cv::Vec3b blank = bgr(s.render.background_color);
  int n1 = 0, n2 = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 60; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      const bool sand = y >= 20, on = figures.at<uint8_t>(y, x) != 0;
      if (!sand) EXPECT_EQ(p, blank) << x << "," << y;  // a figure shows only in sand
      else if (!on) EXPECT_EQ(p, c3) << x << "," << y;
      else if (p == c1) ++n1;
      else if (p == c2) ++n2;
      else ADD_FAILURE() << "not C1 or C2 at " << x << "," << y;
    }
  ASSERT_EQ(n1 + n2, 40 * 20);
  EXPECT_NEAR(double(n1) / (n1 + n2), 0.7, 0.05);
  // Same seed, same picture.
  EXPECT_EQ(cv::norm(img, render(s, half_sand(s), {}, figures), cv::NORM_INF), 0);
}

TEST(Render, MaskPictureIsPlacedScaledAndClippedToTheWindow) {
  const std::string dir = ::testing::TempDir() + "/sandpic_render_test";
  std::filesystem::create_directories(dir);
  cv::Mat mask(20, 20, CV_8UC3, cv::Scalar(255, 255, 255));
  mask(cv::Rect(0, 0, 10, 20)).setTo(cv::Scalar(0, 0, 0));  // the left half is the figure
  ASSERT_TRUE(cv::imwrite(dir + "/mask.png", mask));
  Scene s = small_scene();
  s.render.figures = {Figure{dir + "/mask.png", 55, 5, 0.5, {}}};  // 10x10, the left 5 columns inside
  const cv::Mat f = load_figures(s);
  EXPECT_EQ(cv::countNonZero(f), 5 * 10);
  EXPECT_NE(f.at<uint8_t>(5, 55), 0);
  EXPECT_NE(f.at<uint8_t>(14, 59), 0);
  EXPECT_EQ(f.at<uint8_t>(4, 55), 0);
  s.render.figures[0].x = 100;
  EXPECT_THROW(load_figures(s), InputError);
  s.render.figures[0] = Figure{dir + "/nothing.png", 0, 0, 1, {}};
  try {
    load_figures(s);
    ADD_FAILURE() << "no error for a missing mask";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("render.figures[0].mask"), std::string::npos) << e.what();
  }
}

TEST(Render, FigureKeysAreCheckedAndScaled) {
  Scene s;
  EXPECT_THROW(apply_json(s, json::parse(R"({"render": {"figures": [{"x": 3}]}})")), InputError);
  EXPECT_THROW(apply_json(s, json::parse(R"({"render": {"figures": [{"mask": "a.png", "polygon": [[0, 0], [1, 1]]}]}})")),
               InputError);
  apply_json(s, json::parse(R"({"render": {"figures": [{"polygon": [[10, 20], [30, 20], [30, 40]]},
                                                        {"mask": "m.png", "x": 100, "y": 50}]}})"));
  apply_scale(s, 0.5);
  ASSERT_EQ(s.render.figures.size(), 2u);
  EXPECT_DOUBLE_EQ(s.render.figures[0].polygon[2][1], 20);
  EXPECT_DOUBLE_EQ(s.render.figures[1].x, 50);
  EXPECT_DOUBLE_EQ(s.render.figures[1].scale, 0.5);
  EXPECT_EQ(s.render.figures[1].mask, "m.png");
}

}  // namespace
}  // namespace sandpic
