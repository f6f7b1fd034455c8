#include "physics/raster.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

namespace sandpic {

cv::Mat class_map_from_grains(int width, int height, const std::vector<float>& x, const std::vector<float>& y,
                              const std::vector<uint8_t>& value, double reach, uint8_t empty) {
  // Grains bucketed by pixel; a pixel looks at the buckets within reach.
  std::vector<int32_t> start(size_t(width) * height + 1, 0), items(x.size());
  auto cell = [&](size_t i) -> int64_t {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) return -1;
    int cx = int(std::floor(x[i])), cy = int(std::floor(y[i]));
    if (cx < 0 || cy < 0 || cx >= width || cy >= height) return -1;
    return int64_t(cy) * width + cx;
  };
  for (size_t i = 0; i < x.size(); ++i)
    if (int64_t c = cell(i); c >= 0) ++start[size_t(c) + 1];
  for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<int32_t> fill(start.begin(), start.end() - 1);
  for (size_t i = 0; i < x.size(); ++i)
    if (int64_t c = cell(i); c >= 0) items[size_t(fill[size_t(c)]++)] = int32_t(i);

  cv::Mat map(height, width, CV_8U, cv::Scalar(empty));
  const int r = int(std::ceil(reach));
  tbb::parallel_for(0, height, [&](int py) {
    for (int px = 0; px < width; ++px) {
      double best = reach * reach;
      int32_t found = -1;
      for (int cy = std::max(0, py - r); cy <= std::min(height - 1, py + r); ++cy)
        for (int cx = std::max(0, px - r); cx <= std::min(width - 1, px + r); ++cx) {
          size_t c = size_t(cy) * width + size_t(cx);
          for (int32_t k = start[c]; k < start[c + 1]; ++k) {
            int32_t i = items[size_t(k)];
            double dx = x[size_t(i)] - (px + 0.5), dy = y[size_t(i)] - (py + 0.5), d = dx * dx + dy * dy;
            if (d < best || (d == best && i < found)) best = d, found = i;  // ties by id: deterministic
          }
        }
      if (found >= 0) map.at<uint8_t>(py, px) = value[size_t(found)];
    }
  });
  return map;
}

}  // namespace sandpic
