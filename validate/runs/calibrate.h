#pragma once
// The lattice's rule values fitted to DEM piles, so that a preview
// predicts the final render. Fitted on variants of a scene (other layouts,
// other tessellations, another size), never on the picture that is scored.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "src/scene_file.h"
#include "src/simulator.h"
#include "validate/runs/kept_runs.h"

namespace sandpic {

struct CalibrateOptions {
  // Each variant at each of these sizes (grains, about): two or more sizes
  // separate the DEM's loose surface layer (lattice.surface_px, the same at
  // every size) from its bulk (lattice.bulk, a share of the pile's height).
  std::vector<int64_t> grains = {8000};
  int scenes = 3;                         // variants of the scene (layout seed and tessellation)
  std::vector<uint64_t> physics_seeds = {1, 2};  // DEM runs per variant
  std::string runs_dir;                   // DEM piles kept here and reused while their digest holds ("": none)
  // Also fit these keys by their registry grids (Field::fit_grid: for
  // example lattice.trap_rate and trap_deg, rolling grains caught on the
  // flanks; lattice.spot_busy_s, a busy outlet's grains queueing as in the
  // DEM): the whole fit once per combination of their values, the scene's
  // own first, the best kept. check_fit_keys says which keys may be named.
  std::vector<std::string> fit;
  // Also fit lattice.picture_share to the composition error over this many
  // horizontal bands (validate's --bands), after everything else: it moves no
  // grain and no column top. The composition error is reported either way.
  bool shares = false;
  int bands = 8;
};

// Throws InputError (exit 2) naming a key of `keys` that has no fit grid,
// with the keys that have one.
void check_fit_keys(const std::vector<std::string>& keys);

// The scenes the fit runs on: the scene's physics (friction, restitution,
// water, grains) with layout seeds seed+1000+i and, for a tessellated scene,
// the tessellation kinds varying / uniform / strips in turn.
std::vector<Scene> calibration_scenes(const Scene& base, const CalibrateOptions& opt);

struct Calibration {
  std::array<double, kClasses> repose_deg{}, runout_px{};
  double bulk = 1, surface_px = 0;
  // Every key with a fit grid (fitted or the scene's own), in registry order:
  // {"lattice.trap_rate": 0.2, ...}.
  ordered_json grid = ordered_json::object();
  std::array<double, kClasses> picture_share{1, 1, 1, 1};
  std::vector<std::vector<int>> groups;  // classes the DEM cannot tell apart share their values
  double error_before = 0, error_after = 0;  // mean silhouette error, lattice vs each DEM run
  double noise_floor = 0;                    // mean silhouette error between DEM seeds of one scene
  // The same for the composition error, which lattice.picture_share is fitted to.
  double composition_before = 0, composition_after = 0, composition_floor = 0;
  int64_t lattice_runs = 0;
  double dem_s = 0;  // simulate time of the DEM runs, summed
  ordered_json scenes = ordered_json::array();
};

// `log` hears a line per step. DEM runs go in parallel (TBB), each its own
// simulator; the result does not depend on the thread count.
Calibration calibrate(const Scene& base, const CalibrateOptions& opt, const SimulatorFactory& make,
                      const std::function<void(const std::string&)>& log);

// The file a scene names in lattice.calibration: {"lattice": {...}, "fit": {...}}.
ordered_json calibration_json(const Scene& base, const Calibration& c);

}  // namespace sandpic
