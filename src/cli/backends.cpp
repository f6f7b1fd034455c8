// The one place that chooses a backend from the scene's mode (STYLE.md:
// pbrt-v4's RenderCPU / RenderWavefront choice).
#include "src/cli/backends.h"

#include "lattice/lattice_simulator.h"
#if SANDPIC_WITH_BULLET
#include "physics/dem_simulator.h"
#endif
#include "src/errors.h"

namespace sandpic {

std::unique_ptr<Simulator> make_simulator(const Scene& s, const LammpsOptions& lammps) {
  switch (s.mode) {
    case Mode::Lattice:
      return make_lattice_simulator();
    case Mode::Dem:
#if SANDPIC_WITH_BULLET
      return make_dem_simulator();
#else
      throw key_error("mode", "'dem' needs a build with Bullet (cmake -DSANDPIC_WITH_BULLET=ON); use mode=lattice");
#endif
    case Mode::Lammps:
      // Missing `lmp` is found now, before anything is computed or written.
      if (lammps.from_dump.empty() && find_lmp(lammps).empty())
        throw key_error("mode", "'lammps' needs LAMMPS's `" + lammps.lmp +
                                    "` on PATH (apt-get install lammps openmpi-bin, or scripts/setup.sh)");
      return make_lammps_simulator(lammps);
  }
  throw key_error("mode", "unknown mode");
}

std::unique_ptr<Simulator> make_simulator(const Scene& s) { return make_simulator(s, LammpsOptions{}); }

}  // namespace sandpic
