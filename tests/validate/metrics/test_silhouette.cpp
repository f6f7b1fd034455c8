#include <gtest/gtest.h>

#include <cmath>

#include "src/simulator.h"
#include "validate/metrics/silhouette.h"

namespace sandpic {
namespace {

TEST(Silhouette, HeightsAndErrorAsAFractionOfTheWindow) {
  cv::Mat a(10, 4, CV_8U, cv::Scalar(kNoSand)), b = a.clone();
  a.rowRange(6, 10).setTo(0);  // 4 px of sand everywhere
  b.rowRange(6, 10).setTo(2);
  b.at<uint8_t>(1, 3) = 1;  // one column up to 9 px: the top grain counts, not what is under it
  EXPECT_EQ(silhouette(a), (std::vector<double>{4, 4, 4, 4}));
  EXPECT_EQ(silhouette(b), (std::vector<double>{4, 4, 4, 9}));
  EXPECT_DOUBLE_EQ(silhouette_error(a, b), 5.0 / 4 / 10);
  EXPECT_DOUBLE_EQ(silhouette_error(b, a), silhouette_error(a, b));
  EXPECT_DOUBLE_EQ(silhouette_error(a, a), 0);
  EXPECT_THROW(silhouette_error(a, cv::Mat(9, 4, CV_8U)), std::invalid_argument);
}

// A heap of 40° flanks on a flat floor: the 20-80% band of each flank.
TEST(Silhouette, HeapAngleOfATriangle) {
  std::vector<double> h(201, 2.0);
  const double slope = std::tan(40 * M_PI / 180);
  for (int i = 0; i <= 200; ++i) h[size_t(i)] = std::max(2.0, 60 - slope * std::abs(i - 100));
  EXPECT_NEAR(heap_angle_deg(h), 40, 0.01);
  EXPECT_NEAR(heap_angle_deg(h, 0.5), std::atan(2 * slope) * 180 / M_PI, 0.01);  // columns half as wide
  EXPECT_TRUE(std::isnan(heap_angle_deg(std::vector<double>(50, 3.0))));  // no flank
}

// Many mountains: a sawtooth of slope 1/2 reads atan(1/2) away from its
// corners, which the smoothing rounds off; a flat outline reads 0.
TEST(Silhouette, SceneSlopeIsTheMeanSteepnessSmoothed) {
  std::vector<double> saw(400);
  for (int i = 0; i < 400; ++i) saw[size_t(i)] = 10 + 0.5 * std::abs((i % 80) - 40);
  EXPECT_NEAR(scene_slope_deg(saw, 1), std::atan(0.5) * 180 / M_PI, 0.01);
  const double smoothed = scene_slope_deg(saw, 16);
  EXPECT_LT(smoothed, std::atan(0.5) * 180 / M_PI);
  EXPECT_GT(smoothed, 0.7 * std::atan(0.5) * 180 / M_PI);
  EXPECT_DOUBLE_EQ(scene_slope_deg(std::vector<double>(100, 7.0), 16), 0);
}

}  // namespace
}  // namespace sandpic
