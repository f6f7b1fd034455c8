#include "validate/runs/calibrate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>

#include <Eigen/Core>
#include <tbb/parallel_for.h>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "src/errors.h"
#include "src/init/init.h"
#include "src/pipeline.h"
#include "validate/metrics/compare.h"
#include "validate/runs/kept_runs.h"
#include "validate/metrics/silhouette.h"
#include "validate/metrics/statistics.h"

namespace sandpic {
namespace {

// One calibration scene, prepared once: the lattice reruns only its
// simulation, and the DEM piles' outlines are what it is fitted to.
struct Target {
  Scene scene;
  Prepared prepared;  // the stages before the simulation, once for every run
  std::vector<std::vector<double>> dem;  // silhouette per DEM physics seed
  std::vector<cv::Mat> dem_maps;         // class map per DEM physics seed
};

// Classes with one diameter and density behave alike in the DEM: fitting
// them apart would fit noise.
std::vector<std::vector<int>> physics_groups(const Scene& s) {
  std::vector<std::vector<int>> groups;
  for (int k = 0; k < kClasses; ++k) {
    auto same = [&](const std::vector<int>& g) {
      return s.grains.diameter_mm[g[0]] == s.grains.diameter_mm[k] &&
             s.grains.density_g_cm3[g[0]] == s.grains.density_g_cm3[k];
    };
    auto it = std::find_if(groups.begin(), groups.end(), same);
    if (it == groups.end()) groups.push_back({k});
    else it->push_back(k);
  }
  return groups;
}

// The registry's keys with a fit grid (Field::fit_grid), in its order.
std::vector<const Field*> grid_fields() {
  std::vector<const Field*> out;
  for (const Field& f : scene_fields())
    if (!f.fit_grid.empty()) out.push_back(&f);
  return out;
}

struct Params {
  std::vector<double> angle, runout;  // per group
  double bulk = 1, surface = 0;
  std::vector<double> grid;   // a value per grid_fields() key
  std::vector<double> share;  // lattice.picture_share per group
};

class Fit {
 public:
  Fit(std::vector<Target>& targets, std::vector<std::vector<int>> groups, Simulator& lattice)
      : targets_(targets), groups_(std::move(groups)), lattice_(lattice) {
    for (auto& t : targets_) residual_count_ += int(t.dem.size() * t.dem.front().size());
  }
  int residual_count() const { return residual_count_; }
  int64_t runs() const { return runs_; }

  // Lattice minus DEM column heights over the window height, every column
  // of every scene against every DEM seed.
  Eigen::VectorXd residuals(const Params& p) {
    Eigen::VectorXd r(residual_count_);
    int i = 0;
    for (auto& t : targets_) {
      std::vector<double> h = silhouette(lattice_map(p, t));
      for (auto& d : t.dem)
        for (size_t c = 0; c < h.size(); ++c) r[i++] = (h[c] - d[c]) / t.scene.window.height;
    }
    return r;
  }
  double error(const Params& p) { return residuals(p).cwiseAbs().mean(); }

  // Mean composition error (validate's), every scene against every DEM seed.
  double composition(const Params& p, int bands) {
    double sum = 0;
    int n = 0;
    for (auto& t : targets_) {
      const cv::Mat map = lattice_map(p, t);
      for (const cv::Mat& d : t.dem_maps) sum += mean_composition_error(composition_error(map, d, bands)), ++n;
    }
    return n ? sum / n : 0;
  }

  void apply(const Params& p, Scene& s) const {
    std::array<double, kClasses> deg{};
    for (size_t g = 0; g < groups_.size(); ++g)
      for (int k : groups_[g]) deg[size_t(k)] = p.angle[g], s.lattice.runout_px[size_t(k)] = p.runout[g];
    s.lattice.repose_deg = deg;
    s.lattice.bulk = p.bulk;
    s.lattice.surface_px = p.surface;
    for (size_t i = 0; i < grid_.size(); ++i) grid_[i]->set(s, p.grid[i]);
    for (size_t g = 0; g < groups_.size() && g < p.share.size(); ++g)
      for (int k : groups_[g]) s.lattice.picture_share[size_t(k)] = p.share[g];
  }

