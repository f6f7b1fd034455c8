#include "validate/silhouette.h"

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

double flank_angle_deg(const std::vector<double>& h, double column_width) {
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

}  // namespace sandpic
