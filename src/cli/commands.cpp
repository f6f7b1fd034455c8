#include "src/cli/commands.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <tbb/global_control.h>

#include "src/cli/backends.h"
#include "src/cli/cli_common.h"
#include "src/cli/lammps_options.h"
#include "src/cli/frame_output.h"
#include "src/errors.h"
#include "src/grain_table.h"
#include "src/image_io.h"
#include "src/output.h"
#include "src/pipeline.h"
#include "src/init/init.h"
#include "src/presets.h"
#include "src/scene_file.h"
#include "src/segment/sketch.h"
#include "validate/metrics/compare.h"
#include "validate/metrics/grain_compare.h"
#include "validate/bench/falling_sand.h"
#include "validate/bench/friction_bench.h"
#include "validate/bench/layer_bench.h"
#include "validate/metrics/silhouette.h"
#include "validate/metrics/statistics.h"

namespace sandpic {

void write_png(const std::string& path, const cv::Mat& img) {
  const std::vector<uchar> png = encode_png(img);
  write_atomic(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

std::unique_ptr<tbb::global_control> limit_threads(int n) {
  if (n <= 0) return nullptr;
  return std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, size_t(n));
}

namespace {

struct RenderCommand {
  SceneOptions scene;
  LammpsCliOptions lammps;
  std::string out, stats, stages, frames, video, grains;
  int frame_count = 60;
  double fps = 24, max_memory_gb = 0, max_hours = 24;

  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("render", "render a scene to a PNG picture");
    scene.add_to(cmd);
    scene.check_unread(cmd);
    cmd->add_option("-o,--out", out, "output PNG")->required();
    cmd->add_option("--stats", stats, "write statistics (grain counts, timings) as JSON");
    cmd->add_option("--stages", stages, "write the intermediate pictures of paper Fig. 2 into this folder");
    cmd->add_option("--grains", grains,
                    "write every grain as CSV: id, class, unit, falling order, where its fall started, where it rests");
    cmd->add_option("--frames", frames, "write pictures of the fall (paper Fig. 14c-d) as frame-00000.png, ... into this folder");
    cmd->add_option("--video", video, "write the pictures of the fall as an MP4 video (mp4v)");
    cmd->add_option("--frame-count", frame_count, "frames of the fall, evenly spaced by grains released; the last is the picture")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd->add_option("--fps", fps, "frames per second of --video")->check(CLI::Range(0.1, 1000.0))->capture_default_str();
    cmd->add_option("--max-memory-gb", max_memory_gb,
                    "refuse a scene estimated to need more memory (0: three quarters of this machine's)")
        ->check(CLI::Range(0.0, 1e6));
    cmd->add_option("--max-hours", max_hours, "refuse a scene estimated to take longer to simulate")
        ->check(CLI::Range(0.0, 1e6))
        ->capture_default_str();
    lammps.add_to(cmd);
    cmd->callback([this] { run(); });
  }

  void run() {
    Scene s = scene.build();
    if (s.mode == Mode::Lammps && (!frames.empty() || !video.empty()))
      throw InputError("--frames and --video are not available in mode lammps (its grains are read back once, at the end)");
    if (s.mode != Mode::Lammps && !lammps.opt.from_dump.empty())
      throw InputError("--from-dump needs mode lammps (--mode lammps, or the scene's key 'mode')");
    for (std::string* dir : {&stages, &frames})
      while (dir->size() > 1 && dir->back() == '/') dir->pop_back();
    check_writable(out);
    if (!stats.empty()) check_writable(stats);
    if (!grains.empty()) check_writable(grains);
    if (!stages.empty() && !std::filesystem::is_directory(stages)) check_writable(stages);
    auto threads = limit_threads(scene.threads);
    auto sim = make_simulator(s, lammps.opt);
    RunOptions opt;
    opt.stages = !stages.empty();
    opt.grains = !grains.empty();
    opt.progress = Progress::stderr_is_terminal();
    opt.limits = {max_memory_gb * 1e9, max_hours * 3600, 600};
    // Streamed into temporaries as they come; moved into place at the end.
    std::unique_ptr<FrameOutput> fall;
    if (!frames.empty() || !video.empty()) {
      fall = std::make_unique<FrameOutput>(frames, video, cv::Size(s.window.width, s.window.height), fps);
      opt.frames = frame_count;
      opt.frame = [&](const cv::Mat& picture) { fall->write(picture); };
    }
    RunResult r;
    try {
      r = run_pipeline(s, *sim, opt);
    } catch (const SimulationError& e) {
      throw SimulationError(std::string(e.what()) + "; to reproduce: " + scene.reproduce(s));
    }
    // Every target is checked before the first is written.
    if (!stages.empty()) {
      check_folder(stages);
      for (auto& stage : r.stages) check_writable(stages + "/" + stage.first);
    }
    write_atomic(out, std::string_view(reinterpret_cast<const char*>(r.png.data()), r.png.size()));
    if (!stats.empty()) write_atomic(stats, r.stats.dump(2) + "\n");
    if (!grains.empty()) write_atomic(grains, r.grains);
    for (auto& [name, img] : r.stages) write_png(stages + "/" + name, img);
    if (fall) fall->commit();
  }
};

// paper §5.2: a scene's sketch as a picture to paint over; a scene reads it
// back through segment.sketch.image.
struct SketchCommand {
  SceneOptions scene;
  std::string out;
  int thickness = 3;
  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("sketch", "draw a scene's sketch (ridge lines, arcs) as a picture of the region");
    scene.add_to(cmd);
    cmd->add_option("-o,--out", out, "output PNG")->required();
    cmd->add_option("--thickness", thickness, "stroke width, px")->check(CLI::Range(1, 8));
    cmd->callback([this] {
      Scene s = scene.build();
      const auto& k = s.segment.sketch;
      if (k.ridges.empty() && k.arcs.empty() && k.image.empty())
        throw key_error("segment.sketch.ridges", "the scene has no sketch (segment.sketch.ridges and arcs, or image)");
      check_writable(out);
      write_png(out, sketch_image(scene_sketch(s), k.ridge_color, k.arc_color, s.window.width, s.region.height, thickness));
    });
  }
};

}  // namespace

