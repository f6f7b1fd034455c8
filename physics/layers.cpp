#include "physics/layers.h"

#include <algorithm>
#include <cmath>

namespace sandpic {

int LayerHeights::column(double x) const { return std::clamp(int(std::floor(x + 0.5)), 0, columns() - 1); }

double static_slope_rad(const LayerHeights& h, double x, double y) {
  const int j = h.column(x), n = h.columns();
  const int r = std::min(j + 1, n - 1), l = std::max(j - 1, 0);
  double t1 = r != j ? std::atan((h.hs[size_t(r)] - y) / (r - x)) : 0;
  double t2 = l != j ? std::atan((y - h.hs[size_t(l)]) / (x - l)) : 0;
  return 0.5 * (t1 + t2);
}

bool becomes_static(LayerHeights& h, const LayerRule& r, double x, double y, double moved, int rested) {
  if (moved >= r.rest_px) return false;
  // The paper's |θ| < α keeps grains on a too-steep static slope moving; a
  // grain that has rested several cycles in a row is held by its neighbours
  // whatever the slope, and would otherwise stay in the active set for ever.
  if (rested < r.rest_cycles_any_slope && std::abs(static_slope_rad(h, x, y)) >= r.slope_limit_rad) return false;
  double& hs = h.hs[size_t(h.column(x))];
  hs = std::max(hs, y);
  return true;
}

bool becomes_fixed(LayerHeights& h, const LayerRule& r, double x, double y) {
  const int c = h.column(x);
  const size_t j = size_t(c);
  // The paper looks at column j alone; one tall static grain in a column
  // would then fix grains beside the flow. The lowest H_s within two columns
  // keeps the band whole under the height field's interpolation too.
  double hs = h.hs[j];
  for (int i = std::max(0, c - 2); i <= std::min(h.columns() - 1, c + 2); ++i) hs = std::min(hs, h.hs[size_t(i)]);
  if (!(hs - h.hf[j] > r.band_px && y < hs - r.band_px)) return false;
  h.hf[j] = std::max(h.hf[j], y);
  return true;
}

}  // namespace sandpic
