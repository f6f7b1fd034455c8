#pragma once
// The intermediate pictures of paper Fig. 2, for --stages.
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "src/falling_order.h"

namespace sandpic {

using Stages = std::vector<std::pair<std::string, cv::Mat>>;  // file name, BGR picture

// 1-initialization (Fig. 2a or 2c), 2-filled (2b or 2d), 3-segmentation (2e),
// 4-falling-order (2h); the caller adds the final picture.
Stages stage_pictures(const Scene& s, const Initialization& init, const Segmentation& seg, const FallingOrder& order);

}  // namespace sandpic
