#include "physics/stiffness.h"

#include <algorithm>
#include <cstdio>

namespace sandpic {

namespace {

// The overlap's soft level is dem.target_overlap. (It was half the hard
// limit of one diameter: a 20x step sank grains 0.27 d into each other and
// never sub-stepped, while the piles at the default step needed half the
// step to converge.) The energy's: bodies faster than settling, measured on
// a 1,280-grain scene, where at the defaults they stayed at most at their
// energy at the settling speeds (grains are inserted at that speed).
constexpr double kSoftKinetic = 4;  // × the settling speeds' energy: an rms speed twice the settling speed
// Calm: under half the target and no faster than settling, for
// this many cycles in a row: half the sub-steps.
constexpr double kCalmOverlap = 0.5;
constexpr int64_t kCalmCycles = 100;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace

StiffnessWatch::StiffnessWatch(double target_px, double max_overlap_px, int max_substeps)
    : target_px_(target_px), max_overlap_px_(max_overlap_px), max_n_(std::max(1, max_substeps)) {}

std::string StiffnessWatch::hard(const StiffnessReading& r) const {
  if (r.overlap_px > max_overlap_px_)
    return "grains overlap by " + number(r.overlap_px) + " px, beyond dem.max_overlap (" + number(max_overlap_px_) +
           " px)";
  if (r.kinetic > r.budget * 1.0001 + 1e-9)
    return "kinetic energy " + number(r.kinetic) + " exceeds the energy released (" + number(r.budget) + ")";
  return "";
}

std::string StiffnessWatch::soft(const StiffnessReading& r) const {
  if (r.overlap_px > target_px_)
    return "overlap " + number(r.overlap_px) + " px, over dem.target_overlap (" + number(target_px_) + " px)";
  if (r.kinetic > kSoftKinetic * r.settling)
    return "kinetic energy " + number(r.kinetic / std::max(r.settling, 1e-300)) + "x the settling speeds'";
  return "";
}

bool StiffnessWatch::calm(const StiffnessReading& r) const {
  return r.overlap_px < kCalmOverlap * target_px_ && r.kinetic <= r.settling;
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
