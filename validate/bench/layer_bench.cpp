#include "validate/bench/layer_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <opencv2/imgproc.hpp>

#include "src/errors.h"
#include "src/pipeline.h"
#include "validate/metrics/silhouette.h"
#include "validate/metrics/statistics.h"

namespace sandpic {
namespace {

std::string fmt(const char* f, double v) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

const std::vector<Layers> kOrder = {Layers::AllDynamic, Layers::Three, Layers::Bcre};

}  // namespace

std::vector<LayerBenchRow> run_layer_bench(const Scene& base, const LayerBenchOptions& opt, Simulator& dem,
                                           const std::function<void(const LayerBenchRow&)>& log) {
  const double base_grains = double(initialize(base).grains.size());
  if (base_grains <= 0) throw InputError("the scene has no grains to benchmark");
  std::vector<LayerBenchRow> rows;
  // all-dynamic first: it is every other model's reference.
  std::vector<Layers> order;
  for (Layers l : kOrder)
    if (std::find(opt.layers.begin(), opt.layers.end(), l) != opt.layers.end()) order.push_back(l);
  for (int64_t target : opt.grains) {
    const double scale = std::sqrt(double(target) / base_grains);
    std::map<uint64_t, cv::Mat> reference;
    for (Layers l : order) {
      if (l == Layers::AllDynamic && target > opt.all_dynamic_max) continue;
      if (l == Layers::Bcre && target > opt.bcre_max) continue;
      for (uint64_t seed : opt.seeds) {
        Scene s = base;
        s.mode = Mode::Dem;
        s.dem.layers = l;
        s.physics_seed = seed;
        if (scale != 1) apply_scale(s, scale);
        RunResult r = run_pipeline(s, dem, RunOptions{});
        LayerBenchRow row;
        row.layers = layers_name(l);
        row.target = target;
        row.grains = r.stats["grains"]["total"].get<int64_t>();
        row.seed = seed;
        row.scale = scale;
        row.simulate_s = r.stats["timing"]["simulate_s"].get<double>();
        row.steps = r.stats["backend"]["steps"].get<int64_t>();
        row.peak_bodies = r.stats["backend"]["peak_bodies"].get<int64_t>();
        if (l == Layers::AllDynamic) reference[seed] = r.class_map;
        if (auto ref = reference.find(seed); ref != reference.end()) row.silhouette_error = silhouette_error(r.class_map, ref->second);
        // all-dynamic against itself is 0; its seed-to-seed spread is the yardstick.
        if (l == Layers::AllDynamic) {
          for (auto& [other_seed, map] : reference)
            if (other_seed != seed) {
              LayerBenchRow spread = row;
              spread.layers = "all-dynamic-spread";
              spread.seed = seed;  // against each earlier seed
              spread.simulate_s = NAN;
              spread.silhouette_error = silhouette_error(r.class_map, map);
              rows.push_back(spread);
              log(spread);
            }
        }
        rows.push_back(row);
        log(row);
      }
    }
  }
  return rows;
}

std::string layer_bench_csv(const std::vector<LayerBenchRow>& rows) {
  std::string out = "layers,target_grains,grains,physics_seed,scale,simulate_s,steps,peak_bodies,silhouette_error\n";
  for (const LayerBenchRow& r : rows) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s,%lld,%lld,%llu,%.6f,%s,%lld,%lld,%s\n", r.layers.c_str(), (long long)r.target,
                  (long long)r.grains, (unsigned long long)r.seed, r.scale, fmt("%.4f", r.simulate_s).c_str(),
                  (long long)r.steps, (long long)r.peak_bodies, fmt("%.5f", r.silhouette_error).c_str());
    out += buf;
  }
  return out;
}

