// verify-dem's engine-piles case: the Bullet DEM against LAMMPS's granular
// DEM (physics/lammps_simulator.h) on whole piles, each engine releasing
// the grains, pouring them through the water and piling them its own way.
// The engines case holds the contacts alone against each other (one placed
// column); this one the pictures users see. Full run only: LAMMPS's soft
// contacts need a step about 100x Bullet's (docs/lammps.md), minutes for a
// heap of a few hundred grains.
#include <algorithm>
#include <cmath>
#include <map>

#include "validate/dem/cases.h"
#include "validate/dem/pile_runs.h"
#include "validate/metrics/statistics.h"

namespace sandpic::verify {
namespace {

// One pile (the heap or the default scene) at every friction: Bullet's
// models and LAMMPS, over the plan's seeds.
struct Pile {
  std::string name, measure;  // "heap", "heap angle"
  Scene base;
  double (*measured)(const Run&);
};

void compare_engines(VerifyCase& c, const Pile& pile, const Plan& p, const VerifyOptions& opt) {
  const std::vector<double> friction = {0.1, 0.4, 0.9};
  const double mr = Scene{}.dem.rolling_resistance;
  const std::vector<Layers> models = pile_models(opt);
  std::vector<Scene> scenes;
  for (double mu : friction) {
    for (Layers l : models)
      for (uint64_t seed : p.seeds) scenes.push_back(with(pile.base, l, mu, mr, seed));
    for (uint64_t seed : p.seeds) {
      Scene s = with(pile.base, Layers::AllDynamic, mu, mr, seed);
      s.mode = Mode::Lammps;
      scenes.push_back(s);
    }
  }
  const std::vector<Run> runs = run_all(scenes, opt, "engine-piles, " + pile.name);
  auto engine = [](const Run& r) { return r.scene.mode == Mode::Lammps ? std::string("LAMMPS") : layers_name(r.scene.dem.layers); };
  VerifyPlot plot{pile.name + ": " + pile.measure + " by engine", "friction", pile.measure + " (deg)", {}};
  std::map<std::string, PlotSeries> lines;
  double seconds_bullet = 0, seconds_lammps = 0;
  for (double mu : friction) {
    std::map<std::string, std::vector<const Run*>> by;
    for (const Run& r : runs)
      if (r.scene.physics.friction == mu) by[engine(r)].push_back(&r);
    auto values = [&](const std::string& e) {
      std::vector<double> v;
      for (const Run* r : by[e]) v.push_back(pile.measured(*r));
      return v;
    };
    const std::vector<double> ref = values("LAMMPS");
    const double ref_floor = floor_error(by["LAMMPS"]);
    for (auto& [e, rs] : by) {
      PlotSeries& line = lines[e];
      line.label = e, line.points = true;
      for (const Run* r : rs) {
        line.x.push_back(mu), line.y.push_back(pile.measured(*r));
        (e == "LAMMPS" ? seconds_lammps : seconds_bullet) += r->simulate_s;
      }
    }
    for (Layers l : models) {
      const std::string e = layers_name(l);
      const std::vector<double> v = values(e);
      const std::string name = pile.name + ", " + e + ", friction " + fmt("%.1f", mu);
      c.checks.push_back(within(name + ": mean " + pile.measure + " against LAMMPS's (" + fmt("%.1f", mean(ref)) + "° ± " +
                                    fmt("%.1f", spread(ref)) + ")",
                                mean(v), mean(ref), std::max(2.0, 2 * std::max(spread(v), spread(ref))), "°"));
      const double own = floor_error(by[e]), across = cross_error(by[e], by["LAMMPS"]);
      c.checks.push_back(at_most(name + ": silhouette error against LAMMPS (" + fmt("%.4f", across) + ") over the larger floor (" +
                                     e + " " + fmt("%.4f", own) + ", LAMMPS " + fmt("%.4f", ref_floor) + ")",
                                 across / std::max(own, ref_floor), 2, "×"));
    }
    if (mu == 0.4)
      for (const std::string& e : {std::string("LAMMPS"), layers_name(models.front())})
        c.pictures.emplace_back(pile.name + ", " + e + ", friction 0.4, seed " + std::to_string(p.seeds.front()),
                                by[e].front()->picture);
  }
  for (auto& [e, line] : lines) plot.series.push_back(line);
  c.plots.push_back(std::move(plot));
  c.notes.push_back(pile.name + ": simulation " + fmt("%.0f", seconds_bullet) + " s Bullet (both models), " +
                    fmt("%.0f", seconds_lammps) + " s LAMMPS (one core each)");
}

}  // namespace

// The Bullet DEM against LAMMPS on verify-dem's heap and on the default
// scene at a small scale, friction 0.1 / 0.4 / 0.9 at the default rolling
// resistance: heap angles and scene slopes side by side, and each engine's
// outlines against the other's over its own seed-to-seed floor.
VerifyCase engine_piles(const VerifyOptions& opt) {
  const Plan p = plan(opt);
  VerifyCase c{"engine-piles", "Bullet against LAMMPS on piles",
               "the heap poured from a point (" + std::to_string(p.heap.window.width * p.heap.region.height) +
                   " grains, two sizes) and the default scene at --scale " + fmt("%.2f", p.scene_scale) +
                   ", friction 0.1 / 0.4 / 0.9 at the default rolling resistance, " + std::to_string(p.seeds.size()) +
                   " physics seeds per engine, each engine pouring the grains its own way: Bullet's mean heap angle "
                   "and mean scene slope, all-dynamic (and three-layer if --layers lists it), within max(2°, 2 seed spreads) of LAMMPS's, "
                   "and the silhouette error between the engines (every seed against every seed) at most twice the "
                   "larger engine's seed-to-seed floor"};
  if (lammps_missing(c)) return c;
  compare_engines(c, {"heap", "heap angle", p.heap, heap_angle}, p, opt);
  compare_engines(c, {"default scene", "scene slope", small_default_scene(p), slope}, p, opt);
  return c;
}

}  // namespace sandpic::verify
