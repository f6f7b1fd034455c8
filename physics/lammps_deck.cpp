// The LAMMPS deck: one input file with the grains created in batches as the
// release schedule brings them (paper §7), then a run until the pile is still.
#include "physics/lammps_deck.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>

#include "physics/dem_params.h"
#include "src/errors.h"
#include "src/release.h"
#include "src/water.h"

namespace sandpic {

namespace {

constexpr double kPi = std::numbers::pi;
// The contact's softness: its resting overlap under the estimated load, in
// small-grain diameters (the cross-check asks at most 0.01; the estimate of
// the load is rough, so half of it).
constexpr double kTargetOverlap = 0.005;
// Steps per period of the stiffest contact's oscillation (velocity Verlet is
// stable to about 10; 40 keeps the restitution within a few percent).
constexpr double kStepsPerPeriod = 40;
// Force chains carry several times a column's weight (3: a common bound).
constexpr double kChainFactor = 3;
// Poisson's ratio for Mindlin's tangential stiffness (quartz: 0.17-0.3).
constexpr double kPoisson = 0.3;
// Grains are created in batches this far apart (simulated s): each batch is
// a LAMMPS `run`, whose set-up costs a pass over the atoms.
constexpr double kBatchS = 0.002;
// The pile is settled when no grain moves faster than this many small-grain
// diameters a second (the Bullet backend waits until its grains hold,
// physics/holds.h: 0.05 diameters in 1 s).
constexpr double kSettleDiametersPerS = 0.5;
// A grain is created at least this many small radii clear of where the
// grains already falling would be if they fell straight: in a dense stream
// they knock each other aside (0.1 let a grain be created inside another
// deflected one: the default scene at --scale 0.1, friction 0.4, seed 3
// blew up).
constexpr double kClearance = 0.5;
// A grain kept waiting by the grains in its way is created at most this
// many large-grain radii under the lid.
constexpr double kLowestCreation = 8;
// And the run stops this long after the last grain is due at the floor.
constexpr double kSettleLimitS = 10;

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

std::array<double, kClasses> masses(const Scene& s, const std::array<double, kClasses>& r) {
  std::array<double, kClasses> m{};
  for (int k = 0; k < kClasses; ++k) m[k] = s.grains.density_g_cm3[k] * 4.0 / 3.0 * kPi * std::pow(r[k], 3);
  return m;
}

// A grain's flight from the lid: at its settling speed in water, or falling
// freely from rest without it.
struct Flight {
  double v0 = 0, g = 0;  // start speed (px/s, down) and acceleration while in flight
  double drop(double t) const { return v0 * t + 0.5 * g * t * t; }
  double speed(double t) const { return v0 + g * t; }
  double time_to(double d) const { return g > 0 ? (std::sqrt(v0 * v0 + 2 * g * d) - v0) / g : d / v0; }
};

std::string model_text(const LammpsContact& c) {
  return "hertz " + num(c.kn) + " " + num(c.restitution) + " tangential mindlin " + num(c.kt) + " 1.0 " +
         num(c.friction) + " rolling sds " + num(c.kr) + " " + num(c.gamma_r) + " " + num(c.rolling) + " damping tsuji";
}

// Everything before the grains: the window, the contact model, gravity and
// the water per class, the walls, the thermo line the progress bar reads.
std::string preamble(const Scene& s, const LammpsContact& c, int64_t grains, int thermo_steps) {
  const double W = s.window.width, H = s.window.height;
  const Water w = water_model(s);
  const auto r = dem_radii(s);
  const auto m = masses(s, r);
  const double r_big = *std::max_element(r.begin(), r.end());
  std::string o;
  auto line = [&](const std::string& l) { o += l, o += '\n'; };
  const std::string model_args = model_text(c);
  line("# sandpic's LAMMPS deck (--mode lammps): " + std::to_string(grains) + " grains, window " + num(W) + " x " +
       num(H) + " px");
  line("# units: px, s, mass in g/cm^3 px^3 (units lj, read as such); y up, the floor at y = 0");
  line("units lj");
  line("dimension 2  # the picture's plane: spheres (I = 2/5 m r^2) kept in it by enforce2d, as Bullet's grains");
  line("atom_style sphere");
  line("atom_modify map array");
  line("boundary f f p");
  line("newton off");
  line("comm_modify vel yes");
  line("region window block 0 " + num(W) + " 0 " + num(H) + " -0.5 0.5");
  line("create_box 4 window");
  line("pair_style granular");
  line("pair_coeff * * " + model_args);
  line("neighbor " + num(0.5 * r_big) + " bin");
  line("neigh_modify delay 0 every 1 check yes");
  line("timestep " + num(c.dt));
  line("fix move all nve/sphere");
  line("fix plane all enforce2d");
  for (int k = 0; k < kClasses; ++k) {
    line("group S" + std::to_string(k + 1) + " type " + std::to_string(k + 1));
    line("fix gravity" + std::to_string(k + 1) + " S" + std::to_string(k + 1) + " gravity " +
         num(w.gravity_px_s2[k]) + " vector 0 -1 0  # buoyancy included");
  }
  if (s.dem.water) {
    // Linear drag F = -k·m·v with k the class's rate (src/water.h): the
    // settling speed of Schiller-Naumann's drag.
    std::string scale;
    for (int k = 0; k < kClasses; ++k) scale += " scale " + std::to_string(k + 1) + " " + num(w.drag_per_s[k] * m[k]);
    line("fix water all viscous 1.0" + scale);
  }
  line("fix sides all wall/gran granular " + model_args + " xplane 0 " + num(W));
  line("fix floor all wall/gran granular " + model_args + " yplane 0 " + num(H) + "  # and the lid");
  line("variable speed atom sqrt(vx*vx+vy*vy)");
  line("compute vmax all reduce max v_speed");
  line("variable vmax equal c_vmax");
  line("thermo_style custom step time atoms c_vmax");
  line("thermo_modify flush yes norm no lost error");
  line("thermo " + std::to_string(thermo_steps));
  return o;
}

// The settle: until no grain is faster than `speed`, at most `steps` steps;
// then the final positions.
std::string settle_text(double speed, int thermo_steps, int64_t steps) {
  return "# settle: until no grain is faster than " + num(speed) + " px/s, or " + std::to_string(steps) +
         " steps\nfix settled all halt " + std::to_string(thermo_steps) + " v_vmax < " + num(speed) +
         " error continue\nrun " + std::to_string(steps) +
         " post no\nwrite_dump all custom final.dump id type x y vx vy modify sort id format float %.9g\n";
}

}  // namespace

LammpsContact lammps_contact(const Scene& s, const GrainSet& grains, double column_weight, double stiffness) {
  const Water w = water_model(s);
  const auto r = dem_radii(s);
  const auto m = masses(s, r);
  const auto counts = grains.per_class();
  double weight = 0, dsum = 0, n = 0, single = 0, r_small = INFINITY;
  for (int k = 0; k < kClasses; ++k) {
    if (counts[k] == 0 && grains.size() > 0) continue;
    weight += double(counts[k]) * m[k] * w.gravity_px_s2[k];
    dsum += double(counts[k]) * 2 * r[k], n += double(counts[k]);
    single = std::max(single, m[k] * w.gravity_px_s2[k]);
    r_small = std::min(r_small, r[k]);
  }
  const double mean_d = n > 0 ? dsum / n : 2 * r_small;
  LammpsContact c;
  c.friction = s.physics.friction;
  c.restitution = s.physics.restitution;
  c.rolling = s.dem.rolling_resistance;
  // The deepest resting contact: the weight of a column one mean diameter
  // wide, times the force chains, between two small grains (the smallest R).
  c.load = kChainFactor * std::max(single, column_weight > 0 ? column_weight : weight * mean_d / s.window.width);
  const double R = r_small / 2;
  c.kn = stiffness * c.load / (std::sqrt(R) * std::pow(kTargetOverlap * 2 * r_small, 1.5));
  // The overlap the design load makes at that stiffness (the target, unless
  // --lammps-stiffness scales it).
  c.target_overlap_px = std::pow(c.load / (c.kn * std::sqrt(R)), 2.0 / 3.0);
  const double delta = c.target_overlap_px;
  // A grain landing on the floor at its settling speed overlaps more, for
  // a moment: ½mv² = (2/5)·k_n·√r·δ^2.5 (reported, not bounded: bounding it
  // too took a 20x shorter step at the default scene).
  for (int k = 0; k < kClasses; ++k) {
    if (counts[k] == 0 && grains.size() > 0) continue;
    const double v = w.terminal_px_s[k];
    c.landing_overlap_px = std::max(c.landing_overlap_px, std::pow(1.25 * m[k] * v * v / (c.kn * std::sqrt(r[k])), 0.4));
  }
  const double k_lin = 1.5 * c.kn * std::sqrt(R * delta);  // dF/dδ at the target overlap
  // The lightest pair's period at that stiffness sets the step.
  double m_small = INFINITY;
  for (int k = 0; k < kClasses; ++k)
    if (counts[k] > 0 || grains.size() == 0) m_small = std::min(m_small, m[k]);
  c.dt = 2 * kPi * std::sqrt(m_small / 2 / k_lin) / kStepsPerPeriod;
  c.kt = 2 * (1 - kPoisson) / (2 - kPoisson) * 1.5 * c.kn;  // Mindlin: k_t·a against the normal 1.5·k_n·a
  // The rolling spring as stiff as the normal contact, critically damped for
  // the lightest pair's rolling inertia (I/R² = 0.4 m): it yields elastically
  // by less than the target overlap before it slides at μ_r·F_n·R.
  c.kr = k_lin;
  c.gamma_r = 2 * std::sqrt(c.kr * 0.4 * m_small / 2);
  return c;
}

LammpsDeck lammps_deck(const SimInput& in, double stiffness) {
  const Scene& s = in.scene;
  const double W = s.window.width, H = s.window.height;
  const Water w = water_model(s);
  const auto r = dem_radii(s);
  for (uint8_t k : in.grains.cls)
    if (!(w.gravity_px_s2[k] > 0))
      throw key_error("grains.density_g_cm3[" + std::to_string(k) + "]",
                      "S" + std::to_string(k + 1) + "'s grains are not denser than the water: they would not sink");
  LammpsDeck d;
  d.contact = lammps_contact(s, in.grains, 0, stiffness);
  const LammpsContact& c = d.contact;
  const double r_small = *std::min_element(r.begin(), r.end()), r_big = *std::max_element(r.begin(), r.end());
  d.settle_speed_px_s = kSettleDiametersPerS * 2 * r_small;
  const int64_t batch_steps = std::max<int64_t>(1, std::llround(kBatchS / c.dt));
  d.thermo_steps = int(std::max<int64_t>(1, std::llround(0.01 / c.dt)));

  // The schedule: when each grain would pass the lid (Eq. 1-2 to the outlet,
  // then its flight), in falling order.
  const ReleaseModel model = release_model(s);
  std::array<Flight, kClasses> flight;
  for (int k = 0; k < kClasses; ++k)
    flight[k] = s.dem.water ? Flight{w.terminal_px_s[k], 0} : Flight{0, w.gravity_px_s2[k]};
  struct Due {
    double t;  // when it passes y_top
    double x;
    int64_t order;
  };
  std::vector<Due> due;
  due.reserve(in.order.grain.size());
  for (size_t u = 0; u < in.seg.units.size(); ++u) {
    const Outlet o = outlet(model, in.seg.units[u]);
    for (int64_t i = in.order.unit_begin[u]; i < in.order.unit_begin[u + 1]; ++i) {
      const int32_t id = in.order.grain[size_t(i)];
      const int k = in.grains.cls[size_t(id)];
      const ReleasePath p = release(model, o, in.grains, id);
      const double top = H - r[k], outlet_up = H - o.centre.y();
      // Falling from the lid it reaches the outlet's height at t_release + p.t.
      const double t_out = double(i) / s.dem.release_rate + p.t;
      due.push_back({t_out - flight[k].time_to(std::max(0.0, top - outlet_up)), std::clamp(p.exit_x, r[k], W - r[k]), i});
    }
  }
  std::stable_sort(due.begin(), due.end(), [](const Due& a, const Due& b) { return a.t < b.t; });
  const double t0 = due.empty() ? 0 : std::min(0.0, due.front().t);  // the schedule starts at 0

  std::string o = preamble(s, c, int64_t(due.size()), d.thermo_steps);
  o.reserve(due.size() * 120 + 4096);
  auto line = [&](const std::string& l) { o += l, o += '\n'; };

  // In-flight grains where a creation could meet them: column bins.
  struct Aloft {
    double x, y, t;  // created at (x, y) at t
    int k;
  };
  const double bin_w = 2 * r_big;
  std::vector<std::vector<Aloft>> bins(size_t(std::ceil(W / bin_w)) + 1);
  auto bin_of = [&](double x) { return std::clamp(size_t(x / bin_w), size_t(0), bins.size() - 1); };
  // Free: no grain of the stream where this one would be created, and none
  // it would meet (a fast grain catching a slow one) before it leaves the
  // creation zone: a meeting knocks both aside, away from where the next
  // creations are checked against (a grain created inside a knocked-aside
  // one blew a run up). Straight falls: the gap changes linearly.
  const double zone_bottom = H - kLowestCreation * r_big - 4 * r_big;
  auto free_at = [&](double x, double y, int k, double t, double v) {
    const double leave = v > 0 ? std::max(0.0, y - zone_bottom) / v : 0;
    for (size_t b = bin_of(x) - std::min<size_t>(bin_of(x), 1); b <= std::min(bins.size() - 1, bin_of(x) + 1); ++b) {
      auto& in_bin = bins[b];
      // Grains fallen below the creation zone cannot be in the way.
      std::erase_if(in_bin, [&](const Aloft& a) { return a.y - flight[a.k].drop(t - a.t) < zone_bottom; });
      for (const Aloft& a : in_bin) {
        const double reach = r[a.k] + r[k] + kClearance * r_small, dx = a.x - x;
        if (std::abs(dx) >= reach) continue;
        const double dy0 = a.y - flight[a.k].drop(t - a.t) - y;
        const double dy1 = dy0 + (v - flight[a.k].speed(t - a.t)) * leave;  // a's height over it as it leaves
        const double closest = dy0 * dy1 <= 0 ? 0 : std::min(std::abs(dy0), std::abs(dy1));
        if (dx * dx + closest * closest < reach * reach) return false;
      }
    }
    return true;
  };

  size_t next = 0;
  int64_t steps = 0, atom = 0;
  std::vector<Due> waiting;
  d.grain_of_atom.reserve(due.size());
  while (next < due.size() || !waiting.empty()) {
    const double t = double(steps) * c.dt;  // this batch's time
    while (next < due.size() && due[next].t - t0 <= t) waiting.push_back(due[next++]);
    std::vector<Due> later;
    bool created = false;
    for (const Due& g : waiting) {
      const int32_t id = in.order.grain[size_t(g.order)];
      const int k = in.grains.cls[size_t(id)];
      // Created where it would be now, in the stream from its outlet; one
      // kept waiting (an outlet releases faster than a stream of its width
      // carries grains away) waits no lower than kLowestCreation large
      // radii under the lid, and arrives late, as the Bullet backend's
      // delayed insertions do.
      const double late = std::min(t - (g.t - t0), flight[k].time_to(kLowestCreation * r_big));
      const double y = H - r[k] - flight[k].drop(late);
      if (!free_at(g.x, y, k, t, flight[k].speed(late))) {
        later.push_back(g);
        ++d.delayed;
        continue;
      }
      bins[bin_of(g.x)].push_back({g.x, y, t, k});
      const double lateness = t - (g.t - t0) - late;  // behind the schedule at its height
      d.late_mean_s += lateness;
      d.late_max_s = std::max(d.late_max_s, lateness);
      ++atom;
      d.grain_of_atom.push_back(id);
      line("create_atoms " + std::to_string(k + 1) + " single " + num(g.x) + " " + num(y) + " 0 units box");
      line("set atom " + std::to_string(atom) + " diameter " + num(2 * r[k]) + " density " +
           num(s.grains.density_g_cm3[k]) + " vy " + num(-flight[k].speed(late)));
      created = true;
    }
    waiting.swap(later);
    if (created)
      for (int k = 0; k < kClasses; ++k)
        line("group S" + std::to_string(k + 1) + " type " + std::to_string(k + 1));  // adds the new grains
    if (next < due.size() || !waiting.empty()) {
      // Up to the next batch (or straight to the next grain due).
      int64_t n = batch_steps;
      if (waiting.empty() && next < due.size())
        n = std::max(n, int64_t(std::ceil((due[next].t - t0 - t) / c.dt / double(batch_steps))) * batch_steps);
      line("run " + std::to_string(n) + " post no");
      steps += n;
    }
  }
  if (!d.grain_of_atom.empty()) d.late_mean_s /= double(d.grain_of_atom.size());
  d.release_steps = steps;
  d.release_end_s = double(steps) * c.dt;
  // The last grains still have the window's height to fall.
  const auto counts = in.grains.per_class();
  double slowest = 0;
  for (int k = 0; k < kClasses; ++k)
    if (counts[k] > 0) slowest = std::max(slowest, flight[k].time_to(H));
  d.settle_limit_s = d.release_end_s + slowest + kSettleLimitS;
  const int64_t settle_steps = std::llround((d.settle_limit_s - d.release_end_s) / c.dt);
  d.max_steps = d.release_steps + settle_steps;
  d.expected_steps = std::min<int64_t>(d.max_steps, d.release_steps + std::llround((slowest + 0.5) / c.dt));
  o += settle_text(d.settle_speed_px_s, d.thermo_steps, settle_steps);
  d.input = std::move(o);
  return d;
}

LammpsDeck lammps_placed_deck(const Scene& s, const std::vector<PlacedGrain>& grains, double max_s) {
  GrainSet g;
  g.width = int(grains.size()), g.height = 1;
  for (const PlacedGrain& p : grains) g.cls.push_back(uint8_t(p.cls));
  const auto r = dem_radii(s);
  // The heaviest column one mean diameter wide carries the deepest contact.
  const Water w = water_model(s);
  const auto m = masses(s, r);
  double dsum = 0;
  for (const PlacedGrain& p : grains) dsum += 2 * r[p.cls];
  const double mean_d = grains.empty() ? 1 : dsum / double(grains.size());
  std::map<int64_t, double> column;
  for (const PlacedGrain& p : grains) column[int64_t(std::floor(p.p.x() / mean_d))] += m[p.cls] * w.gravity_px_s2[p.cls];
  double heaviest = 0;
  for (const auto& [x, weight] : column) heaviest = std::max(heaviest, weight);
  LammpsDeck d;
  d.contact = lammps_contact(s, g, heaviest);
  d.settle_speed_px_s = kSettleDiametersPerS * 2 * *std::min_element(r.begin(), r.end());
  d.thermo_steps = int(std::max<int64_t>(1, std::llround(0.01 / d.contact.dt)));
  std::string o = preamble(s, d.contact, int64_t(grains.size()), d.thermo_steps);
  for (size_t i = 0; i < grains.size(); ++i) {
    const PlacedGrain& p = grains[i];
    o += "create_atoms " + std::to_string(p.cls + 1) + " single " + num(p.p.x()) + " " + num(p.p.y()) + " 0 units box\n";
    o += "set atom " + std::to_string(i + 1) + " diameter " + num(2 * r[p.cls]) + " density " +
         num(s.grains.density_g_cm3[p.cls]) + "\n";
    d.grain_of_atom.push_back(int32_t(i));
  }
  for (int k = 0; k < kClasses; ++k) o += "group S" + std::to_string(k + 1) + " type " + std::to_string(k + 1) + "\n";
  // A first 0.05 s unchecked: everything starts at rest.
  const int64_t start = std::llround(0.05 / d.contact.dt);
  o += "run " + std::to_string(start) + " post no\n";
  d.max_steps = std::max<int64_t>(start + 1, std::llround(max_s / d.contact.dt));
  d.expected_steps = d.max_steps;
  d.settle_limit_s = max_s;
  o += settle_text(d.settle_speed_px_s, d.thermo_steps, d.max_steps - start);
  d.input = std::move(o);
  return d;
}

}  // namespace sandpic
