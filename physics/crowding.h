#pragma once
// The insert stage's neighbourhood index: grains bucketed by 2-px cell
// (wider than any grain), so an arriving grain looks only at the grains
// around its insertion point instead of at every body.
#include <cstdint>
#include <vector>

#include "src/grains.h"

namespace sandpic {

class Crowding {
 public:
  Crowding(int width, int height);
  void clear();
  void add(Vec2 p, double r);
  // Would a grain of radius r at p overlap a grain added since clear()?
  bool crowded(Vec2 p, double r) const;

 private:
  static constexpr double kCell = 2.0;  // px; twice the largest grain's diameter at most
  int cell_of(Vec2 p) const;
  int cells_x_, cells_y_;
  std::vector<int32_t> head_, next_;
  std::vector<Vec2> pos_;
  std::vector<double> radius_;
};

}  // namespace sandpic
