#include "validate/metrics/silhouette.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Dense>

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

double heap_angle_deg(const std::vector<double>& h, double column_width) {
  size_t peak = 0;
  for (size_t i = 0; i < h.size(); ++i)
    if (h[i] > h[peak]) peak = i;
  auto fit = [&](int dir) {
    std::vector<double> xs, ys;
    for (long i = long(peak); i >= 0 && i < long(h.size()); i += dir)
      if (h[size_t(i)] > 0.2 * h[peak] && h[size_t(i)] < 0.8 * h[peak])
        xs.push_back(double(i) * column_width), ys.push_back(h[size_t(i)]);
    if (xs.size() < 3) return double(NAN);
    Eigen::MatrixXd A(xs.size(), 2);
    Eigen::VectorXd b(xs.size());
    for (size_t i = 0; i < xs.size(); ++i) A(long(i), 0) = xs[i], A(long(i), 1) = 1, b(long(i)) = ys[i];
    Eigen::Vector2d line = A.colPivHouseholderQr().solve(b);
    return std::atan(std::abs(line(0))) * 180 / std::numbers::pi;
  };
  return (fit(+1) + fit(-1)) / 2;
}

double scene_slope_deg(const std::vector<double>& h, double smoothing) {
  const long n = long(h.size()), half = std::max(0L, std::lround((smoothing - 1) / 2));
  if (n < 2) return 0;
  std::vector<double> prefix(size_t(n) + 1, 0.0), smoothed(static_cast<size_t>(n));
  for (long i = 0; i < n; ++i) prefix[size_t(i) + 1] = prefix[size_t(i)] + h[size_t(i)];
  for (long i = 0; i < n; ++i) {  // the window shrinks at the walls
    const long a = std::max(0L, i - half), b = std::min(n - 1, i + half);
    smoothed[size_t(i)] = (prefix[size_t(b) + 1] - prefix[size_t(a)]) / double(b - a + 1);
  }
  double sum = 0;
  for (long i = 0; i + 1 < n; ++i) sum += std::abs(smoothed[size_t(i) + 1] - smoothed[size_t(i)]);
  return std::atan(sum / double(n - 1)) * 180 / std::numbers::pi;
}

}  // namespace sandpic
