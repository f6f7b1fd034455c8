// The DEM backend. Each step is a short fixed list of named stages:
//   release → insert → move (water → step (Bullet), n sub-steps) → [--frames] frame
//   → [every cycle] classify → freeze → wake → guard (and the stiffness watch's sub-steps)
// each timed (stats: stages_s, with the body-steps the Bullet step solved).
// paper §7: release toward each unit's outlet; §8.1: the three-layer model.
#include "physics/dem_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>
#include <utility>

#include "physics/crowding.h"
#include "physics/dem_cost.h"
#include "physics/holds.h"
#include "physics/outline_watch.h"
#include "physics/layers.h"
#include "physics/raster.h"
#include "physics/stiffness.h"
#include "physics/water_stage.h"
#include "src/water.h"
#include "physics/world.h"
#include "src/errors.h"
#include "src/frames.h"
#include "src/release.h"
#include "src/stage_times.h"

namespace sandpic {

namespace {

ClassSet present_classes(const GrainSet& g) {
  const auto counts = g.per_class();
  ClassSet p{};
  for (int k = 0; k < kClasses; ++k) p[size_t(k)] = counts[size_t(k)] > 0;
  return p;
}

// A grain whose insertion point is taken tries again this many steps later
// (the grain in the way needs about 40 to clear it); retrying every step
// cost 8% of the run in the neighbourhood checks.
constexpr int kRetrySteps = 8;

// The most a run waits for its outline to hold after the last grain arrived
// (simulated s).
constexpr double kHoldWaitS = 5;

// The stages a run's time is reported by (stats: stages_s).
enum Stage : size_t { kRelease, kInsert, kWater, kBulletStep, kFrame, kClassify, kFreeze, kWake, kGuard, kRunOn, kStages };

class DemRun {
 public:
  DemRun(const SimInput& in, Progress& progress);
  SimResult run();

 private:
  void release_stage();
  void insert_stage();
  void check_sinks() const;
  void move_stage();
  void water_stage();
  void set_substeps(int n);
  void classify_stage();
  void freeze_stage();
  void wake_stage();
  void guard_stage();
  void frame_stage();
  void run_on_stage();
  bool outline_holds();
  cv::Mat frame_map() const;
  void record(int32_t id, Vec2 p);
  void make_static(int32_t id, Vec2 p);
  void make_fixed(int32_t id, Vec2 p);
  void make_immovable(int32_t id, Vec2 p);
  template <class F>
  void for_each_body(F f) const;
  double surface(double x, double r) const;
  double insert_height(double x, int k, const Outlet& o) const;
  void sample_layers();
  double kinetic_energy_j() const;
  ordered_json substep_stats() const;
  cv::Mat layer_map() const;

  const Scene& s_;
  const SimInput& in_;
  Progress& progress_;
  const int W_, H_;
  const int64_t n_;
  const Layers layers_;
  Water water_;
  ReleaseModel model_;
  std::vector<Outlet> outlets_;
  std::vector<int32_t> unit_of_order_;
  WaterStage water_stage_;
  const ClassSet present_;  // the classes the run has grains of: its step and masses
  std::array<double, kClasses> radius_, mass_;
  double dt_, small_d_, sub_dt_ = 0;
  LayerRule rule_;
  LayerHeights heights_;
  GrainWorld world_;

  // Per grain id.
  std::vector<Layer> layer_;
  std::vector<int32_t> slot_;
  std::vector<int32_t> rested_;
  std::vector<Vec2> last_;
  std::vector<float> x_, y_;  // settled centre, window px (y down)

