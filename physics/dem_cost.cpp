#include "physics/dem_cost.h"

#include <algorithm>
#include <cmath>

#include "physics/dem_params.h"
#include "src/water.h"

namespace sandpic {
namespace {

// A grain's steps as a body: it comes to rest within a few of its own
// diameters at its settling speed, counted in time steps (dem_time_step:
// the fastest class moves step_diameters small diameters a step). Free of
// units, so the scene's scale drops out; classes weighted alike (the
// picture's shares are not known before initialization).
double body_steps(const Scene& s) {
  const Water w = water_model(s);
  const double dt = dem_time_step(s);
  double sum = 0;
  for (int k = 0; k < kClasses; ++k)
    sum += grain_diameter_px(s, k) / std::max(w.terminal_px_s[k], 1e-9) / dt / kClasses;
  return sum;
}

}  // namespace

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
  // at 100,045 (three layers, the default grains) fit 2,000 s · (n/10^5)^1.75
  // within 30%. Other grains, densities and steps scale it by their body-
  // steps against the default's: grains 100x denser than the water beside
  // grains barely denser (the stress catalogue's density-100:1) settle 13x
  // slower on a 5.8x shorter step.
  Scene reference;
  reference.dem.water = s.dem.water;
  const double steps_ratio = body_steps(s) / body_steps(reference);
  double seconds = 2000 * std::pow(grains / 1e5, 1.75) * steps_ratio;
  // Bouncing grains rest later, and their speed makes the stiffness watch
  // sub-step: about 1/(1 − c·e), c = 0.84 from the stress catalogue's
  // quick scene (2,000 grains: 29.8 s at e = 1 against 5.1 s at e = 0, on
  // a loaded machine), relative to the default e.
  const auto bounces = [](double e) { return 1 / (1 - 0.84 * std::clamp(e, 0.0, 1.0)); };
  seconds *= bounces(s.physics.restitution) / bounces(reference.physics.restitution);
  // The fits above are for a fall analytic until 4 diameters above the pile.
  // A simulated fall adds its steps to each grain's residence (2,631 body-
  // steps per grain at 14,000 grains, growing as n^0.75 with the fit): at
  // --scale 0.2 the whole fall added 1,409 body-steps per grain and took
  // 1.63x the time, as if every grain fell 0.4 of the drop from the region
  // to the floor (outlets lie inside the region, piles rise to meet it).
  const double dt = dem_time_step(s), drop = 0.4 * std::max(1.0, double(s.window.height - s.region.height));
  const Water w = water_model(s);
  double fall_steps = 0;
  for (int k = 0; k < kClasses; ++k) {
    const double v = std::max(w.terminal_px_s[k], 1e-9), analytic = std::min(drop, 4 * grain_diameter_px(s, k));
    fall_steps += (std::min(drop, simulated_fall_px(s, k, v)) - analytic) / v / dt / kClasses;
  }
  const double fall = 1 + fall_steps / (2631 * std::pow(grains / 14000, 0.75) * steps_ratio);
  // The fits are for immovable static grains (dem.static_bodies false).
  // The default band of static bodies is solved with the flow: at --scale
  // 0.2 5,362 body-steps a grain against 4,201, 1.4-1.5x the time.
  const double band = s.dem.layers == Layers::Three && s.dem.static_bodies ? 1.45 : 1.0;
  return {bytes + 2048 * bodies * (fall - 1), seconds * fall * band};
}

}  // namespace sandpic
