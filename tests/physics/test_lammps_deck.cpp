#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "physics/dem_params.h"
#include "physics/lammps_deck.h"
#include "src/pipeline.h"
#include "src/water.h"
#include "tests/test_util.h"

namespace sandpic {
namespace {

Scene small_scene() {
  Scene s = test::one_ellipse_scene(120, 90, 20);
  s.mode = Mode::Lammps;
  s.release.outlet_width_mm = 15;
  return s;
}

LammpsDeck deck_of(const Scene& s) {
  const Prepared p = prepare(s);
  return lammps_deck(p.input(s));
}

// Every grain is created exactly once: the deck's atoms are the scene's
// grains, each with its class's diameter and density.
TEST(LammpsDeck, CreatesEveryGrainOnce) {
  const Scene s = small_scene();
  const Prepared p = prepare(s);
  const LammpsDeck d = lammps_deck(p.input(s));
  ASSERT_EQ(int64_t(d.grain_of_atom.size()), p.init.grains.size());
  std::vector<int32_t> ids = d.grain_of_atom;
  std::sort(ids.begin(), ids.end());
  for (size_t i = 0; i < ids.size(); ++i) ASSERT_EQ(ids[i], int32_t(i));
  std::istringstream in(d.input);
  int creates = 0, sets = 0;
  for (std::string l; std::getline(in, l);) {
    creates += l.rfind("create_atoms ", 0) == 0;
    if (l.rfind("set atom ", 0) == 0) {
      std::istringstream w(l.substr(9));
      int atom = 0;
      std::string key;
      double diameter = 0, density = 0;
      w >> atom >> key >> diameter >> key >> density;
      const int k = p.init.grains.cls[size_t(d.grain_of_atom[size_t(atom - 1)])];
      EXPECT_NEAR(diameter, grain_diameter_px(s, k), 1e-6);
      EXPECT_NEAR(density, s.grains.density_g_cm3[k], 1e-6);
      ++sets;
    }
  }
  EXPECT_EQ(creates, int(ids.size()));
  EXPECT_EQ(sets, int(ids.size()));
  EXPECT_NE(d.input.find("write_dump all custom final.dump"), std::string::npos);
}

// A grain is never created inside another: each creation is checked
// against where every earlier grain is at that moment, falling straight
// down at its settling speed (they do not meet until they land).
TEST(LammpsDeck, CreationsNeverOverlapTheStream) {
  Scene s = small_scene();
  s.dem.release_rate = 20000;  // a crowded outlet: creations must wait
  const Prepared p = prepare(s);
  const LammpsDeck d = lammps_deck(p.input(s));
  EXPECT_GT(d.delayed, 0);
  const Water w = water_model(s);
  const auto r = dem_radii(s);
  struct Made {
    double x, y, t, v, r;
  };
  std::vector<Made> made;
  std::istringstream in(d.input);
  double t = 0, x = 0, y = 0;
  int type = 0;
  for (std::string l; std::getline(in, l);) {
    std::istringstream w_(l);
    std::string cmd;
    w_ >> cmd;
    if (cmd == "run") {
      int64_t n = 0;
      w_ >> n;
      t += double(n) * d.contact.dt;
    } else if (cmd == "create_atoms") {
      std::string single;
      w_ >> type >> single >> x >> y;
      const double rk = r[type - 1];
      for (const Made& m : made) {
        const double my = m.y - m.v * (t - m.t);
        if (my < y - 4 * rk - 4 * m.r) continue;  // landed or far below: not predicted
        ASSERT_GE(std::hypot(m.x - x, my - y), m.r + rk - 1e-9) << l;
      }
      made.push_back({x, y, t, w.terminal_px_s[type - 1], rk});
    }
  }
  EXPECT_EQ(made.size(), d.grain_of_atom.size());
  // Nor do two grains meet while both are still near the lid (falling
  // straight, sampled every millisecond): a meeting there knocks them aside
  // from where later creations are checked against.
  const double r_big = *std::max_element(r.begin(), r.end());
  const double zone = s.window.height - 12 * r_big;
  for (size_t i = 0; i < made.size(); ++i)
    for (size_t j = i + 1; j < made.size(); ++j) {
      const Made &a = made[i], &b = made[j];
      if (std::abs(a.x - b.x) >= a.r + b.r) continue;
      for (double t = b.t; t < b.t + 0.5; t += 0.001) {
        const double ya = a.y - a.v * (t - a.t), yb = b.y - b.v * (t - b.t);
        if (ya < zone || yb < zone) break;
        ASSERT_GE(std::hypot(a.x - b.x, ya - yb), a.r + b.r - 1e-6) << "grains " << i << " and " << j << " at t " << t;
      }
    }
}

// Same scene, same seed: the same deck, byte for byte; another physics seed
// moves the outlets' jitter.
TEST(LammpsDeck, DeterministicPerSeed) {
  Scene s = small_scene();
  EXPECT_EQ(deck_of(s).input, deck_of(s).input);
  Scene other = s;
  other.physics_seed = 7;
  EXPECT_NE(deck_of(other).input, deck_of(s).input);
}

// The contact is as soft as its design: the design load presses two small
// grains together by the target overlap (F = k_n·√R·δ^1.5, R = r/2), a
// hundredth of a small diameter at most, and the step resolves the stiffest
// pair's oscillation in tens of steps.
TEST(LammpsDeck, ContactMeetsItsDesign) {
  const Scene s = small_scene();
  const Prepared p = prepare(s);
  const LammpsContact c = lammps_contact(s, p.init.grains);
  const auto r = dem_radii(s);
  const double r_small = *std::min_element(r.begin(), r.end());
  EXPECT_NEAR(c.kn * std::sqrt(r_small / 2) * std::pow(c.target_overlap_px, 1.5), c.load, 1e-6 * c.load);
  EXPECT_LE(c.target_overlap_px, 0.01 * 2 * r_small);
  const double m = s.grains.density_g_cm3[0] * 4.0 / 3.0 * M_PI * std::pow(r_small, 3);
  const double k_lin = 1.5 * c.kn * std::sqrt(r_small / 2 * c.target_overlap_px);
  const double period = 2 * M_PI * std::sqrt(m / 2 / k_lin);
  EXPECT_GT(period / c.dt, 20);
  EXPECT_LT(period / c.dt, 100);
  // Friction, restitution and rolling resistance are the scene's.
  EXPECT_EQ(c.friction, s.physics.friction);
  EXPECT_EQ(c.restitution, s.physics.restitution);
  EXPECT_EQ(c.rolling, s.dem.rolling_resistance);
}

// Half the stiffness: the design load presses 2^(2/3) deeper (Hertz) and the
// step lengthens with the softer contact's period.
TEST(LammpsDeck, StiffnessScalesTheContactAndTheStep) {
  const Scene s = small_scene();
  const Prepared p = prepare(s);
  const LammpsContact one = lammps_contact(s, p.init.grains), half = lammps_contact(s, p.init.grains, 0, 0.5);
  EXPECT_NEAR(half.kn, one.kn / 2, 1e-9 * one.kn);
  EXPECT_NEAR(half.target_overlap_px, one.target_overlap_px * std::pow(2.0, 2.0 / 3.0), 1e-9);
  EXPECT_GT(half.dt, one.dt * 1.1);
  EXPECT_EQ(half.load, one.load);
}

// A grain that would not sink is refused with its key, as in the DEM.
TEST(LammpsDeck, RefusesGrainsThatFloat) {
  Scene s = small_scene();
  for (double& d : s.grains.density_g_cm3) d = 0.9;
  EXPECT_THROW(deck_of(s), InputError);
}

}  // namespace
}  // namespace sandpic
