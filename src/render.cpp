#include "src/render.h"

#include <opencv2/imgproc.hpp>
#include <tbb/parallel_for.h>

#include "src/init/init.h"
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

cv::Mat render(const Scene& s, const cv::Mat& class_map, const cv::Mat& background) {
  CV_Assert(class_map.type() == CV_8U);
  cv::Mat out(class_map.size(), CV_8UC3);
  std::array<cv::Vec3b, kClasses> colour;
  for (int k = 0; k < kClasses; ++k) colour[k] = bgr(s.grains.colors[k]);
  const cv::Vec3b blank = bgr(s.render.background_color);
  tbb::parallel_for(0, out.rows, [&](int y) {
    const uint8_t* cls = class_map.ptr<uint8_t>(y);
    cv::Vec3b* px = out.ptr<cv::Vec3b>(y);
    const cv::Vec3b* bg = background.empty() ? nullptr : background.ptr<cv::Vec3b>(y);
    for (int x = 0; x < out.cols; ++x)
      px[x] = cls[x] != kNoSand ? colour[cls[x]] : (bg ? bg[x] : blank);
  });
  return out;
}

}  // namespace sandpic
