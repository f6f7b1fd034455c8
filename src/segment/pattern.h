#pragma once
// paper §9-10, Fig. 18: regular patterns. Full-width rows from the bottom of
// the region up, each covered by one unit of two ellipses of different axes
// repeated along x, with thin separating rectangles between the rows.
#include <vector>

#include "src/segment/segment.h"

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

// The units, each with its band: row k is band 2k, its separator 2k + 1, so
// a separator falls after the row below it and before the row above (§6).
std::vector<Unit> pattern_units(const Scene& s);

// The separators' grains take segment.pattern.separator_class (when > 0), so
// the thin rectangles draw lines between the patterned strips.
void paint_separators(const Scene& s, GrainSet& g);

}  // namespace sandpic
