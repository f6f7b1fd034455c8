// verify-dem's engine cross-check: the Bullet DEM (physics/probe.h, every
// grain a body: all-dynamic) and LAMMPS's granular DEM (physics/lammps_deck.h)
// from one placed configuration, a column of grains collapsing in the water
// against the left wall. Both engines start from the same positions, so what
// differs is the contact physics alone (the pipeline's runs also differ in
// how grains reach the pile: docs/lammps.md).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <numbers>

#include <opencv2/imgproc.hpp>
#include <tbb/parallel_for.h>

#include "physics/dem_params.h"
#include "physics/lammps_deck.h"
#include "physics/lammps_simulator.h"
#include "physics/probe.h"
#include "src/rng.h"
#include "validate/dem/cases.h"
#include "validate/metrics/statistics.h"

namespace sandpic::verify {
namespace {

namespace fs = std::filesystem;

// The column: nx × ny sites 1.05 large diameters apart, each a large (S1)
// or small (S3) grain by the seed, jittered by a tenth of a small diameter.
std::vector<PlacedGrain> column(const Scene& s, int nx, int ny, uint64_t seed) {
  const auto r = dem_radii(s);
  const double pitch = 2.1 * r[0];
  std::vector<PlacedGrain> g;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const uint64_t id = uint64_t(j) * uint64_t(nx) + uint64_t(i);
      const int k = uniform(seed, Stream::OutletJitter, id, 0) < 0.5 ? 0 : 2;
      const double jitter = (uniform(seed, Stream::OutletJitter, id, 1) - 0.5) * 0.2 * r[2];
      g.push_back({k, Vec2(r[0] + 0.01 * r[0] + i * pitch + jitter, r[0] * 1.01 + j * pitch)});
    }
  return g;
}

struct Settled {
  std::vector<Vec2> p;  // y up
  double seconds = 0, simulated_s = 0, deepest_overlap = 0;
  bool settled = false;
};

double deepest_overlap(const std::vector<PlacedGrain>& g, const std::vector<Vec2>& p, const std::array<double, kClasses>& r) {
  double deepest = 0;
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j)
      deepest = std::max(deepest, r[g[i].cls] + r[g[j].cls] - (p[i] - p[j]).norm());
  return deepest;
}

// Bullet: every grain a body, stepped until none is faster than LAMMPS's
// settle speed (checked every 0.01 s) or max_s.
Settled run_bullet(const Scene& s, const std::vector<PlacedGrain>& g, double settle_speed, double max_s) {
  GrainProbe probe(s);
  std::vector<int> slot;
  for (const PlacedGrain& x : g) slot.push_back(probe.add(x.cls, x.p));
  const int every = std::max(1, int(std::lround(0.01 / probe.dt())));
  Settled out;
  int64_t n = 0;
  while (n * probe.dt() < max_s) {
    for (int i = 0; i < every; ++i, ++n) probe.step();
    double fastest = 0;
    for (int sl : slot) fastest = std::max(fastest, probe.velocity(sl).norm());
    if (n * probe.dt() > 0.05 && fastest < settle_speed) {
      out.settled = true;
      break;
    }
  }
  out.simulated_s = n * probe.dt();
  for (int sl : slot) out.p.push_back(probe.position(sl));
  return out;
}

Settled run_lammps_column(const Scene& s, const std::vector<PlacedGrain>& g, double max_s) {
  const LammpsDeck deck = lammps_placed_deck(s, g, max_s);
  std::string dir = (fs::temp_directory_path() / "sandpic-engines-XXXXXX").string();
  if (!mkdtemp(dir.data())) throw SimulationError("engines: cannot make a temporary folder");
  struct Remove {
    std::string d;
    ~Remove() {
      std::error_code ec;
      fs::remove_all(d, ec);
    }
  } remove{dir};
  Progress quiet(false);
  const LammpsRun run = run_lammps(deck.input, dir, LammpsOptions{}, quiet, deck.max_steps);
  const std::vector<DumpAtom> atoms = read_lammps_dump(dir + "/final.dump", g.size());
  Settled out;
  double fastest = 0;
  for (const DumpAtom& a : atoms) out.p.emplace_back(a.x, a.y), fastest = std::max(fastest, std::hypot(a.vx, a.vy));
  out.settled = fastest < deck.settle_speed_px_s;
  out.simulated_s = double(run.steps) * deck.contact.dt;
  return out;
}

