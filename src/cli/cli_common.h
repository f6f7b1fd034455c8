#pragma once
// What the commands share: the scene options every scene-running command
// accepts, and writing pictures.
#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>
#include <tbb/global_control.h>

#include "src/errors.h"
#include "src/scene_file.h"

namespace sandpic {

// What every command that runs a scene accepts.
struct SceneOptions {
  std::string scene_path;
  std::string mode;
  std::optional<int64_t> seed, layout_seed, physics_seed;
  double scale = 1;
  std::vector<std::string> sets;
  int threads = 0;
  bool one_mode = false, strict = false;

  void add_to(CLI::App* cmd) {
    cmd->add_option("scene", scene_path, "scene file (JSON); none: the built-in default scene");
    cmd->add_option("--mode", mode, "lattice | dem | lammps (the scene's key 'mode')");
    // The range of the scene file's seeds, so a reported seed can go in one.
    const auto seeds = CLI::Range(int64_t(0), int64_t(9007199254740991));
    cmd->add_option("--seed", seed, "sets the layout and the physics seed")->check(seeds);
    cmd->add_option("--layout-seed", layout_seed, "tessellation, colours, ellipses, falling-order ties")->check(seeds);
    cmd->add_option("--physics-seed", physics_seed, "the simulation's own randomness")->check(seeds);
    cmd->add_option("--scale", scale, "multiplies every length in pixels (grains go by scale²)");
    cmd->add_option("--set", sets, "key.path=value, applied after the scene file")->take_all();
    cmd->add_option("--threads", threads, "worker threads (0: all cores); the picture does not depend on it");
  }

  // `fallback`: the scene when none is given (the built-in default scene).
  // The seed options go before --set, so a key given explicitly wins over one
  // --seed derives (--seed 1 --set physics_seed=2 falls with physics seed 2).
  Scene build(const Scene& fallback = Scene{}) const {
    Scene s = scene_path.empty() ? fallback : load_scene(scene_path);
    if (seed) s.seed = uint64_t(*seed), s.layout_seed.reset(), s.physics_seed.reset();
    if (layout_seed) s.layout_seed = uint64_t(*layout_seed);
    if (physics_seed) s.physics_seed = uint64_t(*physics_seed);
    for (const std::string& a : sets) apply_setting(s, a);
    if (!mode.empty()) apply_setting(s, "mode=" + mode);
    if (one_mode) report_unread(s);
    if (scale != 1) apply_scale(s, scale);
    validate(s);
    return s;
  }

  // For commands that run the scene in its own mode only (render, bench): a
  // key that mode never reads is a warning, with --strict an error (exit 2).
  void check_unread(CLI::App* cmd) {
    one_mode = true;
    cmd->add_flag("--strict", strict, "a scene key the mode never reads is an error, not a warning");
  }
  void report_unread(const Scene& s) const;

  std::string reproduce(const Scene& s) const {
    return "scene " + (scene_path.empty() ? std::string("(default)") : scene_path) + ", layout seed " +
           std::to_string(s.layout()) + ", physics seed " + std::to_string(s.physics_rng());
  }
};

// Parses "a,b,c" with `one` for each item; errors name the option.
template <class T, class F>
std::vector<T> list_option(const std::string& option, const std::string& text, F one) {
  std::vector<T> out;
  size_t from = 0;
  while (from <= text.size()) {
    size_t comma = text.find(',', from);
    std::string item = text.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    try {
      out.push_back(one(item));
    } catch (const InputError&) {
      throw;
    } catch (const std::exception&) {
      throw InputError(option + ": bad item '" + item + "' in '" + text + "'");
    }
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return out;
}

// "three,bcre,...": the DEM's layer models, by their scene names.
inline std::vector<Layers> layers_list(const std::string& text) {
  return list_option<Layers>("--layers", text, [](const std::string& i) {
    for (Layers l : {Layers::Three, Layers::Bcre, Layers::AllDynamic})
      if (layers_name(l) == i) return l;
    throw InputError("--layers: unknown model '" + i + "' (three, bcre or all-dynamic)");
  });
}

inline int64_t positive(const std::string& option, const std::string& item, int64_t max) {
  size_t used = 0;
  long long v = std::stoll(item, &used);
  if (used != item.size() || v < 1 || v > max)
    throw InputError(option + ": '" + item + "' is not a whole number in 1.." + std::to_string(max));
  return v;
}

void write_png(const std::string& path, const cv::Mat& img);
std::unique_ptr<tbb::global_control> limit_threads(int n);
// sandpic validate and sandpic calibrate; the returned object owns them.
std::shared_ptr<void> add_validation_commands(CLI::App& app);
// sandpic stress.
std::shared_ptr<void> add_stress_command(CLI::App& app);
// sandpic studio.
std::shared_ptr<void> add_studio_command(CLI::App& app);
// sandpic verify-dem (src/cli/verify_command.cpp).
std::shared_ptr<void> add_verify_command(CLI::App& app);
// sandpic export-lammps (src/cli/lammps_command.cpp).
std::shared_ptr<void> add_lammps_command(CLI::App& app);

}  // namespace sandpic