 private:
  // One lattice run of a calibration scene with the values p.
  cv::Mat lattice_map(const Params& p, const Target& t) {
    Scene s = t.scene;
    s.mode = Mode::Lattice;
    apply(p, s);
    Progress quiet(false);
    ++runs_;
    return lattice_.simulate(t.prepared.input(s), quiet).class_map;
  }

  std::vector<Target>& targets_;
  std::vector<std::vector<int>> groups_;
  std::vector<const Field*> grid_ = grid_fields();
  Simulator& lattice_;
  int residual_count_ = 0;
  int64_t runs_ = 0;
};

// The angles as Eigen's Levenberg-Marquardt sees them; the lattice is
// piecewise constant in an angle, so the forward differences take whole-degree
// steps (epsfcn) and read the slope of the trend, not of one step.
struct AngleFunctor {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  Fit* fit;
  Params base;
  int n_in, n_out;
  int inputs() const { return n_in; }
  int values() const { return n_out; }
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    Params p = base;
    for (int g = 0; g < n_in; ++g) p.angle[size_t(g)] = std::clamp(x[g], 5.0, 70.0);
    f = fit->residuals(p);
    return 0;
  }
};

Params fit_angles(Fit& fit, Params p) {
  // LM only refines: a coarse scan of one shift for every group first finds
  // the basin (the error falls over 10° and more on the default scene).
  Params start = p;
  double best = fit.error(p);
  for (double shift = -10; shift <= 25; shift += 2.5) {
    Params q = p;
    for (double& a : q.angle) a = std::clamp(a + shift, 5.0, 70.0);
    double e = fit.error(q);
    if (e < best) best = e, start = q;
  }
  p = start;
  AngleFunctor f{&fit, p, int(p.angle.size()), fit.residual_count()};
  Eigen::NumericalDiff<AngleFunctor> nd(f, 0.05 * 0.05);  // h = sqrt(epsfcn)·|x|: 5%, 1.5° at 30°
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<AngleFunctor>> lm(nd);
  lm.parameters.maxfev = 60;
  Eigen::VectorXd x(f.n_in);
  for (int g = 0; g < f.n_in; ++g) x[g] = p.angle[size_t(g)];
  lm.minimize(x);
  Params out = p;
  for (int g = 0; g < f.n_in; ++g) out.angle[size_t(g)] = std::clamp(x[g], 5.0, 70.0);
  return fit.error(out) < best ? out : p;  // LM on a step function can wander: keep the better
}

// Area: the lattice's pile holds exactly the grains' area, so its mean
// height against the DEM's sets lattice.bulk. The DEM's piles also end in a
// loose, rough layer of about constant thickness (a larger share of a low
// pile): with piles of two or more sizes, mean DEM height = bulk · packed
// height + surface is fitted by least squares (Eigen); with one size the
// surface stays as it is and the bulk takes it all.
Params fit_bulk(Fit& fit, std::vector<Target>& targets, Params p, bool sizes) {
  for (int round = 0; round < 2; ++round) {
    Eigen::VectorXd r = fit.residuals(p);  // lattice − DEM, over the window height
    Eigen::MatrixXd A(targets.size(), 2);
    Eigen::VectorXd b(targets.size());
    int i = 0;
    for (size_t t = 0; t < targets.size(); ++t) {
      const double H = targets[t].scene.window.height;
      double dem = 0, lat = 0, sand = 0, n = 0;
      for (auto& d : targets[t].dem)
        for (double h : d) dem += h, lat += h + r[i++] * H, sand += h > 0, n += 1;
      // The lattice's height without its surface layer, per column.
      A(long(t), 0) = (lat - p.surface * sand) / n;
      A(long(t), 1) = sand / n;
      b(long(t)) = dem / n;
    }
    double scale = 1, surface = p.surface;
    if (sizes) {
      Eigen::Vector2d x = A.colPivHouseholderQr().solve(b);
      scale = x(0), surface = x(1);
    }
    if (!sizes || surface < 0) {  // the bulk alone, with the surface kept (or none)
      surface = std::max(0.0, surface);
      Eigen::VectorXd rest = b - surface * A.col(1);
      scale = A.col(0).dot(rest) / std::max(A.col(0).squaredNorm(), 1e-12);
    }
    if (!(scale > 0) || !std::isfinite(surface)) break;
    p.bulk = std::clamp(p.bulk * scale, 0.25, 4.0);
    p.surface = std::clamp(surface, 0.0, 100.0);
  }
  return p;
}

Params fit_runout(Fit& fit, Params p) {
  for (size_t g = 0; g < p.runout.size(); ++g) {
    double best = fit.error(p), best_v = p.runout[g];
    for (double v : {0.0, 1.0, 2.0, 3.0, 4.0, 6.0, 8.0}) {
      Params q = p;
      q.runout[g] = v;
      double e = fit.error(q);
      if (e < best) best = e, best_v = v;
    }
    p.runout[g] = best_v;
  }
  return p;
}

// The picture only: lattice.picture_share moves no grain and keeps every
// column's top, so the silhouette fit stands and each group's share (the
// first group's fixed at 1, only their ratio shows) is fitted to the
// composition error alone: a log-spaced scan, then golden-section search
// around its best.
Params fit_shares(Fit& fit, Params p, int bands) {
  for (size_t g = 1; g < p.share.size(); ++g) {
    auto at = [&](double v) {
      Params q = p;
      q.share[g] = v;
      return fit.composition(q, bands);
    };
    double best_v = p.share[g], best = at(best_v);
    for (double v = 0.25; v <= 8.01; v *= std::pow(2.0, 0.25)) {
      const double e = at(v);
      if (e < best) best = e, best_v = v;
    }
    double lo = best_v / std::pow(2.0, 0.25), hi = best_v * std::pow(2.0, 0.25);
    const double r = (std::sqrt(5.0) - 1) / 2;
    double a = hi - r * (hi - lo), b = lo + r * (hi - lo), ea = at(a), eb = at(b);
    for (int i = 0; i < 12; ++i) {
      if (ea < eb) hi = b, b = a, eb = ea, a = hi - r * (hi - lo), ea = at(a);
      else lo = a, a = b, ea = eb, b = lo + r * (hi - lo), eb = at(b);
    }
    for (auto [v, e] : {std::pair{a, ea}, {b, eb}})
      if (e < best) best = e, best_v = v;
    p.share[g] = std::clamp(best_v, 0.05, 20.0);
  }
  return p;
}

}  // namespace

