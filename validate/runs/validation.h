#pragma once
// Issue 4: `sandpic validate`. The lattice and the DEM on one scene, the DEM
// again with more physics seeds (same layout) for the noise floor: how much
// two equally valid physical results differ. Every metric of compare, the
// lattice's error over that floor, and error against run time for a sweep
// of settings of both modes.
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "src/scene_file.h"
#include "validate/runs/calibrate.h"
#include "validate/metrics/compare.h"

namespace sandpic {

struct ValidateOptions {
  int extra_seeds = 4;                         // DEM runs beyond the scene's own seed (>= 4: five or more)
  bool sweep_lattice = true, sweep_dem = true;
  int64_t all_dynamic_max = 5000;              // all-dynamic in the sweep up to this many grains (cost ~n²)
  int bands = 8;
  double blur_sigma_px = 3;
  int lattice_timing_runs = 7;                 // the lattice's time is the median of this many runs
  int lattice_seeds = 1;                       // lattice physics seeds scored: the scene's, then the next ones
  std::string cache_dir;                       // DEM runs kept here (PNG + stats) and reused while their digest holds
};

struct ValidationRun {
  std::string label, group, setting;  // group: lattice | dem | sweep-lattice | sweep-dem
  uint64_t physics_seed = 0;
  cv::Mat picture;                    // 8-bit BGR
  double simulate_s = 0;
  int64_t grains = 0;
  bool cached = false;
  std::string skipped;                // why a sweep point did not run ("" if it ran)
  Comparison mean;                    // against the DEM runs (mean of each metric); sweep and lattice only
};

// A metric as an error (0: alike): 1 − SSIM for the SSIMs, mean squared
// difference for PSNR (so the ratio of two is the ratio of their MSEs).
struct MetricRow {
  std::string name;
  double lattice = 0, floor = 0;  // the metric itself: lattice vs DEM runs, DEM vs DEM
  double ratio = 0;               // lattice's error over the floor's
  double spread = NAN;            // the metric between lattice seeds (NaN with one seed)
};

struct Validation {
  Scene scene;
  ValidationRun lattice;              // at the scene's physics seed (timed, pictured)
  std::vector<ValidationRun> lattice_seeds;  // at the next --lattice-seeds − 1 seeds (scored with it)
  std::vector<ValidationRun> dem;     // [0] the scene's physics seed, then the extra seeds
  std::vector<ValidationRun> sweep;
  std::vector<MetricRow> metrics;
  double lattice_s = 0, dem_s = 0;    // medians of simulate_s
  double time_ratio = 0;              // dem_s / lattice_s
  cv::Mat heat_map;                   // |blurred luminance difference|, lattice vs DEM [0], outlines drawn
  std::vector<std::string> notes;
};

// Throws InputError for options no run can take (fewer than five DEM runs,
// no lattice seed).
void check_options(const ValidateOptions& opt);
// Checks the options first; a build without Bullet fails at the first DEM run
// (the CLI says so before any work).
Validation run_validation(const Scene& base, const ValidateOptions& opt, const SimulatorFactory& make,
                          const std::function<void(const std::string&)>& log);

ordered_json validation_json(const Validation& v, const std::string& reproduce);

// Mean of each metric of compare over several comparisons (PSNR through the MSE).
Comparison mean_comparison(const std::vector<Comparison>& all);

}  // namespace sandpic
