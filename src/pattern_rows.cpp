#include "src/pattern_rows.h"

#include <algorithm>
#include <cmath>

#include "src/rng.h"

namespace sandpic {

std::vector<PatternRow> pattern_rows(const Scene& s) {
  const auto& p = s.segment.pattern;
  const double H = s.region.height;
  std::vector<PatternRow> rows;
  for (double bottom = H; bottom > 0.5;) {
    KeyedRng rng(s.layout(), Stream::Pattern, rows.size());
    PatternRow r;
    double h = rng.real(p.row_height_min, p.row_height_max);
    // What is left above would make a sliver row: this row takes it.
    if (bottom - h - p.separator < p.row_height_min) h = bottom;
    r.y1 = bottom, r.y0 = std::max(0.0, bottom - h);
    // "two neighboring ellipses of different major and minor axis": the
    // second is drawn until it differs from the first by a fifth at least.
    r.a1 = rng.real(p.semi_major_min, p.semi_major_max);
    r.a2 = r.a1;
    for (int tries = 0; tries < 8 && std::abs(r.a2 - r.a1) < 0.2 * r.a1; ++tries)
      r.a2 = rng.real(p.semi_major_min, p.semi_major_max);
    const double half = (r.y1 - r.y0) / 2;
    r.b1 = half * rng.real(p.minor_share_min, p.minor_share_max);
    r.b2 = half * rng.real(p.minor_share_min, p.minor_share_max);
    r.x_start = -rng.real() * r.period();
    r.separator_y1 = r.y0;
    r.separator_y0 = std::max(0.0, r.y0 - p.separator);
    bottom = r.separator_y0;
    rows.push_back(r);
  }
  return rows;
}

}  // namespace sandpic
