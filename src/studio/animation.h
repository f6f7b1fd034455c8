#pragma once
// The fall as an animation for the studio (issue 7; paper Fig. 14c-d): the
// lattice preview's frames, to play on the page and to download as a video.
#include <string>

#include "src/studio/api.h"

namespace sandpic::studio {

enum class AnimationFormat {
  Frames,  // JPEG frames back to back, their sizes in X-Sandpic-Frame-Sizes: the page plays them
  Video,   // an MP4 file to download (H.264 where OpenCV's ffmpeg has it, else mp4v)
};

struct AnimationRequest {
  int frames = 24;  // paper Fig. 14c-d: evenly spaced by grains released; the last is the picture
  double scale = 1;
  double fps = 12;
  AnimationFormat format = AnimationFormat::Frames;
};

// From the query parameters `frames` (2..120), `scale` (as preview), `fps`
// (1..60) and `format` ("frames" or "mp4"); "" takes the default. Throws
// InputError naming the parameter.
AnimationRequest animation_request(const std::string& frames, const std::string& scale, const std::string& fps,
                                   const std::string& format);

// POST /api/animation: the scene's lattice fall. Same body, same bytes.
Reply animation(const std::string& body, const std::string& root, const AnimationRequest& req);

}  // namespace sandpic::studio
