#pragma once
// The Bullet world of the DEM mode: grains as spheres kept in the picture's
// plane, the window's walls, static grain colliders, and one height field
// that is the floor and, raised as grains are fixed, the fixed layer's top.
// Bullet units: one per pixel, y up, z out of the picture.
#include <memory>
#include <vector>

#include "src/grains.h"

class btCollisionObject;
class btRigidBody;

namespace sandpic {

struct GrainMaterial {
  double friction = 0.4, restitution = 0.1, rolling_resistance = 0.3;
  int solver_iterations = 10;
  double bounce_speed = 0;  // px/s: contacts closing slower than this do not bounce
};

class GrainWorld {
 public:
  // No gravity in the world: the DEM's water stage applies it with drag.
  GrainWorld(int width, int height, const std::array<double, kClasses>& radius_px,
             const std::array<double, kClasses>& mass, const GrainMaterial& material);
  ~GrainWorld();
  GrainWorld(const GrainWorld&) = delete;
  GrainWorld& operator=(const GrainWorld&) = delete;

  int add_body(int cls, Vec2 position, Vec2 velocity);  // returns a slot
  void remove_body(int slot);
  Vec2 position(int slot) const;
  Vec2 velocity(int slot) const;
  void set_velocity(int slot, Vec2 v);

  int add_static(int cls, Vec2 position);  // a collider that never moves
  void remove_static(int slot);

  // The height field's height at column j (x = j, 0..width): the floor, and
  // the top of the fixed layer (three) or of the static layer (bcre).
  void set_ground(int j, double height);

  void step(double dt);
  double deepest_overlap() const;  // px, over all contacts

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sandpic
