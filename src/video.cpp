#include "src/video.h"

#include <dlfcn.h>

#include <filesystem>

#include "src/errors.h"

namespace sandpic {

namespace {

struct Plugin {
  void* (*open)(const char*, int, double, int, int) = nullptr;
  void (*write)(void*, const cv::Mat*) = nullptr;
  void (*close)(void*) = nullptr;
};

// Beside the executable first (a copied build), then where this build put it
// (the test binaries live in a sub-folder).
const Plugin& plugin() {
  static const Plugin p = [] {
    const std::string name = "libsandpic_video.so";
    std::string tried, why;
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::string beside = ec ? std::string() : (exe.parent_path() / name).string();
    for (const std::string& path : {beside, std::string(SANDPIC_VIDEO_PLUGIN)}) {
      if (path.empty() || tried.find(path) != std::string::npos) continue;
      if (void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL)) {
        Plugin q;
        q.open = reinterpret_cast<decltype(q.open)>(dlsym(h, "sandpic_video_open"));
        q.write = reinterpret_cast<decltype(q.write)>(dlsym(h, "sandpic_video_write"));
        q.close = reinterpret_cast<decltype(q.close)>(dlsym(h, "sandpic_video_close"));
        if (q.open && q.write && q.close) return q;
        why = path + " lacks the sandpic_video_* functions";
      } else {
        why = dlerror();
      }
      tried += (tried.empty() ? "" : ", ") + path;
    }
    throw InputError("cannot load the video encoder " + name + " (tried " + tried + "): " + why);
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
