#pragma once
// paper §9-10, Fig. 18: regular patterns as units. Each row
// (src/pattern_rows.h) is covered by one unit of two ellipses of different
// axes repeated along x, with its thin separating rectangle.
#include <vector>

#include "src/pattern_rows.h"
#include "src/segment/segment.h"

namespace sandpic {

// The units, each with its band: row k is band 2k, its separator 2k + 1, so
// a separator falls after the row below it and before the row above (§6).
std::vector<Unit> pattern_units(const Scene& s);

}  // namespace sandpic
