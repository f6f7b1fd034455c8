// The scene's DEM values in the world's units (px, s) and the solver's
// (masses), and the layer model's α.
#include "physics/dem_params.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sandpic {

std::array<double, kClasses> dem_radii(const Scene& s) {
  std::array<double, kClasses> r;
  for (int k = 0; k < kClasses; ++k) r[k] = grain_diameter_px(s, k) / 2;
  return r;
}

double simulated_fall_px(const Scene& s, int k, double terminal_px_s) {
  return std::max(4 * grain_diameter_px(s, k), s.dem.simulated_fall_s * terminal_px_s);
}

namespace {

// A run without grains steps and weighs as if every class were there.
const ClassSet& or_every_class(const ClassSet& present) {
  return present == ClassSet{} ? kAllClasses : present;
}

}  // namespace

// Only the classes in the run: a scene with S3 and S4 at 100 g/cm^3 but no
// grains of them stepped at their settling speed (468,000 steps, 49 s for
// 300 grains whose own step is 5.8x longer).
double dem_time_step(const Scene& s, const ClassSet& in_run) {
  const ClassSet& present = or_every_class(in_run);
  const Water w = water_model(s);
  double fastest = 0, smallest = INFINITY;
  for (int k = 0; k < kClasses; ++k)
    if (present[size_t(k)]) {
      fastest = std::max(fastest, w.terminal_px_s[size_t(k)]);
      smallest = std::min(smallest, grain_diameter_px(s, k));
    }
  return s.dem.step_diameters * smallest / std::max(fastest, 1e-9);
}

// Only ratios between classes matter to the solver, so masses are scaled
// until the heaviest grain's weight per step is 1e-5. (Bullet's own rolling
// row caps its impulse at the coefficient, min(μ_r·N, μ_r): with masses in
// g·px³/cm³ rolling resistance was ~40× too weak. physics/grain_solver has
// no cap; the scale stays as the solver's unit.)
std::array<double, kClasses> dem_masses(const Scene& s, const ClassSet& in_run) {
  const ClassSet& present = or_every_class(in_run);
  const Water w = water_model(s);
  const double dt = dem_time_step(s, present);
  std::array<double, kClasses> m;
  double heaviest = 0;
  for (int k = 0; k < kClasses; ++k) {
    m[k] = s.grains.density_g_cm3[k] * std::pow(grain_diameter_px(s, k), 3);
    if (present[size_t(k)]) heaviest = std::max(heaviest, m[k] * std::max(w.gravity_px_s2[k], 1e-9) * dt);
  }
  for (double& v : m) v *= 1e-5 / heaviest;
  return m;
}

// A fixed α let friction no longer shape the piles: the static layer grew
// as steep as α allowed at 0.4 and 0.9 alike (three layers, one pile of
// 1,260 grains: 42° and 44° at α = 35°; 34° and 43° with this). Friction
// sets how steep grains can stand, so it sets how steep they may freeze.
double dem_slope_limit_deg(const Scene& s) {
  if (s.dem.slope_limit_deg > 0) return s.dem.slope_limit_deg;
  const double repose = std::atan(std::min(s.physics.friction, s.dem.rolling_resistance)) * 180 / std::numbers::pi;
  return std::min(89.0, repose + s.dem.slope_margin_deg);
}

// A resting contact closes by g·dt each step (~11 px/s at the default
// scale) and must not bounce, or piles jitter and creep flat (every grain a
// body at friction 0.4: 20.8° with Bullet's default threshold, 24.6° with
// this); a grain landing at its settling speed (45-174 px/s) does.
double dem_bounce_speed(const Water& w, double dt) {
  return 3 * *std::max_element(w.gravity_px_s2.begin(), w.gravity_px_s2.end()) * dt;
}

GrainMaterial dem_material(const Scene& s, const Water& w, double dt) {
  return GrainMaterial{s.physics.friction, s.physics.restitution, s.dem.rolling_resistance, s.dem.solver_iterations,
                       dem_bounce_speed(w, dt)};
}

}  // namespace sandpic
