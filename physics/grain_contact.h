#pragma once
// The contact between two grains (spheres) in the DEM's Bullet world, found
// as Bullet finds it (centre to centre) but kept from step to step.
//
// Bullet 3.24 compiles its sphere-sphere algorithm with CLEAR_MANIFOLD
// (btSphereSphereCollisionAlgorithm.cpp, line 15), emptying every grain
// pair's contact manifold at every step; its own comment says this
// "disables warmstarting". Every grain-grain contact then started each step
// from zero normal, friction and rolling impulses, and 10 solver iterations
// could not rebuild the forces that hold a pile: a grain in a notch slipped
// 2-3° before its analytic holding angle and piles crept flat. This one
// writes the same point (normal along the centres, the distance, the point
// on B) but carries the previous step's impulses over to it, and keeps a
// pair whose gap is under the contact breaking threshold in contact
// (Bullet's speculative contact: the solver lets it close, no further).
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>

// Registered on the dispatcher for SPHERE_SHAPE_PROXYTYPE pairs.
struct GrainContactCreateFunc : public btCollisionAlgorithmCreateFunc {
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                 const btCollisionObjectWrapper* a,
                                                 const btCollisionObjectWrapper* b) override;
};
