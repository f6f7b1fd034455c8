#pragma once
// DEM runs kept on disk and reused while the scene digest in their stats
// holds: validate and calibrate score a new lattice in seconds against hours
// of DEM. A run is DIR/<label>.png (the picture), <label>.classes.png (its
// class map, 8-bit grey) and <label>.json (its stats).
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "src/pipeline.h"

namespace sandpic {

struct KeptRun {
  cv::Mat picture;    // 8-bit BGR, the window's size
  cv::Mat class_map;  // CV_8U; empty if the folder has none (kept by an older sandpic)
  ordered_json stats;
};

// The run kept as `label` in `dir` if its digest is the scene's and its
// picture the window's size; nothing otherwise (or if dir is "").
std::optional<KeptRun> load_kept(const std::string& dir, const std::string& label, const Scene& s);

// Writes the run's three files (each atomically); dir must exist.
void keep_run(const std::string& dir, const std::string& label, const RunResult& r);

using SimulatorFactory = std::function<std::unique_ptr<Simulator>(const Scene&)>;

// The one way validate and calibrate get a DEM run: the run kept as `label`
// in `dir` while it holds (with a class map, if `need_class_map`), else the
// scene through the pipeline (run_pipeline: its checks, every grain
// accounted for) with a simulator from `make`, kept in `dir` ("": not kept).
struct ReusedRun {
  KeptRun run;
  bool kept = false;  // it came from the folder
};
ReusedRun run_or_reuse(const std::string& dir, const std::string& label, const Scene& s, const SimulatorFactory& make,
                       bool need_class_map = false);

}  // namespace sandpic
