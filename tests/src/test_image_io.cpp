// src/image_io: PNG through libpng, byte for byte what OpenCV wrote before;
// reading and JPEG through the imgcodecs plugin.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "src/errors.h"
#include "src/image_io.h"
#include "src/rng.h"

namespace sandpic {
namespace {

// A picture like sandpic's: a few colours in runs, and noise (the worst
// case for the filter and the compressor).
cv::Mat picture(int w, int h, int type, uint64_t seed) {
  cv::Mat img(h, w, type);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w * img.channels(); ++x) {
      const double u = uniform(seed, Stream::LatticeSlide, uint64_t(y) * 100003 + uint64_t(x));
      img.ptr<uchar>(y)[x] = y < h / 2 ? uchar(40 * ((x / 7 + y / 5) % 4)) : uchar(255 * u);
    }
  return img;
}

TEST(ImageIo, PngBytesAreOpenCvs) {
  for (int type : {CV_8UC1, CV_8UC3, CV_8UC4})
    for (auto [w, h] : {std::pair{1, 1}, {37, 19}, {1000, 70}, {64, 300}}) {
      const cv::Mat img = picture(w, h, type, uint64_t(w * h + type));
      std::vector<uchar> expected;
      ASSERT_TRUE(cv::imencode(".png", img, expected));
      EXPECT_EQ(encode_png(img), expected) << w << " x " << h << ", type " << type;
    }
  // A view into a larger picture (rows with a stride) encodes as a copy does.
  const cv::Mat big = picture(50, 40, CV_8UC3, 7), view = big(cv::Rect(5, 3, 20, 30));
  EXPECT_EQ(encode_png(view), encode_png(view.clone()));
}

TEST(ImageIo, PngRoundTripsThroughThePlugin) {
  const cv::Mat img = picture(33, 21, CV_8UC3, 3);
  const std::vector<uchar> png = encode_png(img);
  const cv::Mat back = decode_picture(png.data(), png.size());
  ASSERT_EQ(back.type(), CV_8UC3);
  EXPECT_EQ(cv::norm(img, back, cv::NORM_INF), 0);
  const cv::Mat grey = decode_picture(png.data(), png.size(), ImageRead::Grey);
  EXPECT_EQ(grey.type(), CV_8UC1);
  EXPECT_TRUE(decode_picture(png.data(), 40).empty());  // cut after the header
  EXPECT_TRUE(read_picture("/nonexistent/picture.png").empty());
}

// A palette PNG holds the same pixels at every bit depth (2, 3, 5, 17 and
// 256 colours: 1, 2, 4, 8 and 8 bits), widths that do not fill the last
// byte included; a picture of 257 colours, grey or BGRA is encode_png's.
TEST(ImageIo, IndexedPngHoldsTheSamePixels) {
  for (int colours : {1, 2, 3, 5, 17, 256})
    for (int w : {1, 7, 37, 1000}) {
      cv::Mat img(23, w, CV_8UC3);
      for (int y = 0; y < img.rows; ++y)
        for (int x = 0; x < w; ++x) {
          const int c = int(uniform(uint64_t(colours), Stream::LatticeSlide, uint64_t(y * w + x)) * colours);
          img.at<cv::Vec3b>(y, x) = cv::Vec3b(uchar(c), uchar(255 - c), uchar(c * 7));
        }
      const std::vector<uchar> png = encode_png_indexed(img);
      ASSERT_GT(png.size(), 26u);
      EXPECT_EQ(png[25], 3) << "palette colour type, " << colours << " colours, width " << w;
      const cv::Mat back = decode_picture(png.data(), png.size());
      ASSERT_EQ(back.type(), CV_8UC3);
      EXPECT_EQ(cv::norm(img, back, cv::NORM_INF), 0) << colours << " colours, width " << w;
      EXPECT_EQ(encode_png_indexed(img.clone()), png);  // the same picture, the same bytes
    }
  const cv::Mat many = picture(40, 20, CV_8UC3, 5);  // noise: more than 256 colours
  EXPECT_EQ(encode_png_indexed(many), encode_png(many));
  const cv::Mat grey = picture(40, 20, CV_8UC1, 5);
  EXPECT_EQ(encode_png_indexed(grey), encode_png(grey));
}

TEST(ImageIo, RefusesWhatPngCannotHold) {
  EXPECT_THROW(encode_png(cv::Mat()), SimulationError);
  EXPECT_THROW(encode_png(cv::Mat(4, 4, CV_16UC3, cv::Scalar(1, 2, 3))), SimulationError);
  EXPECT_THROW(encode_png(cv::Mat(4, 4, CV_8UC2, cv::Scalar(1, 2))), SimulationError);
  // 16-bit PNG through the plugin, as OpenCV writes it.
  const cv::Mat deep(5, 6, CV_16UC3, cv::Scalar(1000, 20000, 65535));
  std::vector<uchar> expected;
  ASSERT_TRUE(cv::imencode(".png", deep, expected));
  EXPECT_EQ(encode_picture(".png", deep), expected);
}

TEST(ImageIo, JpegIsOpenCvs) {
  const cv::Mat img = picture(64, 48, CV_8UC3, 5);
  std::vector<uchar> expected;
  ASSERT_TRUE(cv::imencode(".jpg", img, expected, {cv::IMWRITE_JPEG_QUALITY, 85}));
  EXPECT_EQ(encode_jpeg(img, 85), expected);
}

}  // namespace
}  // namespace sandpic
