#pragma once
// paper §10, Fig. 18: the rows of a regular pattern, from the bottom of the
// region up, each with the two ellipses of its unit and the thin separating
// rectangle above it. Scene geometry: initialization paints the separators
// (src/init), segmentation makes the units (src/segment/pattern.h).
#include <vector>

#include "src/scene.h"

namespace sandpic {

struct PatternRow {
  double y0 = 0, y1 = 0;            // the row, region px (y down)
  double a1 = 1, b1 = 1, a2 = 1, b2 = 1;  // the unit's two ellipses
  double x_start = 0;               // the first unit's left end (<= 0)
  double separator_y0 = 0, separator_y1 = 0;  // the thin rectangle above the row (empty: none)
  double period() const { return 2 * (a1 + a2); }
};

// Bottom-up; each row's unit drawn from (layout seed, row).
std::vector<PatternRow> pattern_rows(const Scene& s);

}  // namespace sandpic
