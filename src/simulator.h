#pragma once
// The one interface through which src/ knows a simulation backend (lattice/,
// physics/). A backend turns released grains into a settled picture.
#include <functional>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "src/falling_order.h"
#include "src/progress.h"
#include "src/scene_file.h"

namespace sandpic {

constexpr uint8_t kNoSand = 255;  // class_map value where no grain lies

// paper Fig. 14c-d, 18b-c: screen shots of the fall while it goes. A backend
// with `count` > 0 calls `frame` exactly `count` times, with a window-size
// class map (CV_8U, class 0..3 or kNoSand) of the pile, the moving grains
// and the grains still waiting in the region: first before any grain is
// released, then evenly spaced by grains released (frame_released), last
// with the very class map it returns.
struct FrameSink {
  int count = 0;
  std::function<void(const cv::Mat& class_map)> frame;
  bool wanted() const { return count > 0 && frame; }
};

struct SimInput {
  const Scene& scene;
  const GrainSet& grains;
  const Segmentation& seg;
  const FallingOrder& order;
  bool stages = false;  // --stages: the backend draws its own pictures
  FrameSink frames = {};
};

struct SimResult {
  cv::Mat class_map;          // window size, CV_8U: class 0..3 or kNoSand
  std::vector<float> x, y;    // settled centre of each grain id, window px
  ordered_json stats;         // the backend's own figures
  std::vector<std::pair<std::string, cv::Mat>> stages;  // the backend's own --stages pictures
};

// What a backend's own part of a run will take, known from the scene alone
// (issue 6: a scene past the limits is refused before anything is allocated).
struct Cost {
  double bytes = 0;    // peak memory beyond the pipeline's own
  double seconds = 0;  // on 2 cores, order of magnitude
};

class Simulator {
 public:
  virtual ~Simulator() = default;
  virtual SimResult simulate(const SimInput& in, Progress& progress) = 0;
  virtual Cost cost(const Scene& s) const = 0;
};

// Chosen in one place (src/cli/backends.cpp), from scene.mode.
std::unique_ptr<Simulator> make_simulator(const Scene& s);

}  // namespace sandpic
