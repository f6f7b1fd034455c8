#pragma once
// Bullet's discrete world with the step's stages a grain does not need
// taken out (a step is Bullet's fixed list: predict motion, collide,
// islands, solve, integrate).
//
// Rotation. A grain is a sphere: its orientation changes neither its
// contacts nor its inertia nor the picture, and its spin enters the solve
// (rolling resistance) as an angular velocity. Bullet integrates every
// body's orientation twice a step (the prediction that widens its bounds,
// and the step's end), through a quaternion and sines, and rebuilds its
// world inertia from it: about a tenth of a DEM run. Here a body moves by
// its velocity alone, as Bullet moves it, and keeps its orientation.
//
// Islands. Bullet groups the bodies into islands (union-find over every
// contact, a sort of the contact manifolds by island) so that resting ones
// can sleep and each island is solved on its own. The layer model decides
// rest (bodies never sleep), and rows of bodies that do not touch do not
// interact, so the solver takes every contact in one call. Its own order
// (physics/grain_solver.h: by height) is what it solves in.
#include <btBulletDynamicsCommon.h>

namespace sandpic {

class GrainDynamicsWorld : public btDiscreteDynamicsWorld {
 public:
  using btDiscreteDynamicsWorld::btDiscreteDynamicsWorld;

 protected:
  void predictUnconstraintMotion(btScalar dt) override;
  void integrateTransforms(btScalar dt) override;
  void calculateSimulationIslands() override {}
  void solveConstraints(btContactSolverInfo& info) override;

 private:
  btAlignedObjectArray<btCollisionObject*> bodies_;
};

}  // namespace sandpic
