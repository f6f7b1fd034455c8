// verify-dem's pile cases: heaps poured from a point and the default scene
// at a small scale (validate/dem/pile_runs.h), the DEM against itself.
#include <algorithm>
#include <cmath>
#include <map>

#include "physics/dem_params.h"
#include "physics/outline_watch.h"
#include "validate/dem/cases.h"
#include "validate/dem/pile_runs.h"
#include "validate/metrics/silhouette.h"
#include "validate/metrics/statistics.h"

namespace sandpic::verify {


// Case 5: the heap angle against sliding friction and rolling resistance,
// all-dynamic and three-layer, over physics seeds.
VerifyCase heap(const VerifyOptions& opt) {
  const Plan p = plan(opt);
  const double default_mr = Scene{}.dem.rolling_resistance, default_mu = Scene{}.physics.friction;
  VerifyCase c{"heap", "Heap angle against friction and rolling resistance",
               "a heap poured from a point (" + std::to_string(p.heap.window.width * p.heap.region.height) +
                   " grains, two sizes): its angle grows with sliding friction and with rolling resistance, seeds "
                   "agree within " + fmt("%g", p.spread_deg) + "°, three-layer equals all-dynamic within max(" +
                   fmt("%.1f", p.layers_deg) + "°, 2 seed spreads), and the default lies in " +
                   fmt("%.0f", p.default_low) + "–" + fmt("%.0f", p.default_high) +
                   "° (real sand: about 25° rounded to 40° angular)"};
  const std::vector<Layers> models = pile_models(opt);
  std::vector<double> rolling = p.rolling;
  if (std::find(rolling.begin(), rolling.end(), default_mr) == rolling.end()) rolling.push_back(default_mr);
  std::sort(rolling.begin(), rolling.end());
  std::vector<Scene> scenes;
  for (Layers l : models)
    for (double mu : p.friction)
      for (double mr : rolling)
        for (uint64_t seed : p.seeds) scenes.push_back(with(p.heap, l, mu, mr, seed));
  if (std::find(p.friction.begin(), p.friction.end(), default_mu) == p.friction.end())
    for (Layers l : models)
      for (uint64_t seed : p.seeds) scenes.push_back(with(p.heap, l, default_mu, default_mr, seed));
  const std::vector<Run> runs = run_all(scenes, opt, "heap");
  // angle[layers][mu][mr] over seeds
  std::map<Layers, std::map<double, std::map<double, std::vector<double>>>> angle;
  for (const Run& r : runs)
    angle[r.scene.dem.layers][r.scene.physics.friction][r.scene.dem.rolling_resistance].push_back(heap_angle(r));
  for (Layers l : models) {
    const std::string name = layers_name(l);
    VerifyPlot plot{"Heap angle, " + name, "rolling resistance μ_r", "heap angle (deg)", {}};
    for (auto& [mu, by_mr] : angle[l]) {
      PlotSeries line{"friction " + fmt("%.1f", mu), {}, {}, false};
      for (auto& [mr, a] : by_mr) {
        line.x.push_back(mr), line.y.push_back(mean(a));
        c.checks.push_back(at_most(name + ", μ " + fmt("%.1f", mu) + ", μ_r " + fmt("%.2f", mr) + ": seed spread (mean " +
                                       fmt("%.1f", mean(a)) + "°)",
                                   spread(a), p.spread_deg, "°"));
      }
      plot.series.push_back(std::move(line));
    }
    c.plots.push_back(std::move(plot));
    // Grows with each: no step down beyond the seed spreads, and the last
    // value above the first by more than two. Rolling resistance adds only
    // while sliding does not cap it: a grain in a notch holds to 30° +
    // atan(min(μ, μ_r/2)) (the notch case), so the rise is checked over the
    // μ_r up to 2μ (at μ 0.1: μ_r 0.2); beyond it nothing is predicted,
    // so neither the rise nor a fall is checked there.
    auto grows = [&](const std::vector<std::vector<double>>& seq, size_t rising, const std::string& what) {
      double worst_drop = 0;
      for (size_t i = 1; i < rising; ++i)
        worst_drop = std::max(worst_drop, mean(seq[i - 1]) - mean(seq[i]) - spread(seq[i - 1]) - spread(seq[i]));
      c.checks.push_back(at_most(name + ": " + what + ", largest fall beyond the seed spreads", worst_drop, 0, "°"));
      if (rising < 2) return;
      const auto &first = seq.front(), &last = seq[rising - 1];
      // The quick heap's seeds scatter by about 3° (see plan()), as much as
      // a rise the notch case predicts (μ 0.9, μ_r 0.1 -> 0.3: 30° +
      // atan(μ_r/2), 5.7°; two seeds measured 6.0° with spreads of 3.6°):
      // there only the rise's sign is checked, the full run's 3,600-grain
      // heaps resolve it beyond 2 seed spreads.
      const double margin = opt.quick ? 0 : 2 * (spread(last) + spread(first));
      c.checks.push_back({name + ": " + what + (opt.quick ? ", rise from first to last" : ", rise from first to last beyond 2 seed spreads"),
                          "°", mean(last) - mean(first) - margin, 0, 0, VerifyCheck::Kind::AtLeast});
    };
    for (double mr : rolling) {
      std::vector<std::vector<double>> seq;
      for (double mu : p.friction) seq.push_back(angle[l][mu][mr]);
      grows(seq, seq.size(), "angle against friction at μ_r " + fmt("%.2f", mr));
    }
    for (double mu : p.friction) {
      std::vector<std::vector<double>> seq;
      size_t rising = 0;
      for (double mr : rolling) {
        seq.push_back(angle[l][mu][mr]);
        rising += mr <= 2 * mu + 1e-9;
      }
      grows(seq, rising, "angle against rolling resistance at μ " + fmt("%.1f", mu) + " (rise over μ_r ≤ 2μ)");
    }
  }
  const auto& def = angle[Layers::AllDynamic][default_mu][default_mr];
  c.checks.push_back(within("all-dynamic, the default (μ " + fmt("%.1f", default_mu) + ", μ_r " + fmt("%.2f", default_mr) +
                                "): heap angle, " + fmt("%.0f", p.default_low) + "–" + fmt("%.0f", p.default_high) + "°",
                            mean(def), (p.default_low + p.default_high) / 2, (p.default_high - p.default_low) / 2, "°"));
  // paper §8.1's α is the heap angle of this case's all-dynamic runs, from
  // a table measured on the full heap (physics/dem_params.cpp): the full run
  // checks the table still holds where it was measured. The quick heap
  // stands steeper (31.0° at the defaults where 3,600 grains stand at
  // 25.7°): reported only.
  auto on_grid = [](const auto& grid, double v) {
    return std::any_of(grid.begin(), grid.end(), [v](double g) { return std::abs(g - v) < 1e-9; });
  };
  for (auto& [mu, by_mr] : angle[Layers::AllDynamic])
    for (auto& [mr, a] : by_mr) {
      if (!on_grid(kHeapFriction, mu) || !on_grid(kHeapRolling, mr)) continue;
      const std::string what = "α's table at μ " + fmt("%.1f", mu) + ", μ_r " + fmt("%.2f", mr) + " against all-dynamic's heap angle";
      const double table = all_dynamic_heap_angle_deg(mu, mr);
      if (opt.quick)
        c.notes.push_back(what + ": " + fmt("%.1f", table) + "° against " + fmt("%.1f", mean(a)) + "° (the quick heap: not checked)");
      else
        c.checks.push_back(within(what, table, mean(a), std::max(2.0, 2 * spread(a)), "°"));
    }
  for (auto& [mu, by_mr] : angle[Layers::Three])
    for (auto& [mr, a] : by_mr) {
      const auto& ref = angle[Layers::AllDynamic][mu][mr];
      c.checks.push_back(within("three-layer against all-dynamic, μ " + fmt("%.1f", mu) + ", μ_r " + fmt("%.2f", mr),
                                mean(a), mean(ref), std::max(p.layers_deg, 2 * std::max(spread(a), spread(ref))), "°"));
    }
  for (Layers l : models)
    if (l != Layers::AllDynamic) c.checks.push_back(work_check(layers_name(l), of(runs, l), of(runs, Layers::AllDynamic)));
  for (const Run& r : runs)
    if (r.scene.physics_seed == p.seeds.front() && r.scene.physics.friction == default_mu &&
        r.scene.dem.rolling_resistance == default_mr)
      c.pictures.emplace_back(layers_name(r.scene.dem.layers) + ", the default, seed " + std::to_string(p.seeds.front()),
                              r.picture);
  double total = 0;
  for (const Run& r : runs) total += r.simulate_s;
  c.notes.push_back(std::to_string(runs.size()) + " runs, " + fmt("%.0f", total) + " s of simulation in all");
  return c;
}

// Case 6: an all-dynamic heap at the defaults settles (its outline holds)
// and goes on 5 s of simulated time: its heap angle does not drift, and no
// two grains ever overlap deeply.
VerifyCase creep(const VerifyOptions& opt) {
  const Plan p = plan(opt);
  const double run_on = opt.quick ? 2 : 5, trend_limit = opt.quick ? 0.5 : 0.1, overlap_limit = 0.05;
  VerifyCase c{"creep", "No creep",
               "an all-dynamic heap at the defaults settles (its outline holds: the top of the sand in every pixel "
               "column but 0.2% of them stays within 0.05 small-grain diameters for 1 s; --quick: reported, not "
               "checked) and, run on " +
                   fmt("%.0f", run_on) + " s of simulated time after that, the least-squares trend of its heap angle at most " +
                   fmt("%.1f", trend_limit) + "°/s, deepest overlap at most " + fmt("%.2f", overlap_limit) +
                   " small-grain diameters over the whole run"};
  std::vector<Scene> scenes;
  for (uint64_t seed : p.seeds) {
    Scene s = with(p.heap, Layers::AllDynamic, Scene{}.physics.friction, Scene{}.dem.rolling_resistance, seed);
    s.dem.run_on_s = run_on;
    scenes.push_back(s);
  }
  const std::vector<Run> runs = run_all(scenes, opt, "creep");
  VerifyPlot plot{"Heap angle after settling (all-dynamic)", "t after settling (s)", "heap angle (deg)", {}};
  for (const Run& r : runs) {
    const auto& samples = r.stats["backend"]["run_on"];
    PlotSeries line{"seed " + std::to_string(*r.scene.physics_seed), {}, {}, false};
    double st = 0, sa = 0, stt = 0, sta = 0, t0 = NAN;
    for (const auto& sm : samples) {
      const std::vector<int> h = sm["heights_px"].get<std::vector<int>>();
      const double t = sm["t_s"].get<double>(), a = heap_angle_deg(std::vector<double>(h.begin(), h.end()));
      if (std::isnan(t0)) t0 = t;
      line.x.push_back(t - t0), line.y.push_back(a);
      st += t - t0, sa += a, stt += (t - t0) * (t - t0), sta += (t - t0) * a;
    }
    const double n = double(line.x.size());
    const double trend = n > 2 ? (n * sta - st * sa) / (n * stt - st * st) : NAN;
    const std::string seed = "seed " + std::to_string(*r.scene.physics_seed);
    // Settled means held (physics/outline_watch.h), not the run's wait for
    // it running out. The quick heaps report it only: of 480 grains, seed
    // 2's outline still moved in 21 of 121 columns when the 5 s wait ran out
    // (a heap angle trend of -0.007 deg/s after).
    const auto& settling = r.stats["backend"]["settling"];
    const std::string held_name = seed + ": outline columns still moving when the run called the heap settled " +
                                  fmt("%.1f", settling["after_last_arrival_s"].get<double>()) + " s after the last grain";
    const double moving = settling["moving_columns"].get<double>();
    if (opt.quick)
      c.notes.push_back(held_name + ": " + fmt("%.0f", moving));
    else
      c.checks.push_back(at_most(held_name, moving, std::floor(kUnsettled * double(r.scene.window.width + 1)), "columns"));
    c.checks.push_back(within(seed + ": trend of the heap angle", trend, 0, trend_limit, "°/s"));
    c.checks.push_back(at_most(seed + ": deepest overlap, whole run", r.stats["backend"]["deepest_overlap_diameters"].get<double>(),
                               overlap_limit, "d"));
    plot.series.push_back(std::move(line));
  }
  c.plots.push_back(std::move(plot));
  return c;
}

// Case 7: the paper's layer models are accelerations: on the default scene
// at a small scale, three-layer and BCRE pile as all-dynamic does.
VerifyCase layers(const VerifyOptions& opt) {
  const Plan p = plan(opt);
  VerifyCase c{"layers", "Three-layer and BCRE equal all-dynamic",
               "the default scene at --scale " + fmt("%.2f", p.scene_scale) +
                   (p.scene_region > 0 ? " with a region " + fmt("%.0f", p.scene_region) + " px tall" : std::string()) +
                   ", friction 0.1 and 0.9: scene slopes (mean |dh/dx| smoothed over 8 large-grain diameters) within "
                   "max(" + fmt("%.1f", p.layers_deg) + "°, 2 seed spreads) of all-dynamic's, and the silhouette error "
                   "against all-dynamic (same seed) at most 1.25× all-dynamic's own seed-to-seed floor (paper Fig. 13: "
                   "BCRE and three layers alike)"};
  const Scene base = small_default_scene(p);
  std::vector<Layers> models = {Layers::AllDynamic};
  for (Layers l : opt.layer_models)
    if (l != Layers::AllDynamic && std::find(models.begin(), models.end(), l) == models.end()) models.push_back(l);
  std::vector<Scene> scenes;
  for (double mu : {0.1, 0.9})
    for (Layers l : models)
      for (uint64_t seed : p.seeds) scenes.push_back(with(base, l, mu, base.dem.rolling_resistance, seed));
  const std::vector<Run> runs = run_all(scenes, opt, "layers");
  VerifyPlot plot{"Scene slope by layer model", "friction", "scene slope (deg)", {}};
  std::map<Layers, PlotSeries> lines;
  for (double mu : {0.1, 0.9}) {
    std::map<Layers, std::vector<const Run*>> by;
    for (const Run& r : runs)
      if (r.scene.physics.friction == mu) by[r.scene.dem.layers].push_back(&r);
    auto slopes = [&](Layers l) {
      std::vector<double> v;
      for (const Run* r : by[l]) v.push_back(slope(*r));
      return v;
    };
    const std::vector<double> all = slopes(Layers::AllDynamic);
    const double floor = floor_error(by[Layers::AllDynamic]);
    for (Layers l : models) {
      const std::vector<double> v = slopes(l);
      PlotSeries& line = lines[l];
      line.label = layers_name(l), line.points = true;
      for (double x : v) line.x.push_back(mu), line.y.push_back(x);
      if (l == Layers::AllDynamic) continue;
      const std::string name = layers_name(l) + ", friction " + fmt("%.1f", mu);
      c.checks.push_back(within(name + ": mean scene slope", mean(v), mean(all),
                                std::max(p.layers_deg, 2 * std::max(spread(v), spread(all))), "°"));
      double err = 0;
      for (size_t i = 0; i < by[l].size(); ++i) err += silhouette_error(by[l][i]->class_map, by[Layers::AllDynamic][i]->class_map);
      err /= double(by[l].size());
      c.checks.push_back(at_most(name + ": silhouette error against all-dynamic over its floor (" + fmt("%.4f", floor) + ")",
                                 err / floor, 1.25, "×"));
      c.checks.push_back(work_check(name, by[l], by[Layers::AllDynamic]));
    }
    for (const Run* r : {by[Layers::AllDynamic].front(), by[models[models.size() > 1 ? 1 : 0]].front()})
      c.pictures.emplace_back(layers_name(r->scene.dem.layers) + ", friction " + fmt("%.1f", mu) + ", seed " +
                                  std::to_string(*r->scene.physics_seed) + ", " + fmt("%.0f", r->simulate_s) + " s",
                              r->picture);
  }
  for (auto& [l, line] : lines) plot.series.push_back(line);
  c.plots.push_back(std::move(plot));
  return c;
}

// Case 8: halving the time step changes the heap angle and the outline by
// less than the seeds do.
VerifyCase step(const VerifyOptions& opt) {
  const Plan p = plan(opt);
  VerifyCase c{"step", "Step convergence",
               "heaps at dem.step_diameters and at half of it, three-layer and all-dynamic, physics seeds " +
                   std::to_string(p.step_seeds.front()) + "–" + std::to_string(p.step_seeds.back()) +
                   ": the mean heap angles differ by no more than seeds alone would make them in 19 cases of 20 "
                   "(Student's two-sample test at 95%, at least 1°), and the "
                   "silhouette error between the two steps (same seed) is at most 1.25× the larger seed-to-seed floor "
                   "(a better-converged solve lets a small heap grow by fewer, larger avalanches: its seeds differ more)"};
  const double step = Scene{}.dem.step_diameters;
  const std::vector<Layers> models = pile_models(opt);
  std::vector<Scene> scenes;
  for (Layers l : models)
    for (double f : {1.0, 0.5})
      for (uint64_t seed : p.step_seeds) {
        Scene s = with(p.heap, l, Scene{}.physics.friction, Scene{}.dem.rolling_resistance, seed);
        s.dem.step_diameters = step * f;
        scenes.push_back(s);
      }
  const std::vector<Run> runs = run_all(scenes, opt, "step");
  const size_t n = p.step_seeds.size();
  for (size_t li = 0; li < models.size(); ++li) {
    const Run* base = &runs[li * 2 * n];
    const Run* half = base + n;
    std::vector<double> a, b;
    std::vector<const Run*> bases, halves;
    double err = 0;
    for (size_t i = 0; i < n; ++i) {
      a.push_back(heap_angle(base[i])), b.push_back(heap_angle(half[i]));
      bases.push_back(base + i), halves.push_back(half + i);
      err += silhouette_error(base[i].class_map, half[i].class_map) / double(n);
    }
    const std::string name = layers_name(base->scene.dem.layers);
    // Student's test (mean_shift_limit): a limit of one seed spread failed
    // a step that changes nothing a third of the time at two seeds. The
    // test's limit is wide on two seeds (4.3 pooled spreads); a step that
    // scatters the seeds is caught by the heap case's seed spread, and one
    // that moves the pile by the outline below.
    c.checks.push_back(within(name + ": mean heap angle at half the step (" + fmt("%.1f", mean(a)) + "° at the step, seed spreads " +
                                  fmt("%.1f", spread(a)) + "° and " + fmt("%.1f", spread(b)) + "°)",
                              mean(b), mean(a), std::max(1.0, mean_shift_limit(a, b)), "°"));
    // As the angles' spread: the floor of either step, whichever is larger.
    const double floor_base = floor_error(bases), floor_half = floor_error(halves);
    const double floor = std::max(floor_base, floor_half);
    c.checks.push_back(at_most(name + ": silhouette error between the steps over the larger floor (" +
                                   fmt("%.4f", floor_base) + " at the step, " + fmt("%.4f", floor_half) + " at half)",
                               err / floor, 1.25, "×"));
    c.notes.push_back(name + ": " + fmt("%.0f", base->simulate_s) + " s at the step, " + fmt("%.0f", half->simulate_s) +
                      " s at half of it (seed " + std::to_string(p.step_seeds.front()) + ")");
  }
  for (size_t li = 1; li < models.size(); ++li)
    c.checks.push_back(work_check(layers_name(models[li]), of(runs, models[li]), of(runs, Layers::AllDynamic)));
  return c;
}

}  // namespace sandpic::verify
