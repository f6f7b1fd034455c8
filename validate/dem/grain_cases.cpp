// verify-dem's single-grain cases: one or three grains in the DEM's own
// world, contact rules and water stage (physics/probe.h), against answers
// worked out here from the physics, not from the DEM's code.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/holds.h"
#include "physics/probe.h"
#include "src/errors.h"
#include "validate/dem/cases.h"

namespace sandpic::verify {
namespace {

constexpr double kDeg = std::numbers::pi / 180;


// A window wide and tall enough for one grain's run.
Scene probe_scene(bool water) {
  Scene s;
  s.window = {1000, 300};
  s.dem.water = water;
  return s;
}

// The classes to test: one of each distinct (diameter, density).
std::vector<int> distinct_classes(const Scene& s) {
  std::vector<int> out;
  for (int k = 0; k < kClasses; ++k) {
    bool seen = false;
    for (int j : out)
      seen = seen || (s.grains.diameter_mm[j] == s.grains.diameter_mm[k] && s.grains.density_g_cm3[j] == s.grains.density_g_cm3[k]);
    if (!seen) out.push_back(k);
  }
  return out;
}

std::string cls_name(int k) { return "S" + std::to_string(k + 1); }

// The settling speed of a sphere in water under Schiller–Naumann drag,
// 3πμdv(1 + 0.15 Re^0.687) = (ρ − ρ_w) g π d³/6, solved here by bisection
// (the water model solves it by a damped fixed point).
double settling_speed_bisect(double d, double rho, double rho_w, double mu, double g) {
  const double weight = (rho - rho_w) * g * std::numbers::pi * d * d * d / 6;
  auto excess = [&](double v) { return 3 * std::numbers::pi * mu * d * v * (1 + 0.15 * std::pow(rho_w * v * d / mu, 0.687)) - weight; };
  double lo = 0, hi = 10;
  for (int i = 0; i < 200; ++i) (excess((lo + hi) / 2) > 0 ? hi : lo) = (lo + hi) / 2;
  return (lo + hi) / 2;
}

}  // namespace

// paper §7 in the device's water: a grain released from rest reaches its
// settling speed as v(t) = v_t (1 − e^(−t g'/v_t)), g' = g (1 − ρ_w/ρ).
VerifyCase settling(const VerifyOptions&) {
  VerifyCase c{"settling", "Settling in water",
               "closed form of the water model's linear drag, v(t) = v_t (1 − exp(−g' t / v_t)), with v_t from "
               "Schiller–Naumann drag solved by bisection; 2% of v_t"};
  const Scene s = probe_scene(true);
  const double px_per_m = 1000 * px_per_mm(s);
  VerifyPlot plot{"Speed of a grain released from rest", "t (ms)", "downward speed (px/s)", {}};
  for (int k : distinct_classes(s)) {
    GrainProbe p(s);
    const double d = s.grains.diameter_mm[k] / 1000, rho = s.grains.density_g_cm3[k] * 1000;
    const double rho_w = s.dem.water_density_g_cm3 * 1000, g = s.release.gravity_m_s2;
    const double vt = settling_speed_bisect(d, rho, rho_w, s.dem.water_viscosity_pa_s, g) * px_per_m;
    const double tau = vt / (g * (1 - rho_w / rho) * px_per_m);
    const int slot = p.add(k, Vec2(500, 250));
    PlotSeries sim{cls_name(k) + " DEM", {}, {}, true}, exact{cls_name(k) + " closed form", {}, {}, false};
    double worst = 0;
    const int n = int(std::ceil(8 * tau / p.dt()));
    for (int i = 1; i <= n; ++i) {
      p.step();
      const double t = i * p.dt(), v = -p.velocity(slot).y(), ve = vt * (1 - std::exp(-t / tau));
      worst = std::max(worst, std::abs(v - ve) / vt);
      if (i % std::max(1, n / 40) == 0) {
        sim.x.push_back(1000 * t), sim.y.push_back(v);
        exact.x.push_back(1000 * t), exact.y.push_back(ve);
      }
    }
    c.checks.push_back(within(cls_name(k) + ": largest |v − v(t)| over 8 time constants / v_t", worst, 0, 0.02, ""));
    c.checks.push_back(within(cls_name(k) + ": speed after 8 time constants", -p.velocity(slot).y(), vt, 0.02 * vt, "px/s"));
    plot.series.push_back(std::move(sim));
    plot.series.push_back(std::move(exact));
  }
  c.plots.push_back(std::move(plot));
  return c;
}

// A grain dropped on the floor without water rebounds to e² of its height;
// at e = 1 it gains no energy over 100 bounces.
VerifyCase restitution(const VerifyOptions&) {
  VerifyCase c{"restitution", "Restitution",
               "rebound height h1 = e² h0 (energy after the bounce over energy before), 5% of e² h0; at e = 1 no "
               "bounce ends higher than the drop"};
  const double h0 = 100;  // px, the grain's bottom above the floor
  VerifyPlot plot{"Height of a grain bouncing on the floor (e = 0.5)", "t (ms)", "bottom above the floor (px)", {}};
  for (double e : {0.1, 0.5, 0.9, 1.0}) {
    Scene s = probe_scene(false);
    s.physics.restitution = e;
    GrainProbe p(s);
    const double r = p.radius(0);
    const int slot = p.add(0, Vec2(500, h0 + r));
    const int bounces = e == 1.0 ? 100 : 1;
    double highest = 0, lowest = 1e30, apex = 0, last_vy = 0;
    int seen = 0;
    PlotSeries trace{"e = 0.5", {}, {}, false};
    const double period = 2 * std::sqrt(2 * h0 / p.water().gravity_px_s2[0]);
    const int64_t limit = int64_t((bounces + 2) * period / p.dt());
    for (int64_t i = 0; i < limit && seen < bounces; ++i) {
      p.step();
      const double y = p.position(slot).y() - r, vy = p.velocity(slot).y();
      if (e == 0.5 && i % 200 == 0) trace.x.push_back(1000 * i * p.dt()), trace.y.push_back(y);
      if (vy > 0) apex = std::max(apex, y);
      if (last_vy > 0 && vy <= 0) {  // an apex after a bounce
        highest = std::max(highest, apex), lowest = std::min(lowest, apex);
        ++seen;
        if (bounces == 1) break;
        apex = 0;
      }
      last_vy = vy;
    }
    if (e == 0.5) plot.series.push_back(std::move(trace));
    if (e < 1)
      c.checks.push_back(within("e = " + std::to_string(e).substr(0, 3) + ": rebound height", apex, e * e * h0,
                                0.05 * e * e * h0, "px"));
    else {  // single precision: 1e-6 of the height a bounce
      c.checks.push_back({"e = 1: highest of 100 rebounds over the drop height", "", highest / h0, 1, 1e-4,
                          VerifyCheck::Kind::AtMost});
      c.checks.push_back({"e = 1: lowest of 100 rebounds over the drop height", "", lowest / h0, 1, 0.01,
                          VerifyCheck::Kind::AtLeast});
    }
    if (seen < bounces) c.notes.push_back("e = " + std::to_string(e) + ": only " + std::to_string(seen) + " bounces");
  }
  c.plots.push_back(std::move(plot));
  return c;
}

// A sphere on an incline (the floor under gravity tilted by θ), no rolling
// resistance: it rolls with a = 5/7 g sin θ while tan θ < 7/2 μ, and slides
// with a = g (sin θ − μ cos θ) above.
VerifyCase incline(const VerifyOptions&) {
  VerifyCase c{"incline", "A sphere on an incline",
               "rolling a = 5/7 g sin θ while tan θ < 7/2 μ (μ = 0.4: θ < 54.5°), sliding a = g (sin θ − μ cos θ) "
               "above; 2%"};
  VerifyPlot plot{"Acceleration down an incline (μ = 0.4, no rolling resistance)", "θ (deg)", "a / g", {}};
  PlotSeries sim{"DEM", {}, {}, true}, exact{"closed form", {}, {}, false};
  for (double deg : {10.0, 20.0, 30.0, 40.0, 50.0, 54.0, 55.0, 60.0, 70.0}) {
    Scene s = probe_scene(false);
    s.physics.friction = 0.4;
    s.dem.rolling_resistance = 0;
    GrainProbe p(s, deg * kDeg);
    const int slot = p.add(0, Vec2(100, p.radius(0)));
    // a: least squares of v(t) over 5 ms.
    double st = 0, sv = 0, stt = 0, stv = 0;
    const int n = int(0.005 / p.dt());
    for (int i = 1; i <= n; ++i) {
      p.step();
      const double t = i * p.dt(), v = p.velocity(slot).x();
      st += t, sv += v, stt += t * t, stv += t * v;
    }
    const double a = (n * stv - st * sv) / (n * stt - st * st), g = p.water().gravity_px_s2[0];
    const double th = deg * kDeg;
    const double expected = std::tan(th) < 3.5 * 0.4 ? 5.0 / 7 * g * std::sin(th) : g * (std::sin(th) - 0.4 * std::cos(th));
    c.checks.push_back(within("θ = " + std::to_string(int(deg)) + "°: a / g", a / g, expected / g, 0.02 * expected / g, ""));
    sim.x.push_back(deg), sim.y.push_back(a / g);
  }
  for (double deg = 5; deg <= 75; deg += 0.5) {
    const double th = deg * kDeg;
    exact.x.push_back(deg);
    exact.y.push_back(std::tan(th) < 1.4 ? 5.0 / 7 * std::sin(th) : std::sin(th) - 0.4 * std::cos(th));
  }
  plot.series = {exact, sim};
  c.plots.push_back(std::move(plot));
  return c;
}

namespace {

// Does a grain, placed by `setup` and left under gravity tilted by θ, hold
// (physics/holds.h)?
template <class Setup>
bool holds(const Scene& s, double theta, int k, Setup setup) {
  GrainProbe p(s, theta);
  const int slot = setup(p);
  const Vec2 start = p.position(slot);
  const int n = int(std::lround(kHoldSeconds / p.dt()));
  for (int i = 0; i < n; ++i) p.step();
  return (p.position(slot) - start).norm() < kHoldDiameters * 2 * p.radius(k);
}

// The steepest θ that holds, by bisection to 0.02° (holding is monotone in θ).
template <class Setup>
double holding_angle(const Scene& s, int k, Setup setup, double hi_deg) {
  double lo = 0, hi = hi_deg;
  while (hi - lo > 0.02) {
    const double mid = (lo + hi) / 2;
    (holds(s, mid * kDeg, k, setup) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

// A lone sphere on the floor holds while tan θ ≤ μ_r (rolling resistance
// μ_r R N against the torque m g R sin θ), for every class's size; friction
// is 1 here so that sliding (at 45°) comes after rolling.
VerifyCase rolling(const VerifyOptions&) {
  VerifyCase c{"rolling", "Rolling resistance",
               "a lone sphere holds on a slope while tan θ ≤ μ_r (torque μ_r R N); friction 1, so it would slide "
               "only past 45°; 1°"};
  VerifyPlot plot{"Steepest slope a lone grain holds on", "rolling resistance μ_r", "θ (deg)", {}};
  PlotSeries exact{"atan μ_r", {}, {}, false};
  for (double mr = 0; mr <= 0.65; mr += 0.01) exact.x.push_back(mr), exact.y.push_back(std::atan(mr) / kDeg);
  plot.series.push_back(exact);
  Scene s = probe_scene(true);
  s.physics.friction = 1;
  for (int k : distinct_classes(s)) {
    PlotSeries sim{cls_name(k), {}, {}, true};
    for (double mr : {0.05, 0.1, 0.3, 0.6}) {
      Scene t = s;
      t.dem.rolling_resistance = mr;
      const double angle = holding_angle(t, k, [k](GrainProbe& p) { return p.add(k, Vec2(500, p.radius(k))); }, 44);
      c.checks.push_back(within(cls_name(k) + ", μ_r = " + std::to_string(mr).substr(0, 4) + ": steepest hold", angle,
                                std::atan(mr) / kDeg, 1, "°"));
      sim.x.push_back(mr), sim.y.push_back(angle);
    }
    plot.series.push_back(std::move(sim));
  }
  c.plots.push_back(std::move(plot));
  return c;
}

// A grain resting in the notch of two touching grains of its size that do
// not move (the static layer's colliders), their contact normals ±30° off
// the vertical: tilted by θ it pivots over the downhill grain once
// tan(θ − 30°) > min(μ, μ_r/2) (the tangential force m g sin(θ − 30°) within
// μN, and its torque within μ_r R_r N with the rolling radius R/2).
VerifyCase notch(const VerifyOptions&) {
  VerifyCase c{"notch", "A grain in a notch",
               "pivoting over the downhill grain: holds while tan(θ − 30°) ≤ min(μ, μ_r / 2), μ = 0.4; 1°"};
  VerifyPlot plot{"Steepest tilt a grain in a notch holds at (μ = 0.4)", "rolling resistance μ_r", "θ (deg)", {}};
  PlotSeries exact{"30° + atan min(μ, μ_r/2)", {}, {}, false};
  for (double mr = 0; mr <= 0.65; mr += 0.01) exact.x.push_back(mr), exact.y.push_back(30 + std::atan(std::min(0.4, mr / 2)) / kDeg);
  plot.series.push_back(exact);
  Scene s = probe_scene(true);
  s.physics.friction = 0.4;
  for (int k : distinct_classes(s)) {
    if (k > 0 && s.grains.diameter_mm[k] == s.grains.diameter_mm[0]) continue;  // the same geometry
    PlotSeries sim{cls_name(k), {}, {}, true};
    for (double mr : {0.0, 0.1, 0.3, 0.6}) {
      Scene t = s;
      t.dem.rolling_resistance = mr;
      const auto setup = [k](GrainProbe& p) {
        const double r = p.radius(k);
        p.add_static(k, Vec2(500 - r, 100));
        p.add_static(k, Vec2(500 + r, 100));
        return p.add(k, Vec2(500, 100 + std::sqrt(3.0) * r));
      };
      const double angle = holding_angle(t, k, setup, 80);
      c.checks.push_back(within(cls_name(k) + ", μ_r = " + std::to_string(mr).substr(0, 3) + ": steepest hold", angle,
                                30 + std::atan(std::min(0.4, mr / 2)) / kDeg, 1, "°"));
      sim.x.push_back(mr), sim.y.push_back(angle);
    }
    plot.series.push_back(std::move(sim));
  }
  c.plots.push_back(std::move(plot));
  return c;
}

}  // namespace sandpic::verify
