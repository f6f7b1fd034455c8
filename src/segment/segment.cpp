#include "src/segment/segment.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <tbb/parallel_for.h>

#include "src/rng.h"

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

std::vector<int32_t> assign_grains(const std::vector<Unit>& units, int width, int height) {
  std::vector<int32_t> owner(size_t(width) * height, -1);
  tbb::parallel_for(0, height, [&](int y) {
    int32_t* row = owner.data() + size_t(y) * width;
    const double yc = y + 0.5;
    for (size_t u = 0; u < units.size(); ++u) {  // falling order: the first unit wins an overlap
      double xa, xb;
      if (!units[u].row_span(yc, xa, xb)) continue;
      // Pixel centres x + 0.5 inside [xa, xb].
      int from = std::max(0, int(std::ceil(xa - 0.5))), to = std::min(width - 1, int(std::floor(xb - 0.5)));
      for (int x = from; x <= to; ++x)
        if (row[x] < 0) row[x] = int32_t(u);
    }
    for (int x = 0; x < width; ++x) {
      if (row[x] >= 0) continue;
      Vec2 p(x + 0.5, yc);
      double best = INFINITY;
      for (size_t u = 0; u < units.size(); ++u) {
        double d = units[u].distance_outside(p);
        if (d < best) best = d, row[x] = int32_t(u);
      }
    }
  });
  return owner;
}

Segmentation segment(const Scene& s, const Tessellation& t) {
  Segmentation seg;
  seg.units = make_units(s, t);
  order_units(seg.units, s.order.row_tolerance, s.layout());
  seg.unit_of = assign_grains(seg.units, s.window.width, s.region.height);
  return seg;
}

}  // namespace sandpic
