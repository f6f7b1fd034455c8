#pragma once
// The scene's DEM values in the world's units (one unit per pixel, seconds)
// and the solver's (masses), shared by the simulator and the tests.
#include <array>

#include "physics/world.h"
#include "src/water.h"
#include "src/scene.h"

namespace sandpic {

// Which of the classes S1..S4 a run has grains of.
using ClassSet = std::array<bool, kClasses>;
constexpr ClassSet kAllClasses{true, true, true, true};

// The time step of a scene: the fastest class in `present` (its settling
// speed in water; no class present: every class) moves dem.step_diameters of
// the smallest present class's diameters per step.
double dem_time_step(const Scene& s, const ClassSet& present = kAllClasses);

// paper §7: how far above the pile (px) a grain of class k, settling at
// terminal_px_s, becomes a body: its last dem.simulated_fall_s of fall, at
// least its last 4 diameters (it lands at its settling speed, not created
// in contact; 4 was the analytic fall's gap, which dem_cost's fits are
// for). The run caps it at the grain's outlet.
double simulated_fall_px(const Scene& s, int k, double terminal_px_s);

// Bullet's radius (px) and mass of each class. Masses are scaled so that a
// grain's weight per step stays far below 1 (see dem_masses in the .cpp).
std::array<double, kClasses> dem_radii(const Scene& s);
std::array<double, kClasses> dem_masses(const Scene& s, const ClassSet& present = kAllClasses);

// The speed (px/s) under which a contact does not bounce.
double dem_bounce_speed(const Water& w, double dt);

// The grains' contact material: the scene's friction, restitution and
// rolling resistance, the solver's iterations, the bounce speed at `dt`.
GrainMaterial dem_material(const Scene& s, const Water& w, double dt);

// The angle a heap of the scene's grains stands at when every grain is a
// body (verify-dem's heap), interpolated in a table measured by sliding
// friction and rolling resistance, clamped at the table's ends,
// and falling to 0 with friction below its lowest.
double all_dynamic_heap_angle_deg(double friction, double rolling_resistance);
inline constexpr std::array<double, 3> kHeapFriction{0.1, 0.4, 0.9};  // the table's rows
inline constexpr std::array<double, 3> kHeapRolling{0.0, 0.1, 0.3};   // and columns

// paper §8.1's α in degrees: dem.slope_limit_deg, or with 0 the angle the
// grains' piles stand at (all_dynamic_heap_angle_deg) plus
// dem.slope_margin_deg.
double dem_slope_limit_deg(const Scene& s);

}  // namespace sandpic