  // ids: dynamic lowest first as of the last cycle, then arrivals; static
  // bodies (dem.static_bodies, within reach of the flow) and immovable
  // static spheres; fixed grains (bcre: static grains) still kept as static
  // spheres.
  std::vector<int32_t> dynamic_, statics_, still_statics_, fixed_spheres_;
  std::vector<int> wedged_;  // slots of bodies pressed into a collider this cycle (classify_stage)
  double buried_px_ = 0;  // a sphere of fixed_spheres_ this far under H_s leaves for the ground
  double trapped_px_ = 0;  // a dynamic grain this far under H_s is out of the flow's reach
  Arrivals arrivals_{16 / s_.dem.release_rate};  // about 16 grains leave per bucket
  std::vector<double> due_;     // per falling-order index: when the grain was due to become a body
  double late_sum_ = 0, late_max_ = 0;  // how much later than due grains became bodies (crowding)
  std::vector<float> landed_;   // tops of slow dynamic grains and static bodies, per column, this cycle
  int64_t released_ = 0, inserted_ = 0, settled_ = 0, fixed_ = 0, delayed_ = 0;
  int64_t static_sleeps_ = 0, static_wakes_ = 0;  // wake_stage: static bodies made spheres, and back
  int64_t resting_ = 0;  // bodies at rest after the last cycle
  double t_ = 0, energy_budget_ = 0, deepest_ = 0;
  double arrived_t_ = -1, settled_t_ = -1;  // when the last grain arrived, when the run settled
  bool held_ = false;                        // settled because the outline held (not kHoldWaitS)
  int64_t moving_end_ = 0;                   // columns of the outline still moving then
  double run_on_end_ = -1, run_on_deepest_ = 0;  // dem.run_on_s: when it ends, the deepest overlap since the last sample
  ordered_json run_on_ = ordered_json::array();
  int64_t steps_ = 0, cycles_ = 0;
  // Body-steps (a body in the world for one sub-step): all, those after the
  // last grain became a body (the tail), and, sampled once a cycle, those
  // with a contact.
  int64_t body_steps_ = 0, tail_body_steps_ = 0, contact_body_steps_ = 0;
  StageTimes<kStages> times_{
      {"release", "insert", "water", "bullet_step", "frames", "classify", "freeze", "wake", "guard", "run_on"}};
  size_t peak_bodies_ = 0;
  ordered_json samples_ = ordered_json::array();
  cv::Mat layer_snapshot_;
  FrameSchedule frames_;
  Crowding crowding_;  // insert_stage's neighbourhood index
  StiffnessWatch watch_;
  OutlineWatch outline_;  // when the run is over
};

DemRun::DemRun(const SimInput& in, Progress& progress)
    : s_(in.scene),
      in_(in),
      progress_(progress),
      W_(in.scene.window.width),
      H_(in.scene.window.height),
      n_(int64_t(in.order.grain.size())),
      layers_(in.scene.dem.layers),
      water_(water_model(in.scene)),
      model_(release_model(in.scene)),
      water_stage_(water_),
      present_(present_classes(in.grains)),
      radius_(dem_radii(in.scene)),
      mass_(dem_masses(in.scene, present_)),
      dt_(dem_time_step(in.scene, present_)),
      small_d_(2 * *std::min_element(radius_.begin(), radius_.end())),
      heights_(in.scene.window.width + 1),
      world_(W_, H_, radius_, mass_, dem_material(in.scene, water_, dt_)),
      frames_{n_, in.frames.wanted() ? in.frames.count : 0},
      crowding_(W_, H_),
      watch_(in.scene.dem.target_overlap * small_d_, in.scene.dem.max_overlap * small_d_, in.scene.dem.max_substeps),
      outline_(kHoldDiameters * small_d_) {
  check_sinks();
  set_substeps(1);
  for (const Unit& u : in.seg.units) outlets_.push_back(outlet(model_, u));
  for (size_t u = 0; u < in.seg.units.size(); ++u)
    for (int64_t i = in.order.unit_begin[u]; i < in.order.unit_begin[u + 1]; ++i) unit_of_order_.push_back(int32_t(u));
  rule_.rest_px = s_.dem.rest_displacement * small_d_;
  rule_.patience_cycles = s_.dem.patience_cycles;
  rule_.slope_limit_rad = dem_slope_limit_deg(s_) * std::numbers::pi / 180;
  const double big_d = 2 * *std::max_element(radius_.begin(), radius_.end());
  rule_.band_px = s_.dem.static_thickness_diameters * big_d;
  rule_.baseline = std::max(1, int(std::lround(s_.dem.slope_baseline_diameters * big_d)));
  rule_.floor_px = big_d;  // the bare floor reads as a first layer's tops
  buried_px_ = (layers_ == Layers::Three ? rule_.band_px : 0) + 2 * big_d;
  // bcre's static layer is immovable: a dynamic grain a diameter under its
  // surface lies in a cage of fixed spheres that the flow above presses it
  // into. Left a body down to ten diameters (three's band) such grains were
  // squeezed 0.12 small diameters into the cage on 300 grains at --scale 0.1
  // (docs/notebook/2026-12-07-the-band-counts-in-grains.md).
  trapped_px_ = layers_ == Layers::Three ? rule_.band_px : big_d;
  // Resting on the static layer: the bottom within a quarter of the smallest
  // diameter of H_s (overlap and the outline's rounding to columns).
  rule_.support_px = 0.25 * small_d_;
  const size_t n = size_t(in.grains.size());
  layer_.assign(n, Layer::Waiting);
  due_.assign(n, 0.0);
  slot_.assign(n, -1);
  rested_.assign(n, 0);
  last_.assign(n, Vec2(NAN, NAN));
  x_.assign(n, NAN);
  y_.assign(n, NAN);
  landed_.assign(size_t(W_ + 1), 0.0f);
}

double DemRun::surface(double x, double r) const {
  int from = std::max(0, int(std::floor(x - r))), to = std::min(W_, int(std::ceil(x + r)));
  float h = 0;
  for (int j = from; j <= to; ++j) h = std::max({h, float(heights_.hs[size_t(j)]), landed_[size_t(j)]});
  return h;
}

// Where a grain of class k falling at x becomes a body: simulated_fall_px
// above the pile (dem_params.h), but never above its outlet, where its fall begins (paper §7:
// the grains fall "as solid bodies" and collide while falling; none of the
// fall is simulated twice). Above a pile that has reached the outlet, its
// centre a diameter above the pile.
double DemRun::insert_height(double x, int k, const Outlet& o) const {
  const double r = radius_[k], below = surface(x, r);
  const double outlet_up = std::max(H_ - o.centre.y(), below + 2 * r);
  return std::min({below + simulated_fall_px(s_, k, water_.terminal_px_s[k]), outlet_up, H_ - r});
}

// Stage: grains leave their units at dem.release_rate in falling order and
// are scheduled to become bodies: Eq. 1-2 to the outlet, then (where the
// fall lasts longer than dem.simulated_fall_s) an analytic fall at their
// settling speed down to insert_height.
void DemRun::release_stage() {
  while (released_ < n_ && double(released_) / s_.dem.release_rate <= t_) {
    const int32_t id = in_.order.grain[size_t(released_)];
    const int k = in_.grains.cls[size_t(id)];
    const Outlet& o = outlets_[size_t(unit_of_order_[size_t(released_)])];
    ReleasePath path = release(model_, o, in_.grains, id);
    const double land = insert_height(path.exit_x, k, o);
    due_[size_t(released_)] = arrival_time(t_, path, H_ - o.centre.y(), land, water_.terminal_px_s[k]);
    arrivals_.push({due_[size_t(released_)], released_});
    ++released_;
  }
}

// Stage: an arriving grain becomes a body at insert_height (at its outlet, or above the pile),
// at its settling speed; if another grain is in the way it tries again
// kRetrySteps later.
void DemRun::insert_stage() {
  if (arrivals_.empty() || arrivals_.top().time > t_) return;
  crowding_.clear();
  for_each_body([&](int32_t id, int slot) { crowding_.add(world_.position(slot), radius_[in_.grains.cls[size_t(id)]]); });
  std::vector<Arrival> later;
  while (!arrivals_.empty() && arrivals_.top().time <= t_) {
    Arrival a = arrivals_.top();
    arrivals_.pop();
    const int32_t id = in_.order.grain[size_t(a.order)];
    const int k = in_.grains.cls[size_t(id)];
    const double r = radius_[k];
    const Outlet& o = outlets_[size_t(unit_of_order_[size_t(a.order)])];
    double x = std::clamp(exit_x(model_, o, id), r, W_ - r);
    double y = insert_height(x, k, o);
    if (crowding_.crowded(Vec2(x, y), r)) {
      later.push_back({t_ + kRetrySteps * dt_, a.order});
      ++delayed_;
      continue;
    }
    Vec2 v(0, -water_.terminal_px_s[k]);
    slot_[size_t(id)] = world_.add_body(k, Vec2(x, y), v);
    layer_[size_t(id)] = Layer::Dynamic;
    dynamic_.push_back(id);
    crowding_.add(Vec2(x, y), r);  // in the way of the next arrivals of this step
    ++inserted_;
    const double late = t_ - due_[size_t(a.order)];
    late_sum_ += late;
    late_max_ = std::max(late_max_, late);
    energy_budget_ += mass_[k] * (0.5 * v.squaredNorm() + water_.gravity_px_s2[k] * y);
  }
  for (const Arrival& a : later) arrivals_.push(a);
  peak_bodies_ = std::max(peak_bodies_, dynamic_.size() + statics_.size());
}

// A grain no denser than the water never settles: it would float, or hang
// where it was inserted until the run's time limit (a neutral one took 109 s
// of simulated time to fail; a floating one flew out through the lid). Only
// the classes the picture uses count.
void DemRun::check_sinks() const {
  if (!s_.dem.water) return;
  std::array<bool, kClasses> used{};
  for (uint8_t k : in_.grains.cls) used[k] = true;
  for (int k = 0; k < kClasses; ++k)
    if (used[k] && !(water_.terminal_px_s[k] > 0))
      throw key_error("grains.density_g_cm3[" + std::to_string(k) + "]",
                      "S" + std::to_string(k + 1) + "'s grains (" + std::to_string(s_.grains.density_g_cm3[k]) +
                          " g/cm³) are not denser than the water (dem.water_density_g_cm3 = " +
                          std::to_string(s_.dem.water_density_g_cm3) + "): they would not sink in the DEM mode");
}

// What depends on the (sub-)step: the drag's decay over it, and the bounce
// threshold (a resting contact closes by g·dt per sub-step). Masses keep
// their scale: a grain's weight per sub-step only falls further under
// Bullet's rolling-friction cap (dem_masses).
void DemRun::set_substeps(int n) {
  sub_dt_ = dt_ / n;
  water_stage_.set_step(sub_dt_);
  world_.set_bounce_speed(dem_bounce_speed(water_, sub_dt_));
}

// Stage: the water and Bullet's contacts, as the stiffness watch's n
// sub-steps of dt/n (one at the defaults).
void DemRun::move_stage() {
  const int64_t bodies = int64_t(dynamic_.size() + statics_.size());
  for (int i = 0; i < watch_.substeps(); ++i) {
    times_.time(kWater, [&] { water_stage(); });
    times_.time(kBulletStep, [&] { world_.step(sub_dt_); });
  }
  body_steps_ += bodies * watch_.substeps();
  if (inserted_ == n_) tail_body_steps_ += bodies * watch_.substeps();
}

// Every body in the world: the dynamic grains and the static bodies.
template <class F>
void DemRun::for_each_body(F f) const {
  for (int32_t id : dynamic_) f(id, slot_[size_t(id)]);
  for (int32_t id : statics_) f(id, slot_[size_t(id)]);
}

// Gravity with buoyancy, and drag (physics/water_stage.h). Bullet then
// solves the contacts.
void DemRun::water_stage() {
  for_each_body([&](int32_t id, int slot) {
    const Vec2 v = world_.velocity(slot);
    world_.push(slot, water_stage_.apply(in_.grains.cls[size_t(id)], v) - v, sub_dt_);
  });
}

void DemRun::record(int32_t id, Vec2 p) {
  x_[size_t(id)] = float(p.x());
  y_[size_t(id)] = float(H_ - p.y());
}

// paper §8.1: static grains are "almost immobile ... and also fully
// controlled by Physx": with dem.static_bodies they stay bodies, so the
// flow can still push them (with dem.static_reach_diameters, wake_stage
// makes those far from it immovable until it comes near). Made immovable,
// the default, the toe of a heap can no longer spread: on verify-dem's quick
// heap three-layer stood 5° steeper than all-dynamic. In bcre the static
// layer is immovable too: each grain an exact static sphere until buried,
// then part of the height field (see make_fixed for why not at once).
void DemRun::make_static(int32_t id, Vec2 p) {
  const int k = in_.grains.cls[size_t(id)];
  const double r = radius_[k];
  record(id, p);
  ++settled_;
  heights_.add_static(p.x(), p.y(), r);
  layer_[size_t(id)] = Layer::Static;
  if (layers_ == Layers::Bcre) {
    world_.remove_body(slot_[size_t(id)]);
    slot_[size_t(id)] = world_.add_static(k, p);
    fixed_spheres_.push_back(id);
  } else if (s_.dem.static_bodies) {
    statics_.push_back(id);
  } else {  // immovable: a static sphere, fixed later as it is
    make_immovable(id, p);
  }
}

// A static body becomes an immovable static sphere at p (already recorded).
void DemRun::make_immovable(int32_t id, Vec2 p) {
  world_.remove_body(slot_[size_t(id)]);
  slot_[size_t(id)] = world_.add_static(in_.grains.cls[size_t(id)], p);
  still_statics_.push_back(id);
}

// Algorithm 2, lines 13-21: a fixed grain leaves the simulation. It stays
// an exact static sphere while bodies may rest on it, and becomes part of the
// height field only once buried (freeze_stage): the field is the grains'
// upper outline, which fills the hollows between them, so a body resting in
// one overlapped it by up to a quarter of its radius and was pushed out
// (sub-steps 8-16 and 10x the time on the default scene at --scale 0.1).
void DemRun::make_fixed(int32_t id, Vec2 p) {
  const int k = in_.grains.cls[size_t(id)];
  world_.remove_body(slot_[size_t(id)]);
  record(id, p);
  heights_.add_static(p.x(), p.y(), radius_[k]);
  heights_.add_fixed(p.x(), p.y(), radius_[k]);
  slot_[size_t(id)] = world_.add_static(k, p);
  fixed_spheres_.push_back(id);
  layer_[size_t(id)] = Layer::Fixed;
  ++fixed_;
}

// Stage (every cycle): paper Algorithm 2, lines 1-12, lowest grains first:
// a column of grains that came to rest together joins the static layer in
// one cycle, each resting on the one just made static under it.
void DemRun::classify_stage() {
  ++cycles_;
  std::fill(landed_.begin(), landed_.end(), 0.0f);
  resting_ = 0;
  struct Body {
    Vec2 p;
    double moved;
    int32_t id;
  };
  std::vector<Body> bodies;
  bodies.reserve(dynamic_.size());
  for (int32_t id : dynamic_) {
    Vec2 p = world_.position(slot_[size_t(id)]);
    Vec2& last = last_[size_t(id)];
    const double moved = std::isfinite(last.x()) ? (p - last).norm() : INFINITY;
    rested_[size_t(id)] = moved < rule_.rest_px ? rested_[size_t(id)] + 1 : 0;
    last = p;
    bodies.push_back({p, moved, id});
  }
  std::sort(bodies.begin(), bodies.end(),
            [](const Body& a, const Body& b) { return a.p.y() != b.p.y() ? a.p.y() < b.p.y() : a.id < b.id; });
  // A grain pressed into a static grain, a wall or the floor deeper than a
  // quarter of a small grain is wedged between immovable things, where the
  // solver cannot resolve it: it joins the static layer where it is. (At
  // the paper's scale grains pushed into such wedges sank 0.7 px into the
  // floor and stopped the run as a divergence.)
  wedged_ = world_.wedged(0.25 * small_d_);
  std::vector<int32_t> still;
  still.reserve(dynamic_.size());
  for (const auto& [p, moved, id] : bodies) {
    const int k = in_.grains.cls[size_t(id)];
    const double r = radius_[k];
    // A grain buried under the static band (jostled, never quite at rest)
    // is out of reach of the flow, and a wedged one cannot get out: both
    // leave the simulation where they are (in bcre: join its static layer).
    const bool trapped = p.y() + r < heights_.hs[size_t(heights_.column(p.x()))] - trapped_px_ ||
                         std::binary_search(wedged_.begin(), wedged_.end(), slot_[size_t(id)]);
    if (layers_ == Layers::Three && trapped) {
      ++settled_;
      make_fixed(id, p);
      continue;
    }
    if (layers_ != Layers::AllDynamic &&
        (trapped || becomes_static(heights_, rule_, p.x(), p.y(), r, moved, rested_[size_t(id)]))) {
      make_static(id, p);
      continue;
    }
    if (world_.velocity(slot_[size_t(id)]).norm() < 0.3 * water_.terminal_px_s[k]) {
      int j = std::clamp(int(std::lround(p.x())), 0, W_);
      landed_[size_t(j)] = std::max(landed_[size_t(j)], float(p.y() + r));
    }
    still.push_back(id);
    resting_ += rested_[size_t(id)] > 0;
  }
  dynamic_.swap(still);
  // Static bodies can be pushed up (light grains over heavy ones that sink
  // through them): the surface for insertion is where they are now, not
  // where they came to rest. (With their resting tops alone, arrivals were
  // put inside them and delayed for minutes: density 100:1 stalled.)
  for (int32_t id : statics_) {
    const Vec2 p = world_.position(slot_[size_t(id)]);
    int j = std::clamp(int(std::lround(p.x())), 0, W_);
    landed_[size_t(j)] = std::max(landed_[size_t(j)], float(p.y() + radius_[in_.grains.cls[size_t(id)]]));
  }
}

// Stage (every cycle): Algorithm 2, lines 13-21. A static grain under the
// static band becomes fixed (make_fixed); a fixed sphere two large grains
// deeper than that (bcre: a static sphere two large grains under H_s) is
// out of every body's reach and joins the height field.
void DemRun::freeze_stage() {
  if (layers_ == Layers::AllDynamic) return;
  // Lowest first: a grain is fixed only on fixed grains, so a stack buried
  // in one cycle is fixed in one cycle, each on the one fixed under it.
  // Each height is read once, not at every comparison.
  auto lowest_first = [](std::vector<int32_t>& ids, auto height) {
    std::vector<std::pair<double, int32_t>> keyed;
    keyed.reserve(ids.size());
    for (int32_t id : ids) keyed.emplace_back(height(id), id);
    std::sort(keyed.begin(), keyed.end());  // by height, then id
    for (size_t i = 0; i < ids.size(); ++i) ids[i] = keyed[i].second;
  };
  lowest_first(statics_, [&](int32_t id) { return world_.position(slot_[size_t(id)]).y(); });
  lowest_first(still_statics_, [&](int32_t id) { return -double(y_[size_t(id)]); });
  std::vector<int32_t> still;
  still.reserve(statics_.size());
  for (int32_t id : statics_) {
    const double r = radius_[in_.grains.cls[size_t(id)]];
    const Vec2 p = world_.position(slot_[size_t(id)]);
    // A static body wedged against an immovable grain cannot get out, as a
    // dynamic one cannot (classify_stage): in the stress catalogue's
    // density-100:1 scene with the band of static bodies, a light one was
    // pressed up into a fixed grain over it by 0.2-0.28 px and held there,
    // and the sub-steps went to 16 for the rest of the run.
    if (becomes_fixed(heights_, rule_, p.x(), p.y(), r) ||
        std::binary_search(wedged_.begin(), wedged_.end(), slot_[size_t(id)]))
      make_fixed(id, p);
    else
      still.push_back(id);
  }
  statics_.swap(still);
  still.clear();
  for (int32_t id : still_statics_) {
    const double r = radius_[in_.grains.cls[size_t(id)]];
    const Vec2 p(x_[size_t(id)], H_ - y_[size_t(id)]);
    if (!becomes_fixed(heights_, rule_, p.x(), p.y(), r)) {
      still.push_back(id);
      continue;
    }
    heights_.add_fixed(p.x(), p.y(), r);
    fixed_spheres_.push_back(id);  // already a static sphere
    layer_[size_t(id)] = Layer::Fixed;
    ++fixed_;
  }
  still_statics_.swap(still);
  std::vector<int32_t> near;
  near.reserve(fixed_spheres_.size());
  for (int32_t id : fixed_spheres_) {
    const double r = radius_[in_.grains.cls[size_t(id)]];
    const Vec2 p(x_[size_t(id)], H_ - y_[size_t(id)]);
    if (p.y() + r < heights_.lowest_hs(heights_.column(p.x()), rule_.baseline) - buried_px_) {
      world_.remove_static(slot_[size_t(id)]);
      world_.raise_ground(p, r);
      slot_[size_t(id)] = -1;
    } else {
      near.push_back(id);
    }
  }
  fixed_spheres_.swap(near);
}

// Stage (every cycle, dem.static_bodies): a static body rests as an
// immovable sphere while no grain is dynamic (nothing can push it: Bullet's
// island sleeping, decided by the layer rule), and with
// dem.static_reach_diameters while no dynamic grain is within reach; a body
// again as soon as one is (insertion puts a grain 4 of its diameters above
// the pile, at least 80 steps from touching it, and a cycle is 40). Sleeping
// with nothing dynamic cut the stress catalogue's density-100:1 scene, whose
// light grains sink for seconds while the pile waits, from 19x the immovable
// statics' time. The reach was a speed lever, not the default: every static
// body solved at every step cost 4.4x the immovable statics' time on the
// default scene at --scale 0.2, a reach of 4 largest diameters 1.9x (with the
// rows in order of height, 4.5x and 4.8x: the reach no longer saves
// body-steps there, docs/notebook/2026-12-04-layer-models-default-scene.md); but a
// sphere cannot yield to the slow settling all-dynamic piles go through:
// verify-dem's quick heap then differed from all-dynamic by 1.5-2.0 deg (mean
// of 2 seeds; one seed 3.3, 2 diameters up to 6;
// docs/notebook/2026-12-03-static-reach.md).
void DemRun::wake_stage() {
  if (layers_ != Layers::Three || !s_.dem.static_bodies) return;
  const bool limited = s_.dem.static_reach_diameters > 0;
  if (!limited && (dynamic_.empty() ? statics_.empty() : still_statics_.empty())) return;  // nothing changes
  // No limit: within reach of anything while anything is dynamic.
  const double reach =
      limited ? s_.dem.static_reach_diameters * 2 * *std::max_element(radius_.begin(), radius_.end()) : W_ + H_;
  // Dynamic bodies bucketed by columns of the reach's width.
  const int cells = int(std::ceil((W_ + 1) / reach)) + 1;
  std::vector<std::vector<Vec2>> near(size_t(std::max(cells, 1)));
  auto cell = [&](double x) { return std::clamp(int(std::floor(std::max(x, 0.0) / reach)), 0, cells - 1); };
  if (limited)
    for (int32_t id : dynamic_) {
      const Vec2 p = world_.position(slot_[size_t(id)]);
      near[size_t(cell(p.x()))].push_back(p);
    }
  auto reached = [&](Vec2 p) {
    if (!limited) return !dynamic_.empty();
    const int c = cell(p.x());
    for (int j = std::max(0, c - 1); j <= std::min(cells - 1, c + 1); ++j)
      for (const Vec2& q : near[size_t(j)])
        if ((q - p).squaredNorm() <= reach * reach) return true;
    return false;
  };
  std::vector<int32_t> bodies, spheres;
  spheres.swap(still_statics_);  // make_immovable appends the sleepers to the emptied list
  for (int32_t id : statics_) {
    const Vec2 p = world_.position(slot_[size_t(id)]);
    if (reached(p)) {
      bodies.push_back(id);
    } else {
      record(id, p);
      make_immovable(id, p);
      ++static_sleeps_;
    }
  }
  for (int32_t id : spheres) {
    const Vec2 p(x_[size_t(id)], H_ - y_[size_t(id)]);
    if (!reached(p)) {
      still_statics_.push_back(id);
      continue;
    }
    world_.remove_static(slot_[size_t(id)]);
    slot_[size_t(id)] = world_.add_body(in_.grains.cls[size_t(id)], p, Vec2(0, 0));
    bodies.push_back(id);
    ++static_wakes_;
  }
  statics_.swap(bodies);
}

std::string at(double t, int64_t steps) {
  return " at t = " + std::to_string(t) + " s (step " + std::to_string(steps) + ")";
}

// Stage (every cycle): a NaN or a grain through a wall stops the run; the
// deepest overlap and the kinetic energy go to the stiffness watch, which
// raises the sub-steps at its soft level and stops the run past a hard limit
// (an overlap deeper than dem.max_overlap, more kinetic energy than gravity
// and insertion have given) at the most sub-steps.
void DemRun::guard_stage() {
  StiffnessReading r;
  for_each_body([&](int32_t id, int slot) {
    const int k = in_.grains.cls[size_t(id)];
    Vec2 p = world_.position(slot), v = world_.velocity(slot);
    if (!p.allFinite() || !v.allFinite())
      throw SimulationError("a grain's position became NaN" + at(t_, steps_) +
                            "; lower dem.step_diameters or raise dem.max_substeps");
    if (p.x() < -radius_[k] || p.x() > W_ + radius_[k] || p.y() < -2 * radius_[k])
      throw SimulationError("a grain left the window through a wall (at " + std::to_string(p.x()) + ", " +
                            std::to_string(p.y()) + " px)" + at(t_, steps_) +
                            "; lower dem.step_diameters or raise dem.max_substeps or dem.solver_iterations");
    r.kinetic += 0.5 * mass_[k] * v.squaredNorm();
    r.settling += 0.5 * mass_[k] * water_.terminal_px_s[k] * water_.terminal_px_s[k];
  });
  r.overlap_px = world_.deepest_overlap();
  r.budget = energy_budget_;
  deepest_ = std::max(deepest_, r.overlap_px);
  switch (watch_.judge(r, t_, steps_)) {
    case StiffnessWatch::Verdict::Calm:
      break;
    case StiffnessWatch::Verdict::Changed:
      set_substeps(watch_.substeps());
      break;
    case StiffnessWatch::Verdict::Diverged:
      throw SimulationError(watch_.reason() + at(t_, steps_) + " with " + std::to_string(watch_.substeps()) +
                            " sub-steps (dem.max_substeps); lower dem.step_diameters or physics.restitution, or raise "
                            "dem.max_substeps or dem.solver_iterations");
  }
}

// The bodies' kinetic energy (translation and rotation about z) in joules,
// with the grains' real masses (the scene's densities and diameters, not
// the solver's scaled ones) and speeds in m/s.
double DemRun::kinetic_energy_j() const {
  const double m_per_px = 1e-3 / px_per_mm(s_);
  double e = 0;
  for_each_body([&](int32_t id, int slot) {
    const int k = in_.grains.cls[size_t(id)];
    const double d = s_.grains.diameter_mm[k] * 1e-3;                                       // m
    const double m = s_.grains.density_g_cm3[k] * 1e3 * std::numbers::pi / 6 * d * d * d;  // kg
    const double v = world_.velocity(slot).norm() * m_per_px, w = world_.spin(slot);
    e += 0.5 * m * v * v + 0.5 * (m * d * d / 10) * w * w;  // a solid sphere: I = m d² / 10
  });
  return e;
}

ordered_json DemRun::substep_stats() const {
  ordered_json changes = ordered_json::array();
  for (const SubStepChange& c : watch_.changes())
    changes.push_back({{"t_s", c.t_s}, {"step", c.step}, {"substeps", c.substeps}, {"reason", c.reason}});
  return changes;
}

void DemRun::sample_layers() {
  samples_.push_back({{"t_s", t_},
                      {"waiting", n_ - inserted_},
                      {"dynamic", dynamic_.size()},
                      {"static", settled_ - fixed_},
                      {"fixed", fixed_}});
}

// paper Fig. 14c-d: the grains as they are now. Fixed ones where
// they settled, bodies where Bullet has them, released grains not yet bodies
// on their way (Eq. 1-2 to the outlet, then straight down at their settling
// speed, as release_stage schedules them), the rest waiting in the region.
// Reads the run only: frames never change a picture.
cv::Mat DemRun::frame_map() const {
  std::vector<float> x(x_), y(y_);
  for_each_body([&](int32_t id, int slot) {
    const Vec2 p = world_.position(slot);
    x[size_t(id)] = float(p.x()), y[size_t(id)] = float(H_ - p.y());
  });
  for (int64_t i = 0; i < released_; ++i) {
    const int32_t id = in_.order.grain[size_t(i)];
    if (layer_[size_t(id)] != Layer::Waiting) continue;
    const int k = in_.grains.cls[size_t(id)];
    const Outlet& o = outlets_[size_t(unit_of_order_[size_t(i)])];
    const ReleasePath path = release(model_, o, in_.grains, id);
    const double since = t_ - double(i) / s_.dem.release_rate;
    Vec2 p(path.exit_x, o.centre.y() + water_.terminal_px_s[k] * (since - path.t));  // y down
    if (since < path.t) p = path.start + Vec2(path.vx * since, 0.5 * model_.gravity_px_s2 * since * since);
    const double lowest = H_ - insert_height(p.x(), k, o);
    x[size_t(id)] = float(p.x()), y[size_t(id)] = float(std::min(p.y(), lowest));
  }
  cv::Mat map = class_map_from_grains(W_, H_, x, y, in_.grains.cls, 1.2, kNoSand);
  draw_waiting(map, in_.grains, std::span<const int32_t>(in_.order.grain).subspan(size_t(released_)));
  return map;
}

// Stage (--frames only): a frame once its share of the grains has left the
// region; the last one is the finished picture (run()).
void DemRun::frame_stage() {
  if (!frames_.due(released_)) return;
  const cv::Mat map = frame_map();
  for (; frames_.due(released_); ++frames_.next) in_.frames.frame(map);
}

// Does the sand's outline hold (physics/outline_watch.h)? Its top in every
// pixel column: grains in the world and the static layer's H_s.
bool DemRun::outline_holds() {
  if (!outline_.due(t_)) return false;
  LayerHeights top(heights_.columns());
  top.hs = heights_.hs;
  for_each_body([&](int32_t id, int slot) {
    const Vec2 p = world_.position(slot);
    top.add_static(p.x(), p.y(), radius_[in_.grains.cls[size_t(id)]]);
  });
  outline_.add(t_, std::move(top.hs));
  return outline_.holds();
}

// Stage (every cycle of dem.run_on_s): the deepest overlap, and every
// 0.25 s of simulated time the sand's height in every pixel column of the
// picture as it stands (frame_map), with that overlap.
void DemRun::run_on_stage() {
  run_on_deepest_ = std::max(run_on_deepest_, world_.deepest_overlap());
  const int64_t every = std::max<int64_t>(1, std::llround(0.25 / (s_.dem.cycle_steps * dt_)));
  if (cycles_ % every && t_ < run_on_end_) return;
  const cv::Mat map = frame_map();
  std::vector<int> heights(size_t(W_), 0);
  for (int c = 0; c < W_; ++c)
    for (int r = 0; r < H_; ++r)
      if (map.at<uint8_t>(r, c) != kNoSand) {
        heights[size_t(c)] = H_ - r;
        break;
      }
  run_on_.push_back({{"t_s", t_}, {"deepest_overlap_diameters", run_on_deepest_ / small_d_}, {"heights_px", heights}});
  run_on_deepest_ = 0;
}

// paper Fig. 2i, 11: dynamic grains red, static blue, fixed black.
cv::Mat DemRun::layer_map() const {
  std::vector<float> x(x_), y(y_);
  std::vector<uint8_t> value(layer_.size(), 255);
  for_each_body([&](int32_t id, int slot) {
    const Vec2 p = world_.position(slot);
    x[size_t(id)] = float(p.x()), y[size_t(id)] = float(H_ - p.y());
  });
  for (size_t i = 0; i < layer_.size(); ++i) value[i] = layer_[i] == Layer::Waiting ? 255 : uint8_t(layer_[i]) - 1;
  cv::Mat codes = class_map_from_grains(W_, H_, x, y, value, 1.0, 255);
  cv::Mat img(H_, W_, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Vec3b colour[3] = {{40, 40, 220}, {220, 120, 40}, {20, 20, 20}};  // BGR
  for (int r = 0; r < H_; ++r)
    for (int c = 0; c < W_; ++c)
      if (uint8_t v = codes.at<uint8_t>(r, c); v < 3) img.at<cv::Vec3b>(r, c) = colour[v];
  return img;
}

SimResult DemRun::run() {
  const int cycle = s_.dem.cycle_steps;
  // A scene that never settles is a failure, not a hang: the release lasts
  // n/rate, the slowest class needs to sink through the window at its
  // settling speed (0.01 mm grains sink at ~0.05 mm/s: a 70 px window takes
  // them 40 minutes of simulated time), and settling gets a generous
  // allowance after that.
  double slowest = INFINITY;
  const auto counts = in_.grains.per_class();
  for (int k = 0; k < kClasses; ++k)
    if (counts[size_t(k)] > 0) slowest = std::min(slowest, water_.terminal_px_s[k]);
  const double limit = double(n_) / s_.dem.release_rate + 2 * H_ / std::max(slowest, 1e-9) + 60.0 + 2000 * cycle * dt_;
  progress_.start("dem", n_);
  frame_stage();  // frame 0: every grain still in the region
  while (released_ < n_ || !arrivals_.empty() || !dynamic_.empty()) {
    times_.time(kRelease, [&] { release_stage(); });
    times_.time(kInsert, [&] { insert_stage(); });
    move_stage();
    t_ += dt_;
    ++steps_;
    times_.time(kFrame, [&] { frame_stage(); });
    if (steps_ % cycle) continue;
    contact_body_steps_ += world_.bodies_in_contact() * cycle * watch_.substeps();
    times_.time(kClassify, [&] { classify_stage(); });
    times_.time(kFreeze, [&] { freeze_stage(); });
    times_.time(kWake, [&] { wake_stage(); });
    times_.time(kGuard, [&] { guard_stage(); });
    if (samples_.size() < 100000 && steps_ % (cycle * 10) == 0) sample_layers();
    if (in_.stages && layer_snapshot_.empty() && inserted_ >= n_ / 2) layer_snapshot_ = layer_map();  // half in
    // The end: every grain has arrived and the picture holds (its outline,
    // physics/outline_watch.h), or kHoldWaitS has passed since the last
    // grain arrived (the stats say which: an all-dynamic heap of 3,600
    // grains had a third of its columns still moving 8 s after). The old
    // test by bodies, a quarter pixel over 25 cycles (0.16 s), passed flanks
    // creeping at 1.5 px/s that slumped by a degree after the run ended.
    if (released_ == n_ && arrivals_.empty()) {
      if (arrived_t_ < 0) arrived_t_ = t_;
      if (run_on_end_ < 0 && (outline_holds() || t_ - arrived_t_ >= kHoldWaitS)) {
        held_ = outline_.holds();
        settled_t_ = t_;
        moving_end_ = outline_.moving_columns();
        // dem.run_on_s: the run goes on that much longer once settled, its
        // outline sampled (verify-dem's creep case).
        run_on_end_ = t_ + s_.dem.run_on_s;
      }
      if (run_on_end_ >= 0 && t_ >= run_on_end_) {
        if (s_.dem.run_on_s > 0) times_.time(kRunOn, [&] { run_on_stage(); });
        break;
      }
    }
    if (run_on_end_ >= 0) times_.time(kRunOn, [&] { run_on_stage(); });
    progress_.update(layers_ == Layers::AllDynamic ? inserted_ : settled_ + resting_);
    if (t_ > limit)
      throw SimulationError(std::to_string(n_ - settled_ - int64_t(dynamic_.size())) + " grains still falling and " +
                            std::to_string(dynamic_.size()) + " still moving on the pile" + at(t_, steps_) +
                            "; raise dem.rest_displacement or dem.slope_limit_deg");
  }
  progress_.finish();
  if (settled_t_ < 0) {  // no body left moving: every grain static
    if (arrived_t_ < 0) arrived_t_ = t_;
    settled_t_ = t_, held_ = true, moving_end_ = 0;
  }
  const double kinetic_end = kinetic_energy_j();
  for_each_body([&](int32_t id, int slot) { record(id, world_.position(slot)); });
  sample_layers();

  SimResult out;
  out.x = x_;
  out.y = y_;
  std::vector<uint8_t> cls(in_.grains.cls.begin(), in_.grains.cls.end());
  out.class_map = class_map_from_grains(W_, H_, x_, y_, cls, 1.2, kNoSand);
  if (frames_.count > 0) in_.frames.frame(out.class_map);  // the last frame is the picture
  if (!layer_snapshot_.empty()) out.stages.emplace_back("6-layers.png", layer_snapshot_);
  if (in_.stages) out.stages.emplace_back("7-layers-end.png", layer_map());
  // Thin the samples to about 200 for the stats.
  ordered_json thin = ordered_json::array();
  size_t every = std::max<size_t>(1, samples_.size() / 200);
  for (size_t i = 0; i < samples_.size(); i += every) thin.push_back(samples_[i]);
  if (!samples_.empty() && (samples_.size() - 1) % every) thin.push_back(samples_.back());
  out.stats["layers"] = layers_name(layers_);
  out.stats["time_step_s"] = dt_;
  out.stats["slope_limit_deg"] = rule_.slope_limit_rad * 180 / std::numbers::pi;
  out.stats["steps"] = steps_;
  out.stats["simulated_s"] = t_;
  out.stats["peak_bodies"] = peak_bodies_;
  if (layers_ == Layers::Three && s_.dem.static_bodies) {
    out.stats["static_sleeps"] = static_sleeps_;
    out.stats["static_wakes"] = static_wakes_;
  }
  out.stats["insertions_delayed"] = delayed_;
  out.stats["insertions_late_mean_s"] = inserted_ ? late_sum_ / double(inserted_) : 0.0;
  out.stats["insertions_late_max_s"] = late_max_;
  out.stats["deepest_overlap_px"] = deepest_;
  out.stats["deepest_overlap_diameters"] = deepest_ / small_d_;
  out.stats["kinetic_energy_end_J"] = kinetic_end;
  // How the run ended: its outline held (or not, after kHoldWaitS), this
  // long after the last grain arrived; the columns still moving then.
  out.stats["settling"] = {{"outline_held", held_},
                           {"after_last_arrival_s", settled_t_ - arrived_t_},
                           {"moving_columns", moving_end_}};
  out.stats["substeps"] = watch_.most_substeps();
  out.stats["substep_changes"] = substep_stats();
  out.stats["terminal_speed_px_s"] = water_.terminal_px_s;
  out.stats["layer_counts"] = thin;
  // Where the time went: each stage's wall seconds, and the body-steps
  // (sub-steps times bodies in the world) the Bullet step solved.
  out.stats["stages_s"] = times_.json();
  out.stats["body_steps"] = {{"all", body_steps_},
                             {"per_grain", n_ > 0 ? double(body_steps_) / double(n_) : 0.0},
                             {"tail", tail_body_steps_},
                             {"in_contact", contact_body_steps_}};
  if (s_.dem.run_on_s > 0) out.stats["run_on"] = run_on_;
  return out;
}

class DemSimulator final : public Simulator {
 public:
  SimResult simulate(const SimInput& in, Progress& progress) override { return DemRun(in, progress).run(); }
  Cost cost(const Scene& s) const override { return dem_cost(s); }
};

}  // namespace

std::unique_ptr<Simulator> make_dem_simulator() { return std::make_unique<DemSimulator>(); }

}  // namespace sandpic
