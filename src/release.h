#pragma once
// paper §7, Eq. 1-2: one release model for both backends. A grain leaves its
// resting place with the horizontal speed that carries it to its unit's
// outlet while it falls, then drops from a point across the outlet's width.
#include <cstdint>
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

// The grains on their way, earliest first (ties in falling order): a
// calendar queue. Arrivals wait unsorted in buckets of `bucket_s` seconds;
// only the earliest bucket is sorted, when it opens, so a landing takes the
// next of the few grains due together instead of sifting through every
// grain in flight (the lattice keeps tens of thousands in flight at the
// paper's scale). The order is exact whatever the width; 0 keeps one sorted
// list (for a few arrivals only).
class Arrivals {
 public:
  explicit Arrivals(double bucket_s = 0) : bucket_s_(bucket_s) {}
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  const Arrival& top();
  void push(const Arrival& a);
  void pop();

 private:
  int64_t bucket(double time) const;
  double bucket_s_;
  size_t size_ = 0;
  int64_t open_ = 0;                 // the bucket open_list_ holds (and any before it)
  int64_t base_ = 0;                 // the bucket first_[0] stands for
  std::vector<Arrival> open_list_;   // the open bucket's, latest first
  std::vector<int32_t> first_;       // per bucket from base_ on: its first arrival in pool_, -1 none
  std::vector<Arrival> pool_;        // arrivals waiting in later buckets, each bucket a list
  std::vector<int32_t> next_;        // the next arrival of the same bucket, -1 none
  std::vector<int32_t> free_;        // slots of pool_ to reuse
};

// When a grain released at t_release (s) reaches `land_px` (px above the
// floor): Eq. 1 to the outlet (`outlet_up_px` above the floor), then straight
// down at its settling speed (0: at once). Both backends order landings by it.
double arrival_time(double t_release, const ReleasePath& p, double outlet_up_px, double land_px, double settling_px_s);
// The same from the time it is at its outlet's height (t_release + p.t).
double arrival_time(double at_outlet_s, double outlet_up_px, double land_px, double settling_px_s);

// Only where the fall starts: what a backend without flight needs.
double exit_x(const ReleaseModel& m, const Outlet& o, int32_t id);

}  // namespace sandpic
