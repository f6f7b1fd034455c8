#include "src/segment/pattern.h"

#include <algorithm>
#include <cmath>


namespace sandpic {

namespace {

Unit ellipse_at(double cx, double cy, double a, double b, int band) {
  Unit u;
  u.ellipse = Ellipse{Vec2(cx, cy), a, std::max(0.5, b), 0};
  u.band = band;
  return u;
}

}  // namespace

std::vector<Unit> pattern_units(const Scene& s) {
  const double W = s.window.width;
  std::vector<Unit> units;
  const std::vector<PatternRow> rows = pattern_rows(s);
  for (size_t k = 0; k < rows.size(); ++k) {
    const PatternRow& r = rows[k];
    const double cy = (r.y0 + r.y1) / 2;
    // The unit copied along the horizontal axis (paper §10).
    for (double x = r.x_start; x < W; x += r.period()) {
      units.push_back(ellipse_at(x + r.a1, cy, r.a1, r.b1, int(2 * k)));
      units.push_back(ellipse_at(x + 2 * r.a1 + r.a2, cy, r.a2, r.b2, int(2 * k)));
      if (r.separator_y1 - r.separator_y0 >= 0.5) {
        // One rectangle per unit width, each with its own outlet, so the
        // separator settles as a thin layer rather than one heap.
        Unit sep;
        sep.is_ellipse = false;
        sep.x0 = std::max(0.0, x), sep.x1 = std::min(W, x + r.period());
        sep.y0 = r.separator_y0, sep.y1 = r.separator_y1;
        sep.band = int(2 * k + 1);
        if (sep.x1 - sep.x0 >= 1) units.push_back(sep);
      }
    }
  }
  return units;
}

}  // namespace sandpic