void SceneOptions::report_unread(const Scene& s) const {
  std::vector<std::string> given;
  for (const std::string& a : sets) given.push_back(a.substr(0, a.find('=')));
  for (const std::string& key : unread_keys(s, given)) {
    const std::string what = "scene key '" + key + "' is not read in " + mode_name(s.mode) + " mode";
    if (strict) throw InputError(what + " (--strict)");
    std::fprintf(stderr, "sandpic: warning: %s\n", what.c_str());
  }
}

namespace {

// docs/scene-reference.md's table of every key, made from the registry (a
// test checks the page against it): its default, whether --scale multiplies
// it, which stages read it (pipeline: the shared one), whether an area may
// set it, the values calibrate --fit tries and validate sweeps, its help.
std::string reference_table() {
  auto cell = [](std::string v) {
    std::string out;
    for (char c : v) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
  };
  std::ostringstream o;
  o << "| key | default | scaled | read by | area | fit grid | sweep | meaning |\n"
       "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  // From keys_json, the studio's list of the same keys: one naming of the readers.
  auto joined = [](const ordered_json& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n.get<std::string>();
    return out;
  };
  for (const ordered_json& k : keys_json()) {
    const std::string readers = joined(k["read_by"]);
    o << "| `" << k["key"].get<std::string>() << "` | `" << cell(k["default"].dump()) << "` | "
      << (k["scaled"].get<bool>() ? "yes" : "") << " | " << readers << " | " << (k["area"].get<bool>() ? "yes" : "")
      << " | " << (k.contains("fit_grid") ? cell(k["fit_grid"].dump()) : "") << " | "
      << cell(joined(k.value("sweep", ordered_json::array()))) << " | "
      << cell(k["help"].get<std::string>()) << " |\n";
  }
  return o.str();
}

struct SceneCommand {
  bool keys = false, list_presets = false, reference = false;
  std::string preset;
  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("scene", "print the complete default scene as JSON");
    cmd->add_flag("--keys", keys, "list every key with its meaning instead");
    cmd->add_flag("--presets", list_presets, "list the presets of paper §9 instead");
    cmd->add_flag("--reference", reference, "every key as docs/scene-reference.md's Markdown table instead");
    cmd->add_option("--preset", preset, "print the complete scene a preset makes");
    cmd->callback([this] {
      if (list_presets) {
        for (const Preset& p : presets()) std::cout << p.name << "\t" << p.about << "\n";
        return;
      }
      if (keys) {
        for (const Field& f : scene_fields()) std::cout << f.path << "\t" << f.help << "\n";
        return;
      }
      if (reference) {
        std::cout << reference_table();
        return;
      }
      Scene s;
      if (!preset.empty()) apply_setting(s, "preset=" + json(preset).dump());
      std::cout << to_json(s).dump(2) << "\n";
    });
  }
};

