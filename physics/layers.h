#pragma once
// paper §8.1, Algorithm 2: the static and fixed layers' heights per column,
// and the rules that move a grain from dynamic to static to fixed. Pure
// functions over plain arrays, so the rules are tested without Bullet.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sandpic {

enum class Layer : uint8_t { Waiting, Dynamic, Static, Fixed };

struct LayerHeights {
  std::vector<double> hs, hf;  // paper H_s[j], H_f[j]: heights (px above the floor) per pixel column
  explicit LayerHeights(int columns) : hs(size_t(columns), 0.0), hf(size_t(columns), 0.0) {}
  int columns() const { return int(hs.size()); }
  int column(double x) const;  // paper: j = floor(x + 0.5), clamped to the window
};

// paper §8.1's θ(x, y) from the static heights of the two neighbouring
// columns, taken as the steepest drop to either side rather than the paper's
// signed mean (θ1 + θ2)/2: on a peak's apex the mean is 0, so grains landing
// there became static at once and a narrow stream built a spike (50° flanks
// where every grain a body gave 25°; with the steepest drop, 31°).
double static_slope_rad(const LayerHeights& h, double x, double y);

struct LayerRule {
  double rest_px = 0;           // at rest: moved less than this in a cycle
  int rest_cycles_any_slope = 0;  // 0: never static on a slope steeper than α
  double slope_limit_rad = 0;   // α
  double band_px = 0;           // static layer thickness
};

// Algorithm 2 lines 1-12: a dynamic grain that moved `moved` px in the last
// cycle and has rested `rested` cycles in a row becomes static? Updates H_s.
bool becomes_static(LayerHeights& h, const LayerRule& r, double x, double y, double moved, int rested);
// Algorithm 2 lines 13-21: a static grain becomes fixed? Updates H_f.
bool becomes_fixed(LayerHeights& h, const LayerRule& r, double x, double y);

}  // namespace sandpic
