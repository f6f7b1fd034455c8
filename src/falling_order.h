#pragma once
// paper §6: units row by row (lowest first), and inside a unit its grains in
// ascending distance to the outlet, equal distances in random order.
#include <vector>

#include "src/segment/segment.h"

namespace sandpic {

struct FallingOrder {
  std::vector<int32_t> grain;       // grain ids, in the order they are released
  std::vector<int64_t> unit_begin;  // unit u: grain[unit_begin[u], unit_begin[u+1])
};

FallingOrder falling_order(const Segmentation& seg, const GrainSet& g, uint64_t layout_seed);

}  // namespace sandpic
