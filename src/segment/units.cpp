// The falling units: automatic ellipses (paper §5.1, Fig. 6a), listed
// ellipses, the tessellation's own cells (Fig. 4b, 5b), ellipses under a
// sketch (§5.2, src/segment/sketch.cpp) or a regular pattern's rows (§10,
// src/segment/pattern.cpp).
#include <algorithm>
#include <cmath>

#include "src/errors.h"
#include "src/rng.h"
#include "src/segment/pattern.h"
#include "src/segment/segment.h"
#include "src/segment/sketch.h"

namespace sandpic {

Vec2 Unit::centre() const { return is_ellipse ? ellipse.c : Vec2((x0 + x1) / 2, (y0 + y1) / 2); }

Vec2 Unit::outlet() const { return is_ellipse ? ellipse.lowest() : Vec2((x0 + x1) / 2, y1); }

double Unit::width() const {
  if (!is_ellipse) return x1 - x0;
  double xa, xb;
  return ellipse.row_span(ellipse.c.y(), xa, xb) ? xb - xa : 0;
}

bool Unit::row_span(double y, double& xa, double& xb) const {
  if (is_ellipse) return ellipse.row_span(y, xa, xb);
  if (y < y0 || y >= y1) return false;
  xa = x0, xb = x1;
  return true;
}

double Unit::distance_outside(const Vec2& p) const {
  if (is_ellipse) return ellipse.distance_outside(p);
  double dx = std::max({x0 - p.x(), 0.0, p.x() - x1}), dy = std::max({y0 - p.y(), 0.0, p.y() - y1});
  return std::hypot(dx, dy);
}

void Unit::shift(const Vec2& d) {
  ellipse.c += d;
  x0 += d.x(), x1 += d.x(), y0 += d.y(), y1 += d.y();
}

namespace {

Unit ellipse_unit(const Ellipse& e) {
  Unit u;
  u.ellipse = e;
  return u;
}

// paper §5.1: ellipses of varying sizes covering the region, larger toward
// the bottom (near mountains are larger). Rows are laid from the bottom up,
// each offset by half a spacing from the one below, like bricks, so the
// gaps of one row fall on the centres of the next.
std::vector<Unit> automatic_ellipses(const Scene& s) {
  const auto& sg = s.segment;
  const double W = s.window.width, H = s.region.height;
  const double e_mid = (sg.eccentricity_min + sg.eccentricity_max) / 2;
  std::vector<Unit> units;
  double bottom = H;
  for (int row = 0; bottom > 0; ++row) {
    KeyedRng rng(s.layout(), Stream::Ellipses, uint64_t(row));
    double a = sg.semi_major_min + (sg.semi_major_max - sg.semi_major_min) * std::clamp(bottom / H, 0.0, 1.0);
    double b = a * std::sqrt(1 - e_mid * e_mid);
    double cy = bottom - 0.75 * b;
    double spacing = 1.5 * a;
    double x = (row % 2 ? 0.0 : -0.5 * spacing) + rng.real(-0.2, 0.2) * spacing;
    for (; x < W + 0.5 * spacing; x += spacing) {
      double e = rng.real(sg.eccentricity_min, sg.eccentricity_max);
      double ai = a * rng.real(0.85, 1.15);
      double cx = x + rng.real(-0.12, 0.12) * spacing;
      units.push_back(ellipse_unit(Ellipse{Vec2(cx, cy), ai, ai * std::sqrt(1 - e * e), 0}));
    }
    bottom = cy - 0.5 * b;
  }
  return units;
}

}  // namespace

std::vector<Unit> make_units(const Scene& s, const Tessellation& t) {
  std::vector<Unit> units;
  switch (s.segment.method) {
    case SegmentMethod::Ellipses:
      return automatic_ellipses(s);
    case SegmentMethod::Sketch:
      return sketch_units(s, scene_sketch(s));
    case SegmentMethod::Pattern:
      return pattern_units(s);
    case SegmentMethod::Explicit:
      for (const EllipseSpec& e : s.segment.ellipses) units.push_back(ellipse_unit(Ellipse::from(e)));
      return units;
    case SegmentMethod::Cells:
      if (t.cells.empty())
        throw key_error("segment.method", "'cells' needs init.method=tessellation (a halftone has no cells)");
      for (const Cell& c : t.cells) {
        Unit u;
        u.is_ellipse = false;
        u.x0 = c.x0, u.y0 = c.y0, u.x1 = c.x1, u.y1 = c.y1;
        units.push_back(u);
      }
      return units;
  }
  return units;
}

}  // namespace sandpic
