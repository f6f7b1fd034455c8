// The picture plugin (src/image_io.h): the only code that links OpenCV's
// imgcodecs. A C interface, so the loader needs no C++ symbol of it; the
// Mats cross it by pointer (both sides share opencv_core).
#include <vector>

#include <opencv2/imgcodecs.hpp>

namespace {

int flags(int how) { return how == 0 ? cv::IMREAD_COLOR : how == 1 ? cv::IMREAD_GRAYSCALE : cv::IMREAD_UNCHANGED; }

}  // namespace

extern "C" {

// Each returns false where OpenCV throws or finds no picture.
bool sandpic_image_read(const char* path, int how, cv::Mat* out) {
  try {
    *out = cv::imread(path, flags(how));
  } catch (const cv::Exception&) {
    out->release();
  }
  return !out->empty();
}

bool sandpic_image_decode(const void* data, size_t size, int how, cv::Mat* out) {
  try {
    *out = cv::imdecode(cv::Mat(1, int(size), CV_8U, const_cast<void*>(data)), flags(how));
  } catch (const cv::Exception&) {
    out->release();
  }
  return !out->empty();
}

// `ext` ".png", ".jpg", ...; `jpeg_quality` < 0: OpenCV's default.
bool sandpic_image_encode(const char* ext, const cv::Mat* img, int jpeg_quality, std::vector<uchar>* out) {
  try {
    std::vector<int> params;
    if (jpeg_quality >= 0) params = {cv::IMWRITE_JPEG_QUALITY, jpeg_quality};
    return cv::imencode(ext, *img, *out, params);
  } catch (const cv::Exception&) {
    return false;
  }
}

}  // extern "C"
