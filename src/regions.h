#pragma once
// paper §10, Fig. 17: "dividing the initialization region into several areas
// for mountains and clouds", each initialized and segmented by its own scene
// (area_scene in scene_file.h) inside its own rectangle.
#include <opencv2/core.hpp>

#include "src/scene.h"

namespace sandpic {

// Area i's rectangle clipped to the region (window px); empty if outside.
cv::Rect area_rect(const Scene& s, size_t i);

// Per pixel of the region (CV_8U): 0 where no area holds it (the scene's own
// settings), else 1 + the first area listed that does. Empty when s has no areas.
cv::Mat area_map(const Scene& s);

// The area of a point (window px), clamped into the region; 0 without areas.
int area_at(const cv::Mat& map, double x, double y);

}  // namespace sandpic
