#include "lattice/lattice_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>

#include "src/errors.h"
#include "src/frames.h"
#include "src/release.h"
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
    SimResult out;
    out.x.assign(size_t(in.grains.size()), NAN);
    out.y.assign(size_t(in.grains.size()), NAN);
    progress.start("lattice", int64_t(in.order.grain.size()));
    FrameSchedule schedule{int64_t(in.order.grain.size()), in.frames.wanted() ? in.frames.count : 0};
    if (schedule.due(0)) emit_frame(in, field, 0, 0, schedule);
    // Sequential on purpose: each grain lands on the surface the previous
    // ones made.
    int64_t landed = 0, released = 0;
    auto land = [&](int32_t id, double x) {
      const uint8_t k = in.grains.cls[size_t(id)];
      int c = std::clamp(int(std::floor(x * columns_per_px)), 0, columns - 1);
      double rise = area[k] * columns_per_px;
      c = field.settle(c, rule_of[k], seed, uint64_t(id));
      if (field.height(c) + rise > H) c = field.room_near(c, rise);
      if (c >= 0) {  // else no room anywhere: the grain stays unaccounted (NaN)
        double centre = field.deposit(c, k, area[k]);
        out.x[size_t(id)] = float((c + 0.5) / columns_per_px);
        out.y[size_t(id)] = float(H - centre);
      }
      ++landed;
      if (schedule.due(landed)) emit_frame(in, field, landed, released, schedule);
    };
    // paper §7 in the device's water, as the DEM releases and drops its
    // grains: they leave in falling order at dem.release_rate and land in
    // the order they reach the pile (Eq. 1 to the outlet, then the class's
    // settling speed down to the surface as it is at release). A unit's small
    // grains land after its big ones and cap its pile, as in the DEM.
    const bool settling = s.lattice.arrival == LatticeArrival::Settling;
    const Water water = settling ? water_model(s) : Water{};
    Arrivals arrivals;
    std::vector<double> exit_at(settling ? in.grains.size() : 0);
    // A landing spot (a pixel column) is busy for lattice.spot_busy_s after
    // a grain lands on it, as the DEM's insert stage waits while a grain is in
    // the way. Grains due on a busy spot wait there; when it frees, the first
    // of them in falling order lands, as in the DEM, whose waiting grains all
    // retry at once and go in falling order. One event per busy spot waits in
    // `arrivals`, so a long queue costs a heap push per grain, not per retry.
    const double busy_s = settling ? s.lattice.spot_busy_s : 0;
    struct Spot {
      double free_at = -INFINITY;
      std::priority_queue<int64_t, std::vector<int64_t>, std::greater<>> waiting;  // falling-order indices
    };
    std::vector<Spot> spots(busy_s > 0 ? size_t(W) : 0);
    std::vector<uint8_t> queued(busy_s > 0 ? in.grains.size() : 0, 0);
    int64_t waited = 0;
    double last_landing_s = 0;
    auto land_at = [&](double time, int32_t id) {
      last_landing_s = std::max(last_landing_s, time);
      land(id, exit_at[size_t(id)]);
    };
    auto land_until = [&](double t) {
      while (!arrivals.empty() && arrivals.top().time <= t) {
        const Arrival a = arrivals.top();
        arrivals.pop();
        const int32_t id = in.order.grain[size_t(a.order)];
        if (busy_s <= 0) {
          land_at(a.time, id);
          continue;
        }
        Spot& spot = spots[size_t(std::clamp(int(std::floor(exit_at[size_t(id)])), 0, W - 1))];
        int32_t lands = id;
        if (queued[size_t(id)]) {  // the spot's event: it is free, the first waiting grain lands
          lands = in.order.grain[size_t(spot.waiting.top())];
          spot.waiting.pop();
          queued[size_t(lands)] = 0;
        } else if (spot.free_at > a.time || !spot.waiting.empty()) {
          spot.waiting.push(a.order);
          queued[size_t(id)] = 1;
          ++waited;
          if (spot.waiting.size() == 1) arrivals.push({spot.free_at, a.order});
          continue;
        }
        spot.free_at = a.time + busy_s;
        if (!spot.waiting.empty()) arrivals.push({spot.free_at, spot.waiting.top()});
        land_at(a.time, lands);
      }
    };
    for (size_t u = 0; u < in.seg.units.size(); ++u) {
      const Outlet o = outlet(model, in.seg.units[u]);
      for (int64_t i = in.order.unit_begin[u]; i < in.order.unit_begin[u + 1]; ++i) {
        const int32_t id = in.order.grain[size_t(i)];
        if (!settling) {
          released = i + 1;
          land(id, exit_x(model, o, id));
          continue;
        }
        const double t = double(i) / s.dem.release_rate;
        released = i;  // the landings due before grain i leaves
        land_until(t);
        released = i + 1;
        const ReleasePath path = release(model, o, in.grains, id);
        exit_at[size_t(id)] = path.exit_x;
        const int c = std::clamp(int(std::floor(path.exit_x * columns_per_px)), 0, columns - 1);
        const double settling_px_s = water.terminal_px_s[in.grains.cls[size_t(id)]];
        arrivals.push({arrival_time(t, path, H - o.centre.y(), field.height(c), settling_px_s), i});
      }
      progress.update(landed);
    }
    land_until(INFINITY);
    progress.finish();
    out.class_map = field.class_map(W, H, kNoSand, s.lattice.surface_px, picture_shares(s));
    if (schedule.count > 0) in.frames.frame(out.class_map);  // the last frame is the picture
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