// Speed is shown by medians of repeated in-process runs, never by a timed test.
struct BenchCommand {
  SceneOptions scene;
  int runs = 9;
  bool peer = false;
  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("bench", "time the pipeline on a scene: medians of repeated runs");
    scene.add_to(cmd);
    scene.check_unread(cmd);
    cmd->add_option("--runs", runs, "timed runs (after one warm-up run)")->check(CLI::Range(1, 1000));
    cmd->add_flag("--peer", peer,
                  "also time a classic falling-sand automaton (one class, a fixed 45° rule) on the same grid and "
                  "grains, run by run beside the lattice");
    cmd->callback([this] { run(); });
  }
  void run() {
    Scene s = scene.build();
    if (peer && s.mode != Mode::Lattice) throw InputError("--peer: the peer is a lattice's; the scene's mode is not lattice");
    auto threads = limit_threads(scene.threads);
    auto sim = make_simulator(s);
    std::vector<std::string> keys = {"init_s", "segment_s", "order_s", "simulate_s", "render_s", "encode_s", "total_s"};
    std::map<std::string, std::vector<double>> t;
    int64_t grains = 0;
    std::vector<int32_t> columns;
    if (peer) columns = entry_columns(s, prepare(s));
    FallingSand sand;
    for (int i = 0; i <= runs; ++i) {
      RunResult r = run_pipeline(s, *sim, RunOptions{});
      grains = r.stats["grains"]["total"];
      double peer_s = 0;
      if (peer) {
        const auto start = std::chrono::steady_clock::now();
        sand = falling_sand(s.window.width, s.window.height, columns, kPeerGrainsPerTick, s.physics_rng());
        peer_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }
      if (i == 0) continue;  // warm-up: page faults, TBB start-up
      for (auto& k : keys) t[k].push_back(r.stats["timing"][k].get<double>());
      if (peer) {
        t["peer_s"].push_back(peer_s);
        t["ratio"].push_back(peer_s / r.stats["timing"]["simulate_s"].get<double>());
      }
    }
    std::printf("sandpic bench: %s, %dx%d window, %lld grains, %d runs\n", s.mode == Mode::Lattice ? "lattice" : "dem",
                s.window.width, s.window.height, (long long)grains, runs);
    std::printf("%-12s %10s %10s %10s %8s\n", "stage", "median_s", "min_s", "max_s", "share");
    double total = median(t["total_s"]);
    for (auto& k : keys)
      std::printf("%-12s %10.4f %10.4f %10.4f %7.1f%%\n", k.c_str(), median(t[k]),
                  *std::min_element(t[k].begin(), t[k].end()), *std::max_element(t[k].begin(), t[k].end()),
                  100 * median(t[k]) / total);
    std::printf("grains per second (simulate): %.3g\n", double(grains) / median(t["simulate_s"]));
    if (!peer) return;
    std::printf("peer: a classic falling-sand automaton on the same %dx%d grid, the same grains entering at the top\n"
                "at the lattice's drop columns in falling order, %d a tick; one class, a fixed 45° rule\n"
                "(%lld ticks, %lld cells fallen, %lld grains at rest, %lld lost)\n",
                s.window.width, s.window.height, kPeerGrainsPerTick, (long long)sand.ticks, (long long)sand.moves,
                (long long)sand.settled, (long long)sand.lost);
    std::printf("%-12s %10.4f %10.4f %10.4f\n", "peer_s", median(t["peer_s"]),
                *std::min_element(t["peer_s"].begin(), t["peer_s"].end()),
                *std::max_element(t["peer_s"].begin(), t["peer_s"].end()));
    std::printf("peer_s / simulate_s, run by run: median %.1f (min %.1f, max %.1f)\n", median(t["ratio"]),
                *std::min_element(t["ratio"].begin(), t["ratio"].end()),
                *std::max_element(t["ratio"].begin(), t["ratio"].end()));
  }
  static constexpr int kPeerGrainsPerTick = 8;
};

