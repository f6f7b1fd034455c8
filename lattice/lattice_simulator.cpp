#include "lattice/lattice_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>

#include <tbb/task_group.h>

#include "src/errors.h"
#include "src/frames.h"
#include "src/release.h"
#include "src/stage_times.h"
#include "src/water.h"

namespace sandpic {

double lattice_area_px(const Scene& s, int k) { return grain_area_px(s, k) * s.lattice.bulk; }

SlopeRule make_slope_rule(double degrees, double rise_px, double column_px, double runout_px) {
  SlopeRule r;
  r.drop_per_column = std::tan(degrees * std::numbers::pi / 180) * column_px;
  // The window spreads a grain's own height step (rise) over enough columns
  // that it changes the slope by at most half the rule's slope.
  // Clamped as a double: at friction 0 the ratio is far beyond any int.
  r.window = int(std::clamp(std::ceil(2 * rise_px / std::max(r.drop_per_column, 1e-9)), 1.0,
                            double(HeightField::kMaxWindow)));
  r.runout = int(std::lround(runout_px / column_px));
  return r;
}

SlopeRule slope_rule(const Scene& s, int k) {
  const double column_px = 1 / s.lattice.resolution;
  SlopeRule r = make_slope_rule(repose_angle_deg(s, k), lattice_area_px(s, k) / column_px, column_px,
                                s.lattice.runout_px[k]);
  if (s.lattice.window_columns > 0) r.window = s.lattice.window_columns;
  if (s.lattice.trap_rate > 0) {
    r.trap_rate = s.lattice.trap_rate;
    r.trap_drop_per_column =
        std::tan(std::min(89.0, repose_angle_deg(s, k) + s.lattice.trap_deg) * std::numbers::pi / 180) * column_px;
  }
  return r;
}

namespace {

// lattice.picture_share as the height field takes it: none when all are equal.
std::vector<double> picture_shares(const Scene& s) {
  const auto& w = s.lattice.picture_share;
  if (std::all_of(w.begin(), w.end(), [&](double v) { return v == w[0]; })) return {};
  return {w.begin(), w.end()};
}

double columns_per_px_of(const Scene& s, int columns) { return columns / double(s.window.width); }

// paper Fig. 14c-d: the pile of the first `landed` grains, and the grains
// after the first `released` of the falling order still at their places in
// the region (those between are on their way down, not drawn).
void emit_frame(const SimInput& in, const HeightField& field, int64_t landed, int64_t released,
                FrameSchedule& schedule) {
  cv::Mat map = field.class_map(in.scene.window.width, in.scene.window.height, kNoSand, in.scene.lattice.surface_px,
                                picture_shares(in.scene));
  draw_waiting(map, in.grains, std::span<const int32_t>(in.order.grain).subspan(size_t(released)));
  for (; schedule.due(landed); ++schedule.next) in.frames.frame(map);
}

// paper §7, Eq. 1-2: where and when each grain reaches its outlet's height
// does not depend on the pile. The plan is worked out chunk by chunk in
// falling order, the next chunk on another core while this one lands. What a
// landing needs (class, column, spot) is kept for every grain, since grains
// land long after they leave; the times only for the chunk being released.
class FallPlan {
 public:
  static constexpr int64_t kChunk = 16384;

  FallPlan(const SimInput& in, const ReleaseModel& model, bool settling, bool spots, int columns)
      : in_(in), model_(model), settling_(settling), columns_per_px_(columns / double(in.scene.window.width)),
        columns_(columns), n_(int64_t(in.order.grain.size())), cls(size_t(n_)), column(size_t(n_)),
        spot(spots ? size_t(n_) : 0) {
    for (const Unit& u : in.seg.units) outlets_.push_back(outlet(model, u));
  }

  struct Chunk {
    int64_t begin = 0, end = 0;
    std::vector<double> due;           // s: at the outlet's height (settling arrival only)
    std::vector<double> outlet_up_px;  // the outlet above the floor (settling arrival only)
  };

  // Plans grains [begin, begin + kChunk) into `c` (and their landing data).
  void plan(Chunk& c, int64_t begin) {
    c.begin = begin;
    c.end = std::min(n_, begin + kChunk);
    c.due.resize(size_t(c.end - c.begin));
    c.outlet_up_px.resize(size_t(c.end - c.begin));
    const std::vector<int64_t>& starts = in_.order.unit_begin;
    size_t u = size_t(std::upper_bound(starts.begin(), starts.end(), begin) - starts.begin()) - 1;
    const double H = in_.scene.window.height, rate = in_.scene.dem.release_rate;
    for (int64_t i = c.begin; i < c.end; ++i) {
      while (i >= starts[u + 1]) ++u;
      const Outlet& o = outlets_[u];
      const int32_t id = in_.order.grain[size_t(i)];
      cls[size_t(i)] = in_.grains.cls[size_t(id)];
      double x;
      if (settling_) {
        const ReleasePath path = release(model_, o, in_.grains, id);
        x = path.exit_x;
        c.due[size_t(i - c.begin)] = double(i) / rate + path.t;
        c.outlet_up_px[size_t(i - c.begin)] = H - o.centre.y();
      } else {
        x = exit_x(model_, o, id);
      }
      column[size_t(i)] = std::clamp(int(std::floor(x * columns_per_px_)), 0, columns_ - 1);
      if (!spot.empty()) spot[size_t(i)] = std::clamp(int(std::floor(x)), 0, in_.scene.window.width - 1);
    }
  }

