// The one place that chooses a backend from the scene's mode (STYLE.md:
// pbrt-v4's RenderCPU / RenderWavefront choice).
#include "lattice/lattice_simulator.h"
#include "src/errors.h"
#include "src/simulator.h"

namespace sandpic {

std::unique_ptr<Simulator> make_simulator(const Scene& s) {
  switch (s.mode) {
    case Mode::Lattice:
      return make_lattice_simulator();
    case Mode::Dem:
      throw key_error("mode", "'dem' is not in this build of sandpic yet; use mode=lattice");
  }
  throw key_error("mode", "unknown mode");
}

}  // namespace sandpic