// paper Fig. 12: the DEM's layer models side by side at several grain counts.
struct BenchLayersCommand {
  SceneOptions scene;
  std::string grains = "2000,5000,10000,20000,50000,100000", seeds = "1,2", layers = "three,bcre,all-dynamic";
  int64_t all_dynamic_max = 5000, bcre_max = 100000000;
  std::string csv, plot;
  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "bench-layers", "paper Fig. 12: DEM time against grains for three, bcre and all-dynamic, and their silhouette error");
    scene.add_to(cmd);
    cmd->add_option("--grains", grains, "grain counts, comma-separated (the scene is scaled to each)")->capture_default_str();
    cmd->add_option("--seeds", seeds, "physics seeds, comma-separated")->capture_default_str();
    cmd->add_option("--layers", layers, "layer models, comma-separated")->capture_default_str();
    cmd->add_option("--all-dynamic-max", all_dynamic_max, "largest count run with all-dynamic (its cost grows as n^2)")
        ->capture_default_str();
    cmd->add_option("--bcre-max", bcre_max, "largest count run with bcre");
    cmd->add_option("--csv", csv, "write every run as CSV");
    cmd->add_option("--plot", plot, "write time against grains as a PNG plot");
    cmd->callback([this] { run(); });
  }
  void run() {
    Scene s = scene.build();
    LayerBenchOptions opt;
    opt.grains = list_option<int64_t>("--grains", grains, [](const std::string& i) { return positive("--grains", i, 100000000); });
    opt.seeds = list_option<uint64_t>("--seeds", seeds, [](const std::string& i) { return uint64_t(positive("--seeds", i, 9007199254740991)); });
    opt.layers = layers_list(layers);
    opt.all_dynamic_max = all_dynamic_max;
    opt.bcre_max = bcre_max;
    if (!csv.empty()) check_writable(csv);
    if (!plot.empty()) check_writable(plot);
    s.mode = Mode::Dem;
    auto threads = limit_threads(scene.threads);
    auto sim = make_simulator(s);  // exit 2 in a build without Bullet
    std::fprintf(stderr, "sandpic bench-layers: %s\n", scene.reproduce(s).c_str());
    auto rows = run_layer_bench(s, opt, *sim, [](const LayerBenchRow& r) {
      std::fprintf(stderr, "  %-18s %8lld grains  seed %-8llu %9.2f s  %8lld steps  silhouette error %.4f\n",
                   r.layers.c_str(), (long long)r.grains, (unsigned long long)r.seed, r.simulate_s, (long long)r.steps,
                   r.silhouette_error);
    });
    std::fputs(layer_bench_table(rows).c_str(), stdout);
    if (!csv.empty()) write_atomic(csv, layer_bench_csv(rows));
    if (!plot.empty()) write_png(plot, layer_bench_plot(rows));
  }
};

