#include "physics/stiffness.h"

#include <algorithm>
#include <cstdio>

namespace sandpic {

namespace {

// Soft levels, measured on a 1,280-grain scene (160 x 120 px, region 8 px):
// at the defaults the deepest overlap stayed under 0.043 of the hard limit
// and the bodies' kinetic energy at most their energy at the settling
// speeds (1.0, grains inserted at that speed); at dem.step_diameters 0.5
// the overlap reached 0.5 of the limit cycles before it crossed it.
constexpr double kSoftOverlap = 0.5;  // share of the hard overlap limit
constexpr double kSoftKinetic = 4;    // × the settling speeds' energy: an rms speed twice the settling speed
// Calm: under an eighth of the hard overlap and no faster than settling,
// for this many cycles in a row: half the sub-steps.
constexpr double kCalmOverlap = 0.125;
constexpr int64_t kCalmCycles = 100;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

StiffnessWatch::StiffnessWatch(double max_overlap_px, int max_substeps)
    : max_overlap_px_(max_overlap_px), max_n_(std::max(1, max_substeps)) {}

std::string StiffnessWatch::hard(const StiffnessReading& r) const {
  if (r.overlap_px > max_overlap_px_)
    return "grains overlap by " + number(r.overlap_px) + " px, beyond dem.max_overlap (" + number(max_overlap_px_) +
           " px)";
  if (r.kinetic > r.budget * 1.0001 + 1e-9)
    return "kinetic energy " + number(r.kinetic) + " exceeds the energy released (" + number(r.budget) + ")";
  return "";
}

std::string StiffnessWatch::soft(const StiffnessReading& r) const {
  if (r.overlap_px > kSoftOverlap * max_overlap_px_)
    return "overlap " + number(r.overlap_px) + " px, over half of dem.max_overlap";
  if (r.kinetic > kSoftKinetic * r.settling)
    return "kinetic energy " + number(r.kinetic / std::max(r.settling, 1e-300)) + "x the settling speeds'";
  return "";
}

bool StiffnessWatch::calm(const StiffnessReading& r) const {
  return r.overlap_px < kCalmOverlap * max_overlap_px_ && r.kinetic <= r.settling;
}

void StiffnessWatch::change(int n, double t_s, int64_t step) {
  n_ = n;
  most_ = std::max(most_, n);
  calm_cycles_ = 0;
  changes_.push_back({t_s, step, n, reason_});
}

StiffnessWatch::Verdict StiffnessWatch::judge(const StiffnessReading& r, double t_s, int64_t step) {
  if (std::string h = hard(r); !h.empty()) {
    reason_ = h;
    if (n_ == max_n_) return Verdict::Diverged;
    change(max_n_, t_s, step);  // the run is nearly lost: the most sub-steps at once
    return Verdict::Changed;
  }
  if (std::string s = soft(r); !s.empty()) {
    calm_cycles_ = 0;
    if (n_ == max_n_) return Verdict::Calm;  // nothing more to give; the hard limit decides
    reason_ = s;
    change(std::min(max_n_, 2 * n_), t_s, step);
    return Verdict::Changed;
  }
  calm_cycles_ = calm(r) ? calm_cycles_ + 1 : 0;
  if (n_ > 1 && calm_cycles_ >= kCalmCycles) {
    reason_ = "calm for " + std::to_string(kCalmCycles) + " cycles";
    change(n_ / 2, t_s, step);
    return Verdict::Changed;
  }
  return Verdict::Calm;
}

}  // namespace sandpic