// The outline (top of the grains, sampled every small radius from the wall)
// and its measures: how far the toe ran out, and the slope angle fitted
// where the outline is between 20% and 80% of its highest.
struct Outline {
  double runout = 0, angle = NAN, height = 0;
  std::vector<double> x, h;
};
Outline outline(const std::vector<PlacedGrain>& g, const std::vector<Vec2>& p, const std::array<double, kClasses>& r) {
  Outline o;
  for (size_t i = 0; i < p.size(); ++i) o.runout = std::max(o.runout, p[i].x() + r[g[i].cls]);
  const double dx = r[2];
  for (double x = 0; x <= o.runout; x += dx) {
    double top = 0;
    for (size_t i = 0; i < p.size(); ++i) {
      const double rk = r[g[i].cls], d = std::abs(p[i].x() - x);
      if (d < rk) top = std::max(top, p[i].y() + std::sqrt(rk * rk - d * d));
    }
    o.x.push_back(x), o.h.push_back(top);
  }
  o.height = o.h.empty() ? 0 : *std::max_element(o.h.begin(), o.h.end());
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (size_t i = 0; i < o.x.size(); ++i)
    if (o.h[i] > 0.2 * o.height && o.h[i] < 0.8 * o.height)
      sx += o.x[i], sy += o.h[i], sxx += o.x[i] * o.x[i], sxy += o.x[i] * o.h[i], ++n;
  if (n >= 3) o.angle = std::atan(std::abs((n * sxy - sx * sy) / (n * sxx - sx * sx))) * 180 / std::numbers::pi;
  return o;
}

cv::Mat draw(const std::vector<PlacedGrain>& g, const std::vector<Vec2>& p, const std::array<double, kClasses>& r,
             int width, int height) {
  cv::Mat img(height, width, CV_8UC3, cv::Scalar(240, 246, 248));
  for (size_t i = 0; i < p.size(); ++i)
    cv::circle(img, cv::Point2d(p[i].x(), height - p[i].y()), int(std::lround(r[g[i].cls])),
               g[i].cls == 0 ? cv::Scalar(40, 80, 160) : cv::Scalar(90, 40, 30), cv::FILLED, cv::LINE_AA);
  return img;
}

}  // namespace

bool lammps_missing(VerifyCase& c) {
  if (!find_lmp(LammpsOptions{}).empty()) return false;
  c.notes.push_back("LAMMPS's lmp is not installed (scripts/setup.sh installs it): nothing to compare with");
  c.checks.push_back(at_most("lmp installed (1: missing)", 1, 0, ""));
  return true;
}