 private:
  const SimInput& in_;
  const ReleaseModel& model_;
  bool settling_;
  double columns_per_px_;
  int columns_;
  int64_t n_;
  std::vector<Outlet> outlets_;

 public:
  // By falling-order index, for every grain planned so far.
  std::vector<uint8_t> cls;
  std::vector<int32_t> column;
  std::vector<int32_t> spot;  // the pixel column it falls on (with lattice.spot_busy_s only)
};

class LatticeSimulator final : public Simulator {
 public:
  // Measured: the default scene at --scale 1 to 3 (0.35 to 3.15
  // million grains) takes 0.43 µs a grain to settle; the pile keeps about
  // 8 bytes a grain beside the pipeline's own arrays.
  Cost cost(const Scene& s) const override {
    const double grains = double(s.window.width) * s.region.height;
    return {8 * grains + 64 * s.window.width * std::max(1.0, s.lattice.resolution), 0.45e-6 * grains};
  }

  SimResult simulate(const SimInput& in, Progress& progress) override {
    const Scene& s = in.scene;
    const int W = s.window.width, H = s.window.height;
    const int columns = std::max(1, int(std::lround(W * s.lattice.resolution)));
    // Classes that share a rule (S1/S2 and S3/S4 by default) share its
    // bookkeeping in the height field.
    std::vector<SlopeRule> rules;
    std::array<int, kClasses> rule_of;
    std::array<double, kClasses> area;
    for (int k = 0; k < kClasses; ++k) {
      SlopeRule r = slope_rule(s, k);
      auto at = std::find(rules.begin(), rules.end(), r);
      rule_of[k] = int(at - rules.begin());
      if (at == rules.end()) rules.push_back(r);
      area[k] = lattice_area_px(s, k);
    }
    // A grain raises one column by its whole rise: a column holds whole
    // grains only, so a grid too fine for the window loses sand.
    double rise = *std::max_element(area.begin(), area.end()) * columns_per_px_of(s, columns);
    if (double(columns) * std::floor(H / rise) < double(in.grains.size()))
      throw key_error("lattice.resolution", "too fine for this window: a column holds " +
                                                std::to_string(int(std::floor(H / rise))) +
                                                " grains of the largest class; lower it");
    HeightField field(columns, double(W) / columns, H, rules);

    const ReleaseModel model = release_model(s);
    const uint64_t seed = s.physics_rng();
    const double columns_per_px = columns / double(W);
    const int64_t n = int64_t(in.order.grain.size());
    SimResult out;
    out.x.assign(size_t(in.grains.size()), NAN);
    out.y.assign(size_t(in.grains.size()), NAN);
    progress.start("lattice", n);
    FrameSchedule schedule{n, in.frames.wanted() ? in.frames.count : 0};
    // Where the time goes (stats: stages_s).
    enum Stage : size_t { kLand, kFrames, kDraw, kStages };
    StageTimes<kStages> times{{"land", "frames", "draw"}};
    if (schedule.due(0)) times.time(kFrames, [&] { emit_frame(in, field, 0, 0, schedule); });

    // paper §7 in the device's water, as the DEM releases and drops its
    // grains: they leave in falling order at dem.release_rate and land in
    // the order they reach the pile (Eq. 1 to the outlet, then the class's
    // settling speed down to the surface as it is at release). A unit's small
    // grains land after its big ones and cap its pile, as in the DEM.
    const bool settling = s.lattice.arrival == LatticeArrival::Settling;
    const Water water = settling ? water_model(s) : Water{};
    // A landing spot (a pixel column) is busy for lattice.spot_busy_s after
    // a grain lands on it, as the DEM's insert stage waits while a grain is in
    // the way. Grains due on a busy spot wait there; when it frees, the first
    // of them in falling order lands, as in the DEM, whose waiting grains all
    // retry at once and go in falling order. One event per busy spot waits in
    // `arrivals`, so a long queue costs a heap push per grain, not per retry.
    const double busy_s = settling ? s.lattice.spot_busy_s : 0;
    FallPlan plan(in, model, settling, busy_s > 0, columns);

    // Sequential on purpose: each grain lands on the surface the previous
    // ones made.
    int64_t landed = 0, released = 0;
    auto land = [&](int64_t i) {
      const uint8_t k = plan.cls[size_t(i)];
      int c = plan.column[size_t(i)];
      double rise = area[k] * columns_per_px;
      const int32_t id = in.order.grain[size_t(i)];
      c = field.settle(c, rule_of[k], seed, uint64_t(id));
      if (field.height(c) + rise > H) c = field.room_near(c, rise);
      if (c >= 0) {  // else no room anywhere: the grain stays unaccounted (NaN)
        double centre = field.deposit(c, k, area[k]);
        out.x[size_t(id)] = float((c + 0.5) / columns_per_px);
        out.y[size_t(id)] = float(H - centre);
      }
      ++landed;
      if (schedule.due(landed)) times.time(kFrames, [&] { emit_frame(in, field, landed, released, schedule); });
    };
    struct Spot {
      double free_at = -INFINITY;
      std::priority_queue<int64_t, std::vector<int64_t>, std::greater<>> waiting;  // falling-order indices
    };
    std::vector<Spot> spots(busy_s > 0 ? size_t(W) : 0);
    std::vector<uint8_t> queued(busy_s > 0 ? size_t(n) : 0, 0);
    // About 16 grains leave per bucket of the calendar queue.
    Arrivals arrivals(16 / s.dem.release_rate);
    int64_t waited = 0;
    double last_landing_s = 0;
    auto land_at = [&](double time, int64_t i) {
      last_landing_s = std::max(last_landing_s, time);
      land(i);
    };
    auto land_until = [&](double t) {
      while (!arrivals.empty() && arrivals.top().time <= t) {
        const Arrival a = arrivals.top();
        arrivals.pop();
        if (busy_s <= 0) {
          land_at(a.time, a.order);
          continue;
        }
        Spot& spot = spots[size_t(plan.spot[size_t(a.order)])];
        int64_t lands = a.order;
        if (queued[size_t(a.order)]) {  // the spot's event: it is free, the first waiting grain lands
          lands = spot.waiting.top();
          spot.waiting.pop();
          queued[size_t(lands)] = 0;
        } else if (spot.free_at > a.time || !spot.waiting.empty()) {
          spot.waiting.push(a.order);
          queued[size_t(a.order)] = 1;
          ++waited;
          if (spot.waiting.size() == 1) arrivals.push({spot.free_at, a.order});
          continue;
        }
        spot.free_at = a.time + busy_s;
        if (!spot.waiting.empty()) arrivals.push({spot.free_at, spot.waiting.top()});
        land_at(a.time, lands);
      }
    };
    times.time_without(kLand, kFrames, [&] {
      std::array<FallPlan::Chunk, 2> chunks;
      tbb::task_group planning;
      if (n > 0) plan.plan(chunks[0], 0);
      for (size_t j = 0; int64_t(j) * FallPlan::kChunk < n; ++j) {
        const FallPlan::Chunk& chunk = chunks[j % 2];
        if (chunk.end < n) planning.run([&, begin = chunk.end] { plan.plan(chunks[(j + 1) % 2], begin); });
        for (int64_t i = chunk.begin; i < chunk.end; ++i) {
          if ((i & 4095) == 0) progress.update(landed);
          if (!settling) {  // lattice.arrival release: in falling order, as they leave
            released = i + 1;
            land(i);
            continue;
          }
          released = i;  // the landings due before grain i leaves
          land_until(double(i) / s.dem.release_rate);
          released = i + 1;
          const size_t at = size_t(i - chunk.begin);
          const double settling_px_s = water.terminal_px_s[plan.cls[size_t(i)]];
          arrivals.push({arrival_time(chunk.due[at], chunk.outlet_up_px[at], field.height(plan.column[size_t(i)]),
                                      settling_px_s),
                         i});
        }
        planning.wait();
      }
      land_until(INFINITY);
    });
    progress.finish();
    times.time(kDraw, [&] { out.class_map = field.class_map(W, H, kNoSand, s.lattice.surface_px, picture_shares(s)); });
    if (schedule.count > 0) in.frames.frame(out.class_map);  // the last frame is the picture
    out.stats["stages_s"] = times.json();
    out.stats["columns"] = columns;
    out.stats["pile_max_height_px"] = field.max_height();
    if (settling) {
      out.stats["last_landing_s"] = last_landing_s;
      out.stats["grains_waited"] = waited;
    }
    for (int k = 0; k < kClasses; ++k) {
      out.stats["repose_deg"].push_back(repose_angle_deg(s, k));
      out.stats["window_columns"].push_back(rules[size_t(rule_of[k])].window);
    }
    return out;
  }
};

}  // namespace

std::unique_ptr<Simulator> make_lattice_simulator() { return std::make_unique<LatticeSimulator>(); }

}  // namespace sandpic