// paper Fig. 9: the pile's slope against friction, over several seeds.
struct BenchFrictionCommand {
  SceneOptions scene;
  std::string friction = "0.1,0.4,0.9", seeds = "1,2,3", layers = "three,all-dynamic";
  std::string csv, pictures;
  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "bench-friction", "paper Fig. 9: the DEM pile's slope against friction, averaged over physics seeds");
    scene.add_to(cmd);
    cmd->add_option("--friction", friction, "friction values, comma-separated")->capture_default_str();
    cmd->add_option("--seeds", seeds, "physics seeds, comma-separated")->capture_default_str();
    cmd->add_option("--layers", layers, "layer models, comma-separated")->capture_default_str();
    cmd->add_option("--csv", csv, "write every run as CSV");
    cmd->add_option("--pictures", pictures, "write every run's picture into this folder");
    cmd->callback([this] { run(); });
  }
  void run() {
    Scene s = scene.build(pile_scene());
    FrictionBenchOptions opt;
    opt.friction = list_option<double>("--friction", friction, [](const std::string& i) {
      size_t used = 0;
      double v = std::stod(i, &used);
      if (used != i.size() || !(v >= 0 && v <= 10)) throw InputError("--friction: '" + i + "' is not a number in 0..10");
      return v;
    });
    opt.seeds = list_option<uint64_t>("--seeds", seeds, [](const std::string& i) { return uint64_t(positive("--seeds", i, 9007199254740991)); });
    opt.layers = layers_list(layers);
    if (!csv.empty()) check_writable(csv);
    if (!pictures.empty()) check_folder(pictures);
    s.mode = Mode::Dem;
    auto threads = limit_threads(scene.threads);
    auto sim = make_simulator(s);  // exit 2 in a build without Bullet
    std::fprintf(stderr, "sandpic bench-friction: %s\n", scene.reproduce(s).c_str());
    auto rows = run_friction_bench(s, opt, *sim, [](const FrictionBenchRow& r) {
      // A picture of many mountains has no heap angle: its scene slope then.
      const bool heap = std::isfinite(r.angle_deg);
      std::fprintf(stderr, "  %-12s friction %.2f  seed %-6llu %7lld grains  %7.2f s  %s %5.1f°  silhouette error %.4f\n",
                   r.layers.c_str(), r.friction, (unsigned long long)r.seed, (long long)r.grains, r.simulate_s,
                   heap ? "heap angle" : "scene slope", heap ? r.angle_deg : r.slope_deg, r.silhouette_error);
    });
    std::fputs(friction_bench_table(rows).c_str(), stdout);
    if (!csv.empty()) write_atomic(csv, friction_bench_csv(rows));
    for (const FrictionBenchRow& r : rows) {
      if (pictures.empty()) break;
      char name[128];
      std::snprintf(name, sizeof name, "/%s-friction%.2f-seed%llu.png", r.layers.c_str(), r.friction,
                    (unsigned long long)r.seed);
      write_png(pictures + name, r.picture);
    }
  }
};

}  // namespace