std::vector<Scene> calibration_scenes(const Scene& base, const CalibrateOptions& opt) {
  if (opt.scenes < 1) throw InputError("--scenes must be at least 1");
  if (opt.grains.empty()) throw InputError("--grains needs at least one size");
  for (int64_t g : opt.grains)
    if (g < 100) throw InputError("--grains must be at least 100");
  const double base_grains = double(initialize(base).grains.size());
  if (base_grains <= 0) throw InputError("the scene has no grains to calibrate on");
  const TessellationKind kinds[] = {TessellationKind::Varying, TessellationKind::Uniform, TessellationKind::Strips};
  std::vector<Scene> out;
  for (int64_t grains : opt.grains)
    for (int i = 0; i < opt.scenes; ++i) {
      Scene s = base;
      s.lattice.calibration.clear();
      s.layout_seed = base.layout() + 1000 + uint64_t(i);
      if (s.init.method == InitMethod::Tessellation) s.init.tessellation = kinds[i % 3];
      const double scale = std::sqrt(double(grains) / base_grains);
      try {
        if (std::abs(scale - 1) > 1e-9) apply_scale(s, scale);
      } catch (const InputError& e) {
        throw InputError("--grains " + std::to_string(grains) + " does not fit this scene: " + e.what());
      }
      validate(s);
      out.push_back(s);
    }
  return out;
}

