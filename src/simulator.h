#pragma once
// The one interface through which src/ knows a simulation backend (lattice/,
// physics/). A backend turns released grains into a settled picture.
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "src/falling_order.h"
#include "src/progress.h"
#include "src/scene_file.h"

namespace sandpic {

constexpr uint8_t kNoSand = 255;  // class_map value where no grain lies

struct SimInput {
  const Scene& scene;
  const GrainSet& grains;
  const Segmentation& seg;
  const FallingOrder& order;
  bool stages = false;  // --stages: the backend draws its own pictures
};

struct SimResult {
  cv::Mat class_map;          // window size, CV_8U: class 0..3 or kNoSand
  std::vector<float> x, y;    // settled centre of each grain id, window px
  ordered_json stats;         // the backend's own figures
  std::vector<std::pair<std::string, cv::Mat>> stages;  // the backend's own --stages pictures
};

class Simulator {
 public:
  virtual ~Simulator() = default;
  virtual SimResult simulate(const SimInput& in, Progress& progress) = 0;
};

// Chosen in one place (src/cli/backends.cpp), from scene.mode.
std::unique_ptr<Simulator> make_simulator(const Scene& s);

}  // namespace sandpic
