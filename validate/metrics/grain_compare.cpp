#include "validate/metrics/grain_compare.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "src/errors.h"

namespace sandpic {

namespace {

// Percentile by the nearest rank of a sorted sample.
double rank_of(const std::vector<double>& sorted, double q) {
  return sorted[std::min(sorted.size() - 1, size_t(std::floor(q * double(sorted.size()))))];
}

TravelStats travel_stats(const std::vector<double>& sorted) {
  TravelStats t;
  t.grains = int64_t(sorted.size());
  if (sorted.empty()) return t;
  double sum = 0;
  int64_t near = 0;
  for (double d : sorted) sum += d, near += d <= 2;
  t.mean_px = sum / double(sorted.size());
  t.median_px = rank_of(sorted, 0.5);
  t.p90_px = rank_of(sorted, 0.9);
  t.within_2px = double(near) / double(sorted.size());
  return t;
}

struct UnitMoments {
  double n = 0, mean = 0, spread = 0;  // grains, mean resting x, its standard deviation
};

std::map<int32_t, UnitMoments> unit_moments(const std::vector<GrainRow>& rows) {
  std::map<int32_t, std::array<double, 3>> sums;  // per unit: n, Σx, Σx²
  for (const GrainRow& r : rows) {
    auto& s = sums[r.unit];
    s[0] += 1, s[1] += r.x, s[2] += r.x * r.x;
  }
  std::map<int32_t, UnitMoments> m;
  for (auto& [unit, s] : sums) {
    const double mean = s[1] / s[0];
    m[unit] = {s[0], mean, std::sqrt(std::max(0.0, s[2] / s[0] - mean * mean))};
  }
  return m;
}

}  // namespace

GrainComparison compare_grains(const std::vector<GrainRow>& a, const std::vector<GrainRow>& b, const std::string& name_a,
                               const std::string& name_b) {
  if (a.size() != b.size())
    throw InputError(name_b + " holds " + std::to_string(b.size()) + " grains but " + name_a + " " +
                     std::to_string(a.size()) + ": not one scene and layout");
  GrainComparison c;
  c.grains = int64_t(a.size());
  c.same_release = true;
  std::array<std::vector<double>, kClasses> ta, tb;
  double dx = 0, dy = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const GrainRow &p = a[i], &q = b[i];
    if (p.id != q.id || p.cls != q.cls || p.unit != q.unit || p.order != q.order)
      throw InputError(name_b + ": grain " + std::to_string(q.id) + " (line " + std::to_string(i + 2) +
                       ") is not the same grain as in " + name_a + ": not one scene and layout");
    // Tables hold positions to 0.001 px: the same point within rounding.
    c.same_release = c.same_release && std::abs(p.release_x - q.release_x) < 0.0015;
    ta[size_t(p.cls)].push_back(std::abs(p.x - p.release_x));
    tb[size_t(q.cls)].push_back(std::abs(q.x - q.release_x));
    dx += std::abs(p.x - q.x), dy += std::abs(p.y - q.y);
  }
  for (int k = 0; k < kClasses; ++k) {
    auto &sa = ta[size_t(k)], &sb = tb[size_t(k)];
    std::sort(sa.begin(), sa.end());
    std::sort(sb.begin(), sb.end());
    c.travel_a[size_t(k)] = travel_stats(sa);
    c.travel_b[size_t(k)] = travel_stats(sb);
    double w = 0;
    for (size_t i = 0; i < sa.size(); ++i) w += std::abs(sa[i] - sb[i]);
    c.travel_distance_px[size_t(k)] = sa.empty() ? 0 : w / double(sa.size());
  }
  // Both tables hold the same grains, so the same units of the same sizes.
  const auto ua = unit_moments(a), ub = unit_moments(b);
  for (const auto& [unit, p] : ua) {
    const UnitMoments& q = ub.at(unit);
    c.unit_spread_a_px += p.n * p.spread, c.unit_spread_b_px += q.n * q.spread;
    c.unit_centroid_distance_px += p.n * std::abs(p.mean - q.mean);
    c.unit_spread_difference_px += p.n * std::abs(p.spread - q.spread);
  }
  if (!a.empty())
    for (double* v : {&c.unit_spread_a_px, &c.unit_spread_b_px, &c.unit_centroid_distance_px, &c.unit_spread_difference_px})
      *v /= double(a.size());
  c.grain_dx_px = c.same_release ? dx / double(a.size()) : NAN;
  c.grain_dy_px = c.same_release ? dy / double(a.size()) : NAN;
  return c;
}

}  // namespace sandpic
