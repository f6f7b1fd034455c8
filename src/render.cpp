#include "src/render.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>
#include <tbb/parallel_for.h>

#include "src/errors.h"
#include "src/init/init.h"
#include "src/rng.h"
#include "src/simulator.h"

namespace sandpic {

cv::Vec3b bgr(Rgb c) { return cv::Vec3b(c.b, c.g, c.r); }

cv::Mat load_background(const Scene& s) {
  if (s.render.background.empty()) return {};
  cv::Mat img = read_image(s.resolve(s.render.background), "render.background");
  if (img.cols != s.window.width || img.rows != s.window.height)
    cv::resize(img, img, cv::Size(s.window.width, s.window.height), 0, 0, cv::INTER_AREA);
  return img;
}

cv::Mat load_figures(const Scene& s) {
  if (s.render.figures.empty()) return {};
  cv::Mat mask(s.window.height, s.window.width, CV_8U, cv::Scalar(0));
  for (size_t i = 0; i < s.render.figures.size(); ++i) {
    const Figure& f = s.render.figures[i];
    if (!f.polygon.empty()) {
      // A pixel is on the figure when its centre (x + 0.5, y + 0.5) is
      // inside the polygon (OpenCV's fillPoly also takes the boundary).
      std::vector<cv::Point2f> pts;
      for (const auto& p : f.polygon) pts.emplace_back(float(p[0]), float(p[1]));
      const cv::Rect box = cv::boundingRect(pts) & cv::Rect(0, 0, mask.cols, mask.rows);
      for (int y = box.y; y < box.y + box.height; ++y)
        for (int x = box.x; x < box.x + box.width; ++x)
          if (cv::pointPolygonTest(pts, cv::Point2f(x + 0.5f, y + 0.5f), false) > 0) mask.at<uint8_t>(y, x) = 255;
      continue;
    }
    const std::string key = "render.figures[" + std::to_string(i) + "].mask";
    cv::Mat img = read_image(s.resolve(f.mask), key), grey, dark;
    cv::cvtColor(img, grey, cv::COLOR_BGR2GRAY);
    if (f.scale != 1) {
      const cv::Size size(std::max(1, int(std::lround(grey.cols * f.scale))), std::max(1, int(std::lround(grey.rows * f.scale))));
      cv::resize(grey, grey, size, 0, 0, f.scale < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
    }
    cv::threshold(grey, dark, 127, 255, cv::THRESH_BINARY_INV);
    // The part of the mask inside the window.
    const cv::Rect at(int(std::lround(f.x)), int(std::lround(f.y)), dark.cols, dark.rows);
    const cv::Rect inside = at & cv::Rect(0, 0, mask.cols, mask.rows);
    if (inside.empty()) throw key_error("render.figures[" + std::to_string(i) + "]", "the figure lies outside the window");
    cv::Mat part = dark(cv::Rect(inside.x - at.x, inside.y - at.y, inside.width, inside.height));
    cv::Mat target = mask(inside);
    cv::bitwise_or(target, part, target);
  }
  return mask;
}

cv::Mat render(const Scene& s, const cv::Mat& class_map, const cv::Mat& background, const cv::Mat& figures) {
  CV_Assert(class_map.type() == CV_8U);
  cv::Mat out(class_map.size(), CV_8UC3);
  std::array<cv::Vec3b, kClasses> colour;
  for (int k = 0; k < kClasses; ++k) colour[k] = bgr(s.grains.colors[k]);
  const cv::Vec3b blank = bgr(s.render.background_color);
  tbb::parallel_for(0, out.rows, [&](int y) {
    const uint8_t* cls = class_map.ptr<uint8_t>(y);
    cv::Vec3b* px = out.ptr<cv::Vec3b>(y);
    const cv::Vec3b* bg = background.empty() ? nullptr : background.ptr<cv::Vec3b>(y);
    const uint8_t* fig = figures.empty() ? nullptr : figures.ptr<uint8_t>(y);
    for (int x = 0; x < out.cols; ++x) {
      if (cls[x] == kNoSand) {
        px[x] = bg ? bg[x] : blank;
      } else if (fig && fig[x]) {  // paper §10: C1 with probability 0.7, C2 with 0.3
        const uint64_t pixel = uint64_t(y) * uint64_t(out.cols) + uint64_t(x);
        px[x] = colour[uniform(s.layout(), Stream::Figure, pixel) < 0.7 ? 0 : 1];
      } else {
        px[x] = colour[cls[x]];
      }
    }
  });
  return out;
}

int mirror_over(cv::Mat& class_map, uint8_t no_sand) {
  CV_Assert(class_map.type() == CV_8U);
  // The mirror row is the deepest valley of the surface: below it every
  // column is sand, so the flipped copy laid over the picture leaves no hole.
  int axis = 0;
  for (int x = 0; x < class_map.cols; ++x) {
    int y = 0;
    while (y < class_map.rows && class_map.at<uint8_t>(y, x) == no_sand) ++y;
    axis = std::max(axis, y);
  }
  // Row axis - 1 - i shows row axis + i, over whatever was there (the copy is
  // placed over the picture, covering the peaks that rose above the valley).
  for (int i = 0; axis - 1 - i >= 0 && axis + i < class_map.rows; ++i)
    class_map.row(axis + i).copyTo(class_map.row(axis - 1 - i));
  return axis;
}

}  // namespace sandpic
