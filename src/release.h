#pragma once
// paper §7, Eq. 1-2: one release model for both backends. A grain leaves its
// resting place with the horizontal speed that carries it to its unit's
// outlet while it falls, then drops from a point across the outlet's width.
#include <functional>
#include <queue>
#include <vector>

#include "src/segment/segment.h"

namespace sandpic {

struct ReleaseModel {
  double gravity_px_s2 = 0;
  double outlet_width_px = 0;   // paper §7: 15 mm
  double window_width_px = 0;   // an outlet lies inside the window
  std::array<double, kClasses> min_drop_px{};  // one grain diameter: keeps v_x finite
  uint64_t physics_seed = 0;
};

ReleaseModel release_model(const Scene& s);

struct ReleasePath {
  Vec2 start, outlet;
  double vx = 0;  // Eq. 2: v_x = Δx sqrt(g / 2Δy), px/s
  double t = 0;   // Eq. 1: time to fall Δy, s
  double exit_x = 0;  // the fall starts here, jittered by the physics seed
};

// paper §7: the outlet in the middle of a unit's lowest edge, never wider
// than the unit itself (a small ellipse has a small gap), and inside the
// window: a unit reaching past a side wall has its outlet moved in, or every
// grain it releases would drop down the wall in one file.
struct Outlet {
  Vec2 centre;
  double width = 0;
};
Outlet outlet(const ReleaseModel& m, const Unit& u);

ReleasePath release(const ReleaseModel& m, const Outlet& o, const GrainSet& g, int32_t id);
// A grain on its way to the pile: landings go by time, ties in falling order.
struct Arrival {
  double time;
  int64_t order;  // index in the falling order
  bool operator>(const Arrival& o) const { return time != o.time ? time > o.time : order > o.order; }
};
using Arrivals = std::priority_queue<Arrival, std::vector<Arrival>, std::greater<>>;

// When a grain released at t_release (s) reaches `land_px` (px above the
// floor): Eq. 1 to the outlet (`outlet_up_px` above the floor), then straight
// down at its settling speed (0: at once). Both backends order landings by it.
double arrival_time(double t_release, const ReleasePath& p, double outlet_up_px, double land_px, double settling_px_s);

// Only where the fall starts: what a backend without flight needs.
double exit_x(const ReleaseModel& m, const Outlet& o, int32_t id);

}  // namespace sandpic
