#include "physics/grain_solver.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace {

// (key, index) pairs, entered in index order, sorted as std::sort sorts them
// (by key, equal keys by index), in linear time: a least-significant-digit
// radix sort of the keys' bits is stable. The height sort took about 4% of a
// DEM run with std::sort. Keys are finite and never -0 (the caller adds +0).
void sort_pairs(std::vector<std::pair<float, int>>& v, std::vector<std::pair<float, int>>& spare) {
  if (v.size() < 256) {
    std::sort(v.begin(), v.end());
    return;
  }
  const auto bits = [](float f) {  // monotone in f: negatives flipped whole, positives above them
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u ^ ((u >> 31) ? 0xFFFFFFFFu : 0x80000000u);
  };
  spare.resize(v.size());
  for (int shift = 0; shift < 32; shift += 8) {
    size_t start[257] = {};
    for (const auto& p : v) ++start[((bits(p.first) >> shift) & 255u) + 1];
    for (int b = 0; b < 256; ++b) start[b + 1] += start[b];
    for (const auto& p : v) spare[start[(bits(p.first) >> shift) & 255u]++] = p;
    v.swap(spare);
  }
}

}  // namespace

void GrainSolver::configure(btContactSolverInfo& info, int iterations) {
  info.m_numIterations = iterations;
  info.m_warmstartingFactor = 1;
  info.m_splitImpulse = true;
  info.m_splitImpulsePenetrationThreshold = 0;
}

// The rows in order of height, highest contact first (see the header: a
// sweep carries a step's weight from the top of a pile to the floor).
void GrainSolver::convertContacts(btPersistentManifold** manifolds, int count, const btContactSolverInfo& info) {
  bounces_.clear();
  pushing_ = false;
  order_.clear();
  order_.reserve(size_t(count));
  for (int i = 0; i < count; ++i) {
    const btPersistentManifold* m = manifolds[i];
    const btScalar y = m->getNumContacts() > 0 ? m->getContactPoint(0).getPositionWorldOnB().y() : btScalar(0);
    order_.emplace_back(-y + btScalar(0), i);  // + 0: a -0 key would sort apart from +0
  }
  static_assert(std::is_same_v<btScalar, float>, "Debian's Bullet is single precision");
  sort_pairs(order_, spare_);  // ties by index: the same order at any thread count
  for (const auto& [key, i] : order_) convert(manifolds[i], info);
}

namespace {
// A row's normal speed at the start of the step, before this step's
// gravity (`forced`: with it, as setupContactConstraint measures it).
btScalar normal_speed(const btSolverConstraint& row, const btSolverBody& a, const btSolverBody& b, bool forced) {
  const auto part = [forced](const btSolverBody& s, const btVector3& n, const btVector3& arm) {
    if (!s.m_originalBody) return btScalar(0);
    const btScalar f = forced ? 1 : 0;
    return n.dot(s.m_linearVelocity + f * s.m_externalForceImpulse) +
           arm.dot(s.m_angularVelocity + f * s.m_externalTorqueImpulse);
  };
  return part(a, row.m_contactNormal1, row.m_relpos1CrossNormal) + part(b, row.m_contactNormal2, row.m_relpos2CrossNormal);
}
}  // namespace

// Applies a row's starting impulse to its two bodies, as the solver's own
// iterations apply theirs.
void GrainSolver::warm_start(btSolverConstraint& row, btScalar impulse) {
  row.m_appliedImpulse = impulse;
  btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
  btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
  a.internalApplyImpulse(row.m_contactNormal1 * a.internalGetInvMass(), row.m_angularComponentA, impulse);
  b.internalApplyImpulse(row.m_contactNormal2 * b.internalGetInvMass(), row.m_angularComponentB, impulse);
}