// How alike two pictures are, on luminance and on the pile.
struct CompareCommand {
  std::string a, b, scene_path, diff_path;
  std::vector<std::string> tolerances;
  bool as_json = false;
  int bands = 8;
  double blur = 3;

  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("compare", "image similarity of two pictures of one scene (SSIM, PSNR, pile measures)");
    cmd->add_option("a", a, "first picture (PNG)")->required();
    cmd->add_option("b", b, "second picture, the same size")->required();
    cmd->add_flag("--json", as_json, "print JSON");
    cmd->add_option("--scene", scene_path, "the pictures' scene: its class colours tell sand from background "
                                          "(none: the default scene's colours)");
    cmd->add_option("--bands", bands, "horizontal bands for the composition error")->check(CLI::Range(1, 100000));
    cmd->add_option("--blur", blur, "σ in px of the Gaussian blur before the blurred SSIM")->check(CLI::Range(0.0, 1000.0));
    cmd->add_option("--diff", diff_path, "write where the pictures differ as a PNG (differing pixels red over the "
                                         "first picture in grey)");
    cmd->add_option("--tolerance", tolerances,
                    "METRIC=BOUND, repeatable: exit 1 when an error (silhouette_error, composition_error) is above "
                    "its bound or a similarity (ssim, ssim_blurred, psnr_db) below it");
    cmd->callback([this] { run(); });
  }

  struct Bound {
    std::string metric;
    double bound;
    bool error;  // an error metric: lower is better
  };

  // Every --tolerance checked before any work, so a typo costs no run.
  std::vector<Bound> bounds() const {
    std::vector<Bound> out;
    for (const std::string& t : tolerances) {
      const size_t eq = t.find('=');
      const std::string name = t.substr(0, eq);
      const bool error = name == "silhouette_error" || name == "composition_error";
      if (!error && name != "ssim" && name != "ssim_blurred" && name != "psnr_db")
        throw InputError("--tolerance '" + t + "': the metric must be silhouette_error, composition_error, ssim, "
                         "ssim_blurred or psnr_db");
      double v = NAN;
      try {
        size_t used = 0;
        v = eq == std::string::npos ? NAN : std::stod(t.substr(eq + 1), &used);
        if (eq + 1 + used != t.size()) v = NAN;
      } catch (const std::exception&) {
      }
      if (!std::isfinite(v)) throw InputError("--tolerance '" + t + "': expected METRIC=NUMBER");
      out.push_back({name, v, error});
    }
    return out;
  }

  static cv::Mat load(const std::string& path) {
    try {
      return read_image(path, "compare");
    } catch (const InputError&) {
      throw InputError("cannot read picture '" + path + "' (missing, unreadable or not an image)");
    }
  }

  void run() {
    const std::vector<Bound> limits = bounds();
    if (!diff_path.empty()) check_writable(diff_path);
    const Scene s = scene_path.empty() ? Scene{} : load_scene(scene_path);
    const cv::Mat ia = load(a), ib = load(b);
    if (ia.size() != ib.size())
      throw InputError(b + " is " + std::to_string(ib.cols) + "x" + std::to_string(ib.rows) + " px but " + a + " is " +
                       std::to_string(ia.cols) + "x" + std::to_string(ia.rows));
    // Pictures in other colours decode as no sand at all and would score
    // silhouette and composition 0: refuse instead of answering zeros.
    for (const auto& [path, img] : {std::pair{a, &ia}, std::pair{b, &ib}})
      if (cv::countNonZero(decode_classes(*img, s.grains.colors) != kNoSand) == 0)
        throw InputError(path + " has no pixel in the class colours of " +
                         (scene_path.empty() ? std::string("the default scene") : scene_path) +
                         "; give the pictures' scene with --scene");
    const Comparison c = compare_pictures(ia, ib, s.grains.colors, bands, blur);
    ordered_json j;
    j["width"] = c.width;
    j["height"] = c.height;
    j["ssim"] = c.ssim;
    j["psnr_db"] = std::isfinite(c.psnr_db) ? ordered_json(c.psnr_db) : ordered_json(nullptr);  // null: identical
    j["identical"] = !std::isfinite(c.psnr_db);
    j["silhouette_error"] = c.silhouette_error;
    j["composition_error"] = c.composition_error;
    j["composition_error_per_band"] = c.composition;
    j["blur_sigma_px"] = c.blur_sigma_px;
    j["ssim_blurred"] = c.ssim_blurred;
    // Each picture's mean outline slope, smoothed over 8 large-grain
    // diameters as verify-dem's layers case measures it (--scale keeps a
    // grain's size in pixels: the scene's own diameters at any scale).
    double big = 0;
    for (int k = 0; k < kClasses; ++k) big = std::max(big, grain_diameter_px(s, k));
    const std::vector<double> sa = silhouette(decode_classes(ia, s.grains.colors)),
                              sb = silhouette(decode_classes(ib, s.grains.colors));
    j["scene_slope_deg"] = {scene_slope_deg(sa, 8 * big), scene_slope_deg(sb, 8 * big)};
    // And as one heap: verify-dem's heap angle (null where there is no heap
    // to fit, as in a picture of many mountains it may still fit one).
    auto angle = [](const std::vector<double>& h) {
      const double a = heap_angle_deg(h);
      return std::isfinite(a) ? ordered_json(a) : ordered_json(nullptr);
    };
    j["heap_angle_deg"] = {angle(sa), angle(sb)};
    if (!diff_path.empty()) write_png(diff_path, difference_picture(ia, ib));
    print(c, j);
    // psnr_db is +inf for identical pictures: above every bound.
    std::string over;
    for (const Bound& l : limits) {
      const double v = j[l.metric].is_null() ? INFINITY : j[l.metric].get<double>();
      if (l.error ? v > l.bound : v < l.bound) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s%s %.6g %s %.6g", over.empty() ? "" : "; ", l.metric.c_str(), v,
                      l.error ? "above its tolerance" : "below its tolerance", l.bound);
        over += buf;
      }
    }
    if (!over.empty()) throw CheckFailed("compare: " + over);
  }

  void print(const Comparison& c, const ordered_json& j) const {
    if (as_json) {
      std::cout << j.dump(2) << "\n";
      return;
    }
    std::printf("ssim               %.6f\n", c.ssim);
    std::printf("scene_slope_deg    %.2f  %.2f\n", j["scene_slope_deg"][0].get<double>(), j["scene_slope_deg"][1].get<double>());
    auto deg = [](const ordered_json& v) -> std::string {
      if (v.is_null()) return "none";
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.2f", v.get<double>());
      return buf;
    };
    std::printf("heap_angle_deg     %s  %s\n", deg(j["heap_angle_deg"][0]).c_str(), deg(j["heap_angle_deg"][1]).c_str());
    if (std::isfinite(c.psnr_db))
      std::printf("psnr_db            %.3f\n", c.psnr_db);
    else
      std::printf("psnr_db            identical\n");
    std::printf("silhouette_error   %.6f\n", c.silhouette_error);
    std::printf("composition_error  %.6f  (%d bands)\n", c.composition_error, int(c.composition.size()));
    std::printf("ssim_blurred       %.6f  (sigma %.3g px)\n", c.ssim_blurred, c.blur_sigma_px);
  }
};

