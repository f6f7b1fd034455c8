#pragma once
// paper §5-6: the falling units (ellipses, or the tessellation's cells), in
// falling order, and the unit each grain belongs to.
#include <vector>

#include "src/init/init.h"
#include "src/segment/ellipse.h"

namespace sandpic {

struct Unit {
  bool is_ellipse = true;
  Ellipse ellipse;             // when is_ellipse
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // a cell, when !is_ellipse
  int row = 0;                 // paper §6: row of the falling order, 0 = lowest
  bool inserted = false;       // paper §5.2, Fig. 8: a long narrow ellipse beside a ridge
  int band = -1;               // a regular pattern's own row order (Fig. 18), or -1
  int area = 0;                // paper §10, Fig. 17: 0, or 1 + its area in s.regions

  Vec2 centre() const;
  Vec2 outlet() const;  // paper §6-7: middle of the lowest edge
  double width() const;
  bool row_span(double y, double& xa, double& xb) const;
  double distance_outside(const Vec2& p) const;
  void shift(const Vec2& d);
};

struct Segmentation {
  std::vector<Unit> units;       // in falling order
  std::vector<int32_t> unit_of;  // per grain id: index into units
};

// The units of segment.method, in no particular order.
std::vector<Unit> make_units(const Scene& s, const Tessellation& t);
// paper §6: rows by centre height, the lowest row first; random within a row.
// Units that all carry a band (a regular pattern) are in rows by band.
void order_units(std::vector<Unit>& units, double row_tolerance, uint64_t seed);
// Every grain in exactly one unit of its area (area_map as regions.h makes
// it; empty: one area): in an overlap the unit that falls first, in no unit
// the nearest one.
std::vector<int32_t> assign_grains(const std::vector<Unit>& units, int width, int height,
                                   const cv::Mat& area_map = {});

Segmentation segment(const Scene& s, const Tessellation& t);

}  // namespace sandpic