void GrainSolver::convert(btPersistentManifold* manifold, const btContactSolverInfo& info) {
  auto* o0 = const_cast<btCollisionObject*>(manifold->getBody0());
  auto* o1 = const_cast<btCollisionObject*>(manifold->getBody1());
  const int a = getOrInitSolverBody(*o0, info.m_timeStep), b = getOrInitSolverBody(*o1, info.m_timeStep);
  if (m_tmpSolverBodyPool[a].m_invMass.fuzzyZero() && m_tmpSolverBodyPool[b].m_invMass.fuzzyZero()) return;
  for (int j = 0; j < manifold->getNumContacts(); ++j) {
    btManifoldPoint& cp = manifold->getContactPoint(j);
    if (cp.getDistance() > manifold->getContactProcessingThreshold()) continue;
    const int index = m_tmpSolverContactConstraintPool.size();
    btSolverConstraint& normal = m_tmpSolverContactConstraintPool.expandNonInitializing();
    normal.m_solverBodyIdA = a, normal.m_solverBodyIdB = b;
    normal.m_originalContactPoint = &cp;
    const btVector3 r0 = cp.getPositionWorldOnA() - o0->getWorldTransform().getOrigin();
    const btVector3 r1 = cp.getPositionWorldOnB() - o1->getWorldTransform().getOrigin();
    btScalar relaxation;
    const btScalar e = cp.m_combinedRestitution;
    cp.m_combinedRestitution = 0;  // the bounce is a pass of its own
    setupContactConstraint(normal, a, b, cp, info, relaxation, r0, r1);  // warm-started by Bullet
    cp.m_combinedRestitution = e;
    if (cp.getDistance() <= 0) {
      // The split-impulse correction: the overlap past the resting overlap
      // is pushed out, and a contact within it may close by what is left of
      // it, no further (a negative target: its row resists a push only past
      // that). Every touching contact takes part, or a push would drive a
      // grain into its other neighbours unresisted.
      const btScalar excess = -cp.getDistance() - rest_overlap_;
      normal.m_rhsPenetration = excess * info.m_erp2 / info.m_timeStep * normal.m_jacDiagABInv;
      pushing_ = pushing_ || excess > 0;
    }
    if (e > 0) {
      // The bounce answers the speed the grains met at, not that speed plus
      // this step's push of the water (physics/world.h), or e = 1 would gain
      // 2 g dt / v of its energy at every bounce.
      const btSolverBody &sa = m_tmpSolverBodyPool[a], &sb = m_tmpSolverBodyPool[b];
      const btScalar closing = normal_speed(normal, sa, sb, false);
      if (closing < -info.m_restitutionVelocityThreshold)
        bounces_.push_back({index, normal_speed(normal, sa, sb, true), -e * closing});
    }
    normal.m_frictionIndex = m_tmpSolverContactFrictionConstraintPool.size();
    btVector3 tangent(-cp.m_normalWorldOnB.y(), cp.m_normalWorldOnB.x(), 0);
    tangent.normalize();
    cp.m_lateralFrictionDir1 = tangent;
    warm_start(addFrictionConstraint(tangent, a, b, index, cp, r0, r1, o0, o1, relaxation, info),
               cp.m_appliedImpulseLateral1);
    if (cp.m_combinedRollingFriction > 0)
      warm_start(addTorsionalFrictionConstraint(btVector3(0, 0, 1), a, b, index, cp, cp.m_combinedRollingFriction, r0,
                                                r1, o0, o1, relaxation),
                 cp.m_appliedImpulseLateral2);
    else
      cp.m_appliedImpulseLateral2 = 0;
  }
}


// The position correction, only in a step where some overlap is past the
// resting overlap (at rest, none is: the pass would only cost).
void GrainSolver::solveGroupCacheFriendlySplitImpulseIterations(btCollisionObject** bodies, int body_count,
                                                                 btPersistentManifold** manifolds, int manifold_count,
                                                                 btTypedConstraint** constraints, int constraint_count,
                                                                 const btContactSolverInfo& info, btIDebugDraw* debug) {
  if (pushing_)
    btSequentialImpulseConstraintSolver::solveGroupCacheFriendlySplitImpulseIterations(
        bodies, body_count, manifolds, manifold_count, constraints, constraint_count, info, debug);
}

