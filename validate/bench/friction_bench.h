#pragma once
// paper Fig. 9: the pile's slope against friction (0.1, 0.4, 0.9 in the
// paper), each friction averaged over several physics seeds, for any DEM
// layer model, with each model's silhouette error against all-dynamic on
// the same friction and seed.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "src/simulator.h"

namespace sandpic {

// One pile from one ellipse: the Fig. 9 scene (3,600 grains, 300×120 px).
Scene pile_scene();

struct FrictionBenchOptions {
  std::vector<double> friction = {0.1, 0.4, 0.9};
  std::vector<uint64_t> seeds = {1, 2, 3};  // physics seeds
  std::vector<Layers> layers = {Layers::Three, Layers::AllDynamic};
};

struct FrictionBenchRow {
  std::string layers;
  double friction = 0;
  uint64_t seed = 0;
  int64_t grains = 0;
  double angle_deg = NAN;  // heap angle (validate/metrics/silhouette.h)
  double slope_deg = NAN;  // scene slope, smoothed over 8 large-grain diameters
  double simulate_s = NAN;
  double silhouette_error = NAN;  // against all-dynamic, same friction and seed; NaN: none ran
  cv::Mat picture;                // the rendered picture (8-bit BGR)
};

std::vector<FrictionBenchRow> run_friction_bench(const Scene& base, const FrictionBenchOptions& opt, Simulator& dem,
                                                 const std::function<void(const FrictionBenchRow&)>& log);

// Per model and friction: mean angle over the seeds, its range, median
// silhouette error, median time; and whether the mean grows with friction.
std::string friction_bench_table(const std::vector<FrictionBenchRow>& rows);
std::string friction_bench_csv(const std::vector<FrictionBenchRow>& rows);

}  // namespace sandpic
