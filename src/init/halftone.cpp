// paper §4.2: initialization by halftoning an input picture.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <filesystem>

#include <opencv2/imgproc.hpp>

#include "src/errors.h"
#include "src/image_io.h"
#include "src/init/init.h"

namespace sandpic {

cv::Mat read_image(const std::string& path, const std::string& key) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw key_error(key, "image '" + path + "' does not exist or is not a file");
  cv::Mat img;
  // Codec libraries (libpng) print their own complaints on stderr; the one
  // line below says it all, so stderr is closed while the file is decoded.
  std::fflush(stderr);
  int saved = dup(STDERR_FILENO), null = open("/dev/null", O_WRONLY);
  if (null >= 0) dup2(null, STDERR_FILENO);
  try {
    img = read_picture(path);  // 16-bit, grey and alpha become 8-bit BGR
  } catch (...) {
    if (saved >= 0) dup2(saved, STDERR_FILENO), close(saved);
    if (null >= 0) close(null);
    throw;
  }
  if (saved >= 0) dup2(saved, STDERR_FILENO), close(saved);
  if (null >= 0) close(null);
  if (img.empty()) throw key_error(key, "cannot read image '" + path + "' (missing, unreadable or not an image)");
  return img;
}

// Fig. 3b. A picture of another size is resized to the region (INTER_AREA
// when shrinking, INTER_LINEAR when enlarging).
cv::Mat luminance(const cv::Mat& bgr, int width, int height) {
  cv::Mat src = bgr;
  if (bgr.cols != width || bgr.rows != height) {
    bool shrink = bgr.cols * bgr.rows > width * height;
    cv::resize(bgr, src, cv::Size(width, height), 0, 0, shrink ? cv::INTER_AREA : cv::INTER_LINEAR);
  }
  cv::Mat y(height, width, CV_64F);
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c) {
      const cv::Vec3b p = src.at<cv::Vec3b>(r, c);
      y.at<double>(r, c) = 0.299 * p[2] + 0.587 * p[1] + 0.114 * p[0];  // BT.601
    }
  return y;
}

GrainSet halftone(const Scene& s, const cv::Mat& lum) {
  GrainSet g = empty_region(s);
  cv::Mat y = lum.clone();
  constexpr double kStep = 255.0 / (kClasses - 1);  // levels 0, 85, 170, 255
  // Raster scan, top down and left to right; the error goes only to pixels
  // not yet quantized (paper §4.2 mask: 7/16 right, 3/16 5/16 1/16 below).
  for (int r = 0; r < g.height; ++r) {
    double* row = y.ptr<double>(r);
    double* below = r + 1 < g.height ? y.ptr<double>(r + 1) : nullptr;
    for (int c = 0; c < g.width; ++c) {
      int level = int(std::lround(std::clamp(row[c], 0.0, 255.0) / kStep));
      double err = row[c] - level * kStep;
      g.cls[size_t(r) * g.width + c] = uint8_t(level);
      if (c + 1 < g.width) row[c + 1] += err * 7 / 16;
      if (below) {
        if (c > 0) below[c - 1] += err * 3 / 16;
        below[c] += err * 5 / 16;
        if (c + 1 < g.width) below[c + 1] += err * 1 / 16;
      }
    }
  }
  return g;
}

}  // namespace sandpic
