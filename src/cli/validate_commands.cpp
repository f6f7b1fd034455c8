// sandpic validate (lattice against the DEM and its noise floor)
// and sandpic calibrate (the lattice fitted to DEM piles).
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "src/cli/cli_common.h"
#include "src/errors.h"
#include "src/output.h"
#include "src/progress.h"
#include "validate/runs/calibrate.h"
#include "validate/report/report_html.h"
#include "validate/runs/validation.h"

namespace sandpic {
namespace {

std::unique_ptr<Simulator> make_any(const Scene& s) { return make_simulator(s); }

// Both commands need the DEM: a build without Bullet says so first.
void need_dem(const Scene& base, const char* command) {
  Scene s = base;
  s.mode = Mode::Dem;
  try {
    make_simulator(s);
  } catch (const InputError&) {
    throw InputError(std::string(command) + " needs the DEM mode, and this sandpic was built without Bullet "
                     "(cmake -DSANDPIC_WITH_BULLET=ON)");
  }
}

// Progress lines on a terminal only.
std::function<void(const std::string&)> logger(const char* command) {
  const bool tty = Progress::stderr_is_terminal();
  return [tty, command](const std::string& line) {
    if (tty) std::fprintf(stderr, "%s: %s\n", command, line.c_str());
  };
}

struct ValidateCommand {
  SceneOptions scene;
  std::string out, sweep = "lattice,dem", calibration, runs;
  int seeds = 4, bands = 8, lattice_seeds = 1;
  double blur = 3;
  int64_t all_dynamic_max = 5000;

  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "validate", "lattice vs DEM on one scene, the DEM's seed-to-seed noise floor, error against run time");
    scene.add_to(cmd);
    cmd->add_option("--out", out, "folder for report.html, report.json and the pictures (DEM runs are kept in "
                                  "OUT/runs and reused while the scene is unchanged)")->required();
    cmd->add_option("--seeds", seeds, "DEM runs beyond the scene's physics seed (at least 4)")->capture_default_str();
    cmd->add_option("--lattice-seeds", lattice_seeds,
                    "score the lattice at this many physics seeds (the scene's, then the next ones): its figures "
                    "are means over them, and the report gives their seed-to-seed spread")
        ->capture_default_str();
    cmd->add_option("--runs", runs, "keep the DEM runs in this folder instead of OUT/runs (a folder shared by "
                                    "several reports; a run is reused while its scene digest holds)");
    cmd->add_option("--sweep", sweep, "settings swept for error against time: lattice, dem, both or none")
        ->capture_default_str();
    cmd->add_option("--calibration", calibration, "a sandpic calibrate file for the lattice run");
    cmd->add_option("--all-dynamic-max", all_dynamic_max, "largest grain count swept with dem.layers=all-dynamic")
        ->capture_default_str();
    cmd->add_option("--bands", bands, "horizontal bands for the composition error")->check(CLI::Range(1, 100000));
    cmd->add_option("--blur", blur, "σ in px of the blur before the blurred SSIM")->check(CLI::Range(0.0, 1000.0));
    cmd->callback([this] { run(); });
  }

  void run() {
    Scene s = scene.build();
    ValidateOptions opt;
    opt.extra_seeds = seeds;
    opt.lattice_seeds = lattice_seeds;
    check_options(opt);  // before the folder is made
    opt.sweep_lattice = opt.sweep_dem = false;
    for (const std::string& item : list_option<std::string>("--sweep", sweep, [this](const std::string& i) {
           if (i != "lattice" && i != "dem" && i != "both" && i != "none")
             throw InputError("--sweep: '" + sweep + "' is not one of lattice, dem, lattice,dem, both, none");
           return i;
         })) {
      opt.sweep_lattice |= item == "lattice" || item == "both";
      opt.sweep_dem |= item == "dem" || item == "both";
    }
    opt.all_dynamic_max = all_dynamic_max;
    opt.bands = bands;
    opt.blur_sigma_px = blur;
    if (!calibration.empty()) {
      if (!std::filesystem::exists(calibration))
        throw InputError("--calibration: cannot read '" + calibration + "'");
      s.lattice.calibration = std::filesystem::absolute(calibration).string();
      with_calibration(s);  // a bad file fails now, not after the DEM runs
    }
    need_dem(s, "validate");
    while (out.size() > 1 && out.back() == '/') out.pop_back();
    check_folder(out);
    if (runs.empty()) runs = out + "/runs";
    check_folder(runs);
    for (const char* f : {"report.json", "report.html", "lattice.png", "difference.png"}) check_writable(out + "/" + f);
    opt.cache_dir = runs;
    auto threads = limit_threads(scene.threads);
    const std::string reproduce = "sandpic validate: " + scene.reproduce(s) +
                                  (scene.scale != 1 ? ", --scale " + std::to_string(scene.scale) : std::string()) +
                                  (calibration.empty() ? std::string() : ", --calibration " + calibration) +
                                  (lattice_seeds > 1 ? ", --lattice-seeds " + std::to_string(lattice_seeds) : std::string());
    Validation v;
    try {
      v = run_validation(s, opt, make_any, logger("validate"));
    } catch (const SimulationError& e) {
      throw SimulationError(std::string(e.what()) + "; to reproduce: " + scene.reproduce(s));
    }
    write_png(out + "/lattice.png", v.lattice.picture);
    write_png(out + "/difference.png", v.heat_map);
    write_atomic(out + "/report.json", validation_json(v, reproduce).dump(2) + "\n");
    write_atomic(out + "/report.html", validation_html(v, reproduce));
    std::printf("sandpic validate: %lld grains, %zu DEM runs\n", (long long)v.lattice.grains, v.dem.size());
    const bool spread = !v.lattice_seeds.empty();
    if (spread) std::printf("lattice: means over %zu physics seeds\n", 1 + v.lattice_seeds.size());
    std::printf("%-18s %12s %12s %8s%s\n", "metric", "lattice", "noise_floor", "ratio", spread ? "  lattice_seed_to_seed" : "");
    for (const MetricRow& m : v.metrics) {
      std::printf("%-18s %12.5f %12.5f %8.3f", m.name.c_str(), m.lattice, m.floor, m.ratio);
      if (spread) std::printf("  %20.5f", m.spread);
      std::printf("\n");
    }
    std::printf("time: lattice %.4g s, DEM %.4g s (medians of simulate_s), ratio %.0f\n", v.lattice_s, v.dem_s,
                v.time_ratio);
    std::printf("report: %s/report.html\n", out.c_str());
  }
};

