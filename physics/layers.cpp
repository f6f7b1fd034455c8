#include "physics/layers.h"

#include <algorithm>
#include <cmath>

namespace sandpic {

int LayerHeights::column(double x) const { return std::clamp(int(std::floor(x + 0.5)), 0, columns() - 1); }

double LayerHeights::outline(double x, double y, double r, int j) {
  const double dx = std::max(0.0, std::abs(j - x) - 0.5);  // to the column's nearest point
  return dx >= r ? y : y + std::sqrt(r * r - dx * dx);
}

double LayerHeights::highest(const std::vector<double>& layer, double x, double r) const {
  double top = 0;
  for (int j = first_column(x, r); j <= last_column(x, r); ++j) top = std::max(top, layer[size_t(j)]);
  return top;
}

void LayerHeights::add_static(double x, double y, double r) {
  for (int j = first_column(x, r); j <= last_column(x, r); ++j)
    hs[size_t(j)] = std::max(hs[size_t(j)], outline(x, y, r, j));
}

void LayerHeights::add_fixed(double x, double y, double r) {
  for (int j = first_column(x, r); j <= last_column(x, r); ++j)
    hf[size_t(j)] = std::max(hf[size_t(j)], outline(x, y, r, j));
}

double LayerHeights::lowest_hs(int j, int reach) const {
  double low = hs[size_t(j)];
  for (int i = std::max(0, j - reach); i <= std::min(columns() - 1, j + reach); ++i) low = std::min(low, hs[size_t(i)]);
  return low;
}

double LayerHeights::surface(int j, double floor_px) const {
  double sum = 0;
  int n = 0;
  for (int i = std::max(0, j - 1); i <= std::min(columns() - 1, j + 1); ++i, ++n) sum += std::max(hs[size_t(i)], floor_px);
  return sum / n;
}

double static_slope_rad(const LayerHeights& h, double x, int baseline, double floor_px) {
  const int j = h.column(x);
  const double level = h.surface(j, floor_px);
  // Beyond a wall there is no drop: the wall holds the grain.
  double steepest = -INFINITY;
  for (int side : {-1, 1}) {
    const int k = j + side * baseline;
    if (k < 0 || k >= h.columns()) continue;
    steepest = std::max(steepest, std::atan2(level - h.surface(k, floor_px), double(baseline)));
  }
  return std::isfinite(steepest) ? steepest : 0;
}

bool becomes_static(const LayerHeights& h, const LayerRule& rule, double x, double y, double r, double moved,
                    int rested) {
  if (moved >= rule.rest_px || rested < 1) return false;
  if (y - r > h.support(x, r) + rule.support_px) return false;  // on a moving grain
  // A grain at rest for long enough becomes static wherever it lies.
  if (rule.patience_cycles > 0 && rested >= rule.patience_cycles) return true;
  // paper §8.1: θ < α keeps grains on a too-steep static slope moving, so
  // the static layer never grows steeper than α.
  return static_slope_rad(h, x, rule.baseline, rule.floor_px) < rule.slope_limit_rad;
}

bool becomes_fixed(const LayerHeights& h, const LayerRule& rule, double x, double y, double r) {
  if (y - r > h.fixed_support(x, r) + rule.support_px) return false;  // on a grain not yet fixed
  return y + r < h.lowest_hs(h.column(x), rule.baseline) - rule.band_px;
}

}  // namespace sandpic
