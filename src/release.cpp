#include "src/release.h"

#include <algorithm>
#include <cmath>

#include "src/rng.h"

namespace sandpic {

ReleaseModel release_model(const Scene& s) {
  ReleaseModel m;
  m.gravity_px_s2 = s.release.gravity_m_s2 * 1000 * px_per_mm(s);
  m.outlet_width_px = s.release.outlet_width_mm * px_per_mm(s);
  m.window_width_px = s.window.width;
  for (int k = 0; k < kClasses; ++k) m.min_drop_px[k] = grain_diameter_px(s, k);
  m.physics_seed = s.physics_rng();
  return m;
}

Outlet outlet(const ReleaseModel& m, const Unit& u) {
  Outlet o{u.outlet(), std::min({m.outlet_width_px, u.width(), m.window_width_px})};
  o.centre.x() = std::clamp(o.centre.x(), o.width / 2, m.window_width_px - o.width / 2);
  return o;
}

ReleasePath release(const ReleaseModel& m, const Outlet& o, const GrainSet& g, int32_t id) {
  ReleasePath p;
  p.start = g.position(id);
  p.outlet = o.centre;
  double dx = p.outlet.x() - p.start.x();
  double dy = std::max(p.outlet.y() - p.start.y(), m.min_drop_px[g.cls[id]]);
  p.vx = dx * std::sqrt(m.gravity_px_s2 / (2 * dy));
  p.t = std::sqrt(2 * dy / m.gravity_px_s2);
  p.exit_x = exit_x(m, o, id);
  return p;
}

double arrival_time(double t_release, const ReleasePath& p, double outlet_up_px, double land_px, double settling_px_s) {
  const double drop = outlet_up_px - land_px;
  const double fall = settling_px_s > 0 ? std::max(0.0, drop) / settling_px_s : 0;
  return t_release + p.t + fall;
}

double exit_x(const ReleaseModel& m, const Outlet& o, int32_t id) {
  return o.centre.x() + (uniform(m.physics_seed, Stream::OutletJitter, uint64_t(id)) - 0.5) * o.width;
}

}  // namespace sandpic
