#include <gtest/gtest.h>

#include "src/simulator.h"
#include "validate/silhouette.h"

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

}  // namespace
}  // namespace sandpic
