#include "physics/grain_dynamics.h"

namespace sandpic {

// Where each body would be without contacts: Bullet widens its bounds to
// reach it. (Bullet also applies damping here: a grain has none, the water
// stage is its drag.)
void GrainDynamicsWorld::predictUnconstraintMotion(btScalar dt) {
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    btRigidBody* b = m_nonStaticRigidBodies[i];
    if (b->isStaticOrKinematicObject()) continue;
    btTransform t = b->getWorldTransform();
    t.setOrigin(t.getOrigin() + b->getLinearVelocity() * dt);  // as predictIntegratedTransform
    b->setInterpolationWorldTransform(t);
  }
}

// The step's end: as btRigidBody::proceedToTransform, without the turn
// (no continuous collision detection is asked for, so none is skipped).
void GrainDynamicsWorld::integrateTransforms(btScalar dt) {
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) {
    btRigidBody* b = m_nonStaticRigidBodies[i];
    b->setHitFraction(1);
    if (!b->isActive() || b->isStaticOrKinematicObject()) continue;
    btTransform t = b->getWorldTransform();
    t.setOrigin(t.getOrigin() + b->getLinearVelocity() * dt);
    b->setInterpolationWorldTransform(t);
    b->setInterpolationLinearVelocity(b->getLinearVelocity());
    b->setInterpolationAngularVelocity(b->getAngularVelocity());
    b->setWorldTransform(t);
  }
}

// Every body and every contact in one call. The grains' world has no
// joints (typed constraints): none are passed.
void GrainDynamicsWorld::solveConstraints(btContactSolverInfo& info) {
  bodies_.resize(0);
  for (int i = 0; i < m_nonStaticRigidBodies.size(); ++i) bodies_.push_back(m_nonStaticRigidBodies[i]);
  btDispatcher* d = getDispatcher();
  m_constraintSolver->prepareSolve(bodies_.size(), d->getNumManifolds());
  m_constraintSolver->solveGroup(bodies_.size() ? &bodies_[0] : nullptr, bodies_.size(),
                                 d->getNumManifolds() ? d->getInternalManifoldPointer() : nullptr,
                                 d->getNumManifolds(), nullptr, 0, info, getDebugDrawer(), d);
  m_constraintSolver->allSolved(info, getDebugDrawer());
}

}  // namespace sandpic
