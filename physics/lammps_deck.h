#pragma once
// The LAMMPS backend's input: a scene's grains, release schedule, water and
// window as a LAMMPS input deck for its GRANULAR package (pair_style
// granular), run by `lmp` as it stands, on one rank or under mpirun. Units:
// px, s, and g/cm³·px³ for mass (LAMMPS's `units lj`, read as such).
#include <cstdint>
#include <string>
#include <vector>

#include "src/simulator.h"

namespace sandpic {

// The contact model (pair_coeff): Hertz normal force F = k_n·√R·δ^1.5 with
// Tsuji damping (restitution e for every pair of classes), Mindlin
// tangential with Coulomb limit μ, SDS rolling resistance limited to
// μ_r·F_n·R (R = R_a·R_b/(R_a+R_b)), as the Bullet backend's rows.
struct LammpsContact {
  double kn = 0;             // Hertz stiffness, force/px² (pressure)
  double kt = 0;             // Mindlin tangential stiffness, force/px² (× contact radius a)
  double kr = 0, gamma_r = 0;  // rolling spring (force/px) and its damping (force·s/px)
  double friction = 0, restitution = 0, rolling = 0;
  double load = 0;           // the largest resting contact force it was chosen for
  double target_overlap_px = 0;  // the overlap that load makes
  double landing_overlap_px = 0;  // a grain's at landing on the floor at its settling speed (no damping)
  double dt = 0;             // s: 1/kStepsPerPeriod of the stiffest pair's period at that overlap
};

struct LammpsDeck {
  std::string input;                  // in.sandpic
  std::vector<int32_t> grain_of_atom;  // LAMMPS atom id − 1 → grain id (atoms are created in this order)
  LammpsContact contact;
  double release_end_s = 0;   // the last grain created
  double settle_limit_s = 0;  // the run stops here if it has not settled by then
  double settle_speed_px_s = 0;  // settled: no grain faster than this
  int64_t release_steps = 0, max_steps = 0;
  int64_t expected_steps = 0;  // the progress bar's: the release, the last grain's fall and half a second
  int64_t delayed = 0;        // creations moved to a later batch: another grain was in the way
  double late_mean_s = 0, late_max_s = 0;  // how far behind the release schedule grains were created
  int thermo_steps = 0;       // a thermo line every this many steps (the progress bar reads them)
};

// Everything but the start of the grains' fall is the Bullet backend's:
// release at dem.release_rate in falling order, Eq. 1-2 to the outlet
// (src/release.h), then down at the class's settling speed. The Bullet
// backend makes a grain a body at its outlet (or above the pile where the
// pile has reached the outlet, or for only the last dem.simulated_fall_s of
// a long fall); a deck written in advance cannot know the pile's
// height, so each grain is created under the lid, early enough to
// pass its outlet when the Bullet backend's grain would, and falls from
// there. The pile does reach the lowest outlets (the default scene's bottom
// row of units falls until late, their outlets 35 px up at --scale 0.1, the
// piles 31-39 px high at the end): created at the outlets, a first try piled
// that scene high at the walls and low in the middle, most likely grains
// created inside the pile and thrown aside (docs/notebook/2026-12-04-the-fall.md).
// `stiffness` multiplies the contact's (the step follows): the check that
// the soft contacts do not set the piles (docs/lammps.md).
LammpsDeck lammps_deck(const SimInput& in, double stiffness = 1);

// Grains placed by hand (y up), all at rest at t = 0, then the same settle
// as a scene's deck, for at most `max_s` simulated seconds: verify-dem's
// cross-check of the two engines from one configuration. grain_of_atom is
// the index into `grains`.
struct PlacedGrain {
  int cls = 0;
  Vec2 p;
};
LammpsDeck lammps_placed_deck(const Scene& s, const std::vector<PlacedGrain>& grains, double max_s);

// The deck's contact model and step for a scene (what stats and docs
// report); `column_weight` > 0: the weight the heaviest column one mean
// diameter wide carries (else estimated from the grains over the window).
LammpsContact lammps_contact(const Scene& s, const GrainSet& grains, double column_weight = 0, double stiffness = 1);

}  // namespace sandpic
