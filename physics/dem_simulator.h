#pragma once
// The DEM backend: every grain a Bullet rigid body once it nears the pile,
// made affordable by the paper's three-layer model (§7-8).
#include <array>
#include <memory>

#include "src/simulator.h"

namespace sandpic {

std::unique_ptr<Simulator> make_dem_simulator();

// The time step of a scene: the fastest grain (its settling speed in water)
// moves dem.step_diameters small-grain diameters per step.
double dem_time_step(const Scene& s);

// Bullet's radius (px) and mass of each class. Masses are scaled so that a
// grain's weight per step stays far below 1 (see dem_masses in the .cpp).
std::array<double, kClasses> dem_radii(const Scene& s);
// paper §8.1's α in degrees: dem.slope_limit_deg, or with 0 the angle at
// which a lone grain starts to slide (friction) or roll (rolling
// resistance), whichever is lower, plus dem.slope_margin_deg.
double dem_slope_limit_deg(const Scene& s);
std::array<double, kClasses> dem_masses(const Scene& s);

}  // namespace sandpic
