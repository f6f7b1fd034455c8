#pragma once
// paper Fig. 12: simulation time against grain count for the DEM's layer
// models (three, bcre, all-dynamic), measured side by side in one run, with
// each model's silhouette error against all-dynamic on the same scene and
// seed (the price in accuracy of each speed-up).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "src/simulator.h"

namespace sandpic {

struct LayerBenchOptions {
  std::vector<int64_t> grains = {2000, 5000, 10000, 20000, 50000, 100000};  // targets
  std::vector<Layers> layers = {Layers::Three, Layers::Bcre, Layers::AllDynamic};
  std::vector<uint64_t> seeds = {1, 2};  // physics seeds
  // all-dynamic's cost grows as n² (every grain a body until the end): it
  // is run up to this count, and is the reference only where it ran.
  int64_t all_dynamic_max = 5000;
  int64_t bcre_max = 100000000;  // BCRE's bumpy height field is slow to settle on
};

struct LayerBenchRow {
  std::string layers;
  int64_t target = 0, grains = 0;
  uint64_t seed = 0;
  double scale = 1, simulate_s = 0;
  int64_t steps = 0, peak_bodies = 0;
  double silhouette_error = NAN;  // against all-dynamic, same count and seed; NaN: no reference
};

// Runs every (count, seed, layers) on the scene scaled to each count (grain
// size in px kept, so the time step is the same everywhere). `log` hears
// each row as it is measured.
std::vector<LayerBenchRow> run_layer_bench(const Scene& base, const LayerBenchOptions& opt, Simulator& dem,
                                           const std::function<void(const LayerBenchRow&)>& log);

std::string layer_bench_csv(const std::vector<LayerBenchRow>& rows);
// Medians per count and model, the speed-up of three over the others, and
// all-dynamic's own seed-to-seed silhouette spread.
std::string layer_bench_table(const std::vector<LayerBenchRow>& rows);
// Time against grains, log-log, one line per model (8-bit BGR).
cv::Mat layer_bench_plot(const std::vector<LayerBenchRow>& rows);

}  // namespace sandpic
