#pragma once
// MP4 files through OpenCV's videoio, loaded on first use. videoio brings
// ffmpeg and some 220 shared libraries with it, and loading them cost every
// process about 75 ms at start, a third of a lattice render's whole time,
// though few runs write a video. So the encoder is a plugin
// (libsandpic_video.so, src/video_plugin.cpp, built beside the executable)
// that only --video and the studio's MP4 download load.
#include <string>

#include <opencv2/core.hpp>

namespace sandpic {

class VideoWriter {
 public:
  VideoWriter() = default;
  ~VideoWriter() { release(); }
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Opens `path` for the codec `fourcc` ("mp4v", "avc1"); false when OpenCV
  // cannot encode it here. Throws InputError (exit 2) naming the plugin's
  // file when it cannot be loaded.
  bool open(const std::string& path, const char fourcc[4], double fps, cv::Size size);
  bool is_open() const { return handle_ != nullptr; }
  void write(const cv::Mat& bgr);  // 8-bit BGR, the size opened
  void release();                  // finishes the file

 private:
  void* handle_ = nullptr;
};

}  // namespace sandpic
