#pragma once
// The device's water acting on the DEM's bodies (paper §7, in water):
// gravity with buoyancy and a linear drag whose terminal speed is the
// class's settling speed (src/water.h), integrated exactly over a
// (sub-)step: v ← v_t + (v − v_t)·e^(−k·dt). Without water (no drag) it is
// plain gravity, v ← v + g·dt. Shared by the DEM run and verify-dem's
// single-grain cases, so both move grains the same way.
#include <array>

#include "src/grains.h"
#include "src/water.h"

namespace sandpic {

class WaterStage {
 public:
  // `down`: the unit direction of gravity (verify-dem tilts it to make an
  // incline of the floor).
  explicit WaterStage(const Water& water, Vec2 down = Vec2(0, -1));
  // The (sub-)step the next velocities are for: the drag's decay over it.
  void set_step(double dt);
  Vec2 apply(int cls, Vec2 v) const;
  const Water& water() const { return water_; }

 private:
  Water water_;
  Vec2 down_;
  double dt_ = 0;
  std::array<double, kClasses> decay_{};
};

}  // namespace sandpic
