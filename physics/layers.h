#pragma once
// paper §8.1, Algorithm 2: the static and fixed layers' heights per column,
// and the rules that move a grain from dynamic to static to fixed. Pure
// functions over plain arrays, so the rules are tested without Bullet.
//
// Where we depart from the paper, and why (each departure's cost in accuracy
// is measured against all-dynamic by `sandpic bench-layers`):
// - H_s and H_f hold the *top outline* of the layer over every pixel column a
//   grain covers, not the centre height of the grains whose centres round to
//   the column. Our grains are 0.56-1.11 px wide: with centres only, most
//   columns had no static grain, every neighbour looked like a cliff, and
//   almost no grain ever passed the slope test (51 static of 2,550).
// - The slope θ is the steepest drop of the static surface, H_s smoothed
//   over 3 columns, from the grain's column to the same smoothed H_s a few
//   grain diameters to either side (`baseline` columns), not the signed mean
//   (θ1 + θ2)/2 one column away: the mean is 0 on an apex (a narrow stream
//   then built 50-65° spikes), and one column is grain-scale noise. Both
//   ends are read alike, so the outline's dips between grains cancel, and
//   the bare floor counts as a layer of the largest grains' tops
//   (`floor_px`). We measured from the grain's bottom to H_s (the grains'
//   tops) before: a grain nested in a flank has its bottom 0.3-1.1 px under
//   the tops beside it, so over 4 columns the drop read up to 15° low and
//   the static layer grew past α (17° under verify-dem's quick heap at α
//   9.2°). From the grain's top, a grain lying on a flat static bed read as
//   a 14° bump, and no new layer could start below that.
// - A grain becomes static only where it rests on the static layer (its
//   bottom within `support_px` of H_s): a resting grain on top of a moving
//   one stays dynamic, so the static layer grows from the floor up, whole.
// - Rest is a displacement over a cycle, not the paper's 3×10⁻⁵ m/s (far
//   below any solver's resting jitter).
// - Where a static grain uphill reaches over the grain's column (beside a
//   flank), its outline is part of the surface there: the grain would
//   extend the flank, and stays dynamic beside one steeper than α.
// - α is the angle all-dynamic piles stand at unless the scene sets it
//   (dem_slope_limit_deg), not the paper's fixed 30°.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sandpic {

enum class Layer : uint8_t { Waiting, Dynamic, Static, Fixed };

struct LayerHeights {
  // paper H_s[j], H_f[j]: top of the static layer (static grains, and the
  // fixed layer and floor under them) and of the fixed layer, px above the
  // floor, per pixel column j (centred on x = j).
  std::vector<double> hs, hf;
  explicit LayerHeights(int columns) : hs(size_t(columns), 0.0), hf(size_t(columns), 0.0) {}
  int columns() const { return int(hs.size()); }
  int column(double x) const;  // paper: j = floor(x + 0.5), clamped to the window

  // Columns [first, last] a grain of radius r centred at x covers, and its
  // upper outline over column j (its top at the column's nearest point).
  int first_column(double x, double r) const { return column(x - r); }
  int last_column(double x, double r) const { return column(x + r); }
  static double outline(double x, double y, double r, int j);
  // The highest H_s (H_f) under a grain: what it would rest on.
  double support(double x, double r) const { return highest(hs, x, r); }
  double fixed_support(double x, double r) const { return highest(hf, x, r); }
  // Raise H_s (static) or H_f (fixed) to a grain's outline.
  void add_static(double x, double y, double r);
  void add_fixed(double x, double y, double r);
  // H_s smoothed over columns j - 1 .. j + 1, a column lower than floor_px
  // read as that high: the static surface at a grain's scale.
  double surface(int j, double floor_px) const;
  // The lowest H_s within `reach` columns of j.
  double lowest_hs(int j, int reach) const;

 private:
  double highest(const std::vector<double>& layer, double x, double r) const;
};

// paper §8.1's θ(x, y): the steepest drop of surface() from a grain's
// column to `baseline` columns to either side (radians; negative in a
// hollow).
double static_slope_rad(const LayerHeights& h, double x, int baseline, double floor_px = 0);

struct LayerRule {
  double rest_px = 0;             // at rest: moved less than this in a cycle
  int patience_cycles = 0;        // at rest this many cycles: static anywhere (0: never)
  double slope_limit_rad = 0;     // α
  int baseline = 3;               // columns to either side for θ
  double support_px = 0;          // resting on the static layer: bottom at most this above H_s
  double band_px = 0;             // static layer thickness
  double floor_px = 0;            // the bare floor counts as a layer this high (the largest diameter)
};

// Algorithm 2 lines 1-12: a dynamic grain of radius r at (x, y) that moved
// `moved` px in the last cycle and has rested `rested` cycles in a row
// becomes static? (The caller then calls add_static.)
bool becomes_static(const LayerHeights& h, const LayerRule& rule, double x, double y, double r, double moved,
                    int rested);
// Algorithm 2 lines 13-21: a static grain becomes fixed once its top lies
// deeper than the band under the lowest H_s nearby (the paper looks at column
// j alone: one tall static grain would then fix grains beside the flow), and
// only resting on the fixed layer (its bottom within `support_px` of H_f),
// so that layer grows from the floor up, whole, as the static layer does.
// A grain fixed on one not yet at rest cages it: a static body under fixed
// grains, squeezed by the pile, overlapped its neighbour by 0.31 diameters
// that no step could undo, and the sub-steps went to 8.
bool becomes_fixed(const LayerHeights& h, const LayerRule& rule, double x, double y, double r);

}  // namespace sandpic