struct CalibrateCommand {
  SceneOptions scene;
  std::string out, seeds = "1,2", grains = "8000", runs, fit;
  int scenes = 3;
  bool trap = false;
  bool spot = false;
  bool shares = false;
  int bands = 8;

  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "calibrate", "fit the lattice's rule values (angle of repose, run-out, bulk) to DEM piles of variants of a scene");
    scene.add_to(cmd);
    cmd->add_option("--out", out, "the calibration (JSON); a scene uses it through lattice.calibration")->required();
    cmd->add_option("--grains", grains,
                    "grains per calibration scene, comma-separated sizes (two or more also fit lattice.surface_px)")
        ->capture_default_str();
    cmd->add_option("--runs", runs, "keep the DEM piles in this folder and reuse them while their scene digest holds");
    cmd->add_option("--scenes", scenes, "calibration scenes (other layouts and tessellations of the scene)")
        ->capture_default_str()->check(CLI::Range(1, 100));
    cmd->add_option("--seeds", seeds, "DEM physics seeds per calibration scene, comma-separated (two or more)")
        ->capture_default_str();
    cmd->add_option("--fit", fit,
                    "also fit these keys, comma-separated, by trying the values of their grids (scene --reference: "
                    "\"fit grid\"): the whole fit runs once per combination, the best kept");
    cmd->add_flag("--trap", trap, "--fit lattice.trap_rate,lattice.trap_deg (rolling grains caught on the flanks)");
    cmd->add_flag("--spot", spot,
                  "--fit lattice.spot_busy_s (a busy outlet's grains queue and land mixed, as in the DEM)");
    cmd->add_flag("--shares", shares,
                  "also fit lattice.picture_share (small grains drawn larger where they mix with big ones, as the DEM's "
                  "nearest-grain picture shows them) to the composition error; moves no grain");
    cmd->add_option("--bands", bands, "horizontal bands of the composition error (reported, and fitted with --shares)")
        ->capture_default_str()->check(CLI::Range(1, 100000));
    cmd->callback([this] { run(); });
  }

  void run() {
    Scene s = scene.build();
    CalibrateOptions opt;
    opt.bands = bands;
    opt.shares = shares;
    if (!fit.empty()) opt.fit = list_option<std::string>("--fit", fit, [](const std::string& k) { return k; });
    if (trap) opt.fit.insert(opt.fit.end(), {"lattice.trap_rate", "lattice.trap_deg"});
    if (spot) opt.fit.push_back("lattice.spot_busy_s");
    opt.grains = list_option<int64_t>("--grains", grains, [](const std::string& i) {
      return int64_t(positive("--grains", i, 10000000));
    });
    opt.runs_dir = runs;
    opt.scenes = scenes;
    opt.physics_seeds = list_option<uint64_t>("--seeds", seeds, [](const std::string& i) {
      return uint64_t(positive("--seeds", i, 9007199254740991));
    });
    need_dem(s, "calibrate");
    check_writable(out);
    if (!opt.runs_dir.empty()) check_folder(opt.runs_dir);
    auto threads = limit_threads(scene.threads);
    Calibration c = calibrate(s, opt, make_any, logger("calibrate"));
    write_atomic(out, calibration_json(s, c).dump(2) + "\n");
    std::printf("sandpic calibrate: %zu scenes x %zu DEM seeds, %lld lattice runs\n", c.scenes.size(),
                opt.physics_seeds.size(), (long long)c.lattice_runs);
    std::printf("repose_deg %.2f %.2f %.2f %.2f  runout_px %g %g %g %g  bulk %.4f  surface_px %.2f",
                c.repose_deg[0], c.repose_deg[1], c.repose_deg[2], c.repose_deg[3], c.runout_px[0], c.runout_px[1],
                c.runout_px[2], c.runout_px[3], c.bulk, c.surface_px);
    for (const auto& [key, value] : c.grid.items())
      std::printf("  %s %g", key.substr(key.find('.') + 1).c_str(), value.get<double>());
    std::printf("\n");
    std::printf("silhouette error on the calibration scenes: %.5f before, %.5f after (DEM seed to seed %.5f)\n",
                c.error_before, c.error_after, c.noise_floor);
    std::printf("picture_share %.3f %.3f %.3f %.3f: composition error %.5f before, %.5f after (DEM seed to seed %.5f)\n",
                c.picture_share[0], c.picture_share[1], c.picture_share[2], c.picture_share[3], c.composition_before,
                c.composition_after, c.composition_floor);
  }
};

struct ValidationCommands {
  ValidateCommand validate;
  CalibrateCommand calibrate;
};

}  // namespace

std::shared_ptr<void> add_validation_commands(CLI::App& app) {
  auto c = std::make_shared<ValidationCommands>();
  c->validate.add_to(app);
  c->calibrate.add_to(app);
  return c;
}

}  // namespace sandpic
