#pragma once
// When a DEM run is over: the sand's outline holds (physics/holds.h). Its
// top in every pixel column is sampled every tenth of kHoldSeconds; the
// outline holds when over the last kHoldSeconds each column spanned less
// than a hold distance, in all columns but a few (kUnsettled of them).
//
// The outline and not every grain: the outline is what the picture shows.
// (Before the resting overlap, physics/grain_solver.h, an all-dynamic heap
// never held grain by grain: 6-9% of its grains moved more than 0.05
// diameters in any second, mostly down, inside the heap.)
// A span and not a distance from where a column last moved: a column
// sinking steadily at half the limit (an all-dynamic heap's surface, as it
// compacts) was counted as moving whenever it crossed the limit again.
// Plain data, tested without Bullet.
#include <cstdint>
#include <deque>
#include <vector>

namespace sandpic {

class OutlineWatch {
 public:
  // hold_px: the span a column may have over kHoldSeconds.
  explicit OutlineWatch(double hold_px) : hold_px_(hold_px) {}
  // Is an outline due at time t (s)? (Every tenth of kHoldSeconds.)
  bool due(double t) const;
  // The outline at time t: the top of the sand per pixel column (px).
  void add(double t, std::vector<double> top);
  // Columns that did not hold over the last kHoldSeconds (all of them until
  // the outlines span kHoldSeconds).
  int64_t moving_columns() const;
  bool holds() const;

 private:
  struct Outline {
    double t;
    std::vector<double> top;
  };
  double hold_px_;
  std::deque<Outline> outlines_;
};

// All but this fraction of the columns must hold: a grain jittering on a
// static layer somewhere must not keep a run going (every body at rest at
// once left some runs going for 12 s of simulated time).
constexpr double kUnsettled = 0.002;

}  // namespace sandpic
