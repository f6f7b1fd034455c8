#pragma once
// The DEM's stiffness watch. Every cycle the guard's readings (the deepest
// overlap, the bodies' kinetic energy) are judged against a soft level, the
// overlap a converged contact solve keeps (dem.target_overlap), far below
// the hard divergence limits. At the soft level the run doubles
// its sub-steps (each step's water stage and world step done as n sub-steps
// of dt/n, so a cycle is still dem.cycle_steps steps), up to
// dem.max_substeps; past a hard limit below the most sub-steps it goes
// straight to the most; past one at the most it has diverged. After a long
// calm stretch it halves them again, down to one.
#include <cstdint>
#include <string>
#include <vector>

namespace sandpic {

// One cycle's readings, in the world's units (px, s, the solver's masses).
struct StiffnessReading {
  double overlap_px = 0;  // deepest overlap between two grains, or a grain and a collider, now
  double kinetic = 0;     // kinetic energy of the bodies
  double settling = 0;    // the same bodies' kinetic energy at their settling speeds
  double budget = 0;      // all the energy gravity and insertion have given so far
};

struct SubStepChange {
  double t_s = 0;
  int64_t step = 0;
  int substeps = 1;
  std::string reason;
};

class StiffnessWatch {
 public:
  enum class Verdict { Calm, Changed, Diverged };

  // target_px: dem.target_overlap in px, the soft level; max_overlap_px:
  // dem.max_overlap in px, the hard limit.
  StiffnessWatch(double target_px, double max_overlap_px, int max_substeps);

  // Judges one cycle; on Changed the new count is substeps() and the change
  // is in changes(); on Diverged, reason() says what crossed which limit.
  Verdict judge(const StiffnessReading& r, double t_s, int64_t step);

  int substeps() const { return n_; }
  int most_substeps() const { return most_; }
  const std::vector<SubStepChange>& changes() const { return changes_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string hard(const StiffnessReading& r) const;
  std::string soft(const StiffnessReading& r) const;
  bool calm(const StiffnessReading& r) const;
  void change(int n, double t_s, int64_t step);

  double target_px_, max_overlap_px_;
  int max_n_, n_ = 1, most_ = 1;
  int64_t calm_cycles_ = 0;
  std::string reason_;
  std::vector<SubStepChange> changes_;
};

}  // namespace sandpic
