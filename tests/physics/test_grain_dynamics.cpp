#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include <BulletCollision/CollisionDispatch/btSphereBoxCollisionAlgorithm.h>
#include <btBulletDynamicsCommon.h>

#include "physics/grain_dynamics.h"
#include "physics/grain_solver.h"

namespace sandpic {
namespace {

// A small world of spheres over a floor, with Bullet's own world or the
// grains' one (physics/grain_dynamics.h) and the grains' solver in both.
template <class World>
struct Spheres {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btSphereBoxCollisionAlgorithm::CreateFunc sphere_box, box_sphere;
  btDbvtBroadphase broadphase;
  GrainSolver solver;
  World world{&dispatcher, &broadphase, &solver, &config};
  btSphereShape sphere{0.5};
  btBoxShape floor_shape{btVector3(100, 10, 10)};
  btCollisionObject floor;
  std::vector<std::unique_ptr<btRigidBody>> bodies;

  Spheres() {
    box_sphere.m_swapped = true;
    dispatcher.registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, &sphere_box);
    dispatcher.registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, &box_sphere);
    GrainSolver::configure(world.getSolverInfo(), 10);
    world.setGravity(btVector3(0, -100, 0));
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(0, -10, 0));
    floor.setCollisionShape(&floor_shape);
    floor.setWorldTransform(t);
    floor.setFriction(0.6f);
    world.addCollisionObject(&floor);
  }
  ~Spheres() {
    for (auto& b : bodies) world.removeRigidBody(b.get());
    world.removeCollisionObject(&floor);
  }
  btRigidBody& add(btVector3 at, btVector3 v, double spin) {
    btVector3 inertia;
    sphere.calculateLocalInertia(1, inertia);
    btRigidBody::btRigidBodyConstructionInfo info(1, nullptr, &sphere, inertia);
    info.m_startWorldTransform.setIdentity();
    info.m_startWorldTransform.setOrigin(at);
    info.m_friction = 0.6f;
    bodies.push_back(std::make_unique<btRigidBody>(info));
    btRigidBody& b = *bodies.back();
    b.setLinearFactor(btVector3(1, 1, 0));
    b.setAngularFactor(btVector3(0, 0, 1));
    b.setActivationState(DISABLE_DEACTIVATION);
    world.addRigidBody(&b);
    b.setLinearVelocity(v);
    b.setAngularVelocity(btVector3(0, 0, btScalar(spin)));
    return b;
  }
  void step(int n) {
    for (int i = 0; i < n; ++i) world.stepSimulation(1e-3f, 0, 1e-3f);
  }
};

// Bodies move as Bullet moves them, by the same arithmetic, and keep their
// orientation where Bullet turns them.
TEST(GrainDynamicsWorld, MovesBodiesAsBulletDoesWithoutTurningThem) {
  Spheres<btDiscreteDynamicsWorld> bullet;
  Spheres<GrainDynamicsWorld> grains;
  btRigidBody& a = bullet.add(btVector3(0, 50, 0), btVector3(3, 20, 0), 7);
  btRigidBody& b = grains.add(btVector3(0, 50, 0), btVector3(3, 20, 0), 7);
  bullet.step(200);
  grains.step(200);
  EXPECT_EQ(a.getWorldTransform().getOrigin(), b.getWorldTransform().getOrigin());
  EXPECT_EQ(a.getLinearVelocity(), b.getLinearVelocity());
  EXPECT_FLOAT_EQ(b.getAngularVelocity().z(), 7);
  EXPECT_GT(std::abs(a.getWorldTransform().getRotation().getAngle()), 0.5);  // Bullet turned it 1.4 rad
  EXPECT_EQ(b.getWorldTransform().getRotation().getAngle(), 0);
}

// The grains' world with Bullet's islands put back.
struct WithIslands : GrainDynamicsWorld {
  using GrainDynamicsWorld::GrainDynamicsWorld;
  void calculateSimulationIslands() override { btDiscreteDynamicsWorld::calculateSimulationIslands(); }
  void solveConstraints(btContactSolverInfo& info) override { btDiscreteDynamicsWorld::solveConstraints(info); }
};

// Two piles that do not touch are solved in one call, not as two islands,
// with the same result to the bit: rows of bodies that do not touch do not
// interact, and the solver orders the rest by height.
TEST(GrainDynamicsWorld, SolvesPilesThatDoNotTouchInOneCall) {
  Spheres<WithIslands> islands;
  Spheres<GrainDynamicsWorld> grains;
  std::vector<btRigidBody*> a, b;
  for (double x : {-20.0, 20.0})
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4 - row; ++k) {
        // Heights a little apart: rows of equal height meet the solver in
        // the order they are given, which islands change.
        const btVector3 at(btScalar(x + 1.02 * k - 1.5 + 0.5 * row), btScalar(0.5 + 0.9 * row + 0.013 * k), 0);
        a.push_back(&islands.add(at, btVector3(0, 0, 0), 0));
        b.push_back(&grains.add(at, btVector3(0, 0, 0), 0));
      }
  islands.step(300);
  grains.step(300);
  double top = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]->getWorldTransform().getOrigin(), b[i]->getWorldTransform().getOrigin()) << "sphere " << i;
    top = std::max(top, double(b[i]->getWorldTransform().getOrigin().y()));
  }
  EXPECT_GT(islands.dispatcher.getNumManifolds(), 20);  // the piles touch inside
  EXPECT_LT(top, 3.5);                                  // and settled under gravity
}

}  // namespace
}  // namespace sandpic
