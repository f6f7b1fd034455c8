#pragma once
// paper §4: initialization of the region, by tessellation and filling
// (§4.3-4.4, Algorithm 1) or by halftoning an input picture (§4.2).
#include <vector>

#include <opencv2/core.hpp>

#include "src/grains.h"
#include "src/scene.h"

namespace sandpic {

// A rectangle of the tessellation, half-open [x0, x1) x [y0, y1) in region px.
struct Cell {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int dominant = 0, secondary = 1;  // classes drawn by Algorithm 1
  int area = 0;  // paper §10, Fig. 17: 0 the scene's own, else 1 + its area in s.regions
};

struct Tessellation {
  std::vector<Cell> cells;  // row by row from the top-left
};

Tessellation tessellate(const Scene& s);

// paper Algorithm 1: per cell a dominant and a non-dominant class, then each
// grain dominant with probability init.dominant_share.
void fill_cells(const Scene& s, Tessellation& t, GrainSet& g);

// paper §4.2: BT.601 luminance, then 4-level Floyd-Steinberg error diffusion;
// level k from dark to light becomes class S(k+1). `lum` is the region's
// luminance (CV_64F, 0..255), as luminance() makes it.
GrainSet halftone(const Scene& s, const cv::Mat& lum);
// The luminance picture halftoning works on, resized to the region (Fig. 3b).
cv::Mat luminance(const cv::Mat& bgr, int width, int height);

// Reads an image file for the pipeline, as 8-bit BGR; names the file on failure.
cv::Mat read_image(const std::string& path, const std::string& key);

struct Initialization {
  Tessellation tessellation;  // empty for halftone
  GrainSet grains;
  cv::Mat input;  // halftone input as luminance, for --stages
};

// The region's grains, with every area of s.regions (Fig. 17) initialized by
// its own scene inside its rectangle; cells in window px, tagged by area.
Initialization initialize(const Scene& s);

// paper §10, Fig. 18: the separators' grains take
// segment.pattern.separator_class (when > 0), so the thin rectangles draw
// lines between the patterned strips.
void paint_separators(const Scene& s, GrainSet& g);

}  // namespace sandpic
