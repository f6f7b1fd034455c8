#include "src/water.h"

#include <cmath>

namespace sandpic {

double settling_speed(double d, double rho, double rho_f, double mu, double g) {
  double g_eff = g * (1 - rho_f / rho);
  if (g_eff <= 0) return 0;
  double v = g_eff * rho * d * d / (18 * mu);  // Stokes
  for (int i = 0; i < 100; ++i) {  // fixed point on the Reynolds number
    double re = rho_f * v * d / mu;
    double next = g_eff * rho * d * d / (18 * mu * (1 + 0.15 * std::pow(re, 0.687)));
    if (std::abs(next - v) < 1e-12) break;
    v = 0.5 * (v + next);
  }
  return v;
}

Water water_model(const Scene& s) {
  Water w;
  const double px_per_m = 1000 * px_per_mm(s), g = s.release.gravity_m_s2;
  for (int k = 0; k < kClasses; ++k) {
    const double rho = s.grains.density_g_cm3[k] * 1000, d = s.grains.diameter_mm[k] / 1000;
    if (!s.dem.water) {
      // No water: free fall, limited only by the window's height.
      w.gravity_px_s2[k] = g * px_per_m;
      w.terminal_px_s[k] = std::sqrt(2 * w.gravity_px_s2[k] * s.window.height);
      w.drag_per_s[k] = 0;
      continue;
    }
    const double rho_f = s.dem.water_density_g_cm3 * 1000;
    w.gravity_px_s2[k] = g * (1 - rho_f / rho) * px_per_m;
    w.terminal_px_s[k] = settling_speed(d, rho, rho_f, s.dem.water_viscosity_pa_s, g) * px_per_m;
    w.drag_per_s[k] = w.terminal_px_s[k] > 0 ? w.gravity_px_s2[k] / w.terminal_px_s[k] : 0;
  }
  return w;
}

}  // namespace sandpic
