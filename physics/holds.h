#pragma once
// What "holds" means, one definition for the DEM run's end
// (physics/dem_simulator.cpp) and verify-dem's lone-grain cases: a grain
// holds when it moves less than kHoldDiameters of its diameter in
// kHoldSeconds of simulated time. Slower than any creep the eye would see
// in a picture over minutes, faster than the solver's resting jitter.

namespace sandpic {

constexpr double kHoldDiameters = 0.05;
constexpr double kHoldSeconds = 1.0;

}  // namespace sandpic
