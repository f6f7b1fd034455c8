#include "physics/probe.h"

#include <cmath>

#include "physics/dem_params.h"
#include "physics/world.h"

namespace sandpic {

GrainProbe::GrainProbe(const Scene& s, double tilt_rad)
    : radius_(dem_radii(s)),
      dt_(dem_time_step(s)),
      water_(water_model(s), Vec2(std::sin(tilt_rad), -std::cos(tilt_rad))),
      world_(std::make_unique<GrainWorld>(s.window.width, s.window.height, radius_, dem_masses(s),
                                          dem_material(s, water_.water(), dt_))) {
  water_.set_step(dt_);
}

GrainProbe::~GrainProbe() = default;

int GrainProbe::add(int cls, Vec2 p, Vec2 v) {
  const int slot = world_->add_body(cls, p, v);
  bodies_.emplace_back(slot, cls);
  return slot;
}

void GrainProbe::add_static(int cls, Vec2 p) { world_->add_static(cls, p); }

void GrainProbe::step() {
  for (const auto& [slot, cls] : bodies_) {
    const Vec2 v = world_->velocity(slot);
    world_->push(slot, water_.apply(cls, v) - v, dt_);
  }
  world_->step(dt_);
}

void GrainProbe::raise_ground(Vec2 p, double r) { world_->raise_ground(p, r); }

Vec2 GrainProbe::position(int slot) const { return world_->position(slot); }
Vec2 GrainProbe::velocity(int slot) const { return world_->velocity(slot); }
double GrainProbe::spin(int slot) const { return world_->spin(slot); }

}  // namespace sandpic
