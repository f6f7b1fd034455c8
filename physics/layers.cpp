#include "physics/layers.h"

#include <algorithm>
#include <cmath>

namespace sandpic {

int LayerHeights::column(double x) const { return std::clamp(int(std::floor(x + 0.5)), 0, columns() - 1); }

double static_slope_rad(const LayerHeights& h, double x, double y) {
  const int j = h.column(x), n = h.columns();
  const int r = std::min(j + 1, n - 1), l = std::max(j - 1, 0);
  // The paper's θ1, θ2 read as drops: how far the grain would fall to reach
  // the static surface one column to either side.
  double drop_r = r != j ? std::atan((y - h.hs[size_t(r)]) / (r - x)) : -INFINITY;
  double drop_l = l != j ? std::atan((y - h.hs[size_t(l)]) / (x - l)) : -INFINITY;
  double steepest = std::max(drop_r, drop_l);
  return std::isfinite(steepest) ? steepest : 0;
}

bool becomes_static(LayerHeights& h, const LayerRule& r, double x, double y, double moved, int rested) {
  if (moved >= r.rest_px) return false;
  // paper §8.1: θ < α keeps grains on a too-steep static slope moving, so
  // the static layer never grows steeper than α. Optionally (a speed-up, at
  // a cost in accuracy), a grain that rested several cycles in a row becomes
  // static whatever the slope.
  const bool patient = r.rest_cycles_any_slope > 0 && rested >= r.rest_cycles_any_slope;
  if (!patient && static_slope_rad(h, x, y) >= r.slope_limit_rad) return false;
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
