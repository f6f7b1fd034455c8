#include "physics/outline_watch.h"

#include <algorithm>
#include <cmath>

#include "physics/holds.h"

namespace sandpic {

bool OutlineWatch::due(double t) const {
  // The tolerance: t is a sum of steps, and a sample a rounding early must
  // not wait a whole cycle more.
  return outlines_.empty() || t - outlines_.back().t >= kHoldSeconds / 10 * (1 - 1e-9);
}

void OutlineWatch::add(double t, std::vector<double> top) {
  outlines_.push_back({t, std::move(top)});
  // Keep the newest outlines that reach back kHoldSeconds, and no older.
  while (outlines_.size() > 2 && t - outlines_[1].t >= kHoldSeconds) outlines_.pop_front();
}

int64_t OutlineWatch::moving_columns() const {
  if (outlines_.empty()) return 0;
  const size_t columns = outlines_.back().top.size();
  if (outlines_.back().t - outlines_.front().t < kHoldSeconds * (1 - 1e-9)) return int64_t(columns);
  int64_t moving = 0;
  for (size_t j = 0; j < columns; ++j) {
    double lo = INFINITY, hi = -INFINITY;
    bool finite = true;
    for (const Outline& o : outlines_) lo = std::min(lo, o.top[j]), hi = std::max(hi, o.top[j]), finite &= std::isfinite(o.top[j]);
    moving += !(finite && hi - lo < hold_px_);
  }
  return moving;
}

bool OutlineWatch::holds() const {
  return !outlines_.empty() && double(moving_columns()) <= kUnsettled * double(outlines_.back().top.size());
}

}  // namespace sandpic
