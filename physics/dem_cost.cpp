#include "physics/dem_cost.h"

#include <algorithm>
#include <cmath>

namespace sandpic {

Cost dem_cost(const Scene& s) {
  const double grains = double(s.window.width) * s.region.height;
  // Peak bodies (dynamic + static) of the default scene: 814 at 3,500
  // grains, 1,414 at 7,950, about 15·√n; all-dynamic keeps every grain.
  const double bodies = s.dem.layers == Layers::AllDynamic ? grains : std::min(grains, 15 * std::sqrt(grains));
  // ~100 bytes of run arrays a grain (layer, slot, anchors, positions), ~2 kB
  // a Bullet body (btRigidBody, its broadphase proxy, contact manifolds).
  const double bytes = 100 * grains + 2048 * bodies;
  // Simulated time grows with the grains (the release lasts n/rate) and so
  // does the active set: 4.2 s at 3,500 grains, 24 s at 7,950 and 2,010 s
  // at 100,045 (issue 3) fit 2,000 s · (n/10^5)^1.75 within 30%.
  const double seconds = 2000 * std::pow(grains / 1e5, 1.75) * (0.05 / s.dem.step_diameters);
  return {bytes, seconds};
}

}  // namespace sandpic