// One row within ±limit (a limit of zero takes a warm-started impulse off).
btScalar GrainSolver::solve_limited(btSolverConstraint& row, btScalar limit) {
  row.m_lowerLimit = -limit, row.m_upperLimit = limit;
  const btScalar r = resolveSingleConstraintRowGeneric(m_tmpSolverBodyPool[row.m_solverBodyIdA],
                                                       m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
  return r * r;
}

btScalar GrainSolver::solveSingleIteration(int iteration, btCollisionObject**, int, btPersistentManifold**, int,
                                           btTypedConstraint**, int, const btContactSolverInfo&, btIDebugDraw*) {
  btScalar residual = 0;
  // Symmetric Gauss-Seidel: top down on even iterations, bottom up on odd.
  const int n = m_tmpSolverContactConstraintPool.size();
  for (int i = 0; i < n; ++i) {
    const int j = iteration % 2 ? n - 1 - i : i;
    const btSolverConstraint& c = m_tmpSolverContactConstraintPool[j];
    const btScalar r =
        resolveSingleConstraintRowLowerLimit(m_tmpSolverBodyPool[c.m_solverBodyIdA], m_tmpSolverBodyPool[c.m_solverBodyIdB], c);
    residual = btMax(residual, r * r);
  }
  // Coulomb: |friction| <= mu N.
  for (int j = 0; j < m_tmpSolverContactFrictionConstraintPool.size(); ++j) {
    btSolverConstraint& f = m_tmpSolverContactFrictionConstraintPool[j];
    residual = btMax(residual, solve_limited(f, f.m_friction * m_tmpSolverContactConstraintPool[f.m_frictionIndex].m_appliedImpulse));
  }
  // Rolling: |torque| <= mu_r R_r N (m_friction holds mu_r R_r, physics/world.cpp).
  for (int j = 0; j < m_tmpSolverContactRollingFrictionConstraintPool.size(); ++j) {
    btSolverConstraint& r = m_tmpSolverContactRollingFrictionConstraintPool[j];
    residual = btMax(residual, solve_limited(r, r.m_friction * m_tmpSolverContactConstraintPool[r.m_frictionIndex].m_appliedImpulse));
  }
  return residual;
}

btScalar GrainSolver::solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int count,
                                                    const btContactSolverInfo& info) {
  // The bounce: a loaded contact that closed fast leaves at e times its closing speed.
  for (Bounce& b : bounces_) {
    btSolverConstraint& row = m_tmpSolverContactConstraintPool[b.row];
    b.load = row.m_appliedImpulse;
    b.point = static_cast<btManifoldPoint*>(row.m_originalContactPoint);
    if (b.load <= 0) continue;
    row.m_rhs = (b.leaving - b.closing) * row.m_jacDiagABInv;
    resolveSingleConstraintRowLowerLimit(m_tmpSolverBodyPool[row.m_solverBodyIdA], m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
  }
  for (int j = 0; j < m_tmpSolverContactRollingFrictionConstraintPool.size(); ++j) {
    const btSolverConstraint& r = m_tmpSolverContactRollingFrictionConstraintPool[j];
    static_cast<btManifoldPoint*>(m_tmpSolverContactConstraintPool[r.m_frictionIndex].m_originalContactPoint)
        ->m_appliedImpulseLateral2 = r.m_appliedImpulse;
  }
  // Writes the normal and friction impulses back to the contacts, then
  // the loads without their bounces.
  const btScalar r = btSequentialImpulseConstraintSolver::solveGroupCacheFriendlyFinish(bodies, count, info);
  for (const Bounce& b : bounces_) b.point->m_appliedImpulse = b.load;
  return r;
}