// Two runs of one scene grain by grain (render --grains): how far
// each class travels from where its fall started, how wide a unit spreads,
// and, for runs with the same physics seed, how far apart each grain rests.
struct CompareGrainsCommand {
  std::string a, b;
  bool as_json = false;

  void add_to(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("compare-grains", "two runs of one scene compared grain by grain (render --grains tables)");
    cmd->add_option("a", a, "first grain table (CSV from render --grains)")->required();
    cmd->add_option("b", b, "second grain table, of the same scene and layout")->required();
    cmd->add_flag("--json", as_json, "print JSON");
    cmd->callback([this] { run(); });
  }

  static std::vector<GrainRow> load(const std::string& path) {
    std::optional<std::string> text = read_text(path);
    if (!text) throw InputError("cannot read grain table '" + path + "'");
    return parse_grain_table(*text, path);
  }

  static ordered_json travel_json(const TravelStats& t) {
    return {{"grains", t.grains}, {"mean_px", t.mean_px}, {"median_px", t.median_px}, {"p90_px", t.p90_px},
            {"within_2px", t.within_2px}};
  }

  void run() {
    const GrainComparison c = compare_grains(load(a), load(b), a, b);
    ordered_json j;
    j["grains"] = c.grains;
    j["same_release"] = c.same_release;
    for (int k = 0; k < kClasses; ++k) {
      ordered_json cls;
      cls["a"] = travel_json(c.travel_a[size_t(k)]);
      cls["b"] = travel_json(c.travel_b[size_t(k)]);
      cls["travel_distance_px"] = c.travel_distance_px[size_t(k)];
      j["travel"].push_back(cls);
    }
    j["unit_spread_px"] = {{"a", c.unit_spread_a_px}, {"b", c.unit_spread_b_px}};
    j["unit_centroid_distance_px"] = c.unit_centroid_distance_px;
    j["unit_spread_difference_px"] = c.unit_spread_difference_px;
    auto number_or_null = [](double v) { return std::isfinite(v) ? ordered_json(v) : ordered_json(nullptr); };
    j["grain_distance_px"] = {{"x", number_or_null(c.grain_dx_px)}, {"y", number_or_null(c.grain_dy_px)}};
    if (as_json) {
      std::cout << j.dump(2) << "\n";
      return;
    }
    std::printf("%lld grains, %s\n", static_cast<long long>(c.grains),
                c.same_release ? "released at the same points (same scene and physics seed)"
                               : "released at different points (another physics seed): travel compares, grains do not");
    std::printf("travel from where the fall started (px): median / p90 / share within 2 px\n");
    std::printf("class  grains      a: median    p90  <=2px      b: median    p90  <=2px   distance\n");
    for (int k = 0; k < kClasses; ++k) {
      const TravelStats &ta = c.travel_a[size_t(k)], &tb = c.travel_b[size_t(k)];
      if (ta.grains == 0) continue;
      std::printf("S%d    %7lld   %12.2f %6.2f %6.2f   %12.2f %6.2f %6.2f   %8.2f\n", k + 1,
                  static_cast<long long>(ta.grains), ta.median_px, ta.p90_px, ta.within_2px, tb.median_px, tb.p90_px,
                  tb.within_2px, c.travel_distance_px[size_t(k)]);
    }
    std::printf("unit spread (px)   a %.2f   b %.2f\n", c.unit_spread_a_px, c.unit_spread_b_px);
    std::printf("units, a against b (px): centroid distance %.2f   spread difference %.2f\n",
                c.unit_centroid_distance_px, c.unit_spread_difference_px);
    if (c.same_release) std::printf("grain distance (px)  x %.2f   y %.2f\n", c.grain_dx_px, c.grain_dy_px);
  }
};