Calibration calibrate(const Scene& base, const CalibrateOptions& opt, const SimulatorFactory& make,
                      const std::function<void(const std::string&)>& log) {
  if (opt.physics_seeds.size() < 2) throw InputError("calibrate needs at least two physics seeds (--seeds)");
  check_fit_keys(opt.fit);
  std::vector<Target> targets;
  for (Scene& s : calibration_scenes(base, opt)) {
    Target t;
    t.scene = s;
    t.prepared = prepare(s);
    t.dem.resize(opt.physics_seeds.size());
    targets.push_back(std::move(t));
  }
  // The DEM runs, in parallel: each job its own simulator and scene copy.
  const size_t per = opt.physics_seeds.size(), jobs = targets.size() * per;
  std::vector<double> seconds(jobs);
  std::vector<cv::Mat> maps(jobs);
  std::mutex mu;
  tbb::parallel_for(size_t(0), jobs, size_t(1), [&](size_t j) {
    Scene s = targets[j / per].scene;
    s.mode = Mode::Dem;
    s.physics_seed = opt.physics_seeds[j % per];
    const std::string label = "dem-" + std::to_string(targets[j / per].prepared.init.grains.size()) + "-layout-" +
                              std::to_string(s.layout()) + "-seed-" + std::to_string(s.physics_rng());
    const ReusedRun got = run_or_reuse(opt.runs_dir, label, s, make, /*need_class_map=*/true);
    maps[j] = got.run.class_map;
    seconds[j] = got.run.stats["timing"]["simulate_s"].get<double>();
    std::lock_guard lock(mu);
    log("DEM pile " + std::to_string(j + 1) + "/" + std::to_string(jobs) + ": " + label + ", " +
        std::to_string(seconds[j]) + " s" + (got.kept ? " (kept from an earlier run)" : ""));
  });
  Calibration c;
  double floor_sum = 0;
  int floor_n = 0;
  for (size_t j = 0; j < jobs; ++j) {
    targets[j / per].dem[j % per] = silhouette(maps[j]);
    targets[j / per].dem_maps.push_back(maps[j]);
    c.dem_s += seconds[j];
  }
  for (size_t t = 0; t < targets.size(); ++t) {
    for (size_t a = 0; a < per; ++a)
      for (size_t b = a + 1; b < per; ++b) {
        floor_sum += silhouette_error(maps[t * per + a], maps[t * per + b]), ++floor_n;
        c.composition_floor += mean_composition_error(composition_error(maps[t * per + a], maps[t * per + b], opt.bands));
      }
    const Scene& s = targets[t].scene;
    const ordered_json init = to_json(s)["init"];  // the scene file's names
    c.scenes.push_back({{"layout_seed", s.layout()},
                        {"tessellation", s.init.method == InitMethod::Halftone ? init["method"] : init["tessellation"]},
                        {"window", {s.window.width, s.window.height}},
                        {"grains", int64_t(targets[t].prepared.init.grains.size())}});
  }
  c.noise_floor = floor_n ? floor_sum / floor_n : 0;
  c.composition_floor = floor_n ? c.composition_floor / floor_n : 0;

  Scene lattice_scene = base;
  lattice_scene.mode = Mode::Lattice;
  auto lattice = make(lattice_scene);
  c.groups = physics_groups(base);
  Fit fit(targets, c.groups, *lattice);
  Params p;
  for (auto& g : c.groups) {
    p.angle.push_back(repose_angle_deg(base, g[0]));
    p.runout.push_back(base.lattice.runout_px[size_t(g[0])]);
    p.share.push_back(base.lattice.picture_share[size_t(g[0])] / base.lattice.picture_share[size_t(c.groups[0][0])]);
  }
  p.bulk = base.lattice.bulk;
  p.surface = base.lattice.surface_px;
  const std::vector<const Field*> grid = grid_fields();
  for (const Field* f : grid) p.grid.push_back(f->get(base).get<double>());
  c.error_before = fit.error(p);
  c.composition_before = fit.composition(p, opt.bands);
  // Two pile sizes at least (their heights a quarter apart) tell the
  // surface layer from the bulk.
  double low = INFINITY, high = 0;
  for (auto& t : targets) low = std::min(low, double(t.scene.region.height)), high = std::max(high, double(t.scene.region.height));
  const bool sizes = high > 1.25 * low;
  log("lattice before: silhouette error " + std::to_string(c.error_before) + " (DEM seed to seed " +
      std::to_string(c.noise_floor) + ")");
  // Bulk first (it sets the mean height), then shape: angles, run-out, and
  // the angles again on the new run-out.
  auto fit_all = [&](Params q) {
    for (int round = 0; round < 2; ++round) {
      q = fit_bulk(fit, targets, q, sizes);
      q = fit_angles(fit, q);
      q = fit_runout(fit, q);
      log("round " + std::to_string(round + 1) + ": silhouette error " + std::to_string(fit.error(q)));
    }
    return q;
  };
  // A grid key changes what the rest fits to (trapping moves the angle the
  // flanks end at, a busy spot which grains land first), so the whole fit
  // runs for every combination of the grids asked for: the scene's own values
  // first, then each grid value (one equal to the scene's own is not repeated).
  std::vector<bool> asked(grid.size());
  for (size_t i = 0; i < grid.size(); ++i) asked[i] = std::find(opt.fit.begin(), opt.fit.end(), grid[i]->path) != opt.fit.end();
  std::vector<std::vector<double>> candidates = {p.grid};
  for (size_t i = 0; i < grid.size(); ++i) {
    if (!asked[i]) continue;
    std::vector<double> values = {p.grid[i]};
    for (double v : grid[i]->fit_grid)
      if (std::find(values.begin(), values.end(), v) == values.end()) values.push_back(v);
    std::vector<std::vector<double>> more;
    for (const auto& c : candidates)
      for (double v : values) {
        auto q = c;
        q[i] = v;
        more.push_back(q);
      }
    candidates = std::move(more);
  }
  if (candidates.size() == 1) {
    p = fit_all(p);
  } else {
    Params best;
    double best_e = INFINITY;
    for (const auto& values : candidates) {
      Params q = p;
      q.grid = values;
      std::string what;
      for (size_t i = 0; i < grid.size(); ++i)
        if (asked[i])
          what += (what.empty() ? "" : ", ") + grid[i]->path + " " + json(values[i]).dump();
      log(what + ":");
      q = fit_all(q);
      const double e = fit.error(q);
      if (e < best_e) best_e = e, best = q;
    }
    p = best;
  }
  c.error_after = fit.error(p);
  if (opt.shares) p = fit_shares(fit, p, opt.bands);
  c.composition_after = fit.composition(p, opt.bands);
  log("composition error " + std::to_string(c.composition_before) + " before, " +
      std::to_string(c.composition_after) + " after (DEM seed to seed " + std::to_string(c.composition_floor) + ")");
  Scene applied = base;
  fit.apply(p, applied);
  c.repose_deg = *applied.lattice.repose_deg;
  c.runout_px = applied.lattice.runout_px;
  c.bulk = p.bulk;
  c.surface_px = p.surface;
  for (size_t i = 0; i < grid.size(); ++i) c.grid[grid[i]->path] = p.grid[i];
  c.picture_share = applied.lattice.picture_share;
  c.lattice_runs = fit.runs();
  return c;
}

