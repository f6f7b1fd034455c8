#include "physics/world.h"

#include <algorithm>
#include <cmath>

#include <BulletCollision/CollisionDispatch/btSphereBoxCollisionAlgorithm.h>
#include <btBulletDynamicsCommon.h>

#include "physics/grain_contact.h"
#include "physics/grain_dynamics.h"
#include "physics/grain_solver.h"
#include "physics/ground.h"

namespace sandpic {
namespace {

// Bullet multiplies the two bodies' friction and restitution at a contact;
// each body gets the square root, so a contact gets the scene's value.
// Rolling resistance is a torque of μr·R_r·N at a contact (the rolling
// radius R_r = R_a·R_b/(R_a + R_b), as in LAMMPS's SDS model and Ai et al.
// 2011): each object carries μr·R (a length: Bullet's rolling friction) and
// this combines them harmonically. A flat collider (floor, walls, the fixed
// layer's top) is a grain of infinite radius, so a lone grain on it holds
// up to tan θ = μr whatever its size. (The mean of the two, used before,
// gave a small grain on the floor the big grain's resistance: it held to
// 42° at μr = 0.6 against 31°.)
constexpr double kFlatRadius = 1e12;
btScalar rolling_length(const btCollisionObject* a, const btCollisionObject* b) {
  const btScalar la = a->getRollingFriction(), lb = b->getRollingFriction();
  return la + lb > 0 ? la * lb / (la + lb) : btScalar(0);
}

// Slots are reused last-freed first: deterministic, and the arrays stay small.
template <class T>
int store(std::vector<std::unique_ptr<T>>& items, std::vector<int>& free, std::unique_ptr<T> item) {
  if (free.empty()) {
    items.push_back(std::move(item));
    return int(items.size()) - 1;
  }
  int slot = free.back();
  free.pop_back();
  items[size_t(slot)] = std::move(item);
  return slot;
}

}  // namespace

struct GrainWorld::Impl {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  // Bullet 3.24 pairs a sphere with a box through GJK/EPA in single
  // precision (its sphere-box algorithm is compiled but not registered):
  // against the window's floor, 2,000 px wide for a 0.56-1.11 px grain, it
  // gave contact normals up to 13° off the vertical, some pointing into the
  // floor, and a grain at rest on the floor slid and was kicked to 1,000
  // px/s within 50 steps. The closed-form sphere-box test is exact.
  btSphereBoxCollisionAlgorithm::CreateFunc sphere_box, box_sphere;
  GrainContactCreateFunc grain_grain;  // physics/grain_contact.h
  btDbvtBroadphase broadphase;
  GrainSolver solver;  // physics/grain_solver.h
  GrainDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};  // physics/grain_dynamics.h

  std::array<std::unique_ptr<btSphereShape>, kClasses> spheres;
  std::array<btVector3, kClasses> inertia;
  std::array<double, kClasses> mass{}, radius{};
  GrainMaterial material;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  std::vector<int> free_bodies;
  std::vector<std::unique_ptr<btCollisionObject>> statics;
  std::vector<int> free_statics;

  std::unique_ptr<Ground> ground;
  std::unique_ptr<btBoxShape> wall_shape, floor_shape;
  std::vector<std::unique_ptr<btCollisionObject>> fixed_objects;
  int width = 0, height = 0;

  void set_surface(btCollisionObject& o, double r) const {
    o.setFriction(btScalar(std::sqrt(material.friction)));
    o.setRestitution(btScalar(std::sqrt(material.restitution)));
    o.setRollingFriction(btScalar(material.rolling_resistance * r));
  }

