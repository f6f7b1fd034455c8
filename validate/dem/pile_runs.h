#pragma once
// verify-dem's piles: the heaps and the small default scene its pile cases
// (heap, creep, layers, step, engine-piles) run through the pipeline, with
// the DEM or LAMMPS as each scene's mode says, several at once on TBB's
// threads (each run is a world of its own, so the results do not depend on
// the thread count), and the measures they take of them.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "src/scene_file.h"
#include "validate/dem/verify_dem.h"

namespace sandpic::verify {

// What the piles are in each mode.
struct Plan {
  Scene heap;                          // a heap poured from a point
  std::vector<uint64_t> seeds;         // physics seeds
  std::vector<uint64_t> step_seeds;    // the step case's
  double scene_scale;                  // the default scene's scale for the layers case
  double scene_region = 0;             // and its region's height (px; 0: as scaled)
  double spread_deg, layers_deg;       // tolerances: seed spread, three vs all-dynamic slope
  double default_low = 25, default_high = 40;  // the default's heap angle: sand's
  std::vector<double> friction, rolling;
};
Plan plan(const VerifyOptions& opt);

// The default scene as the layers and engine-piles cases run it.
Scene small_default_scene(const Plan& p);

struct Run {
  Scene scene;
  cv::Mat class_map, picture;
  ordered_json stats;
  double simulate_s = 0;
};

// Every scene through the pipeline (opt.sets applied first), in parallel;
// results in order. A scene run before in this process is not run again:
// the step case's heaps at the default step are the heap case's, and the
// engine-piles case's Bullet runs are the heap and layers cases'.
std::vector<Run> run_all(std::vector<Scene> scenes, const VerifyOptions& opt, const std::string& what);

// The mean silhouette error between every pair of runs (the floor).
double floor_error(const std::vector<const Run*>& runs);
// The mean silhouette error between every run of a and every run of b.
double cross_error(const std::vector<const Run*>& a, const std::vector<const Run*>& b);

// A scene in DEM mode with these layers, friction, rolling resistance and
// physics seed.
Scene with(Scene s, Layers l, double mu, double mr, uint64_t seed);

// The DEM runs of one layer model, in order.
std::vector<const Run*> of(const std::vector<Run>& runs, Layers l);

// The layer models the heap, step and engine-piles cases run: all-dynamic
// first, then three-layer if --layers lists it (the layers case takes every
// model listed).
std::vector<Layers> pile_models(const VerifyOptions& opt);

// A layer model is an acceleration (paper §8): its runs must solve fewer
// bodies than all-dynamic's on the same scenes, or the comparison compares
// all-dynamic with itself (three-layer whose static grains stay bodies, on
// a pile too low for the fixed layer: byte-identical runs). A check that
// its body-steps are at most 0.99 of all-dynamic's.
VerifyCheck work_check(const std::string& model, const std::vector<const Run*>& runs,
                       const std::vector<const Run*>& all_dynamic);

double heap_angle(const Run& r);
// The scene slope, smoothed over 8 large-grain diameters.
double slope(const Run& r);

}  // namespace sandpic::verify
