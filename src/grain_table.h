#pragma once
// Every grain of a run, one line each (render --grains): where its fall
// started and where it came to rest. Both backends start a grain's fall at
// the same point for one scene and physics seed (paper §7, src/release.h),
// so two tables of one scene and seed compare grain by grain
// (validate/metrics/grain_compare.h): how far each grain travelled once it reached
// the pile, and where the two backends part.
#include <cstdint>
#include <string>
#include <vector>

#include "src/falling_order.h"

namespace sandpic {

struct GrainRow {
  int32_t id = 0;         // grain id: y * region width + x of its place in the region
  int cls = 0;            // class 0..3 (S1..S4)
  int32_t unit = 0;       // its unit, in falling order
  int64_t order = 0;      // its place in the falling order
  double release_x = 0;   // px: where its fall below the outlet starts
  double x = 0, y = 0;    // px, window coordinates (y down): its centre at rest
};

// The header line and one line per grain, in id order. x and y are the
// backend's positions (a symmetric pattern's mirror is not applied).
std::string grain_table_csv(const Scene& s, const GrainSet& g, const Segmentation& seg, const FallingOrder& order,
                            const std::vector<float>& x, const std::vector<float>& y);

// Parses what grain_table_csv writes; `name` is the file, for errors
// (InputError naming the file and line).
std::vector<GrainRow> parse_grain_table(const std::string& text, const std::string& name);

}  // namespace sandpic
