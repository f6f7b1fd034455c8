#pragma once
// The DEM backend: every grain a Bullet rigid body once it nears the pile,
// made affordable by the paper's three-layer model (§7-8).
#include <memory>

#include "src/simulator.h"

namespace sandpic {

std::unique_ptr<Simulator> make_dem_simulator();

// The time step of a scene: the fastest grain (its settling speed in water)
// moves dem.step_diameters small-grain diameters per step.
double dem_time_step(const Scene& s);

}  // namespace sandpic
