#include "physics/grain_contact.h"

#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>

namespace {

class GrainContact : public btActivatingCollisionAlgorithm {
 public:
  GrainContact(const btCollisionAlgorithmConstructionInfo& ci, const btCollisionObjectWrapper* a,
               const btCollisionObjectWrapper* b)
      : btActivatingCollisionAlgorithm(ci, a, b),
        manifold_(m_dispatcher->getNewManifold(a->getCollisionObject(), b->getCollisionObject())) {}
  ~GrainContact() override { m_dispatcher->releaseManifold(manifold_); }

  void processCollision(const btCollisionObjectWrapper* a, const btCollisionObjectWrapper* b, const btDispatcherInfo&,
                        btManifoldResult* out) override {
    out->setPersistentManifold(manifold_);
    const btScalar ra = static_cast<const btSphereShape*>(a->getCollisionShape())->getRadius();
    const btScalar rb = static_cast<const btSphereShape*>(b->getCollisionShape())->getRadius();
    const btVector3 diff = a->getWorldTransform().getOrigin() - b->getWorldTransform().getOrigin();
    const btScalar len = diff.length(), gap = len - (ra + rb);
    // The solver's memory of this contact, to be carried to its new point.
    const bool had = manifold_->getNumContacts() > 0;
    btManifoldPoint old;
    if (had) old = manifold_->getContactPoint(0);
    manifold_->clearManifold();
    if (gap > manifold_->getContactBreakingThreshold()) return;
    const btVector3 normal = len > SIMD_EPSILON ? diff / len : btVector3(1, 0, 0);
    out->addContactPoint(normal, b->getWorldTransform().getOrigin() + normal * rb, gap);
    if (!had || manifold_->getNumContacts() == 0) return;
    btManifoldPoint& p = manifold_->getContactPoint(0);
    p.m_appliedImpulse = old.m_appliedImpulse;
    p.m_appliedImpulseLateral1 = old.m_appliedImpulseLateral1;
    p.m_appliedImpulseLateral2 = old.m_appliedImpulseLateral2;
    p.m_prevRHS = old.m_prevRHS;
    p.m_lifeTime = old.m_lifeTime + 1;
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return 1;
  }
  void getAllContactManifolds(btManifoldArray& manifolds) override { manifolds.push_back(manifold_); }

 private:
  btPersistentManifold* manifold_;
};

}  // namespace

btCollisionAlgorithm* GrainContactCreateFunc::CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                                       const btCollisionObjectWrapper* a,
                                                                       const btCollisionObjectWrapper* b) {
  void* mem = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(GrainContact));
  return new (mem) GrainContact(ci, a, b);
}
