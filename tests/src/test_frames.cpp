#include <gtest/gtest.h>

#include "src/frames.h"
#include "src/simulator.h"

namespace sandpic {
namespace {

TEST(Frames, EvenlySpacedFromNoneToAll) {
  EXPECT_EQ(frame_released(100, 5, 0), 0);
  EXPECT_EQ(frame_released(100, 5, 1), 25);
  EXPECT_EQ(frame_released(100, 5, 3), 75);
  EXPECT_EQ(frame_released(100, 5, 4), 100);
  EXPECT_EQ(frame_released(100, 1, 0), 100);  // one frame: the picture
  EXPECT_EQ(frame_released(3, 7, 2), 1);      // more frames than grains: some repeat
}

// The schedule leaves the last frame to the end of the run.
TEST(Frames, ScheduleStopsBeforeTheLastFrame) {
  FrameSchedule f{10, 3};
  EXPECT_TRUE(f.due(0));
  ++f.next;
  EXPECT_FALSE(f.due(4));
  EXPECT_TRUE(f.due(5));
  ++f.next;
  EXPECT_FALSE(f.due(10));
  EXPECT_FALSE((FrameSchedule{10, 0}).due(10));
}

TEST(Frames, WaitingGrainsAtTheirPixelsInTheRegion) {
  GrainSet g;
  g.width = 4;
  g.height = 2;
  g.cls = {0, 1, 2, 3, 3, 2, 1, 0};
  cv::Mat map(5, 4, CV_8U, cv::Scalar(kNoSand));
  const std::vector<int32_t> waiting = {1, 6};  // (1, 0) and (2, 1)
  draw_waiting(map, g, waiting);
  EXPECT_EQ(map.at<uint8_t>(0, 1), 1);
  EXPECT_EQ(map.at<uint8_t>(1, 2), 1);
  EXPECT_EQ(cv::countNonZero(map != kNoSand), 2);
}

}  // namespace
}  // namespace sandpic
