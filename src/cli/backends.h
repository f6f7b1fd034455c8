#pragma once
// The CLI's choice of backend: the scene's mode, with the LAMMPS backend's
// command-line options (never scene keys: physics/lammps_simulator.h).
#include <memory>

#include "physics/lammps_simulator.h"
#include "src/simulator.h"

namespace sandpic {

std::unique_ptr<Simulator> make_simulator(const Scene& s, const LammpsOptions& lammps);

}  // namespace sandpic
