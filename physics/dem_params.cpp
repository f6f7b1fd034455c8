// The scene's DEM values in the world's units (px, s) and the solver's
// (masses), and the layer model's α.
#include "physics/dem_params.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

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

namespace {

// The heap angle of verify-dem's full heap (3,600 grains of two sizes poured
// from a point, every grain a body, the default step), mean of physics seeds
// 1 and 2 (rolling resistance 0: seed 1), by sliding friction (rows,
// kHeapFriction) and rolling resistance (columns, kHeapRolling);
// docs/notebook/2026-12-07-alpha-from-the-piles.md.
constexpr double kHeapAngleDeg[3][3] = {
    {7.5, 9.2, 10.05},
    {16.0, 25.7, 32.95},
    {24.1, 29.25, 38.75},
};

// Where v falls on a grid: the cell's first index and the weight of the next
// point, clamped to the grid's ends.
template <size_t N>
std::pair<size_t, double> grid_cell(const std::array<double, N>& grid, double v) {
  if (v <= grid.front()) return {0, 0.0};
  if (v >= grid.back()) return {grid.size() - 2, 1.0};
  size_t i = 0;
  while (v > grid[i + 1]) ++i;
  return {i, (v - grid[i]) / (grid[i + 1] - grid[i])};
}

}  // namespace

double all_dynamic_heap_angle_deg(double friction, double rolling_resistance) {
  const auto [i, u] = grid_cell(kHeapFriction, friction);
  const auto [j, v] = grid_cell(kHeapRolling, rolling_resistance);
  auto row = [&, j = j, v = v](size_t r) { return (1 - v) * kHeapAngleDeg[r][j] + v * kHeapAngleDeg[r][j + 1]; };
  const double angle = (1 - u) * row(i) + u * row(i + 1);
  // Below the table's lowest friction: frictionless grains hold no slope.
  return friction < kHeapFriction.front() ? angle * friction / kHeapFriction.front() : angle;
}

// paper §8.1: θ < α keeps a grain on a slope steeper than α moving. α is
// the angle the grains' own piles stand at: a grain at rest on a gentler
// slope stays where it is when every grain is a body, so it may join the
// static layer; on a steeper one it rests only for the moment. Lower, as
// α was until 2026-12-07 (the angle a lone grain slides or rolls at plus
// 5°: 10.7° at the defaults, where the piles stand at 25°), the grains on
// the default scene's flanks (13-14°) never became static: with a band of
// static bodies a third of the picture's grains were still bodies at the
// end, at 2.2x the body-steps. Higher, grains resting for the moment on
// a steep flank freeze there (a fixed 35°: piles of 42-47° at friction 0.4
// and 0.9 alike).
double dem_slope_limit_deg(const Scene& s) {
  if (s.dem.slope_limit_deg > 0) return s.dem.slope_limit_deg;
  const double repose = all_dynamic_heap_angle_deg(s.physics.friction, s.dem.rolling_resistance);
  return std::clamp(repose + s.dem.slope_margin_deg, 0.0, 89.0);
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
