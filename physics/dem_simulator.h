#pragma once
// The DEM backend: every grain a Bullet rigid body from its outlet down,
// made affordable by the paper's three-layer model (§7-8).
#include <memory>

#include "physics/dem_params.h"
#include "src/simulator.h"

namespace sandpic {

std::unique_ptr<Simulator> make_dem_simulator();

}  // namespace sandpic