  // A collider that never moves, in the world's static tree (static pairs
  // are never tested against each other).
  std::unique_ptr<btCollisionObject> static_object(btCollisionShape* shape, btVector3 at, double r) {
    auto o = std::make_unique<btCollisionObject>();
    o->setCollisionShape(shape);
    btTransform t;
    t.setIdentity();
    t.setOrigin(at);
    o->setWorldTransform(t);
    set_surface(*o, r);
    o->setActivationState(ISLAND_SLEEPING);  // never moves: its bounds are never refreshed
    world.addCollisionObject(o.get(), btBroadphaseProxy::StaticFilter,
                             btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    return o;
  }

  void add_fixed(btCollisionShape* shape, btVector3 at) { fixed_objects.push_back(static_object(shape, at, kFlatRadius)); }
};

GrainWorld::GrainWorld(int width, int height, const std::array<double, kClasses>& radius_px,
                       const std::array<double, kClasses>& mass, const GrainMaterial& material)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.box_sphere.m_swapped = true;
  m.dispatcher.registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, &m.sphere_box);
  m.dispatcher.registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, &m.box_sphere);
  m.dispatcher.registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE, &m.grain_grain);
  gCalculateCombinedRollingFrictionCallback = &rolling_length;
  m.width = width, m.height = height, m.material = material, m.mass = mass;
  m.radius = radius_px;
  m.world.setGravity(btVector3(0, 0, 0));
  GrainSolver::configure(m.world.getSolverInfo(), material.solver_iterations);
  // Bullet's default 0.2 units/s would make every resting contact bounce:
  // gravity closes it by g·dt (~11 px/s) each step. Only impacts bounce.
  m.world.getSolverInfo().m_restitutionVelocityThreshold = btScalar(material.bounce_speed);
  // Only moving bodies need their bounds refreshed each step. Bullet's
  // default refreshes every object, and a refreshed static collider leaves
  // the broadphase's tree of fixed objects for the tree of moving ones.
  m.world.setForceUpdateAllAabbs(false);
  double smallest = INFINITY;
  for (double r : radius_px)
    if (r > 0) smallest = std::min(smallest, 2 * r);
  if (std::isfinite(smallest)) m.solver.set_rest_overlap(btScalar(kRestOverlap * smallest));
  for (int k = 0; k < kClasses; ++k) {
    m.spheres[k] = std::make_unique<btSphereShape>(btScalar(radius_px[k]));
    m.spheres[k]->calculateLocalInertia(btScalar(mass[k]), m.inertia[k]);
  }
  // The fixed layer's top: height field tiles two rows deep in z, the
  // grains' plane (z = 0) running down their middle.
  m.ground = std::make_unique<Ground>(
      width, height,
      [&m](btCollisionShape* shape, Vec2 c) {
        return m.static_object(shape, btVector3(btScalar(c.x()), btScalar(c.y()), 0), kFlatRadius);
      },
      [&m](btCollisionObject* o) { m.world.removeCollisionObject(o); });
  // The window's sides, and a solid floor under the height field (a
  // triangle surface alone lets a pressed sphere through).
  m.wall_shape = std::make_unique<btBoxShape>(btVector3(10, btScalar(height), 10));
  m.add_fixed(m.wall_shape.get(), btVector3(-10, btScalar(height), 0));
  m.add_fixed(m.wall_shape.get(), btVector3(btScalar(width + 10), btScalar(height), 0));
  m.floor_shape = std::make_unique<btBoxShape>(btVector3(btScalar(width), 10, 10));
  m.add_fixed(m.floor_shape.get(), btVector3(btScalar(width / 2.0), -10, 0));
  // The frame is closed: a lid at the window's top edge.
  m.add_fixed(m.floor_shape.get(), btVector3(btScalar(width / 2.0), btScalar(height + 10), 0));
}

GrainWorld::~GrainWorld() {
  Impl& m = *impl_;
  m.ground.reset();
  for (auto& b : m.bodies)
    if (b) m.world.removeRigidBody(b.get());
  for (auto& s : m.statics)
    if (s) m.world.removeCollisionObject(s.get());
  for (auto& o : m.fixed_objects) m.world.removeCollisionObject(o.get());
}

int GrainWorld::add_body(int cls, Vec2 p, Vec2 v) {
  Impl& m = *impl_;
  btRigidBody::btRigidBodyConstructionInfo info(btScalar(m.mass[cls]), nullptr, m.spheres[cls].get(), m.inertia[cls]);
  info.m_startWorldTransform.setIdentity();
  info.m_startWorldTransform.setOrigin(btVector3(btScalar(p.x()), btScalar(p.y()), 0));
  auto body = std::make_unique<btRigidBody>(info);
  m.set_surface(*body, m.radius[cls]);
  body->setLinearFactor(btVector3(1, 1, 0));   // in the picture's plane
  body->setAngularFactor(btVector3(0, 0, 1));  // rolling in the plane only
  // A grain rolls about z only: Bullet's rolling-friction row about the
  // in-plane tangent would be solved for nothing, and a sphere has no
  // gyroscopic torque.
  body->setAnisotropicFriction(btVector3(0, 0, 1), btCollisionObject::CF_ANISOTROPIC_ROLLING_FRICTION);
  body->setFlags(body->getFlags() & ~BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY);
  body->setActivationState(DISABLE_DEACTIVATION);  // the layer model decides rest, not Bullet
  m.world.addRigidBody(body.get());
  body->setLinearVelocity(btVector3(btScalar(v.x()), btScalar(v.y()), 0));
  btRigidBody* raw = body.get();
  const int slot = store(m.bodies, m.free_bodies, std::move(body));
  raw->setUserIndex(slot);
  return slot;
}

