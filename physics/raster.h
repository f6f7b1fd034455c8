#pragma once
// Settled grains to a class map: each pixel takes the class of the nearest
// grain centre within `reach` px, so a packed pile reads as solid sand.
#include <vector>

#include <opencv2/core.hpp>

namespace sandpic {

cv::Mat class_map_from_grains(int width, int height, const std::vector<float>& x, const std::vector<float>& y,
                              const std::vector<uint8_t>& value, double reach, uint8_t empty);

}  // namespace sandpic
