#pragma once
// Helpers shared by the tests: small scenes and pile measurements.
#include <cmath>
#include <vector>

#include <opencv2/core.hpp>

#include "src/pipeline.h"
#include "src/render.h"
#include "src/scene.h"
#include "src/simulator.h"
#include "validate/metrics/silhouette.h"

namespace sandpic::test {

// A scene small enough for a unit test: one ellipse over the middle.
inline Scene one_ellipse_scene(int width = 400, int height = 300, int region = 80) {
  Scene s;
  s.window.width = width;
  s.window.height = height;
  s.region.height = region;
  s.segment.method = SegmentMethod::Explicit;
  s.segment.ellipses = {EllipseSpec{width / 2.0, region / 2.0, width * 0.3, region * 0.45, 0}};
  s.init.tessellation = TessellationKind::Uniform;
  s.init.cell_width = 20;
  s.init.cell_height = 10;
  s.release.outlet_width_mm = 1;  // a narrow outlet: one clean cone
  return s;
}

// The pipeline up to the simulation, without rendering: a backend's raw result.
inline SimResult simulate_scene(const Scene& s, Simulator& sim) {
  const Prepared p = prepare(s);
  Progress quiet(false);
  return sim.simulate(p.input(s), quiet);
}

// A picture's blank pixels in the region and sand pixels below it: a first
// frame of the fall has none of either (every grain waiting at its place).
struct FirstFrameCounts {
  int region_blank = 0, floor_sand = 0;
};
inline FirstFrameCounts first_frame_counts(const Scene& s, const cv::Mat& picture) {
  const cv::Vec3b blank = bgr(s.render.background_color);
  FirstFrameCounts n;
  for (int y = 0; y < picture.rows; ++y)
    for (int x = 0; x < picture.cols; ++x) {
      const bool is_blank = picture.at<cv::Vec3b>(y, x) == blank;
      if (y < s.region.height) n.region_blank += is_blank;
      else n.floor_sand += !is_blank;
    }
  return n;
}

// Sand height of every pixel column of a class map: validate/'s silhouette.
inline std::vector<double> column_heights(const cv::Mat& class_map) { return silhouette(class_map); }

// Slope angle of a single pile, in degrees: validate/'s.
inline double heap_angle_deg(const std::vector<double>& h, double column_width = 1) {
  return sandpic::heap_angle_deg(h, column_width);
}

}  // namespace sandpic::test
