#include "src/pipeline.h"

#include <cassert>
#include <chrono>
#include <cmath>


#include "src/errors.h"
#include "src/grain_table.h"
#include "src/image_io.h"
#include "src/render.h"

namespace sandpic {
namespace {

class Clock {
 public:
  double lap() {
    auto now = std::chrono::steady_clock::now();
    double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }
  double total() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
};

// Every grain accounted for: a settled grain lies inside the window.
int64_t grains_in_picture(const Scene& s, const SimResult& r) {
  int64_t n = 0;
  for (size_t i = 0; i < r.x.size(); ++i)
    if (std::isfinite(r.x[i]) && std::isfinite(r.y[i]) && r.x[i] >= 0 && r.x[i] <= s.window.width && r.y[i] >= 0 &&
        r.y[i] <= s.window.height)
      ++n;
  return n;
}

// The classes the picture shows: the settled sand, with render.symmetric
// its flipped copy laid over it (paper §10, Fig. 18c: a copy of the sand,
// not new grains). mirror_row, if given, gets the mirror's row (-1: none).
cv::Mat shown_classes(const Scene& s, const cv::Mat& class_map, int* mirror_row = nullptr) {
  if (!s.render.symmetric) return class_map;
  cv::Mat mirrored = class_map.clone();
  const int row = mirror_over(mirrored, kNoSand);
  if (mirror_row) *mirror_row = row;
  return mirrored;
}

}  // namespace

Prepared prepare(const Scene& s, ordered_json* timing) {
  Clock clock;
  Prepared p;
  p.init = initialize(s);
  if (timing) (*timing)["init_s"] = clock.lap();
  p.seg = segment(s, p.init.tessellation);
  if (timing) (*timing)["segment_s"] = clock.lap();
  p.order = falling_order(p.seg, p.init.grains, s.layout());
  if (timing) (*timing)["order_s"] = clock.lap();
  return p;
}

std::string layout_key(const Scene& s) {
  std::string key = "layout_seed=" + std::to_string(s.layout());
  for (const Field& f : scene_fields())
    if (f.readers & kPipeline) key.append(";").append(f.path).append("=").append(f.get(s).dump());
  return key;
}

RunResult run_pipeline(const Scene& given, Simulator& sim, const RunOptions& opt) {
  validate(given);
  const Scene s = given.mode == Mode::Lattice ? with_calibration(given) : given;
  const Estimate estimate = estimate_run(s, sim);
  check_estimate(estimate, opt.limits);
  Clock clock;
  ordered_json timing;
  cv::Mat background = load_background(s);  // read early: a bad file fails before the work
  cv::Mat figures = load_figures(s);
  timing["load_s"] = clock.lap();
  std::shared_ptr<const Prepared> prepared = opt.prepared;
  if (prepared)
    for (const char* k : {"init_s", "segment_s", "order_s"}) timing[k] = 0.0;
  else
    prepared = std::make_shared<const Prepared>(prepare(s, &timing));
  clock.lap();  // reused, or timed by prepare itself: not a part of simulate_s
  const auto& [init, seg, order] = *prepared;

  Progress progress(opt.progress, opt.fraction, opt.cancel);
  SimInput in{s, init.grains, seg, order, opt.stages};
  int frames = 0;
  double frames_s = 0;  // a part of simulate_s
  if (opt.frames > 0 && opt.frame)
    in.frames = {opt.frames, [&](const cv::Mat& class_map) {
                   const auto start = std::chrono::steady_clock::now();
                   const bool last = frames + 1 == opt.frames;  // the last frame is the picture
                   opt.frame(render(s, last ? shown_classes(s, class_map) : class_map, background, figures));
                   ++frames;
                   frames_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                 }};
  SimResult sim_result = sim.simulate(in, progress);
  timing["simulate_s"] = clock.lap();
  timing["frames_s"] = frames_s;
  assert(frames == (in.frames.wanted() ? opt.frames : 0));

  const int64_t total = init.grains.size(), in_picture = grains_in_picture(s, sim_result);
  if (in_picture != total)
    throw SimulationError(std::to_string(total - in_picture) + " of " + std::to_string(total) +
                          " grains did not settle inside the window (seed " + std::to_string(s.seed) + ")");

  RunResult out;
  int mirror_row = -1;
  out.class_map = shown_classes(s, sim_result.class_map, &mirror_row);
  out.picture = render(s, out.class_map, background, figures);
  timing["render_s"] = clock.lap();
  out.png = opt.palette_png ? encode_png_indexed(out.picture) : encode_png(out.picture);
  timing["encode_s"] = clock.lap();
  if (opt.grains) out.grains = grain_table_csv(s, init.grains, seg, order, sim_result.x, sim_result.y);
  if (opt.stages) {
    out.stages = stage_pictures(s, init, seg, order);
    out.stages.emplace_back("5-picture.png", out.picture);
    for (auto& stage : sim_result.stages) out.stages.push_back(stage);
    timing["stages_s"] = clock.lap();
  }
  timing["total_s"] = clock.total();
  if (opt.prepared) timing["layout_reused"] = true;
  out.prepared = std::move(prepared);

  ordered_json& st = out.stats;
  st["mode"] = mode_name(s.mode);
  st["scene_digest"] = scene_digest(s);
  if (s.mode == Mode::Lattice && !s.lattice.calibration.empty()) st["calibration"] = s.resolve(s.lattice.calibration);
  st["seed"] = s.seed;
  st["layout_seed"] = s.layout();
  st["physics_seed"] = s.physics_rng();
  st["window"] = {s.window.width, s.window.height};
  st["region"] = {s.window.width, s.region.height};
  st["units"] = seg.units.size();
  st["frames"] = frames;
  st["grains"]["total"] = total;
  st["grains"]["per_class"] = init.grains.per_class();
  st["grains"]["released"] = int64_t(order.grain.size());
  st["grains"]["in_picture"] = in_picture;
  if (mirror_row >= 0) st["symmetric"]["mirror_row"] = mirror_row;
  st["timing"] = timing;
  st["estimate"] = {{"bytes", estimate.bytes}, {"seconds", estimate.seconds}};
  st["backend"] = sim_result.stats;
  return out;
}

}  // namespace sandpic
