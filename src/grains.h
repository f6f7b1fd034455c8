#pragma once
// The grains of the initialization region: one per pixel (paper §4.1 at the
// paper's scale), identified by id = y * width + x.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "src/scene.h"

namespace sandpic {

using Vec2 = Eigen::Vector2d;

struct GrainSet {
  int width = 0, height = 0;  // the region, px
  std::vector<uint8_t> cls;   // class 0..3 (S1..S4) of each grain

  int64_t size() const { return int64_t(width) * height; }
  // A grain's resting place before release: the centre of its pixel.
  Vec2 position(int64_t id) const { return {double(id % width) + 0.5, double(id / width) + 0.5}; }
  std::array<int64_t, kClasses> per_class() const;
};

GrainSet empty_region(const Scene& s);

}  // namespace sandpic
