#include "validate/runs/validation.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>

#include <opencv2/imgproc.hpp>
#include <tbb/parallel_for.h>

#include "src/errors.h"
#include "src/output.h"
#include "src/pipeline.h"
#include "validate/runs/kept_runs.h"
#include "validate/metrics/silhouette.h"
#include "validate/metrics/statistics.h"

namespace sandpic {
namespace {

struct Job {
  std::string label, group, setting;
  Scene scene;
  std::string skipped;
};

std::string num(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

ordered_json finite(double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(nullptr); }

// A run's names, before it runs (and all of a skipped one).
ValidationRun describe(const Job& j) {
  ValidationRun r;
  r.label = j.label, r.group = j.group, r.setting = j.setting, r.physics_seed = j.scene.physics_rng();
  r.skipped = j.skipped;
  return r;
}

// A run's picture, simulate time and grain count, from its stats.
void take(ValidationRun& r, const cv::Mat& picture, const ordered_json& stats) {
  r.picture = picture;
  r.simulate_s = stats["timing"]["simulate_s"].get<double>();
  r.grains = stats["grains"]["total"].get<int64_t>();
}

ValidationRun run_job(const Job& j, const ValidateOptions& opt, const SimulatorFactory& make) {
  ValidationRun r = describe(j);
  if (!r.skipped.empty()) return r;
  const ReusedRun got = run_or_reuse(opt.cache_dir, j.label, j.scene, make);
  take(r, got.run.picture, got.run.stats);
  r.cached = got.kept;
  return r;
}

// The lattice is timed as the median of several runs: one takes milliseconds.
ValidationRun run_lattice(const Job& j, const ValidateOptions& opt, const SimulatorFactory& make) {
  ValidationRun r = describe(j);
  if (!r.skipped.empty()) return r;
  auto sim = make(j.scene);
  std::vector<double> t;
  for (int i = 0; i < std::max(1, opt.lattice_timing_runs); ++i) {
    RunResult out;
    try {
      out = run_pipeline(j.scene, *sim, RunOptions{});
    } catch (const InputError& e) {
      if (j.group == "lattice") throw;
      r.skipped = e.what();  // a sweep value this scene cannot take (a grid too fine)
      return r;
    }
    if (i == 0) take(r, out.picture, out.stats);
    t.push_back(out.stats["timing"]["simulate_s"].get<double>());
  }
  r.simulate_s = median(t);
  return r;
}

// The lattice at the next opt.lattice_seeds − 1 physics seeds after the
// job's own (untimed: one run each), to score it over several seeds.
std::vector<ValidationRun> more_seeds(const Job& j, const ValidateOptions& opt, const SimulatorFactory& make) {
  std::vector<ValidationRun> runs;
  auto sim = make(j.scene);
  for (int i = 1; i < opt.lattice_seeds; ++i) {
    Job k = j;
    k.label = j.label + "-seed-" + std::to_string(j.scene.physics_rng() + uint64_t(i));
    k.scene.physics_seed = j.scene.physics_rng() + uint64_t(i);
    ValidationRun r = describe(k);
    RunResult out = run_pipeline(k.scene, *sim, RunOptions{});
    take(r, out.picture, out.stats);
    runs.push_back(std::move(r));
  }
  return runs;
}

// The sweep: every key of `section` ("lattice." or "dem.") that the registry
// gives sweep points (Field::sweep), each point `base` with that one key
// changed.
std::vector<Job> sweep_jobs(const Scene& base, const std::string& section, const char* group) {
  std::vector<Job> jobs;
  for (const Field& f : scene_fields()) {
    if (!f.path.starts_with(section)) continue;
    const ordered_json value = f.get(base);
    for (const SweepPoint& p : f.sweep) {
      const ordered_json v = p.change(f, value, base);
      if (v.is_null() || v == value) continue;
      const std::string setting = sweep_setting(f, p, v);
      Job j{"sweep-" + setting, group, setting, base, ""};
      f.set(j.scene, json::parse(v.dump()));
      jobs.push_back(j);
    }
  }
  return jobs;
}

std::vector<Job> lattice_sweep(const Scene& lat) {
  // Around the values the lattice really uses (a calibration's, if named).
  Scene eff = with_calibration(lat);
  eff.lattice.calibration.clear();
  return sweep_jobs(eff, "lattice.", "sweep-lattice");
}

std::vector<Job> dem_sweep(const Scene& dem, int64_t grains, const ValidateOptions& opt) {
  std::vector<Job> jobs = sweep_jobs(dem, "dem.", "sweep-dem");
  for (Job& j : jobs)
    if (j.scene.dem.layers == Layers::AllDynamic && dem.dem.layers != Layers::AllDynamic && grains > opt.all_dynamic_max)
      j.skipped = "all-dynamic skipped: " + std::to_string(grains) + " grains is above --all-dynamic-max " +
                  std::to_string(opt.all_dynamic_max) + " (its time grows about as grains²)";
  return jobs;
}

cv::Mat heat_map(const cv::Mat& a, const cv::Mat& b, const Scene& s, double sigma) {
  cv::Mat la = luminance601(a), lb = luminance601(b), d;
  if (sigma > 0) {
    cv::GaussianBlur(la, la, cv::Size(), sigma, sigma, cv::BORDER_REFLECT);
    cv::GaussianBlur(lb, lb, cv::Size(), sigma, sigma, cv::BORDER_REFLECT);
  }
  cv::absdiff(la, lb, d);
  cv::Mat d8, heat;
  d.convertTo(d8, CV_8U, 4.0);  // a difference of 64 in luminance is full scale
  cv::applyColorMap(d8, heat, cv::COLORMAP_INFERNO);
  // The two piles' outlines: lattice white, DEM cyan.
  auto outline = [&](const cv::Mat& pic, cv::Scalar colour) {
    std::vector<double> h = silhouette(decode_classes(pic, s.grains.colors));
    std::vector<cv::Point> line;
    for (size_t x = 0; x < h.size(); ++x) line.emplace_back(int(x), int(pic.rows - h[x]));
    cv::polylines(heat, line, false, colour, 1);
  };
  outline(b, cv::Scalar(255, 255, 0));
  outline(a, cv::Scalar(255, 255, 255));
  return heat;
}

}  // namespace

Comparison mean_comparison(const std::vector<Comparison>& all) {
  Comparison m;
  if (all.empty()) return m;
  m.width = all[0].width, m.height = all[0].height, m.blur_sigma_px = all[0].blur_sigma_px;
  m.composition.assign(all[0].composition.size(), 0);
  double mse = 0;
  for (const Comparison& c : all) {
    m.ssim += c.ssim / all.size();
    m.silhouette_error += c.silhouette_error / all.size();
    m.composition_error += c.composition_error / all.size();
    m.ssim_blurred += c.ssim_blurred / all.size();
    for (size_t b = 0; b < m.composition.size() && b < c.composition.size(); ++b)
      m.composition[b] += c.composition[b] / all.size();
    mse += (std::isfinite(c.psnr_db) ? 255.0 * 255.0 * std::pow(10.0, -c.psnr_db / 10) : 0.0) / all.size();
  }
  m.psnr_db = mse > 0 ? 10 * std::log10(255.0 * 255.0 / mse) : INFINITY;
  return m;
}

void check_options(const ValidateOptions& opt) {
  if (opt.extra_seeds < 4)
    throw InputError("--seeds must be at least 4: the noise floor is the mean over five or more DEM runs");
  if (opt.lattice_seeds < 1 || opt.lattice_seeds > 1000)
    throw InputError("--lattice-seeds must be 1 to 1000: the lattice is scored at that many physics seeds");
}

Validation run_validation(const Scene& base, const ValidateOptions& opt, const SimulatorFactory& make,
                          const std::function<void(const std::string&)>& log) {
  check_options(opt);
  Validation v;
  v.scene = base;
  Scene lat = base, dem = base;
  lat.mode = Mode::Lattice;
  dem.mode = Mode::Dem;
  dem.lattice.calibration.clear();
  const uint64_t seed0 = base.physics_rng();
  dem.physics_seed = seed0;

  // The DEM jobs: the ensemble, then the DEM sweep. The lattice's grain
  // count (the same scene) decides whether all-dynamic is affordable.
  v.lattice = run_lattice(Job{"lattice", "lattice", "", lat, ""}, opt, make);
  log("lattice: " + std::to_string(v.lattice.grains) + " grains, " + num("%.4f", v.lattice.simulate_s) + " s");
  std::vector<Job> jobs;
  for (int i = 0; i <= opt.extra_seeds; ++i) {
    Job j{"dem-seed-" + std::to_string(seed0 + uint64_t(i)), "dem", "", dem, ""};
    j.scene.physics_seed = seed0 + uint64_t(i);
    jobs.push_back(j);
  }
  const size_t ensemble = jobs.size();
  if (opt.sweep_dem)
    for (Job& j : dem_sweep(dem, v.lattice.grains, opt)) jobs.push_back(j);
  std::vector<ValidationRun> done(jobs.size());
  std::mutex mu;
  size_t finished = 0;
  tbb::parallel_for(size_t(0), jobs.size(), size_t(1), [&](size_t i) {
    done[i] = run_job(jobs[i], opt, make);
    std::lock_guard lock(mu);
    ++finished;
    log("DEM " + std::to_string(finished) + "/" + std::to_string(jobs.size()) + " " + jobs[i].label + ": " +
        (done[i].skipped.empty() ? num("%.2f s", done[i].simulate_s) + (done[i].cached ? " (kept from an earlier run)" : "")
                                 : done[i].skipped));
  });
  v.dem.assign(done.begin(), done.begin() + long(ensemble));
  for (size_t i = ensemble; i < done.size(); ++i) v.sweep.push_back(done[i]);
  // Every comparison is against every DEM run of the ensemble; a lattice
  // scored at several seeds is the mean over every seed and DEM run.
  const auto& colours = base.grains.colors;
  auto compare = [&](const ValidationRun& a, const ValidationRun& b) {
    return compare_pictures(a.picture, b.picture, colours, opt.bands, opt.blur_sigma_px);
  };
  auto against_dem = [&](ValidationRun& r, const std::vector<ValidationRun>& more) {
    if (!r.skipped.empty()) return;
    std::vector<Comparison> c;
    for (auto& d : v.dem) c.push_back(compare(r, d));
    for (auto& l : more)
      for (auto& d : v.dem) c.push_back(compare(l, d));
    r.mean = mean_comparison(c);
  };
  v.lattice_seeds = more_seeds(Job{"lattice", "lattice", "", lat, ""}, opt, make);
  against_dem(v.lattice, v.lattice_seeds);
  if (opt.sweep_lattice)
    for (Job& j : lattice_sweep(lat)) {
      v.sweep.push_back(run_lattice(j, opt, make));
      if (v.sweep.back().skipped.empty()) against_dem(v.sweep.back(), more_seeds(j, opt, make));
    }
  for (auto& r : v.sweep)
    if (r.group == "sweep-dem") against_dem(r, {});
  std::vector<Comparison> pairs, lattice_pairs;
  for (size_t a = 0; a < v.dem.size(); ++a)
    for (size_t b = a + 1; b < v.dem.size(); ++b) pairs.push_back(compare(v.dem[a], v.dem[b]));
  std::vector<const ValidationRun*> lats{&v.lattice};
  for (auto& r : v.lattice_seeds) lats.push_back(&r);
  for (size_t a = 0; a < lats.size(); ++a)
    for (size_t b = a + 1; b < lats.size(); ++b) lattice_pairs.push_back(compare(*lats[a], *lats[b]));
  const Comparison floor = mean_comparison(pairs), &l = v.lattice.mean, sp = mean_comparison(lattice_pairs);
  // One lattice seed has no spread.
  auto spread = [&](double x) { return lattice_pairs.empty() ? NAN : x; };
  auto ratio = [](double a, double b) { return b > 0 ? a / b : a > 0 ? INFINITY : 1.0; };
  v.metrics = {
      {"silhouette_error", l.silhouette_error, floor.silhouette_error, ratio(l.silhouette_error, floor.silhouette_error),
       spread(sp.silhouette_error)},
      {"composition_error", l.composition_error, floor.composition_error,
       ratio(l.composition_error, floor.composition_error), spread(sp.composition_error)},
      {"ssim", l.ssim, floor.ssim, ratio(1 - l.ssim, 1 - floor.ssim), spread(sp.ssim)},
      {"ssim_blurred", l.ssim_blurred, floor.ssim_blurred, ratio(1 - l.ssim_blurred, 1 - floor.ssim_blurred),
       spread(sp.ssim_blurred)},
      {"psnr_db", l.psnr_db, floor.psnr_db,
       std::isfinite(floor.psnr_db) ? std::pow(10.0, (floor.psnr_db - l.psnr_db) / 10) : INFINITY, spread(sp.psnr_db)},
  };
  std::vector<double> dem_t;
  int cached = 0;
  for (auto& d : v.dem) dem_t.push_back(d.simulate_s), cached += d.cached;
  v.dem_s = median(dem_t);
  v.lattice_s = v.lattice.simulate_s;
  v.time_ratio = v.lattice_s > 0 ? v.dem_s / v.lattice_s : INFINITY;
  v.heat_map = heat_map(v.lattice.picture, v.dem[0].picture, base, opt.blur_sigma_px);
  if (cached)
    v.notes.push_back(std::to_string(cached) + " of " + std::to_string(v.dem.size()) +
                      " DEM runs were kept from an earlier run in this folder (same scene digest); their times are "
                      "those of that run");
  v.notes.push_back("DEM runs go in parallel (one per core), so their times include sharing the machine");
  for (auto& r : v.sweep)
    if (!r.skipped.empty()) v.notes.push_back(r.setting + ": " + r.skipped);
  return v;
}

ordered_json validation_json(const Validation& v, const std::string& reproduce) {
  ordered_json j;
  j["reproduce"] = reproduce;
  j["scene_digest"] = scene_digest(v.scene);
  j["window"] = {v.scene.window.width, v.scene.window.height};
  j["grains"] = v.lattice.grains;
  ordered_json& h = j["headline"];
  for (const MetricRow& m : v.metrics) h[m.name + "_ratio"] = finite(m.ratio);
  h["time_ratio"] = finite(v.time_ratio);
  h["lattice_seeds"] = 1 + v.lattice_seeds.size();
  h["lattice_simulate_s"] = v.lattice_s;
  h["dem_simulate_s"] = v.dem_s;
  j["metrics"] = ordered_json::array();
  for (const MetricRow& m : v.metrics)
  {
    ordered_json row = {{"name", m.name}, {"lattice", finite(m.lattice)}, {"noise_floor", finite(m.floor)},
                        {"ratio", finite(m.ratio)}};
    if (!std::isnan(m.spread)) row["lattice_seed_to_seed"] = finite(m.spread);
    j["metrics"].push_back(row);
  }
  j["metrics_note"] = "ratio: lattice-vs-DEM error over DEM-vs-DEM error (1 - SSIM for the SSIMs, MSE for PSNR); "
                      "lattice: the mean over every lattice seed and DEM run; lattice_seed_to_seed: the mean over "
                      "pairs of lattice seeds (with --lattice-seeds 2 or more)";
  auto run = [](const ValidationRun& r) {
    ordered_json o = {{"label", r.label},   {"group", r.group},           {"setting", r.setting},
                      {"physics_seed", r.physics_seed}, {"simulate_s", finite(r.simulate_s)}, {"cached", r.cached}};
    if (!r.skipped.empty()) o["skipped"] = r.skipped;
    if (r.skipped.empty() && r.mean.width > 0) {
      o["silhouette_error"] = r.mean.silhouette_error;
      o["composition_error"] = r.mean.composition_error;
      o["ssim"] = r.mean.ssim;
      o["ssim_blurred"] = r.mean.ssim_blurred;
      o["psnr_db"] = finite(r.mean.psnr_db);
    }
    return o;
  };
  j["runs"] = ordered_json::array();
  j["runs"].push_back(run(v.lattice));
  for (auto& l : v.lattice_seeds) j["runs"].push_back(run(l));
  for (auto& d : v.dem) j["runs"].push_back(run(d));
  j["sweep"] = ordered_json::array();
  for (auto& s : v.sweep) j["sweep"].push_back(run(s));
  j["notes"] = v.notes;
  return j;
}

}  // namespace sandpic
