#include "src/release.h"

#include <algorithm>
#include <cmath>

#include "src/rng.h"

namespace sandpic {

ReleaseModel release_model(const Scene& s) {
  ReleaseModel m;
  m.gravity_px_s2 = s.release.gravity_m_s2 * 1000 * px_per_mm(s);
  m.outlet_width_px = s.release.outlet_width_mm * px_per_mm(s);
  m.window_width_px = s.window.width;
  for (int k = 0; k < kClasses; ++k) m.min_drop_px[k] = grain_diameter_px(s, k);
  m.physics_seed = s.physics_rng();
  return m;
}

Outlet outlet(const ReleaseModel& m, const Unit& u) {
  Outlet o{u.outlet(), std::min({m.outlet_width_px, u.width(), m.window_width_px})};
  o.centre.x() = std::clamp(o.centre.x(), o.width / 2, m.window_width_px - o.width / 2);
  return o;
}

ReleasePath release(const ReleaseModel& m, const Outlet& o, const GrainSet& g, int32_t id) {
  ReleasePath p;
  p.start = g.position(id);
  p.outlet = o.centre;
  double dx = p.outlet.x() - p.start.x();
  double dy = std::max(p.outlet.y() - p.start.y(), m.min_drop_px[g.cls[id]]);
  p.vx = dx * std::sqrt(m.gravity_px_s2 / (2 * dy));
  p.t = std::sqrt(2 * dy / m.gravity_px_s2);
  p.exit_x = exit_x(m, o, id);
  return p;
}

double arrival_time(double at_outlet_s, double outlet_up_px, double land_px, double settling_px_s) {
  const double drop = outlet_up_px - land_px;
  const double fall = settling_px_s > 0 ? std::max(0.0, drop) / settling_px_s : 0;
  return at_outlet_s + fall;
}

double arrival_time(double t_release, const ReleasePath& p, double outlet_up_px, double land_px, double settling_px_s) {
  return arrival_time(t_release + p.t, outlet_up_px, land_px, settling_px_s);
}

double exit_x(const ReleaseModel& m, const Outlet& o, int32_t id) {
  return o.centre.x() + (uniform(m.physics_seed, Stream::OutletJitter, uint64_t(id)) - 0.5) * o.width;
}

// Buckets are counted from base_: first_[b - base_]. The last bucket takes
// everything later (a grain sinking for hours), so the index stays bounded and
// never decreases with time, which is all the order needs.
int64_t Arrivals::bucket(double time) const {
  constexpr double kMostBuckets = 1 << 20;
  const double b = std::floor(time / bucket_s_);
  return b >= 0 ? int64_t(std::min(b, kMostBuckets)) : 0;  // NaN: the first
}

void Arrivals::push(const Arrival& a) {
  ++size_;
  const int64_t b = bucket_s_ > 0 ? bucket(a.time) : open_;
  if (b <= open_) {
    // Into its place among the open bucket's, latest first.
    open_list_.insert(std::upper_bound(open_list_.begin(), open_list_.end(), a, std::greater<>{}), a);
    return;
  }
  const size_t at = size_t(b - base_);
  if (first_.size() <= at) first_.resize(std::max(at + 1, 2 * first_.size()), -1);
  int32_t slot;
  if (free_.empty()) {
    slot = int32_t(pool_.size());
    pool_.push_back(a);
    next_.push_back(first_[at]);
  } else {
    slot = free_.back();
    free_.pop_back();
    pool_[size_t(slot)] = a;
    next_[size_t(slot)] = first_[at];
  }
  first_[at] = slot;
}

// The open bucket empty: open the next that has arrivals.
const Arrival& Arrivals::top() {
  while (open_list_.empty() && size_ > 0) {
    size_t at = size_t(open_ - base_) + 1;
    while (first_[at] < 0) ++at;  // size_ > 0: some later bucket has arrivals
    open_ = base_ + int64_t(at);
    for (int32_t i = first_[at]; i >= 0; i = next_[size_t(i)]) {
      open_list_.push_back(pool_[size_t(i)]);
      free_.push_back(i);
    }
    first_[at] = -1;
    std::sort(open_list_.begin(), open_list_.end(), std::greater<>{});
    if (2 * at > first_.size()) {  // drop the buckets behind, now and then
      first_.erase(first_.begin(), first_.begin() + std::ptrdiff_t(at));
      base_ = open_;
    }
  }
  return open_list_.back();
}

void Arrivals::pop() {
  top();
  open_list_.pop_back();
  --size_;
}

}  // namespace sandpic
