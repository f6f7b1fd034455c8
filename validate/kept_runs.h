#pragma once
// DEM runs kept on disk and reused while the scene digest in their stats
// holds: validate and calibrate score a new lattice in seconds against hours
// of DEM. A run is DIR/<label>.png (the picture), <label>.classes.png (its
// class map, 8-bit grey) and <label>.json (its stats).
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

}  // namespace sandpic
