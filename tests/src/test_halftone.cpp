#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "src/errors.h"
#include "src/init/init.h"

namespace sandpic {
namespace {

Scene region_of(int w, int h) {
  Scene s;
  s.window.width = w;
  s.window.height = 4 * h;
  s.region.height = h;
  return s;
}

cv::Mat grey(std::initializer_list<std::initializer_list<double>> rows) {
  cv::Mat m(int(rows.size()), int(rows.begin()->size()), CV_64F);
  int r = 0;
  for (auto& row : rows) {
    int c = 0;
    for (double v : row) m.at<double>(r, c++) = v;
    ++r;
  }
  return m;
}

TEST(Halftone, LuminanceIsBt601) {
  cv::Mat img(1, 3, CV_8UC3);
  img.at<cv::Vec3b>(0, 0) = {0, 0, 255};  // BGR: red
  img.at<cv::Vec3b>(0, 1) = {0, 255, 0};
  img.at<cv::Vec3b>(0, 2) = {255, 0, 0};
  cv::Mat y = luminance(img, 3, 1);
  EXPECT_NEAR(y.at<double>(0, 0), 0.299 * 255, 1e-9);
  EXPECT_NEAR(y.at<double>(0, 1), 0.587 * 255, 1e-9);
  EXPECT_NEAR(y.at<double>(0, 2), 0.114 * 255, 1e-9);
}

// Worked by hand: levels 0, 85, 170, 255; 100 -> 85 (error 15: 7/16 right,
// 5/16 below, 1/16 below right); 206.5625 -> 170 (error 36.5625: 3/16 below
// left, 5/16 below); 61.54 -> 85; 32.10 -> 0.
TEST(Halftone, FloydSteinbergOnAKnownImage) {
  GrainSet g = halftone(region_of(2, 2), grey({{100, 200}, {50, 30}}));
  EXPECT_EQ(std::vector<int>(g.cls.begin(), g.cls.end()), (std::vector<int>{1, 2, 1, 0}));
}

TEST(Halftone, DarkToLightIsS1ToS4) {
  EXPECT_EQ(halftone(region_of(2, 1), grey({{0, 0}})).cls, (std::vector<uint8_t>{0, 0}));
  EXPECT_EQ(halftone(region_of(2, 1), grey({{255, 255}})).cls, (std::vector<uint8_t>{3, 3}));
  EXPECT_EQ(halftone(region_of(4, 1), grey({{0, 85, 170, 255}})).cls, (std::vector<uint8_t>{0, 1, 2, 3}));
}

TEST(Halftone, ErrorDiffusionKeepsTheMeanGrey) {
  cv::Mat flat(64, 64, CV_64F, cv::Scalar(128));
  GrainSet g = halftone(region_of(64, 64), flat);
  double sum = 0;
  for (uint8_t c : g.cls) {
    EXPECT_TRUE(c == 1 || c == 2);  // 128 lies between levels 85 and 170
    sum += c * 85.0;
  }
  EXPECT_NEAR(sum / double(g.cls.size()), 128, 1.0);
}

TEST(Halftone, InitializeResizesAndNamesAMissingImage) {
  Scene s = region_of(40, 20);
  s.init.method = InitMethod::Halftone;
  std::string path = testing::TempDir() + "/halftone_in.png";
  cv::Mat img(10, 20, CV_8UC3, cv::Scalar(255, 255, 255));
  cv::imwrite(path, img);
  s.init.image = path;
  Initialization init = initialize(s);
  EXPECT_EQ(init.grains.size(), 40 * 20);
  EXPECT_EQ(init.grains.per_class()[3], 40 * 20);
  s.init.image = testing::TempDir() + "/missing.png";
  try {
    initialize(s);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("init.image"), std::string::npos);
  }
}

}  // namespace
}  // namespace sandpic
