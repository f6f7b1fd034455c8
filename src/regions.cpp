#include "src/regions.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "src/errors.h"

namespace sandpic {

cv::Rect area_rect(const Scene& s, size_t i) {
  const auto& r = s.regions.at(i).rect;
  const int x0 = int(std::lround(std::clamp(r[0], 0.0, double(s.window.width))));
  const int y0 = int(std::lround(std::clamp(r[1], 0.0, double(s.region.height))));
  const int x1 = int(std::lround(std::clamp(r[2], 0.0, double(s.window.width))));
  const int y1 = int(std::lround(std::clamp(r[3], 0.0, double(s.region.height))));
  return cv::Rect(x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0));
}

cv::Mat area_map(const Scene& s) {
  if (s.regions.empty()) return {};
  if (s.regions.size() > 254) throw key_error("regions", "at most 254 areas");
  cv::Mat map(s.region.height, s.window.width, CV_8U, cv::Scalar(0));
  for (size_t i = s.regions.size(); i-- > 0;) {  // the first listed is drawn last: it wins
    const cv::Rect r = area_rect(s, i);
    const std::string where = "regions[" + std::to_string(i) + "]";
    if (r.empty()) throw key_error(where + ".rect", "the area lies outside the initialization region");
    cv::Mat mine(map.size(), CV_8U, cv::Scalar(0));
    mine(r).setTo(255);
    if (!s.regions[i].polygon.empty()) {
      // Pixel centres inside the polygon: a fill of the polygon shifted by half a pixel.
      std::vector<cv::Point> pts;
      for (const auto& p : s.regions[i].polygon)
        pts.emplace_back(int(std::lround((p[0] - 0.5) * 16)), int(std::lround((p[1] - 0.5) * 16)));
      cv::Mat poly(map.size(), CV_8U, cv::Scalar(0));
      cv::fillPoly(poly, std::vector<std::vector<cv::Point>>{pts}, cv::Scalar(255), cv::LINE_8, 4);
      cv::bitwise_and(mine, poly, mine);
    }
    if (cv::countNonZero(mine) == 0) throw key_error(where, "holds no pixel of the initialization region");
    map.setTo(cv::Scalar(double(i + 1)), mine);
  }
  return map;
}

int area_at(const cv::Mat& map, double x, double y) {
  if (map.empty()) return 0;
  const int xi = std::clamp(int(std::floor(x)), 0, map.cols - 1), yi = std::clamp(int(std::floor(y)), 0, map.rows - 1);
  return map.at<uint8_t>(yi, xi);
}

}  // namespace sandpic
