#include "validate/bench/friction_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "src/pipeline.h"
#include "validate/metrics/silhouette.h"
#include "validate/metrics/statistics.h"

namespace sandpic {

Scene pile_scene() {
  Scene s;
  s.description = "paper Fig. 9: one pile from one ellipse";
  s.window = {300, 120};
  s.region.height = 12;
  s.init.tessellation = TessellationKind::Uniform;
  s.init.cell_width = 20;
  s.init.cell_height = 6;
  s.segment.method = SegmentMethod::Explicit;
  s.segment.ellipses = {EllipseSpec{150, 6, 150, 6, 0}};
  s.release.outlet_width_mm = 3;  // a narrow stream: one clean cone
  s.mode = Mode::Dem;
  return s;
}

std::vector<FrictionBenchRow> run_friction_bench(const Scene& base, const FrictionBenchOptions& opt, Simulator& dem,
                                                 const std::function<void(const FrictionBenchRow&)>& log) {
  std::vector<Layers> order;  // all-dynamic first: the others' reference
  for (Layers l : {Layers::AllDynamic, Layers::Three, Layers::Bcre})
    if (std::find(opt.layers.begin(), opt.layers.end(), l) != opt.layers.end()) order.push_back(l);
  std::vector<FrictionBenchRow> rows;
  for (double mu : opt.friction) {
    std::map<uint64_t, cv::Mat> reference;
    for (Layers l : order)
      for (uint64_t seed : opt.seeds) {
        Scene s = base;
        s.mode = Mode::Dem;
        s.physics.friction = mu;
        s.dem.layers = l;
        s.physics_seed = seed;
        RunResult r = run_pipeline(s, dem, RunOptions{});
        FrictionBenchRow row;
        row.layers = layers_name(l);
        row.friction = mu;
        row.seed = seed;
        row.grains = r.stats["grains"]["total"].get<int64_t>();
        const std::vector<double> outline = silhouette(r.class_map);
        row.angle_deg = heap_angle_deg(outline);
        double largest = 0;
        for (int k = 0; k < kClasses; ++k) largest = std::max(largest, grain_diameter_px(s, k));
        row.slope_deg = scene_slope_deg(outline, 8 * largest);
        row.simulate_s = r.stats["timing"]["simulate_s"].get<double>();
        row.picture = r.picture;
        if (l == Layers::AllDynamic) reference[seed] = r.class_map;
        if (auto ref = reference.find(seed); ref != reference.end())
          row.silhouette_error = silhouette_error(r.class_map, ref->second);
        rows.push_back(row);
        log(row);
      }
  }
  return rows;
}

std::string friction_bench_table(const std::vector<FrictionBenchRow>& rows) {
  std::map<std::string, std::map<double, std::vector<const FrictionBenchRow*>>> by;
  for (const FrictionBenchRow& r : rows) by[r.layers][r.friction].push_back(&r);
  std::string out = "layers        friction  mean_angle  min_angle  max_angle  mean_slope  err_vs_all-dyn  median_s\n";
  for (auto& [layers, m] : by) {
    // A picture of many mountains has no heap angle (NaN): then the scene
    // slope is what friction must raise.
    double last = -1, last_slope = -1;
    bool grows = true, slope_grows = true, angles = true;
    for (auto& [mu, v] : m) {
      std::vector<double> a, e, t;
      double slope = 0;
      for (auto* r : v)
        a.push_back(r->angle_deg), e.push_back(r->silhouette_error), t.push_back(r->simulate_s), slope += r->slope_deg / double(v.size());
      double sum = 0;
      int n = 0;
      for (double x : a)
        if (std::isfinite(x)) sum += x, ++n;
      double mean = n ? sum / n : NAN;
      grows = grows && std::isfinite(mean) && mean > last;
      slope_grows = slope_grows && slope > last_slope;
      angles = angles && std::isfinite(mean);
      last = mean, last_slope = slope;
      char buf[256];
      std::snprintf(buf, sizeof buf, "%-13s %8.2f %11.1f %10.1f %10.1f %11.1f %15.4f %9.1f\n", layers.c_str(), mu, mean,
                    *std::min_element(a.begin(), a.end()), *std::max_element(a.begin(), a.end()), slope, median(e),
                    median(t));
      out += buf;
    }
    if (angles)
      out += layers + ": the mean angle " + (grows ? "grows" : "does NOT grow") + " with friction\n";
    else
      out += layers + ": no heap angle (not one heap); the mean scene slope " +
             (slope_grows ? "grows" : "does NOT grow") + " with friction\n";
  }
  return out;
}

std::string friction_bench_csv(const std::vector<FrictionBenchRow>& rows) {
  std::string out = "layers,friction,physics_seed,grains,angle_deg,slope_deg,simulate_s,silhouette_error\n";
  for (const FrictionBenchRow& r : rows) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s,%.3f,%llu,%lld,%.3f,%.3f,%.4f,%.5f\n", r.layers.c_str(), r.friction,
                  (unsigned long long)r.seed, (long long)r.grains, r.angle_deg, r.slope_deg, r.simulate_s,
                  r.silhouette_error);
    out += buf;
  }
  return out;
}

}  // namespace sandpic
