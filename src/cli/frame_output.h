#pragma once
// --frames DIR and --video OUT.mp4 (paper Fig. 14c-d): frames are written as
// the run makes them, never all held in memory, into a temporary folder and
// a temporary video file beside the targets; commit() moves them into place
// once the run has succeeded, and a failed run leaves nothing behind.
#include <string>

#include <opencv2/core.hpp>

#include "src/video.h"

namespace sandpic {

class FrameOutput {
 public:
  // Checks both targets and opens the temporaries; throws InputError naming
  // the option (a --frames path that is a file, a video the codec or
  // container cannot be written to). An empty path leaves that output out.
  FrameOutput(const std::string& dir, const std::string& video, cv::Size size, double fps);
  ~FrameOutput();  // removes what was not committed
  FrameOutput(const FrameOutput&) = delete;
  FrameOutput& operator=(const FrameOutput&) = delete;

  void write(const cv::Mat& picture);  // 8-bit BGR, the window's size
  void commit();

 private:
  std::string dir_, video_, tmp_dir_, tmp_video_;
  VideoWriter writer_;
  int written_ = 0;
};

// frame-00000.png, frame-00001.png, ...
std::string frame_name(int k);

}  // namespace sandpic
