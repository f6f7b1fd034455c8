#pragma once
// Rendering: settled grains to a picture of the window, the emptied upper
// part blank or filled by a background picture (paper §10, Fig. 14g).
#include <opencv2/core.hpp>

#include "src/scene.h"

namespace sandpic {

// The background picture resized to the window, or an empty Mat if none.
cv::Mat load_background(const Scene& s);

// paper §10, Fig. 16: render.figures as one mask of the window (CV_8U, 255
// on a figure), or an empty Mat if none. Mask pictures are read here.
cv::Mat load_figures(const Scene& s);

// class_map: CV_8U of the window, class 0..3 or kNoSand. Sand on `figures`
// is drawn in C1 with probability 0.7, else C2, keyed by (layout seed,
// pixel). Returns 8-bit BGR.
cv::Mat render(const Scene& s, const cv::Mat& class_map, const cv::Mat& background, const cv::Mat& figures = {});

cv::Vec3b bgr(Rgb c);

// paper §10, Fig. 18c: "copy the asymmetric pattern and flip it vertically,
// and place flipped asymmetric pattern over" it. The class map above the
// surface's deepest valley becomes the mirror image of the sand below it,
// exactly symmetric about that row. Returns the row (the window's height
// when a column holds no sand: nothing is mirrored).
int mirror_over(cv::Mat& class_map, uint8_t no_sand);

}  // namespace sandpic
