// paper §10, Fig. 18: a regular pattern's thin separating rectangles,
// painted in their class at initialization.
#include <algorithm>
#include <cmath>

#include "src/init/init.h"
#include "src/pattern_rows.h"

namespace sandpic {

void paint_separators(const Scene& s, GrainSet& g) {
  const auto& p = s.segment.pattern;
  if (s.segment.method != SegmentMethod::Pattern || p.separator_class == 0 || p.separator <= 0) return;
  const uint8_t k = uint8_t(p.separator_class - 1);
  for (const PatternRow& r : pattern_rows(s)) {
    // Pixel rows whose centres lie in the separator.
    const int from = std::max(0, int(std::ceil(r.separator_y0 - 0.5)));
    const int to = std::min(g.height - 1, int(std::ceil(r.separator_y1 - 0.5)) - 1);
    for (int y = from; y <= to; ++y) std::fill_n(g.cls.begin() + size_t(y) * g.width, g.width, k);
  }
}

}  // namespace sandpic