void GrainWorld::remove_body(int slot) {
  Impl& m = *impl_;
  m.world.removeRigidBody(m.bodies[size_t(slot)].get());
  m.bodies[size_t(slot)].reset();
  m.free_bodies.push_back(slot);
}

Vec2 GrainWorld::position(int slot) const {
  const btVector3& o = impl_->bodies[size_t(slot)]->getWorldTransform().getOrigin();
  return {o.x(), o.y()};
}

Vec2 GrainWorld::velocity(int slot) const {
  const btVector3& v = impl_->bodies[size_t(slot)]->getLinearVelocity();
  return {v.x(), v.y()};
}

double GrainWorld::spin(int slot) const { return impl_->bodies[size_t(slot)]->getAngularVelocity().z(); }

void GrainWorld::set_velocity(int slot, Vec2 v) {
  impl_->bodies[size_t(slot)]->setLinearVelocity(btVector3(btScalar(v.x()), btScalar(v.y()), 0));
}

void GrainWorld::push(int slot, Vec2 dv, double dt) {
  btRigidBody& b = *impl_->bodies[size_t(slot)];
  const double m = 1 / double(b.getInvMass());
  b.applyCentralForce(btVector3(btScalar(m * dv.x() / dt), btScalar(m * dv.y() / dt), 0));  // cleared by the step
}

int GrainWorld::add_static(int cls, Vec2 p) {
  Impl& m = *impl_;
  auto o = m.static_object(m.spheres[cls].get(), btVector3(btScalar(p.x()), btScalar(p.y()), 0), m.radius[cls]);
  return store(m.statics, m.free_statics, std::move(o));
}

void GrainWorld::remove_static(int slot) {
  Impl& m = *impl_;
  m.world.removeCollisionObject(m.statics[size_t(slot)].get());
  m.statics[size_t(slot)].reset();
  m.free_statics.push_back(slot);
}

void GrainWorld::raise_ground(Vec2 p, double r) { impl_->ground->raise(p, r); }

void GrainWorld::step(double dt) { impl_->world.stepSimulation(btScalar(dt), 0, btScalar(dt)); }

void GrainWorld::set_bounce_speed(double px_s) {
  impl_->world.getSolverInfo().m_restitutionVelocityThreshold = btScalar(px_s);
}

std::vector<int> GrainWorld::wedged(double depth) const {
  std::vector<int> slots;
  btDispatcher& d = impl_->dispatcher;
  for (int i = 0; i < d.getNumManifolds(); ++i) {
    const btPersistentManifold* pm = d.getManifoldByIndexInternal(i);
    const btCollisionObject *a = pm->getBody0(), *b = pm->getBody1();
    if (a->isStaticObject() == b->isStaticObject()) continue;  // a body against a collider only
    for (int c = 0; c < pm->getNumContacts(); ++c)
      if (-pm->getContactPoint(c).getDistance() > depth) {
        slots.push_back((a->isStaticObject() ? b : a)->getUserIndex());
        break;
      }
  }
  std::sort(slots.begin(), slots.end());
  slots.erase(std::unique(slots.begin(), slots.end()), slots.end());
  return slots;
}

int64_t GrainWorld::bodies_in_contact() const {
  std::vector<char> touched(impl_->bodies.size(), 0);
  btDispatcher& d = impl_->dispatcher;
  for (int i = 0; i < d.getNumManifolds(); ++i) {
    const btPersistentManifold* pm = d.getManifoldByIndexInternal(i);
    if (pm->getNumContacts() == 0) continue;
    for (const btCollisionObject* o : {pm->getBody0(), pm->getBody1()})
      if (!o->isStaticObject()) touched[size_t(o->getUserIndex())] = 1;
  }
  return std::count(touched.begin(), touched.end(), char(1));
}

double GrainWorld::deepest_overlap() const {
  double deepest = 0;
  btDispatcher& d = impl_->dispatcher;
  for (int i = 0; i < d.getNumManifolds(); ++i) {
    const btPersistentManifold* pm = d.getManifoldByIndexInternal(i);
    for (int c = 0; c < pm->getNumContacts(); ++c) deepest = std::max(deepest, double(-pm->getContactPoint(c).getDistance()));
  }
  return deepest;
}

}  // namespace sandpic
