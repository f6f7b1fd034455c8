#pragma once
// The device's water: buoyancy and drag per grain class, so that heavy and
// light grains settle at different speeds. Effective gravity is
// g·(1 − ρ_water/ρ_grain); drag is linear in the speed, with the rate chosen
// so that the terminal speed equals that of a sphere settling in water with
// the Schiller–Naumann drag (Stokes' law corrected by 1 + 0.15·Re^0.687).
#include <array>

#include "src/scene.h"

namespace sandpic {

struct Water {
  std::array<double, kClasses> gravity_px_s2{};   // effective gravity, buoyancy included
  std::array<double, kClasses> terminal_px_s{};   // settling speed
  std::array<double, kClasses> drag_per_s{};      // k: dv/dt = g_eff − k v
};

Water water_model(const Scene& s);

// Terminal settling speed (m/s) of a sphere of diameter d (m) and density
// rho (kg/m³) in a fluid of density rho_f and viscosity mu, under gravity g.
double settling_speed(double d, double rho, double rho_f, double mu, double g);

}  // namespace sandpic