VerifyCase engines(const VerifyOptions& opt) {
  const bool quick = opt.quick;
  const int nx = quick ? 10 : 24, ny = quick ? 8 : 16;
  const std::vector<double> friction = quick ? std::vector<double>{0.4} : std::vector<double>{0.1, 0.4, 0.9};
  const std::vector<uint64_t> seeds = quick ? std::vector<uint64_t>{1, 2} : std::vector<uint64_t>{1, 2, 3};
  const double max_s = 4;
  VerifyCase c{"engines", "Bullet against LAMMPS",
               "a column of " + std::to_string(nx * ny) + " grains (two sizes) collapsing in the water against the left "
               "wall, from the same positions in both engines (Bullet: every grain a body; LAMMPS: soft Hertz "
               "contacts, docs/lammps.md): the runout and the height left at the wall within max(2 large diameters, 2 "
               "seed spreads) of each other, the outline between the engines (mean |Δh| over the deposit) at most "
               "twice the larger engine's seed-to-seed floor; LAMMPS's deepest overlap at most 1% of a small "
               "diameter"};
  if (lammps_missing(c)) return c;
  Scene s;
  s.window = {1000, 300};
  const auto r = dem_radii(s);
  const double settle_speed = 0.5 * 2 * r[2];
  struct Run {
    double mu;
    uint64_t seed;
    bool lammps;
    std::vector<PlacedGrain> g;
    Settled out;
  };
  std::vector<Run> runs;
  for (double mu : friction)
    for (uint64_t seed : seeds)
      for (bool lammps : {false, true}) runs.push_back({mu, seed, lammps, column(s, nx, ny, seed), {}});
  std::atomic<int> done{0};
  tbb::parallel_for(size_t(0), runs.size(), [&](size_t i) {
    Run& run = runs[i];
    Scene si = s;
    si.physics.friction = run.mu;
    const auto t0 = std::chrono::steady_clock::now();
    run.out = run.lammps ? run_lammps_column(si, run.g, max_s) : run_bullet(si, run.g, settle_speed, max_s);
    run.out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.out.deepest_overlap = deepest_overlap(run.g, run.out.p, r);
    opt.log("engines: " + std::to_string(++done) + "/" + std::to_string(runs.size()) + " runs");
  });
  VerifyPlot plot{"Outline after the collapse, seed " + std::to_string(seeds.front()), "x (px)", "height (px)", {}};
  double bullet_s = 0, lammps_s = 0, deepest = 0;
  for (double mu : friction) {
    std::vector<double> angle[2], runout[2], height[2];
    std::vector<Outline> outlines[2];
    for (const Run& run : runs) {
      if (run.mu != mu) continue;
      const Outline o = outline(run.g, run.out.p, r);
      angle[run.lammps].push_back(o.angle), runout[run.lammps].push_back(o.runout);
      height[run.lammps].push_back(o.h.empty() ? 0 : o.h.front());
      outlines[run.lammps].push_back(o);
      (run.lammps ? lammps_s : bullet_s) += run.out.seconds;
      if (run.lammps) deepest = std::max(deepest, run.out.deepest_overlap);
      if (!run.out.settled)
        c.notes.push_back(std::string(run.lammps ? "LAMMPS" : "Bullet") + " at friction " + fmt("%.1f", mu) + ", seed " +
                          std::to_string(run.seed) + " had not settled after " + fmt("%.1f", run.out.simulated_s) + " s");
      if (run.seed == seeds.front()) {
        plot.series.push_back({std::string(run.lammps ? "LAMMPS" : "Bullet") + ", friction " + fmt("%.1f", mu), o.x, o.h, false});
        if (mu == friction[friction.size() / 2])
          c.pictures.emplace_back(std::string(run.lammps ? "LAMMPS" : "Bullet") + ", friction " + fmt("%.1f", mu) +
                                      ", seed " + std::to_string(run.seed),
                                  draw(run.g, run.out.p, r, int(std::min(1000.0, 1.3 * o.runout + 20)), 300));
      }
    }
    const std::string m = "friction " + fmt("%.1f", mu);
    const double spread_r = std::max(spread(runout[0]), spread(runout[1]));
    c.checks.push_back(within(m + ": LAMMPS runout (mean " + fmt("%.1f", mean(runout[1])) + " px) against Bullet's",
                              mean(runout[1]), mean(runout[0]), std::max(4 * r[0], 2 * spread_r), "px"));
    const double spread_h = std::max(spread(height[0]), spread(height[1]));
    c.checks.push_back(within(m + ": LAMMPS height at the wall (mean " + fmt("%.1f", mean(height[1])) + " px) against Bullet's",
                              mean(height[1]), mean(height[0]), std::max(4 * r[0], 2 * spread_h), "px"));
    // Outlines: between every pair of runs, within and across the engines.
    auto apart = [](const Outline& a, const Outline& b) {
      double sum = 0;
      const size_t n = std::max(a.h.size(), b.h.size());
      for (size_t i = 0; i < n; ++i) sum += std::abs((i < a.h.size() ? a.h[i] : 0) - (i < b.h.size() ? b.h[i] : 0));
      return n ? sum / double(n) : 0.0;
    };
    double floor[2] = {0, 0}, across = 0;
    for (int e = 0; e < 2; ++e) {
      std::vector<double> d;
      for (size_t i = 0; i < outlines[e].size(); ++i)
        for (size_t j = i + 1; j < outlines[e].size(); ++j) d.push_back(apart(outlines[e][i], outlines[e][j]));
      floor[e] = mean(d);
    }
    std::vector<double> d;
    for (const Outline& a : outlines[0])
      for (const Outline& b : outlines[1]) d.push_back(apart(a, b));
    across = mean(d);
    c.checks.push_back(at_most(m + ": outline Bullet against LAMMPS (mean |Δh| " + fmt("%.2f", across) +
                                   " px) over the larger seed-to-seed floor (Bullet " + fmt("%.2f", floor[0]) +
                                   ", LAMMPS " + fmt("%.2f", floor[1]) + " px)",
                               across / std::max(floor[0], floor[1]), 2, "x"));
    c.notes.push_back(m + ": slope angle (20-80% of the height) Bullet " + fmt("%.1f", mean(angle[0])) + "° ± " +
                      fmt("%.1f", spread(angle[0])) + ", LAMMPS " + fmt("%.1f", mean(angle[1])) + "° ± " +
                      fmt("%.1f", spread(angle[1])));
  }
  c.checks.push_back(at_most("LAMMPS: deepest overlap at rest, small diameters", deepest / (2 * r[2]), 0.01, ""));
  c.plots.push_back(std::move(plot));
  c.notes.push_back(std::to_string(runs.size()) + " runs: Bullet " + fmt("%.0f", bullet_s) + " s, LAMMPS " +
                    fmt("%.0f", lammps_s) + " s in all (one core each)");
  return c;
}

}  // namespace sandpic::verify
