#pragma once
// The lattice backend: grains leave their unit's outlet in falling order and
// settle one at a time on a height field by angle-of-repose rules per class,
// so the strata of a pile are its former surfaces (paper Fig. 6b).
#include <memory>

#include "lattice/height_field.h"
#include "src/simulator.h"

namespace sandpic {

// paper §7, Fig. 9: the angle of repose grows with friction, and big grains
// pile steeper than small ones (repose_angle_deg, src/scene.h).
SlopeRule slope_rule(const Scene& s, int k);
// Area a grain of class k takes in the lattice's pile: grain_area_px · lattice.bulk.
double lattice_area_px(const Scene& s, int k);
// The rule for an angle, a grain's rise on its column (px) and a column width.
SlopeRule make_slope_rule(double degrees, double rise_px, double column_px, double runout_px = 0);

std::unique_ptr<Simulator> make_lattice_simulator();

}  // namespace sandpic
