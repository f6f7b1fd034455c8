#pragma once
// paper §5.2, Fig. 7-8: segmentation guided by a sketch. Long ridge lines
// suggest mountain ridges, arc-like curves across them mountain profiles;
// an ellipse goes under every crossing, smaller the higher it is, and where
// two crossings along a ridge are far apart two long narrow ellipses on the
// lower one keep the ridge visible in the piles.
#include <vector>

#include <opencv2/core.hpp>

#include "src/segment/segment.h"

namespace sandpic {

struct Sketch {
  std::vector<std::vector<Vec2>> ridges, arcs;  // window px, y down
  // Crossings of one arc and one ridge closer than this along the ridge are
  // one: a line through a corner point, or a stroke's line wavering where
  // it was joined across the other stroke.
  double merge_px = 0.5;
};

// paper Ψ_P: a crossing of an arc with a ridge line.
struct Crossing {
  Vec2 p;
  int ridge = 0, arc = 0;
  double along = 0;  // distance along the ridge from its first point
};

// The sketch of a scene: its lines, or the strokes of segment.sketch.image.
Sketch scene_sketch(const Scene& s);

// The strokes of a picture (BGR; resized to width x height if it is not)
// in the two colours: each connected stroke becomes a line through its
// middle. Where one stroke is drawn over the other, the covered stroke is
// joined across the gap.
Sketch sketch_from_image(const cv::Mat& bgr, Rgb ridge, Rgb arc, int width, int height);

// The sketch drawn as a picture of the region (BGR, white ground), strokes
// `thickness` px wide in the two colours, arcs over ridges: what
// sketch_from_image reads back, for a designer to paint over.
cv::Mat sketch_image(const Sketch& k, Rgb ridge, Rgb arc, int width, int height, int thickness);

// Draws lines (antialiased) on a BGR picture: the sketch picture and --stages share it.
void draw_lines(cv::Mat& img, const std::vector<std::vector<Vec2>>& lines, cv::Scalar bgr, int thickness);

// Every crossing of an arc with a ridge, by ridge and then along it.
std::vector<Crossing> crossings(const Sketch& k);

// The paper's semi-major axis for a crossing at window y `y` (px, y down) in
// a region of height `region_h`: 0.5 A_m - α P(y) (segment.sketch.shrink_per_px), P(y) measured up from
// the region's bottom, at least segment.sketch.semi_major_floor.
double sketch_semi_major(const Scene& s, double a_m, double y);

// A_m: the region's width over the number of ridge lines that reach the
// bottom band of the region (at least one).
double sketch_max_major(const Scene& s, const Sketch& k);

// The falling units of a sketch: one ellipse per crossing inside the region,
// and the inserted narrow ellipses (Unit::inserted).
std::vector<Unit> sketch_units(const Scene& s, const Sketch& k);

// The narrow ellipses' centres sit on the lower ellipse at these parametric
// angles, measured from its major axis upward (the paper leaves the ranges
// to the implementer): upper right and upper left, 20° wide, so the two
// flank the ridge where it leaves the top of the lower ellipse's pile.
constexpr double kNarrowRightMinDeg = 30, kNarrowRightMaxDeg = 50;
constexpr double kNarrowLeftMinDeg = 130, kNarrowLeftMaxDeg = 150;
constexpr double kNarrowMajorRatio = 0.6;  // paper: 0.6 a of the lower ellipse
constexpr double kNarrowEccMin = 0.96, kNarrowEccMax = 0.98;

}  // namespace sandpic
