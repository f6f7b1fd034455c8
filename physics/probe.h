#pragma once
// A few grains in the DEM's own world, contact rules and water stage, placed
// by hand: verify-dem's single-grain cases (settling, restitution, an
// incline, rolling resistance) compare them with closed-form answers. An
// incline is the window's floor under gravity tilted by θ: the same contact
// as a slope, without a slope's own collider.
#include <memory>

#include "physics/water_stage.h"
#include "src/grains.h"
#include "src/scene.h"

namespace sandpic {

class GrainWorld;

class GrainProbe {
 public:
  // The scene's window, grains, materials and time step (dem_time_step);
  // gravity tilted by `tilt_rad` towards +x.
  explicit GrainProbe(const Scene& s, double tilt_rad = 0);
  ~GrainProbe();
  GrainProbe(const GrainProbe&) = delete;
  GrainProbe& operator=(const GrainProbe&) = delete;

  int add(int cls, Vec2 position, Vec2 velocity = Vec2::Zero());  // a body; returns its slot
  void add_static(int cls, Vec2 position);  // a grain that never moves (a static-layer collider)
  void step();  // one time step: the water stage, then Bullet's
  // Raises the ground (the fixed layer's top) as GrainWorld::raise_ground.
  void raise_ground(Vec2 p, double r);
  double dt() const { return dt_; }
  double radius(int cls) const { return radius_[size_t(cls)]; }
  const Water& water() const { return water_.water(); }
  Vec2 position(int slot) const;
  Vec2 velocity(int slot) const;
  double spin(int slot) const;

 private:
  std::array<double, kClasses> radius_;
  double dt_;
  WaterStage water_;
  std::unique_ptr<GrainWorld> world_;
  std::vector<std::pair<int, int>> bodies_;  // (slot, class)
};

}  // namespace sandpic
