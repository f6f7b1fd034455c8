#pragma once
// Shared objects loaded on first use (src/video.h, src/image_io.h): OpenCV's
// videoio and imgcodecs bring ffmpeg, GDAL and some 340 shared libraries
// between them, and loading those cost every process about 125 ms at start
// though few runs need them.
#include <initializer_list>
#include <string>
#include <vector>

namespace sandpic {

// The functions `symbols` of the plugin `file` (libsandpic_*.so), looked
// for beside the executable first (a copied build), then at `built` (where
// this build put it: the test binaries live in a sub-folder). Throws
// InputError (exit 2) naming what it tried and why, as `what` ("the video
// encoder").
std::vector<void*> load_plugin(const std::string& file, const std::string& built, const std::string& what,
                               std::initializer_list<const char*> symbols);

}  // namespace sandpic
