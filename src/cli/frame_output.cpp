#include "src/cli/frame_output.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <regex>
#include <vector>


#include "src/errors.h"
#include "src/image_io.h"
#include "src/output.h"

namespace sandpic {
namespace fs = std::filesystem;

std::string frame_name(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame-%05d.png", k);
  return name;
}

namespace {

// The folder is checked as -o checks a file: its own folder must exist and
// be writable; it may exist already (frames replace the frame-*.png in it).
void check_frames_folder(const std::string& dir) {
  if (fs::exists(dir) && !fs::is_directory(dir)) throw InputError("--frames: '" + dir + "' is a file, not a folder");
  try {
    check_parent_writable(dir);
  } catch (const InputError& e) {
    throw InputError(std::string("--frames: ") + e.what());
  }
  if (fs::is_directory(dir) && access(dir.c_str(), W_OK) != 0)
    throw InputError("--frames: cannot write into folder '" + dir + "'");
}

// Into a folder that exists: earlier frames go (a shorter run must not leave
// some of a longer one's), the new ones move in, other files stay.
void move_frames_into(const std::string& tmp, const std::string& dir) {
  static const std::regex frame(R"(frame-\d{5,}\.png)");
  std::vector<fs::path> old;
  for (const auto& e : fs::directory_iterator(dir))
    if (std::regex_match(e.path().filename().string(), frame)) old.push_back(e.path());
  for (const auto& p : old) fs::remove(p);
  for (const auto& e : fs::directory_iterator(tmp)) move_into_place(e.path().string(), (fs::path(dir) / e.path().filename()).string());
  fs::remove(tmp);
}

}  // namespace

FrameOutput::FrameOutput(const std::string& dir, const std::string& video, cv::Size size, double fps)
    : dir_(dir), video_(video) {
  if (!dir_.empty()) check_frames_folder(dir_);
  if (!video_.empty()) {
    try {
      check_writable(video_);
    } catch (const InputError& e) {
      throw InputError(std::string("--video: ") + e.what());
    }
  }
  if (!video_.empty()) {
    tmp_video_ = temp_file_beside(video_);
    bool opened = false;
    try {
      opened = writer_.open(tmp_video_, "mp4v", fps, size);
    } catch (const InputError& e) {
      std::error_code ec;
      fs::remove(tmp_video_, ec);  // the destructor does not run after a throw
      throw InputError(std::string("--video: ") + e.what());
    }
    if (!opened) {
      std::error_code ec;
      fs::remove(tmp_video_, ec);
      throw InputError("--video: cannot write '" + video_ + "': OpenCV cannot encode mp4v video into a '" +
                       fs::path(video_).extension().string() + "' file here (use .mp4; needs OpenCV's ffmpeg backend)");
    }
  }
  if (!dir_.empty()) tmp_dir_ = temp_folder_beside(dir_);
}

FrameOutput::~FrameOutput() {
  std::error_code ec;
  if (!tmp_dir_.empty()) fs::remove_all(tmp_dir_, ec);
  if (!tmp_video_.empty()) {
    writer_.release();
    fs::remove(tmp_video_, ec);
  }
}

void FrameOutput::write(const cv::Mat& picture) {
  if (!tmp_dir_.empty()) {
    const std::vector<uchar> png = encode_png(picture);
    write_atomic(tmp_dir_ + "/" + frame_name(written_), std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
  }
  writer_.write(picture);
  ++written_;
}

void FrameOutput::commit() {
  if (!tmp_video_.empty()) {
    writer_.release();
    move_into_place(tmp_video_, video_);
    tmp_video_.clear();
  }
  if (tmp_dir_.empty()) return;
  if (fs::exists(dir_))
    move_frames_into(tmp_dir_, dir_);
  else
    move_into_place(tmp_dir_, dir_);
  tmp_dir_.clear();
}

}  // namespace sandpic
