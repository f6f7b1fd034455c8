#pragma once
// The pipeline: initialize → segment → order → simulate → render, each a free
// function over plain data, timed into the stats (paper Table 1's columns).
#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "src/estimate.h"
#include "src/init/init.h"
#include "src/segment/segment.h"
#include "src/simulator.h"
#include "src/stages.h"

namespace sandpic {

struct RunOptions {
  bool stages = false;    // keep the intermediate pictures of Fig. 2
  bool progress = false;  // draw a progress bar on stderr
  bool palette_png = false;  // RunResult::png as a palette PNG where it can be (encode_png_indexed: the studio's previews)
  // The simulation's done / total, kept up to date for another thread (the
  // studio's render status); nullptr: none.
  std::atomic<double>* fraction = nullptr;
  // Set by another thread to stop the run: run_pipeline throws Cancelled at
  // the backend's next progress update. nullptr: the run cannot be stopped.
  const std::atomic<bool>* cancel = nullptr;
  // paper Fig. 14c-d: `frames` pictures of the fall (8-bit BGR, window
  // size, drawn as the final picture is), handed to `frame` one at a time
  // as the backend makes them: the caller streams them out. The last one is
  // the picture. 0 or no `frame`: none, at no cost.
  int frames = 0;
  std::function<void(const cv::Mat& picture)> frame = nullptr;
  Limits limits = {};  // checked against estimate_run before anything is allocated
  bool grains = false;  // keep every grain's release point and resting place (RunResult::grains)
  // The stages before the simulation, from an earlier run of a scene with the
  // same layout_key (the studio's previews while a physics key is dragged);
  // nullptr: prepared here.
  std::shared_ptr<const struct Prepared> prepared = nullptr;
};

struct RunResult {
  cv::Mat picture;          // 8-bit BGR, window size
  cv::Mat class_map;        // the backend's: CV_8U, class 0..3 or kNoSand
  std::vector<uchar> png;   // the picture, encoded
  ordered_json stats;
  Stages stages;
  std::string grains;  // with RunOptions::grains: the grain table (src/grain_table.h), CSV
  std::shared_ptr<const struct Prepared> prepared;  // what the simulation started from, to reuse
};

// The stages before the simulation, what every backend starts from:
// initialization (paper §4), segmentation into units (§5) and the falling
// order (§6). Calibration and tests simulate these many times over.
struct Prepared {
  Initialization init;
  Segmentation seg;
  FallingOrder order;
  SimInput input(const Scene& s) const { return SimInput{s, init.grains, seg, order}; }
};
// `timing`, if given, gets init_s, segment_s and order_s.
Prepared prepare(const Scene& s, ordered_json* timing = nullptr);
// The values of every key the stages before the simulation read (paper
// §4-6) and the layout seed: scenes with the same key prepare the same.
std::string layout_key(const Scene& s);

// Throws InputError (bad scene or file), SimulationError (a grain lost, a
// NaN) or Cancelled (opt.cancel set): nothing is returned that should not be written.
RunResult run_pipeline(const Scene& s, Simulator& sim, const RunOptions& opt);

}  // namespace sandpic
