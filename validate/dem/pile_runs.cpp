#include "validate/dem/pile_runs.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include "physics/dem_params.h"
#include "physics/dem_simulator.h"
#include "physics/lammps_simulator.h"
#include "src/pipeline.h"
#include "src/water.h"
#include "validate/bench/friction_bench.h"
#include "validate/metrics/silhouette.h"

namespace sandpic::verify {

Plan plan(const VerifyOptions& opt) {
  Plan p;
  p.heap = pile_scene();  // 300×120 px, a 12 px region: 3,600 grains
  p.seeds = {1, 2, 3};
  p.step_seeds = p.seeds;
  p.scene_scale = 0.1;   // 3,500 grains
  p.spread_deg = 2;
  p.layers_deg = 1.5;
  p.friction = {0.1, 0.4, 0.9};
  p.rolling = {0, 0.3, 0.6};
  if (opt.quick) {  // a few hundred grains: looser tolerances
    p.heap.window = {120, 60};
    p.heap.region.height = 4;  // 480 grains
    p.heap.segment.ellipses = {EllipseSpec{60, 2, 60, 2, 0}};
    p.heap.init.cell_height = 4;
    p.seeds = {1, 2};
    // The step case compares two samples of heaps: on two seeds a change
    // of the run's bits alone (the same physics) failed it in two of four
    // tries, the outline's floor then being one pair of runs. Four seeds
    // (the step's first two are the heap case's): over physics seeds 1-8
    // the default stood 32.9 ± 4.4° at the step and 32.6 ± 2.5° at half
    // of it (docs/notebook/2026-12-08-a-step-without-turns.md).
    p.step_seeds = {1, 2, 3, 4};
    p.scene_region = 6;  // 600 grains (the scale's smallest: init.row_height_min)
    // A heap this small scatters: over physics seeds 1-8 the default's
    // angle had a standard deviation of 3.0-3.2° (26.7-37.6°), and two
    // seeds' spread |a - b|/√2 passes 1.96 σ = 6.3° one time in twenty.
    p.spread_deg = 6.5;
    p.layers_deg = 4;
    p.default_high = 45;  // a heap 15 px high stands steeper: 41° where 3,600 grains stand at 31°
    p.friction = {0.1, 0.9};
    // And the default. Without rolling resistance a heap of a few hundred
    // round grains spreads to the walls of this window (3.5° at friction
    // 0.1): no heap angle to compare; the full run has μ_r 0 in a wider one.
    p.rolling = {0.3};
  }
  // Poured, not dropped: the release lasts twice the slowest grain's fall,
  // so the heap grows under a steady stream. At the default release rate
  // all 480 grains of the quick heap were in the water at once and landed
  // as two slugs (fast classes, then slow): seeds stood up to 10° apart and
  // contacts overlapped by 0.048 diameters; poured, at most 1.6° and 0.025.
  const Water w = water_model(p.heap);
  const double slowest = *std::min_element(w.terminal_px_s.begin(), w.terminal_px_s.end());
  const double fall_s = (p.heap.window.height - p.heap.region.height) / slowest;
  p.heap.dem.release_rate = double(p.heap.window.width) * p.heap.region.height / (2 * fall_s);
  return p;
}

Scene small_default_scene(const Plan& p) {
  Scene s;
  apply_scale(s, p.scene_scale);
  if (p.scene_region > 0) s.region.height = p.scene_region;
  return s;
}

namespace {

// Runs already made in this process, by scene (a scene and its seeds give
// the same bytes every time).
struct RunCache {
  std::mutex m;
  std::map<std::string, Run> runs;
};
RunCache& run_cache() {
  static RunCache c;
  return c;
}

}  // namespace

std::vector<Run> run_all(std::vector<Scene> scenes, const VerifyOptions& opt, const std::string& what) {
  std::vector<Run> runs(scenes.size());
  std::vector<std::string> keys(scenes.size());
  std::vector<size_t> todo;
  RunCache& cache = run_cache();
  for (size_t i = 0; i < scenes.size(); ++i) {
    for (const std::string& a : opt.sets) apply_setting(scenes[i], a);
    keys[i] = to_json(scenes[i]).dump();
    std::lock_guard<std::mutex> lock(cache.m);
    if (auto it = cache.runs.find(keys[i]); it != cache.runs.end()) runs[i] = it->second;
    else todo.push_back(i);
  }
  std::atomic<int> done{int(scenes.size() - todo.size())};
  auto run_one = [&](size_t i) {
    auto sim = scenes[i].mode == Mode::Lammps ? make_lammps_simulator(LammpsOptions{}) : make_dem_simulator();
    RunResult r = run_pipeline(scenes[i], *sim, RunOptions{});
    runs[i] = {scenes[i], r.class_map, r.picture, r.stats, r.stats["timing"]["simulate_s"].get<double>()};
    {
      std::lock_guard<std::mutex> lock(cache.m);
      cache.runs.emplace(keys[i], runs[i]);
    }
    opt.log(what + ": " + std::to_string(++done) + "/" + std::to_string(scenes.size()) + " runs");
  };
  // One run a task (simple_partitioner, grain 1), as stress does: runs take
  // 100-600 s, and the default partitioner's chunks can hold two long ones on
  // one thread while the other core has nothing left.
  tbb::parallel_for(
      tbb::blocked_range<size_t>(0, todo.size(), 1),
      [&](const tbb::blocked_range<size_t>& range) {
        for (size_t k = range.begin(); k != range.end(); ++k) run_one(todo[k]);
      },
      tbb::simple_partitioner());
  return runs;
}

double floor_error(const std::vector<const Run*>& runs) {
  double sum = 0;
  int n = 0;
  for (size_t i = 0; i < runs.size(); ++i)
    for (size_t j = i + 1; j < runs.size(); ++j) sum += silhouette_error(runs[i]->class_map, runs[j]->class_map), ++n;
  return n ? sum / n : NAN;
}

double cross_error(const std::vector<const Run*>& a, const std::vector<const Run*>& b) {
  double sum = 0;
  int n = 0;
  for (const Run* x : a)
    for (const Run* y : b) sum += silhouette_error(x->class_map, y->class_map), ++n;
  return n ? sum / n : NAN;
}

Scene with(Scene s, Layers l, double mu, double mr, uint64_t seed) {
  s.mode = Mode::Dem;
  s.dem.layers = l;
  s.physics.friction = mu;
  s.dem.rolling_resistance = mr;
  s.physics_seed = seed;
  return s;
}

std::vector<const Run*> of(const std::vector<Run>& runs, Layers l) {
  std::vector<const Run*> v;
  for (const Run& r : runs)
    if (r.scene.mode == Mode::Dem && r.scene.dem.layers == l) v.push_back(&r);
  return v;
}

std::vector<Layers> pile_models(const VerifyOptions& opt) {
  std::vector<Layers> m = {Layers::AllDynamic};
  if (std::find(opt.layer_models.begin(), opt.layer_models.end(), Layers::Three) != opt.layer_models.end())
    m.push_back(Layers::Three);
  return m;
}

VerifyCheck work_check(const std::string& model, const std::vector<const Run*>& runs,
                       const std::vector<const Run*>& all_dynamic) {
  auto body_steps = [](const std::vector<const Run*>& rs) {
    double n = 0;
    for (const Run* r : rs) n += r->stats["backend"]["body_steps"]["all"].get<double>();
    return n;
  };
  const double ratio = body_steps(runs) / body_steps(all_dynamic);
  return {model + ": body-steps over all-dynamic's on the same scenes (1: the model took no grain out of the solve)",
          "×", ratio, 0.99, 0, VerifyCheck::Kind::AtMost};
}

double heap_angle(const Run& r) { return heap_angle_deg(silhouette(r.class_map)); }

double slope(const Run& r) {
  const auto radii = dem_radii(r.scene);
  return scene_slope_deg(silhouette(r.class_map), 16 * *std::max_element(radii.begin(), radii.end()));
}

}  // namespace sandpic::verify
