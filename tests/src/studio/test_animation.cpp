// The fall as an animation (paper Fig. 14c-d): frames to play on
// the page, an MP4 to download.
#include "src/studio/animation.h"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "tests/test_folder.h"

namespace sandpic::studio {
namespace {

std::vector<cv::Mat> frames_of(const Reply& r) {
  std::vector<cv::Mat> out;
  size_t at = 0;
  std::stringstream sizes(r.headers.at("X-Sandpic-Frame-Sizes"));
  for (std::string n; std::getline(sizes, n, ',');) {
    const size_t len = std::stoul(n);
    EXPECT_LE(at + len, r.body.size());
    out.push_back(cv::imdecode(cv::Mat(1, int(len), CV_8U, const_cast<char*>(r.body.data() + at)), cv::IMREAD_COLOR));
    at += len;
  }
  EXPECT_EQ(at, r.body.size());  // nothing but the frames
  return out;
}

double mean_abs_diff(const cv::Mat& a, const cv::Mat& b) { return cv::mean(cv::abs(a - b) + cv::abs(b - a))[0]; }

TEST(StudioAnimation, FramesFromAFullRegionToThePreview) {
  const std::string root = test::fresh_folder("anim");
  AnimationRequest req;
  req.frames = 6;
  req.scale = 0.2;
  const Reply r = animation("{}", root, req);
  ASSERT_EQ(r.status, 200);
  const std::vector<cv::Mat> f = frames_of(r);
  ASSERT_EQ(f.size(), 6u);
  for (const cv::Mat& m : f) {
    ASSERT_FALSE(m.empty());
    EXPECT_EQ(m.cols, 200);
    EXPECT_EQ(m.rows, 140);
  }
  // The fall goes somewhere: the first frame (the full region) is not the
  // last, and the last is the preview's picture (as a JPEG of it).
  EXPECT_GT(mean_abs_diff(f.front(), f.back()), 10);
  const Reply png = preview("{}", root, 0.2);
  const cv::Mat picture =
      cv::imdecode(cv::Mat(1, int(png.body.size()), CV_8U, const_cast<char*>(png.body.data())), cv::IMREAD_COLOR);
  std::vector<uchar> jpeg;
  cv::imencode(".jpg", picture, jpeg, {cv::IMWRITE_JPEG_QUALITY, 85});
  EXPECT_EQ(cv::norm(f.back(), cv::imdecode(jpeg, cv::IMREAD_COLOR), cv::NORM_INF), 0);
  // Same body, same bytes.
  EXPECT_EQ(animation("{}", root, req).body, r.body);
}

TEST(StudioAnimation, AnMp4ToDownload) {
  const std::string root = test::fresh_folder("mp4");
  const AnimationRequest req = animation_request("4", "0.1", "", "mp4");
  const Reply r = animation("{}", root, req);
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(r.content_type, "video/mp4");
  ASSERT_GT(r.body.size(), 12u);
  EXPECT_EQ(r.body.substr(4, 4), "ftyp");  // an ISO media file
  EXPECT_NE(r.headers.at("Content-Disposition").find(".mp4"), std::string::npos);
}

TEST(StudioAnimation, BadParametersAreNamed) {
  const auto message = [](auto f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([] { animation_request("1", "", "", ""); }).rfind("frames:", 0), 0u);
  EXPECT_EQ(message([] { animation_request("2.5", "", "", ""); }).rfind("frames:", 0), 0u);
  EXPECT_EQ(message([] { animation_request("500", "", "", ""); }).rfind("frames:", 0), 0u);
  EXPECT_EQ(message([] { animation_request("", "9", "", ""); }).rfind("scale:", 0), 0u);
  EXPECT_EQ(message([] { animation_request("", "", "0", ""); }).rfind("fps:", 0), 0u);
  EXPECT_EQ(message([] { animation_request("", "", "", "gif"); }).rfind("format:", 0), 0u);
  const AnimationRequest d = animation_request("", "", "", "");
  EXPECT_EQ(d.frames, 24);
  EXPECT_EQ(d.format, AnimationFormat::Frames);
  // A bad scene is the scene's error, naming its key.
  EXPECT_EQ(key_of(message([] { animation(R"({"physics": {"friction": -1}})", ".", AnimationRequest{}); })),
            "physics.friction");
}

}  // namespace
}  // namespace sandpic::studio