int cli_main(int argc, char** argv) {
  // OpenCV's own warnings would break the one-line error promise.
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  CLI::App app{"sandpic: moving sand pictures, after 'Computer Simulation and Generation of Moving Sand Pictures'"};
  app.require_subcommand(1);
  RenderCommand render;
  SceneCommand scene;
  SketchCommand sketch;
  BenchCommand bench;
  BenchLayersCommand bench_layers;
  BenchFrictionCommand bench_friction;
  CompareCommand compare;
  CompareGrainsCommand compare_grains_cmd;
  render.add_to(app);
  scene.add_to(app);
  sketch.add_to(app);
  bench.add_to(app);
  bench_layers.add_to(app);
  bench_friction.add_to(app);
  compare.add_to(app);
  compare_grains_cmd.add_to(app);
  auto validation = add_validation_commands(app);
  auto stress = add_stress_command(app);
  auto studio = add_studio_command(app);
  auto verify = add_verify_command(app);
  auto lammps = add_lammps_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "sandpic: %s (see sandpic --help)\n", e.what());
    return 2;
  } catch (const InputError& e) {
    std::fprintf(stderr, "sandpic: error: %s\n", e.what());
    return 2;
  } catch (const SimulationError& e) {
    std::fprintf(stderr, "sandpic: simulation failed: %s\n", e.what());
    return 3;
  } catch (const CheckFailed& e) {
    std::fprintf(stderr, "sandpic: %s\n", e.what());
    return 1;
  } catch (const nlohmann::json::exception& e) {  // a value no key check caught
    std::fprintf(stderr, "sandpic: error: bad value: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "sandpic: error: not enough memory for this scene; lower window or region sizes\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sandpic: simulation failed: %s\n", e.what());
    return 3;
  }
  return 0;
}

}  // namespace sandpic
