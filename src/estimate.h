#pragma once
// What a run will take, from the scene alone, and the limits it must stay
// under: a scene past them is refused with the figure before anything is
// allocated, instead of failing half-way or taking the machine.
#include <cstdint>
#include <limits>
#include <string>

#include "src/simulator.h"

namespace sandpic {

struct Estimate {
  int64_t grains = 0;  // one a pixel of the region (§4.1)
  double bytes = 0;    // peak memory of the whole run
  double seconds = 0;  // on 2 cores; an order of magnitude
};

struct Limits {
  double max_bytes = 0;  // 0: three quarters of this machine's memory
  double max_seconds = std::numeric_limits<double>::infinity();
  double note_seconds = std::numeric_limits<double>::infinity();  // longer: one line on stderr first
};

Estimate estimate_run(const Scene& s, const Simulator& sim);
// Memory the process may use: physical memory, or the cgroup's limit if lower.
double machine_memory_bytes();
// Throws InputError naming the figure and the limit; prints the note.
void check_estimate(const Estimate& e, const Limits& l);
std::string human_bytes(double bytes);
std::string human_seconds(double seconds);

}  // namespace sandpic
