#include "src/segment/segment.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <tbb/parallel_for.h>

#include "src/errors.h"
#include "src/regions.h"
#include "src/rng.h"
#include "src/scene_file.h"

namespace sandpic {

void order_units(std::vector<Unit>& units, double row_tolerance, uint64_t seed) {
  const size_t n = units.size();
  std::vector<size_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  // Lowest centre first (largest y), then group rows within the tolerance.
  std::stable_sort(idx.begin(), idx.end(),
                   [&](size_t i, size_t j) { return units[i].centre().y() > units[j].centre().y(); });
  std::vector<int> row(n);
  double row_start = 0;
  int r = -1;
  for (size_t i : idx) {
    double y = units[i].centre().y();
    if (r < 0 || row_start - y > row_tolerance) ++r, row_start = y;
    row[i] = r;
  }
  // A regular pattern's rows are its bands: a thin separator is its own row
  // even when its centre is near the ellipses' (Fig. 18).
  if (n > 0 && std::all_of(units.begin(), units.end(), [](const Unit& u) { return u.band >= 0; }))
    for (size_t i = 0; i < n; ++i) row[i] = units[i].band;
  // paper §6: "place the segmentation cells on each row randomly".
  std::vector<uint64_t> tie(n);
  for (size_t i = 0; i < n; ++i) tie[i] = key(seed, Stream::UnitOrder, i);
  std::sort(idx.begin(), idx.end(), [&](size_t i, size_t j) {
    return row[i] != row[j] ? row[i] < row[j] : (tie[i] != tie[j] ? tie[i] < tie[j] : i < j);
  });
  std::vector<Unit> sorted;
  sorted.reserve(n);
  for (size_t i : idx) {
    sorted.push_back(units[i]);
    sorted.back().row = row[i];
  }
  units = std::move(sorted);
}

std::vector<int32_t> assign_grains(const std::vector<Unit>& units, int width, int height, const cv::Mat& area_map) {
  std::vector<int32_t> owner(size_t(width) * height, -1);
  // An area with no unit of its own lends its grains to the nearest unit of any area.
  std::vector<bool> has_units(256, false);
  for (const Unit& u : units) has_units[size_t(u.area)] = true;
  tbb::parallel_for(0, height, [&](int y) {
    int32_t* row = owner.data() + size_t(y) * width;
    const uint8_t* area = area_map.empty() ? nullptr : area_map.ptr<uint8_t>(y);
    auto same_area = [&](int x, const Unit& u) { return !area || !has_units[area[x]] || u.area == area[x]; };
    const double yc = y + 0.5;
    for (size_t u = 0; u < units.size(); ++u) {  // falling order: the first unit wins an overlap
      double xa, xb;
      if (!units[u].row_span(yc, xa, xb)) continue;
      // Pixel centres x + 0.5 inside [xa, xb].
      int from = std::max(0, int(std::ceil(xa - 0.5))), to = std::min(width - 1, int(std::floor(xb - 0.5)));
      for (int x = from; x <= to; ++x)
        if (row[x] < 0 && same_area(x, units[u])) row[x] = int32_t(u);
    }
    for (int x = 0; x < width; ++x) {
      if (row[x] >= 0) continue;
      Vec2 p(x + 0.5, yc);
      double best = INFINITY;
      for (size_t u = 0; u < units.size(); ++u) {
        if (!same_area(x, units[u])) continue;
        double d = units[u].distance_outside(p);
        if (d < best) best = d, row[x] = int32_t(u);
      }
    }
  });
  return owner;
}

namespace {

// Units of an area made by its own scene: automatic ellipses, cells and
// patterns inside its rectangle (a scene of the rectangle's size, shifted);
// listed ellipses and sketches in window px as given. A unit belongs to the
// area its centre lies in.
void add_area_units(const Scene& s, const Tessellation& t, const cv::Mat& map, int area, std::vector<Unit>& out) {
  Scene a = area == 0 ? s : area_scene(s, size_t(area - 1));
  cv::Rect r(0, 0, s.window.width, s.region.height);
  const SegmentMethod m = a.segment.method;
  if (area > 0 && m != SegmentMethod::Explicit && m != SegmentMethod::Sketch) {
    r = area_rect(s, size_t(area - 1));
    a.window.width = r.width, a.region.height = r.height;
  }
  Tessellation own;
  for (Cell c : t.cells)
    if (c.area == area) {
      c.x0 -= r.x, c.x1 -= r.x, c.y0 -= r.y, c.y1 -= r.y;
      own.cells.push_back(c);
    }
  for (Unit u : make_units(a, own)) {
    u.shift(Vec2(r.x, r.y));
    u.area = area;
    const Vec2 c = u.centre();
    if (area_at(map, c.x(), c.y()) == area) out.push_back(u);
  }
}

}  // namespace

Segmentation segment(const Scene& s, const Tessellation& t) {
  Segmentation seg;
  const cv::Mat map = area_map(s);
  if (map.empty()) {
    seg.units = make_units(s, t);
  } else {  // paper §10, Fig. 17: each area segmented by its own scene
    for (int area = 0; area <= int(s.regions.size()); ++area) add_area_units(s, t, map, area, seg.units);
    if (seg.units.empty()) throw key_error("regions", "no falling unit has its centre in any area");
  }
  order_units(seg.units, s.order.row_tolerance, s.layout());
  seg.unit_of = assign_grains(seg.units, s.window.width, s.region.height, map);
  return seg;
}

}  // namespace sandpic
