#include "validate/metrics/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

#include "src/render.h"
#include "src/simulator.h"
#include "validate/metrics/silhouette.h"

namespace sandpic {

cv::Mat luminance601(const cv::Mat& bgr) {
  CV_Assert(bgr.type() == CV_8UC3);
  cv::Mat y(bgr.size(), CV_64F);
  for (int r = 0; r < bgr.rows; ++r) {
    const cv::Vec3b* p = bgr.ptr<cv::Vec3b>(r);
    double* out = y.ptr<double>(r);
    for (int c = 0; c < bgr.cols; ++c) out[c] = 0.299 * p[c][2] + 0.587 * p[c][1] + 0.114 * p[c][0];
  }
  return y;
}

namespace {

// scipy.ndimage.gaussian_filter(sigma, truncate): radius int(truncate·σ +
// 0.5), normalised weights, borders mirrored with the edge pixel repeated
// ('reflect' there, BORDER_REFLECT here).
cv::Mat gaussian(const cv::Mat& img, double sigma, double truncate) {
  const int radius = int(truncate * sigma + 0.5);
  cv::Mat k = cv::getGaussianKernel(2 * radius + 1, sigma, CV_64F);
  cv::Mat out;
  cv::sepFilter2D(img, out, CV_64F, k, k, cv::Point(-1, -1), 0, cv::BORDER_REFLECT);
  return out;
}

}  // namespace

double ssim(const cv::Mat& a, const cv::Mat& b) {
  CV_Assert(a.type() == CV_64F && b.type() == CV_64F && a.size() == b.size());
  constexpr double kSigma = 1.5, kTruncate = 3.5, kRange = 255;
  const double c1 = std::pow(0.01 * kRange, 2), c2 = std::pow(0.03 * kRange, 2);
  const cv::Mat ux = gaussian(a, kSigma, kTruncate), uy = gaussian(b, kSigma, kTruncate);
  const cv::Mat uxx = gaussian(a.mul(a), kSigma, kTruncate), uyy = gaussian(b.mul(b), kSigma, kTruncate),
                uxy = gaussian(a.mul(b), kSigma, kTruncate);
  auto mean_over = [&](cv::Rect area) {
    double sum = 0;
    for (int r = area.y; r < area.y + area.height; ++r)
      for (int c = area.x; c < area.x + area.width; ++c) {
        const double mx = ux.at<double>(r, c), my = uy.at<double>(r, c);
        const double vx = uxx.at<double>(r, c) - mx * mx, vy = uyy.at<double>(r, c) - my * my,
                     vxy = uxy.at<double>(r, c) - mx * my;
        sum += ((2 * mx * my + c1) * (2 * vxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      }
    return sum / double(area.area());
  };
  // scikit-image averages 5 px inside the borders ((win_size − 1) / 2); a
  // picture too small to have such an inner area is averaged whole.
  const int pad = int(kTruncate * kSigma + 0.5);
  if (a.cols > 2 * pad && a.rows > 2 * pad) return mean_over(cv::Rect(pad, pad, a.cols - 2 * pad, a.rows - 2 * pad));
  return mean_over(cv::Rect(0, 0, a.cols, a.rows));
}

double psnr(const cv::Mat& a, const cv::Mat& b) {
  CV_Assert(a.type() == CV_64F && b.type() == CV_64F && a.size() == b.size());
  cv::Mat d = a - b;
  const double mse = d.dot(d) / double(a.total());
  if (mse == 0) return std::numeric_limits<double>::infinity();
  return 10 * std::log10(255.0 * 255.0 / mse);
}

cv::Mat decode_classes(const cv::Mat& bgr, const std::array<Rgb, kClasses>& colours) {
  CV_Assert(bgr.type() == CV_8UC3);
  std::array<cv::Vec3b, kClasses> colour;
  for (int k = 0; k < kClasses; ++k) colour[k] = sandpic::bgr(colours[k]);  // as render() draws them
  cv::Mat out(bgr.size(), CV_8U, cv::Scalar(kNoSand));
  for (int r = 0; r < bgr.rows; ++r) {
    const cv::Vec3b* p = bgr.ptr<cv::Vec3b>(r);
    uint8_t* o = out.ptr<uint8_t>(r);
    for (int c = 0; c < bgr.cols; ++c)
      for (int k = 0; k < kClasses; ++k)
        if (p[c] == colour[k]) {
          o[c] = uint8_t(k);
          break;
        }
  }
  return out;
}

std::vector<double> composition_error(const cv::Mat& a, const cv::Mat& b, int bands) {
  CV_Assert(a.type() == CV_8U && b.type() == CV_8U && a.size() == b.size() && bands >= 1);
  bands = std::min(bands, a.rows);
  std::vector<double> err;
  for (int band = 0; band < bands; ++band) {
    const int from = int(int64_t(a.rows) * band / bands), to = int(int64_t(a.rows) * (band + 1) / bands);
    std::array<int64_t, kClasses + 1> ca{}, cb{};  // the last: no sand
    for (int r = from; r < to; ++r)
      for (int c = 0; c < a.cols; ++c) {
        const uint8_t x = a.at<uint8_t>(r, c), y = b.at<uint8_t>(r, c);
        ++ca[x < kClasses ? x : kClasses];
        ++cb[y < kClasses ? y : kClasses];
      }
    const double n = double(int64_t(to - from) * a.cols);
    double tv = 0;
    for (int k = 0; k <= kClasses; ++k) tv += std::abs(double(ca[size_t(k)] - cb[size_t(k)])) / n;
    err.push_back(tv / 2);
  }
  return err;
}

double mean_composition_error(const std::vector<double>& per_band) {
  double sum = 0;
  for (double e : per_band) sum += e;
  return per_band.empty() ? 0 : sum / double(per_band.size());
}

cv::Mat difference_picture(const cv::Mat& a, const cv::Mat& b) {
  const cv::Mat luma = luminance601(a);
  cv::Mat out(a.size(), CV_8UC3);
  for (int y = 0; y < a.rows; ++y)
    for (int x = 0; x < a.cols; ++x) {
      const cv::Vec3b p = a.at<cv::Vec3b>(y, x), q = b.at<cv::Vec3b>(y, x);
      int d = 0;
      for (int ch = 0; ch < 3; ++ch) d = std::max(d, std::abs(int(p[ch]) - int(q[ch])));
      if (d == 0) {
        const auto grey = uint8_t(std::lround(0.35 * luma.at<double>(y, x)));
        out.at<cv::Vec3b>(y, x) = {grey, grey, grey};
      } else {  // even a difference of 1 is plain to see
        out.at<cv::Vec3b>(y, x) = {30, 30, uint8_t(128 + d / 2)};
      }
    }
  return out;
}

Comparison compare_pictures(const cv::Mat& a, const cv::Mat& b, const std::array<Rgb, kClasses>& colours, int bands,
                            double blur_sigma_px) {
  CV_Assert(a.size() == b.size());
  Comparison c;
  c.width = a.cols, c.height = a.rows;
  const cv::Mat ya = luminance601(a), yb = luminance601(b);
  c.ssim = ssim(ya, yb);
  c.psnr_db = psnr(ya, yb);
  const cv::Mat ka = decode_classes(a, colours), kb = decode_classes(b, colours);
  c.silhouette_error = silhouette_error(ka, kb);
  c.composition = composition_error(ka, kb, bands);
  c.composition_error = mean_composition_error(c.composition);
  c.blur_sigma_px = blur_sigma_px;
  c.ssim_blurred = blur_sigma_px > 0 ? ssim(gaussian(ya, blur_sigma_px, 4), gaussian(yb, blur_sigma_px, 4)) : c.ssim;
  return c;
}

}  // namespace sandpic