std::string layer_bench_table(const std::vector<LayerBenchRow>& rows) {
  std::map<int64_t, std::map<std::string, std::vector<const LayerBenchRow*>>> by;
  for (const LayerBenchRow& r : rows) by[r.target][r.layers].push_back(&r);
  auto med = [](const std::vector<const LayerBenchRow*>& v, double LayerBenchRow::*f) {
    std::vector<double> x;
    for (auto* r : v) x.push_back(r->*f);
    return median(x);
  };
  std::string out =
      "grains     three_s    bcre_s  all-dyn_s  all-dyn/three  bcre/three  err_three  err_bcre  all-dyn_spread\n";
  for (auto& [target, m] : by) {
    double t3 = med(m["three"], &LayerBenchRow::simulate_s), tb = med(m["bcre"], &LayerBenchRow::simulate_s),
           ta = med(m["all-dynamic"], &LayerBenchRow::simulate_s);
    int64_t grains = 0;
    for (auto& [name, v] : m)
      if (!v.empty()) grains = v.front()->grains;
    char buf[512];
    std::snprintf(buf, sizeof buf, "%-9lld %8s %9s %10s %14s %11s %10s %9s %15s\n", (long long)grains,
                  fmt("%.2f", t3).c_str(), fmt("%.2f", tb).c_str(), fmt("%.2f", ta).c_str(),
                  fmt("%.2f", ta / t3).c_str(), fmt("%.2f", tb / t3).c_str(),
                  fmt("%.4f", med(m["three"], &LayerBenchRow::silhouette_error)).c_str(),
                  fmt("%.4f", med(m["bcre"], &LayerBenchRow::silhouette_error)).c_str(),
                  fmt("%.4f", med(m["all-dynamic-spread"], &LayerBenchRow::silhouette_error)).c_str());
    out += buf;
  }
  return out;
}

cv::Mat layer_bench_plot(const std::vector<LayerBenchRow>& rows) {
  const int W = 800, H = 520, left = 80, right = 175, top = 30, bottom = 60;
  cv::Mat img(H, W, CV_8UC3, cv::Scalar(255, 255, 255));
  std::map<std::string, std::map<int64_t, std::vector<double>>> pts;
  std::map<std::string, std::map<int64_t, int64_t>> counts;
  for (const LayerBenchRow& r : rows)
    if (std::isfinite(r.simulate_s) && r.simulate_s > 0) {
      pts[r.layers][r.target].push_back(r.simulate_s);
      counts[r.layers][r.target] = r.grains;
    }
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for (auto& [name, m] : pts)
    for (auto& [t, v] : m) {
      double g = double(counts[name][t]), s = median(v);
      x0 = std::min(x0, g), x1 = std::max(x1, g), y0 = std::min(y0, s), y1 = std::max(y1, s);
    }
  if (x1 <= 0) return img;
  // Decades that enclose the data.
  double lx0 = std::floor(std::log10(x0)), lx1 = std::max(lx0 + 1, std::ceil(std::log10(x1)));
  double ly0 = std::floor(std::log10(y0)), ly1 = std::max(ly0 + 1, std::ceil(std::log10(y1)));
  auto px = [&](double g) { return left + (std::log10(g) - lx0) / (lx1 - lx0) * (W - left - right); };
  auto py = [&](double s) { return H - bottom - (std::log10(s) - ly0) / (ly1 - ly0) * (H - top - bottom); };
  const cv::Scalar grey(200, 200, 200), black(0, 0, 0);
  for (double d = lx0; d <= lx1; ++d) {
    int x = int(px(std::pow(10, d)));
    cv::line(img, {x, top}, {x, H - bottom}, grey);
    cv::putText(img, "1e" + std::to_string(int(d)), {x - 15, H - bottom + 20}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black);
  }
  for (double d = ly0; d <= ly1; ++d) {
    int y = int(py(std::pow(10, d)));
    cv::line(img, {left, y}, {W - right, y}, grey);
    cv::putText(img, "1e" + std::to_string(int(d)) + " s", {10, y + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black);
  }
  cv::rectangle(img, {left, top}, {W - right, H - bottom}, black);
  cv::putText(img, "grains", {(W - right) / 2, H - 15}, cv::FONT_HERSHEY_SIMPLEX, 0.55, black);
  cv::putText(img, "simulate time (median over seeds) vs grains, paper Fig. 12", {left, 20}, cv::FONT_HERSHEY_SIMPLEX,
              0.5, black);
  const std::map<std::string, cv::Scalar> colour = {
      {"three", {40, 40, 220}}, {"bcre", {200, 120, 30}}, {"all-dynamic", {30, 30, 30}}};
  int legend = top + 20;
  for (auto& [name, c] : colour) {
    if (!pts.count(name)) continue;
    std::vector<cv::Point> line;
    for (auto& [t, v] : pts[name]) line.emplace_back(int(px(double(counts[name][t]))), int(py(median(v))));
    cv::polylines(img, line, false, c, 2, cv::LINE_AA);
    for (auto& p : line) cv::circle(img, p, 4, c, cv::FILLED, cv::LINE_AA);
    cv::line(img, {W - right + 15, legend}, {W - right + 45, legend}, c, 2, cv::LINE_AA);
    cv::putText(img, name, {W - right + 50, legend + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.5, black);
    legend += 25;
  }
  return img;
}

}  // namespace sandpic
