#include "src/segment/pattern.h"

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
