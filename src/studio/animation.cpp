#include "src/studio/animation.h"

#include <cmath>
#include <filesystem>
#include <random>


#include "src/image_io.h"
#include "src/output.h"
#include "src/pipeline.h"
#include "src/video.h"

namespace sandpic::studio {

namespace fs = std::filesystem;

namespace {

double number_param(const std::string& name, const std::string& text, double lo, double hi, double dflt) {
  if (text.empty()) return dflt;
  const auto v = number_of(text);
  if (!v || !(*v >= lo && *v <= hi))
    throw InputError(name + ": '" + text + "' is not a number in [" + std::to_string(int(lo)) + ", " +
                     std::to_string(int(hi)) + "]");
  return *v;
}

// A video through OpenCV's ffmpeg backend, which writes files only: into a
// private temporary file, read back, removed. H.264 plays in browsers and
// players alike; mp4v (what --video writes) is the fallback where the
// encoder is missing.
std::string encode_video(const std::vector<cv::Mat>& frames, double fps) {
  const fs::path tmp = fs::temp_directory_path() / ("sandpic-studio-" + std::to_string(std::random_device{}()) + ".mp4");
  std::string bytes;
  for (const char* fourcc : {"avc1", "mp4v"}) {
    {
      VideoWriter w;
      if (!w.open(tmp.string(), fourcc, fps, frames.front().size())) continue;
      for (const cv::Mat& f : frames) w.write(f);
    }
    if (auto b = read_text(tmp.string()); b && !b->empty()) {
      bytes = std::move(*b);
      break;
    }
  }
  std::error_code ec;
  fs::remove(tmp, ec);
  if (bytes.empty()) throw std::runtime_error("OpenCV cannot encode MP4 video here (its ffmpeg backend is missing)");
  return bytes;
}

}  // namespace

AnimationRequest animation_request(const std::string& frames, const std::string& scale, const std::string& fps,
                                   const std::string& format) {
  AnimationRequest r;
  const double n = number_param("frames", frames, 2, 120, r.frames);
  if (n != std::floor(n)) throw InputError("frames: '" + frames + "' is not a whole number");
  r.frames = int(n);
  r.scale = scale_param(scale);
  r.fps = number_param("fps", fps, 1, 60, r.fps);
  if (format.empty() || format == "frames")
    r.format = AnimationFormat::Frames;
  else if (format == "mp4")
    r.format = AnimationFormat::Video;
  else
    throw InputError("format: '" + format + "' is neither 'frames' nor 'mp4'");
  return r;
}

Reply animation(const std::string& body, const std::string& root, const AnimationRequest& req) {
  Scene s = scaled(scene_from_request(body, root), req.scale);
  s.mode = Mode::Lattice;  // the live preview's fall; the DEM's is a final render's
  auto sim = make_simulator(s);
  std::vector<cv::Mat> frames;
  RunOptions opt;
  opt.frames = req.frames;
  opt.frame = [&](const cv::Mat& picture) { frames.push_back(picture.clone()); };
  run_pipeline(s, *sim, opt);
  Reply r;
  if (req.format == AnimationFormat::Video) {
    r.content_type = "video/mp4";
    r.body = encode_video(frames, req.fps);
    r.headers["Content-Disposition"] = "attachment; filename=\"sandpic-fall-seed-" + std::to_string(s.seed) + ".mp4\"";
    return r;
  }
  // JPEG: a frame is seen for a twelfth of a second, and at 1000 x 700 it
  // is a fifth of the PNG's bytes and encodes in a few milliseconds.
  std::string sizes;
  for (const cv::Mat& f : frames) {
    const std::vector<uchar> buf = encode_jpeg(f, 85);
    r.body.append(reinterpret_cast<const char*>(buf.data()), buf.size());
    if (!sizes.empty()) sizes += ',';
    sizes += std::to_string(buf.size());
  }
  r.content_type = "application/octet-stream";
  r.headers["X-Sandpic-Frame-Sizes"] = sizes;
  r.headers["X-Sandpic-Fps"] = std::to_string(req.fps);
  return r;
}

}  // namespace sandpic::studio
