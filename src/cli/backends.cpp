// The one place that chooses a backend from the scene's mode (STYLE.md:
// pbrt-v4's RenderCPU / RenderWavefront choice).
#include "lattice/lattice_simulator.h"
#if SANDPIC_WITH_BULLET
#include "physics/dem_simulator.h"
#endif
#include "src/errors.h"
#include "src/simulator.h"

namespace sandpic {

std::unique_ptr<Simulator> make_simulator(const Scene& s) {
  switch (s.mode) {
    case Mode::Lattice:
      return make_lattice_simulator();
    case Mode::Dem:
#if SANDPIC_WITH_BULLET
      return make_dem_simulator();
#else
      throw key_error("mode", "'dem' needs a build with Bullet (cmake -DSANDPIC_WITH_BULLET=ON); use mode=lattice");
#endif
  }
  throw key_error("mode", "unknown mode");
}

}  // namespace sandpic
