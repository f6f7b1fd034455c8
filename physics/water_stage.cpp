#include "physics/water_stage.h"

#include <cmath>

namespace sandpic {

WaterStage::WaterStage(const Water& water, Vec2 down) : water_(water), down_(down.normalized()) {}

void WaterStage::set_step(double dt) {
  dt_ = dt;
  for (int k = 0; k < kClasses; ++k) decay_[k] = std::exp(-water_.drag_per_s[k] * dt);
}

Vec2 WaterStage::apply(int k, Vec2 v) const {
  if (water_.drag_per_s[k] > 0) {
    const Vec2 terminal = down_ * water_.terminal_px_s[k];
    return terminal + (v - terminal) * decay_[k];
  }
  return v + down_ * (water_.gravity_px_s2[k] * dt_);
}

}  // namespace sandpic
