#pragma once
// Rendering: settled grains to a picture of the window, the emptied upper
// part blank or filled by a background picture (paper §10, Fig. 14g).
#include <opencv2/core.hpp>

#include "src/scene.h"

namespace sandpic {

// The background picture resized to the window, or an empty Mat if none.
cv::Mat load_background(const Scene& s);

// class_map: CV_8U of the window, class 0..3 or kNoSand. Returns 8-bit BGR.
cv::Mat render(const Scene& s, const cv::Mat& class_map, const cv::Mat& background);

cv::Vec3b bgr(Rgb c);

}  // namespace sandpic
