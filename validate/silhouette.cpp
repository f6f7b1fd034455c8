#include "validate/silhouette.h"

#include <cmath>
#include <stdexcept>

#include "src/simulator.h"

namespace sandpic {

std::vector<double> silhouette(const cv::Mat& class_map) {
  CV_Assert(class_map.type() == CV_8U);
  std::vector<double> h(size_t(class_map.cols), 0);
  for (int x = 0; x < class_map.cols; ++x)
    for (int y = 0; y < class_map.rows; ++y)
      if (class_map.at<uint8_t>(y, x) != kNoSand) {
        h[size_t(x)] = class_map.rows - y;
        break;
      }
  return h;
}

double silhouette_error(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size()) throw std::invalid_argument("silhouette_error: pictures of different sizes");
  std::vector<double> ha = silhouette(a), hb = silhouette(b);
  double sum = 0;
  for (size_t i = 0; i < ha.size(); ++i) sum += std::abs(ha[i] - hb[i]);
  return ha.empty() ? 0 : sum / double(ha.size()) / a.rows;
}

}  // namespace sandpic
