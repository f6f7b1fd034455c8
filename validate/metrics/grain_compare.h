#pragma once
// Two runs of one scene compared grain by grain (render --grains),
// not only by their pictures. A grain's travel is how far from the point its
// fall started it came to rest (|x - release_x|): the part of the pile's
// shape the backend's piling decides, per class. Two DEM runs with different
// physics seeds release their grains at different points, so their travel
// distributions compare (the noise floor) but their grains do not; two runs
// with the same seed (a lattice and a DEM run) also compare grain by grain.
#include <array>
#include <vector>

#include "src/grain_table.h"
#include "src/scene.h"

namespace sandpic {

struct TravelStats {
  int64_t grains = 0;
  double mean_px = 0, median_px = 0, p90_px = 0;
  double within_2px = 0;  // share of the class that rests within 2 px of where its fall started
};

struct GrainComparison {
  int64_t grains = 0;
  bool same_release = false;  // every grain's fall starts at the same point in both runs
  std::array<TravelStats, kClasses> travel_a, travel_b;
  // Per class, the mean |difference| between the two sorted travel
  // distributions (Wasserstein-1, px): 0 when grains travel alike.
  std::array<double, kClasses> travel_distance_px{};
  // Mean over grains of the standard deviation of their unit's resting x:
  // how widely a unit's sand spreads.
  double unit_spread_a_px = 0, unit_spread_b_px = 0;
  // Per unit, grain-weighted means over the units: how far apart the two runs
  // put a unit's sand (|Δ mean resting x|) and how differently widely they
  // spread it (|Δ standard deviation|). A layout's units are the same in any
  // physics seed, so these compare two DEM seeds too (their noise floor).
  double unit_centroid_distance_px = 0, unit_spread_difference_px = 0;
  // Mean |Δx| and |Δy| of each grain between the runs; NaN unless same_release.
  double grain_dx_px = 0, grain_dy_px = 0;
};

// Throws InputError unless both tables hold the same grains (id, class, unit
// and place in the falling order): they must come from one scene and layout.
GrainComparison compare_grains(const std::vector<GrainRow>& a, const std::vector<GrainRow>& b, const std::string& name_a,
                               const std::string& name_b);

}  // namespace sandpic
