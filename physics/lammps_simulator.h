#pragma once
// The LAMMPS backend (--mode lammps): the scene as a LAMMPS deck
// (physics/lammps_deck.h), run by `lmp` as a child process, its final
// positions read back and drawn as the Bullet backend draws its own. A
// reference DEM to hold the Bullet backend against, and a way to run a
// picture on many cores or a cluster.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "src/simulator.h"

namespace sandpic {

// Command-line options only, never scene keys: a scene file (or the studio,
// which accepts scenes) can never make sandpic run a command of its choice.
struct LammpsOptions {
  std::string lmp = "lmp";  // the LAMMPS executable (on PATH or a path)
  int ranks = 1;            // MPI ranks: > 1 runs `mpirun -np N lmp ...`
  std::string launcher;     // instead of mpirun, e.g. "srun -n 256" (split on spaces)
  std::string folder;       // keep the deck, log and dump here (default: a temporary folder, removed)
  std::string from_dump;    // read this dump of the deck's run instead of running LAMMPS
  double stiffness = 1;     // multiplies the contact stiffness (the step follows)
};

std::unique_ptr<Simulator> make_lammps_simulator(const LammpsOptions& opt);

// Writes the deck of a scene's run into `folder` (in.sandpic, atoms.txt:
// each atom's grain id, run.sh, deck.json: its figures) without running it. Returns the deck's
// figures as JSON (those the stats report).
ordered_json export_lammps(const SimInput& in, const std::string& folder);

// One run of `lmp` (as `opt` says) on `input`, in `folder`: in.sandpic,
// log.lammps and final.dump there. A progress bar of `total_steps` from its
// thermo lines. Throws SimulationError with LAMMPS's error line (exit 3).
struct LammpsRun {
  std::string version;  // "29 Sep 2021 - Update 2"
  int64_t steps = 0;    // the last step it reported
};
LammpsRun run_lammps(const std::string& input, const std::string& folder, const LammpsOptions& opt, Progress& progress,
                     int64_t total_steps);

// The final positions and velocities (px, px/s; y up) of a deck's atoms, by
// atom id - 1. InputError naming the file if it is not a dump of `atoms`
// atoms of sandpic's deck.
struct DumpAtom {
  double x = NAN, y = NAN, vx = NAN, vy = NAN;
};
std::vector<DumpAtom> read_lammps_dump(const std::string& path, size_t atoms);

// The `lmp` that `opt` would run, found on PATH; "" if there is none.
std::string find_lmp(const LammpsOptions& opt);

}  // namespace sandpic
