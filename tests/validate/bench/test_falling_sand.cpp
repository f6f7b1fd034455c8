#include <gtest/gtest.h>

#include <vector>

#include "src/simulator.h"
#include "tests/test_util.h"
#include "validate/bench/falling_sand.h"

namespace sandpic {
namespace {

// The peer's rule (down, else diagonally down) piles sand from one point at
// 45°, keeps every grain, and a full entry cell stops the rest (lost, not a hang).
TEST(FallingSand, OnePointPilesAtFortyFiveDegreesAndKeepsEveryGrain) {
  const std::vector<int32_t> middle(20000, 200);
  const FallingSand sand = falling_sand(400, 300, middle, 8, 1);
  EXPECT_EQ(sand.settled, 20000);
  EXPECT_EQ(sand.lost, 0);
  EXPECT_EQ(cv::countNonZero(sand.grid), 20000);
  cv::Mat class_map(sand.grid.size(), CV_8U, cv::Scalar(kNoSand));
  class_map.setTo(0, sand.grid);
  EXPECT_NEAR(test::heap_angle_deg(test::column_heights(class_map)), 45, 3);

  // A stream as wide as an outlet: grains side by side hold each other up
  // for a tick, not for good (they would stand in towers).
  std::vector<int32_t> wide;
  for (int i = 0; i < 20000; ++i) wide.push_back(180 + (i * 7) % 40);
  const FallingSand stream = falling_sand(400, 300, wide, 8, 1);
  EXPECT_EQ(stream.settled, 20000);
  cv::Mat stream_map(stream.grid.size(), CV_8U, cv::Scalar(kNoSand));
  stream_map.setTo(0, stream.grid);
  EXPECT_NEAR(test::heap_angle_deg(test::column_heights(stream_map)), 45, 3);

  const FallingSand full = falling_sand(20, 10, std::vector<int32_t>(500, 10), 8, 1);
  EXPECT_EQ(full.settled + full.lost, 500);
  EXPECT_GT(full.lost, 0);
  EXPECT_EQ(cv::countNonZero(full.grid), full.settled);
}

// Same columns and seed, same grid: the peer is deterministic.
TEST(FallingSand, SameSeedSameGrid) {
  std::vector<int32_t> columns;
  for (int i = 0; i < 5000; ++i) columns.push_back(50 + (i * 37) % 100);
  const FallingSand a = falling_sand(200, 150, columns, 4, 9), b = falling_sand(200, 150, columns, 4, 9);
  EXPECT_EQ(cv::countNonZero(a.grid != b.grid), 0);
  EXPECT_EQ(a.moves, b.moves);
}

}  // namespace
}  // namespace sandpic
