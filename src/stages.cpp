#include "src/stages.h"

#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

#include "src/regions.h"
#include "src/release.h"
#include "src/render.h"
#include "src/segment/sketch.h"

namespace sandpic {
namespace {

cv::Mat region_classes(const Scene& s, const GrainSet& g) {
  cv::Mat img(g.height, g.width, CV_8UC3);
  for (int64_t id = 0; id < g.size(); ++id)
    img.at<cv::Vec3b>(int(id / g.width), int(id % g.width)) = bgr(s.grains.colors[g.cls[size_t(id)]]);
  return img;
}

cv::Mat initialization(const Scene& s, const Initialization& init) {
  if (!init.input.empty()) {  // Fig. 3b: the luminance that is halftoned
    cv::Mat grey, img;
    init.input.convertTo(grey, CV_8U);
    cv::cvtColor(grey, img, cv::COLOR_GRAY2BGR);
    return img;
  }
  cv::Mat img(s.region.height, s.window.width, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Mat areas = area_map(s);
  for (const Cell& c : init.tessellation.cells) {  // Fig. 2a: the cells; Fig. 17a: each area's own
    cv::Mat cell = img(cv::Rect(c.x0, c.y0, c.x1 - c.x0, c.y1 - c.y0));
    cv::Mat mask;
    if (!areas.empty()) mask = areas(cv::Rect(c.x0, c.y0, c.x1 - c.x0, c.y1 - c.y0)) == c.area;
    cv::Mat drawn = cell.clone();
    cv::rectangle(drawn, cv::Point(0, 0), cv::Point(drawn.cols - 1, drawn.rows - 1), cv::Scalar(0, 0, 0), 1);
    drawn.copyTo(cell, mask);
  }
  return img;
}

void draw_units(const Scene& s, const Segmentation& seg, cv::Mat& img) {
  const ReleaseModel model = release_model(s);
  for (const Unit& u : seg.units) {
    if (u.is_ellipse) {
      const Ellipse& e = u.ellipse;
      // paper Fig. 8: inserted narrow ellipses in red
      cv::ellipse(img, cv::Point2d(e.c.x(), e.c.y()), cv::Size2d(e.a, e.b), e.theta * 180 / std::numbers::pi, 0, 360,
                  u.inserted ? cv::Scalar(0, 0, 230) : cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    } else {
      cv::rectangle(img, cv::Point2d(u.x0, u.y0), cv::Point2d(u.x1 - 1, u.y1 - 1), cv::Scalar(0, 0, 0), 1);
    }
    const Outlet o = outlet(model, u);  // paper Fig. 10: the outlet, in orange
    cv::line(img, cv::Point2d(o.centre.x() - o.width / 2, o.centre.y() - 1),
             cv::Point2d(o.centre.x() + o.width / 2, o.centre.y() - 1), cv::Scalar(0, 140, 255), 2);
  }
}

// paper Fig. 8: ridge lines in blue, arc-like curves in green.
void draw_sketch(const Sketch& k, cv::Mat& img) {
  draw_lines(img, k.ridges, cv::Scalar(200, 80, 20), 2);
  draw_lines(img, k.arcs, cv::Scalar(40, 170, 40), 2);
}

// Fig. 2h: release rank of every grain, early (blue) to late (red).
cv::Mat falling_order_map(const GrainSet& g, const FallingOrder& order) {
  cv::Mat rank(g.height, g.width, CV_8U);
  const double n = std::max<double>(1, double(order.grain.size()) - 1);
  for (size_t i = 0; i < order.grain.size(); ++i) {
    int32_t id = order.grain[i];
    rank.at<uint8_t>(id / g.width, id % g.width) = uint8_t(std::lround(255 * double(i) / n));
  }
  cv::Mat img;
  cv::applyColorMap(rank, img, cv::COLORMAP_TURBO);
  return img;
}

}  // namespace

Stages stage_pictures(const Scene& s, const Initialization& init, const Segmentation& seg, const FallingOrder& order) {
  Stages out;
  out.emplace_back("1-initialization.png", initialization(s, init));
  cv::Mat filled = region_classes(s, init.grains);
  out.emplace_back("2-filled.png", filled);
  cv::Mat segmented = filled.clone();
  if (s.segment.method == SegmentMethod::Sketch) draw_sketch(scene_sketch(s), segmented);
  draw_units(s, seg, segmented);
  out.emplace_back("3-segmentation.png", segmented);
  out.emplace_back("4-falling-order.png", falling_order_map(init.grains, order));
  return out;
}

}  // namespace sandpic
