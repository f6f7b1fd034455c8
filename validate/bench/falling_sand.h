#pragma once
// A peer to measure the lattice against: the classic falling-sand cellular
// automaton of pixel sand games. Every grain is one cell of a grid the size
// of the window; each tick, each moving grain falls one cell, straight down if
// that cell is free, else diagonally down to a free side (which side first by
// chance); a grain with the floor, a wall or resting grains in all three
// cells below rests for good (resting cells never empty); one held up by a
// grain still moving tries again next tick. One class, a fixed 45° angle of
// repose. Grains enter at the top row at the columns the
// lattice drops them from, in falling order, a few each tick.
#include <cstdint>
#include <span>

#include <opencv2/core.hpp>

#include "src/pipeline.h"

namespace sandpic {

struct FallingSand {
  cv::Mat grid;            // CV_8U, window size: 1 where a grain rests
  int64_t settled = 0;     // grains at rest in the grid
  int64_t lost = 0;        // grains that found their entry cell full for good
  int64_t ticks = 0;
  int64_t moves = 0;       // cells fallen, summed over grains
};

// `columns`: each grain's entry column, in falling order.
FallingSand falling_sand(int width, int height, std::span<const int32_t> columns, int per_tick, uint64_t seed);

// The columns the lattice drops a scene's grains from (its release model,
// lattice.arrival release), in falling order.
std::vector<int32_t> entry_columns(const Scene& s, const Prepared& p);

}  // namespace sandpic
