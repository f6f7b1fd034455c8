#pragma once
// Bullet's sequential-impulse solver with the rows a grain contact needs, in
// the picture's plane, every one warm-started from the previous step.
//
// Bullet 3.24 warm-starts a contact's normal row only (at 0.85 of last
// step's impulse); its friction and rolling rows start from zero at every
// step, and every contact also carries a spinning row that a grain held in
// the plane cannot use. Alternating between a friction row and a rolling row
// from zero removes only 2/7 of the error per iteration (a sphere's contact
// slip is 7/2 of its impulse over its mass), so 10 iterations left a grain
// resting in a notch creeping 2-3° below its analytic holding angle, and a
// pile's forces were never rebuilt. Here a contact has three rows: normal,
// friction along the in-plane tangent z × n (the same direction every step,
// so last step's impulse means the same thing), and rolling about z; all
// three start from last step's impulses in full. The friction and rolling
// limits follow the normal impulse at every iteration, also when it falls
// to zero (Bullet skips the row then, which would leave a warm-started
// impulse on a contact that opened). A contact's rolling impulse is kept
// in its manifold point's second lateral impulse, which one friction
// direction leaves unused.
//
// Order. A grain's weight reaches the floor through every contact under it,
// and a Gauss-Seidel sweep passes a change of load on only as far as the
// rows it has solved after it: in Bullet's order (the broadphase's pairs,
// arbitrary in height) a pile 40 grains deep got each step's weight only
// part of the way down in 10 iterations, and what the solve left over became
// motion. A heap of 3,600 grains (verify-dem's full heap, all-dynamic,
// friction 0.4) slumped for 8 s of simulated time after its last grain
// landed, in bursts of a thousand grains down to the floor, and stopped at
// 12.6 s; 4x the iterations did not stop it, half the step did (6.2 s, at
// the same cost). So the rows are solved in order of height: normal rows
// top down, then bottom up (the floor's answer going back up), alternately
// (symmetric Gauss-Seidel); friction and rolling rows top down. At the step
// the heap then came to rest at 6.2 s and 8.8 s (seeds 1 and 2), in a third
// and 60% of the time (docs/notebook/2026-12-04-solver-order.md).
//
// Overlap is corrected by split impulse (a position correction that adds
// no velocity) at every depth past the resting overlap below: with
// Bullet's default it starts only past 0.04 px, and shallower overlaps were
// pushed apart through the velocities, an impulse that, warm-started, would
// be pushed again at every step.
//
// Resting overlap. The position correction pushes overlapping grains apart
// along their normals only, without friction. Applied to every overlap, it
// acted at rest on overlaps at the level of single-precision rounding of
// the positions, every step: the pushes, and the fall back into the
// neighbours that each push opened, ratcheted a resting heap down its
// slopes. On a 480-grain heap whose outline had held for a second, the
// grains drifted 0.002 px in 2 s (median), and 15-20 surface grains
// avalanched 1-2 px a second later; with the correction switched off at
// the same moment the drift was 3e-5 px and nothing moved (10, 40 or 160
// iterations, friction rows first, a rotational drag in the water: all
// drifted and avalanched as before). So an overlap up to kRestOverlap
// (physics/world.h) of the smallest grain's diameter is left as it is: the
// velocity rows still keep it from deepening, and only the excess beyond it
// is pushed out. Every other touching contact takes part in the push and
// resists it past its own resting overlap: Bullet's push pass skips a row
// without a correction of its own, and a push then drove a grain into its
// other neighbours unresisted, deeper than the resting overlap, to be
// pushed again at the next step
// (docs/notebook/2026-12-05-resting-overlap.md).
//
// Restitution is a pass of its own after the iterations (as Box2D v3's):
// a contact that closed faster than the bounce speed and carries a load
// leaves at e times the speed it closed at. Bullet adds the bounce to the
// row's target instead, and a contact found while its grain is still a
// fraction of a step away (a speculative contact) takes the gap off that
// target: a grain falling at 3,300 px/s met the floor at the 0.4-step gap
// it was found at, left at e v − gap/dt < 0 and never rebounded, at any e.
// The bounce is not kept for warm-starting: a contact starts the next step
// from the load it carried, not from the bounce.
#include <utility>
#include <vector>

#include <BulletCollision/NarrowPhaseCollision/btManifoldPoint.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>

class GrainSolver : public btSequentialImpulseConstraintSolver {
 public:
  // Overlaps up to this depth (world units) are not pushed apart.
  void set_rest_overlap(btScalar depth) { rest_overlap_ = depth; }

  // The solver settings it is made for (warm-starting in full, split
  // impulse for every overlap, its iteration count).
  static void configure(btContactSolverInfo& info, int iterations);

 protected:
  void convertContacts(btPersistentManifold** manifolds, int count, const btContactSolverInfo& info) override;
  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int body_count,
                                btPersistentManifold** manifolds, int manifold_count, btTypedConstraint** constraints,
                                int constraint_count, const btContactSolverInfo& info, btIDebugDraw* debug) override;
  void solveGroupCacheFriendlySplitImpulseIterations(btCollisionObject** bodies, int body_count,
                                                     btPersistentManifold** manifolds, int manifold_count,
                                                     btTypedConstraint** constraints, int constraint_count,
                                                     const btContactSolverInfo& info, btIDebugDraw* debug) override;
  btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int count,
                                         const btContactSolverInfo& info) override;

 private:
  void convert(btPersistentManifold* manifold, const btContactSolverInfo& info);
  void warm_start(btSolverConstraint& row, btScalar impulse);
  btScalar solve_limited(btSolverConstraint& row, btScalar limit);

  struct Bounce {
    int row;
    btScalar closing, leaving;  // normal speeds before the solve (with gravity) and wanted after it (px/s)
    btScalar load = 0;          // the row's impulse before the bounce
    btManifoldPoint* point = nullptr;
  };
  btScalar rest_overlap_ = 0;
  bool pushing_ = false;  // some overlap in this step is past the resting overlap
  std::vector<Bounce> bounces_;
  std::vector<std::pair<btScalar, int>> order_, spare_;  // (−height, manifold) of this step's contacts
};
