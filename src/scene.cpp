#include "src/scene.h"

#include <cmath>
#include <numbers>

namespace sandpic {

std::string Scene::resolve(const std::string& path) const {
  if (path.empty() || path.front() == '/' || base_dir.empty()) return path;
  return base_dir + "/" + path;
}

double px_per_mm(const Scene& s) { return 1.0 / s.units.mm_per_pixel; }

double grain_diameter_px(const Scene& s, int k) { return s.grains.diameter_mm[k] * px_per_mm(s); }

std::string layers_name(Layers l) { return l == Layers::Three ? "three" : l == Layers::Bcre ? "bcre" : "all-dynamic"; }

double repose_angle_deg(const Scene& s, int k) {
  if (s.lattice.repose_deg) return (*s.lattice.repose_deg)[k];
  return std::atan(s.lattice.repose_gain[k] * s.physics.friction) * 180 / std::numbers::pi;
}

double grain_area_px(const Scene& s, int k) {
  double d = grain_diameter_px(s, k);
  return std::numbers::pi / 4 * d * d / s.units.packing;
}

std::string mode_name(Mode m) { return m == Mode::Lattice ? "lattice" : m == Mode::Dem ? "dem" : "lammps"; }

}  // namespace sandpic
