#pragma once
// The Bullet world of the DEM mode: grains as spheres kept in the picture's
// plane, the window's walls, static grain colliders, and one height field
// that is the floor and, raised as grains are fixed, the fixed layer's top.
// Bullet units: one per pixel, y up, z out of the picture. The height field
// (physics/ground.h) has kGroundPerPx vertices per pixel: at one a small
// grain (0.56 px) often spans no vertex, and raising the nearest ones to its
// top puffed BCRE piles.
#include <cstdint>
#include <memory>
#include <vector>

#include "src/grains.h"

class btCollisionObject;
class btRigidBody;

namespace sandpic {

// How deep a resting contact may overlap before it is pushed apart, as a
// share of the smallest grain's diameter (physics/grain_solver.h): far above
// the rounding of positions (1e-4 px at 2,000 px from the origin, against
// 0.005 px for a grain of 0.5 px), and a fifth of the deepest overlap
// verify-dem allows.
constexpr double kRestOverlap = 0.01;

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
  double spin(int slot) const;  // rad/s about z
  void set_velocity(int slot, Vec2 v);
  // The velocity change the water makes over the next step of `dt`, given
  // to Bullet as a force so its solver can tell the speed a contact met at
  // from the push of the step it meets in (physics/grain_solver.h: bounces).
  void push(int slot, Vec2 dv, double dt);

  int add_static(int cls, Vec2 position);  // a collider that never moves
  void remove_static(int slot);

  // Raises the height field (the floor, and the top of the fixed layer in
  // three, of the static layer in bcre) to the upper outline of a grain of
  // radius r centred at p; r = 0 raises the nearest vertex to p.y.
  void raise_ground(Vec2 p, double r);

  void step(double dt);
  // The DEM's sub-steps: a contact closes by g·dt per (sub-)step, so the
  // bounce threshold follows the step it is solved at.
  void set_bounce_speed(double px_s);
  double deepest_overlap() const;  // px, over all contacts
  // Bodies pressed deeper than `depth` px into a collider (a static grain,
  // the ground, a wall): wedged between immovable things, as no body can
  // be between bodies.
  std::vector<int> wedged(double depth) const;
  // Bodies with at least one contact point (each gives the solver rows).
  int64_t bodies_in_contact() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sandpic
