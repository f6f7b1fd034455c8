#pragma once
// render's options for --mode lammps: how `lmp` is started and where its
// files go. Command-line only: a scene can never name a command to run.
#include <string>

#include <CLI/CLI.hpp>

#include "physics/lammps_simulator.h"

namespace sandpic {

struct LammpsCliOptions {
  LammpsOptions opt;
  void add_to(CLI::App* cmd) {
    cmd->add_option("--ranks", opt.ranks, "--mode lammps: MPI ranks (mpirun -np N); pictures agree within the seed "
                                          "spread across rank counts, byte for byte at one count")
        ->check(CLI::Range(1, 100000));
    cmd->add_option("--launcher", opt.launcher, "--mode lammps: run lmp under this command instead of mpirun, "
                                                "e.g. 'srun -n 256'");
    cmd->add_option("--lmp", opt.lmp, "--mode lammps: the LAMMPS executable")->capture_default_str();
    cmd->add_option("--lammps-dir", opt.folder, "--mode lammps: keep the deck, log and dump in this folder "
                                                "(default: a temporary one, kept only if LAMMPS fails)");
    cmd->add_option("--lammps-stiffness", opt.stiffness, "--mode lammps: multiplies the soft contacts' stiffness "
                                                         "(the step follows; 0.5: the check that they do not set the piles)")
        ->check(CLI::Range(0.01, 100.0));
    cmd->add_option("--from-dump", opt.from_dump, "--mode lammps: draw this dump of the scene's deck (a run of "
                                                  "sandpic export-lammps's run.sh) instead of running LAMMPS");
  }
};

}  // namespace sandpic
