// The video plugin (src/video.h): the only code that links OpenCV's videoio.
// A C interface, so the loader needs no C++ symbol of it.
#include <opencv2/videoio.hpp>

extern "C" {

void* sandpic_video_open(const char* path, int fourcc, double fps, int width, int height) {
  auto* w = new cv::VideoWriter(path, fourcc, fps, cv::Size(width, height));
  if (w->isOpened()) return w;
  delete w;
  return nullptr;
}

void sandpic_video_write(void* writer, const cv::Mat* frame) { static_cast<cv::VideoWriter*>(writer)->write(*frame); }

void sandpic_video_close(void* writer) { delete static_cast<cv::VideoWriter*>(writer); }

}  // extern "C"
