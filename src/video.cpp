#include "src/video.h"

#include "src/plugin.h"

namespace sandpic {

namespace {

struct Plugin {
  void* (*open)(const char*, int, double, int, int) = nullptr;
  void (*write)(void*, const cv::Mat*) = nullptr;
  void (*close)(void*) = nullptr;
};

const Plugin& plugin() {
  static const Plugin p = [] {
    const auto f = load_plugin("libsandpic_video.so", SANDPIC_VIDEO_PLUGIN, "the video encoder",
                               {"sandpic_video_open", "sandpic_video_write", "sandpic_video_close"});
    Plugin q;
    q.open = reinterpret_cast<decltype(q.open)>(f[0]);
    q.write = reinterpret_cast<decltype(q.write)>(f[1]);
    q.close = reinterpret_cast<decltype(q.close)>(f[2]);
    return q;
  }();
  return p;
}

}  // namespace

bool VideoWriter::open(const std::string& path, const char fourcc[4], double fps, cv::Size size) {
  release();
  const int code = fourcc[0] | (fourcc[1] << 8) | (fourcc[2] << 16) | (fourcc[3] << 24);  // cv::VideoWriter::fourcc
  handle_ = plugin().open(path.c_str(), code, fps, size.width, size.height);
  return handle_ != nullptr;
}

void VideoWriter::write(const cv::Mat& bgr) {
  if (handle_) plugin().write(handle_, &bgr);
}

void VideoWriter::release() {
  if (handle_) plugin().close(handle_);
  handle_ = nullptr;
}

}  // namespace sandpic
