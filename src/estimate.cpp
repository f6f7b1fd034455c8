#include "src/estimate.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "src/errors.h"

namespace sandpic {

// Measured with the lattice on the default scene at --scale 1 to
// 3: 88 MB at 0.35 million grains, 184 MB at 3.15 million. The process
// with its libraries takes ~75 MB; the pipeline keeps ~12 bytes a grain
// (class, unit, order, settled position) and ~8 bytes a pixel of the window
// (class map, picture, background) and of the region (cells, luminance).
Estimate estimate_run(const Scene& s, const Simulator& sim) {
  Estimate e;
  const double window_px = double(s.window.width) * s.window.height, region_px = double(s.window.width) * s.region.height;
  e.grains = int64_t(region_px);
  const Cost c = sim.cost(s);
  e.bytes = 75e6 + 12 * region_px + 8 * window_px + 8 * region_px + c.bytes;
  // Initialization, segmentation, falling order and rendering: ~1 µs a
  // grain (320 million grains, lattice: 306 s of a 477 s run).
  e.seconds = 1e-6 * region_px + c.seconds;
  return e;
}

double machine_memory_bytes() {
  double bytes = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");  // "max" when unlimited
  double limit = 0;
  if (cgroup >> limit && limit > 0) bytes = std::min(bytes, limit);
  return bytes;
}

std::string human_bytes(double b) {
  char buf[32];
  if (b >= 1e9) std::snprintf(buf, sizeof buf, "%.1f GB", b / 1e9);
  else std::snprintf(buf, sizeof buf, "%.0f MB", b / 1e6);
  return buf;
}

std::string human_seconds(double s) {
  char buf[32];
  if (s >= 3600) std::snprintf(buf, sizeof buf, "%.1f h", s / 3600);
  else if (s >= 60) std::snprintf(buf, sizeof buf, "%.0f min", s / 60);
  else std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

void check_estimate(const Estimate& e, const Limits& l) {
  const double max_bytes = l.max_bytes > 0 ? l.max_bytes : 0.75 * machine_memory_bytes();
  const std::string what = std::to_string(e.grains) + " grains";
  if (e.bytes > max_bytes)
    throw InputError("the scene needs about " + human_bytes(e.bytes) + " of memory (" + what + ", " +
                     human_bytes(max_bytes) + " allowed, --max-memory-gb); lower window, region.height or --scale");
  if (e.seconds > l.max_seconds)
    throw InputError("the scene would take about " + human_seconds(e.seconds) + " to simulate (" + what + ", " +
                     human_seconds(l.max_seconds) + " allowed, --max-hours); lower --scale or use --mode lattice");
  if (e.seconds > l.note_seconds)
    std::fprintf(stderr, "sandpic: note: about %s to simulate %lld grains (%s of memory)\n", human_seconds(e.seconds).c_str(),
                 (long long)e.grains, human_bytes(e.bytes).c_str());
}

}  // namespace sandpic
