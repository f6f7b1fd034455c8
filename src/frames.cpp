#include "src/frames.h"

#include <cassert>

namespace sandpic {

int64_t frame_released(int64_t total, int count, int k) {
  assert(count > 0 && k >= 0 && k < count);
  if (k == count - 1) return total;
  return k * total / (count - 1);
}

void draw_waiting(cv::Mat& class_map, const GrainSet& g, std::span<const int32_t> waiting) {
  assert(class_map.type() == CV_8U && class_map.cols == g.width && class_map.rows >= g.height);
  for (int32_t id : waiting) class_map.at<uint8_t>(id / g.width, id % g.width) = g.cls[size_t(id)];
}

}  // namespace sandpic
