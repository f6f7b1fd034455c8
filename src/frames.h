#pragma once
// paper Fig. 14c-d, 18b-c: screen shots of the fall while it goes. What both
// backends share to draw one: when a frame falls due, and the grains still
// waiting at their places in the initialization region.
#include <cstdint>
#include <span>

#include <opencv2/core.hpp>

#include "src/grains.h"

namespace sandpic {

// Grains released from the region by frame k of `count`: none at frame 0,
// then evenly spaced; the last frame (k = count - 1) is the finished run.
int64_t frame_released(int64_t total, int count, int k);

// Which frame comes next. Plain data: a backend keeps one per run.
struct FrameSchedule {
  int64_t total = 0;
  int count = 0;
  int next = 0;  // frames emitted so far
  // A frame before the last is due once `released` grains have left.
  bool due(int64_t released) const {
    return next < count - 1 && released >= frame_released(total, count, next);
  }
};

// Draws each grain of `waiting` at its pixel of the region (grain id =
// y * width + x; the region is the window's top rows), over what is there.
void draw_waiting(cv::Mat& class_map, const GrainSet& g, std::span<const int32_t> waiting);

}  // namespace sandpic