void check_fit_keys(const std::vector<std::string>& keys) {
  std::string fittable;
  for (const Field* f : grid_fields()) fittable += (fittable.empty() ? "" : ", ") + f->path;
  for (const std::string& k : keys) {
    const Field* f = find_field(k);
    if (!f || f->fit_grid.empty())
      throw InputError("calibrate --fit: " + std::string(f ? "scene key '" + k + "' has no fit grid" : "no scene key '" + k + "'") +
                       " (keys fitted by trying values: " + fittable + ")");
  }
}

ordered_json calibration_json(const Scene& base, const Calibration& c) {
  ordered_json j;
  j["description"] = "sandpic calibrate: lattice rule values fitted to DEM piles; name this file in lattice.calibration";
  j["lattice"]["repose_deg"] = c.repose_deg;
  j["lattice"]["runout_px"] = c.runout_px;
  j["lattice"]["bulk"] = c.bulk;
  j["lattice"]["surface_px"] = c.surface_px;
  for (const auto& [key, value] : c.grid.items()) j["lattice"][key.substr(key.find('.') + 1)] = value;
  j["lattice"]["picture_share"] = c.picture_share;
  ordered_json& f = j["fit"];
  f["physics"] = {{"friction", base.physics.friction},
                  {"restitution", base.physics.restitution},
                  {"rolling_resistance", base.dem.rolling_resistance},
                  {"water", base.dem.water},
                  {"layers", layers_name(base.dem.layers)}};
  f["groups"] = c.groups;
  f["scenes"] = c.scenes;
  f["silhouette_error_before"] = c.error_before;
  f["silhouette_error_after"] = c.error_after;
  f["dem_noise_floor"] = c.noise_floor;
  f["composition_error_before"] = c.composition_before;
  f["composition_error_after"] = c.composition_after;
  f["dem_composition_floor"] = c.composition_floor;
  f["lattice_runs"] = c.lattice_runs;
  f["dem_simulate_s"] = c.dem_s;
  return j;
}

}  // namespace sandpic
