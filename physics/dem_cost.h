#pragma once
// What a DEM run will take, from the scene alone, before a body is made.
#include "src/simulator.h"

namespace sandpic {

// Memory: the run's per-grain arrays and the Bullet bodies of the active
// layers at their peak. Time: a power law through measured runs of the
// default scene (three layers, 2 cores), scaled by the steps a grain spends
// as a body (its settling speed against the time step) and by restitution.
// An order of magnitude, to refuse or warn before starting, not a promise.
Cost dem_cost(const Scene& s);

}  // namespace sandpic
