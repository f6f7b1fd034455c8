#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <opencv2/videoio.hpp>

#include "src/cli/frame_output.h"
#include "src/errors.h"

namespace sandpic {
namespace {
namespace fs = std::filesystem;

std::string fresh(const std::string& name) {
  const std::string dir = testing::TempDir() + "/frame_output_" + name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

cv::Mat frame(int k) { return cv::Mat(48, 64, CV_8UC3, cv::Scalar(20 * k, 100, 255 - 20 * k)); }

TEST(FrameOutput, FramesAndVideoAppearOnlyOnCommit) {
  const std::string dir = fresh("commit");
  {
    FrameOutput out(dir + "/frames", dir + "/fall.mp4", cv::Size(64, 48), 24);
    for (int k = 0; k < 5; ++k) out.write(frame(k));
    EXPECT_FALSE(fs::exists(dir + "/frames"));
    EXPECT_FALSE(fs::exists(dir + "/fall.mp4"));
    out.commit();
  }
  for (int k = 0; k < 5; ++k) EXPECT_TRUE(fs::exists(dir + "/frames/" + frame_name(k))) << k;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);  // no temporaries left
  cv::VideoCapture video(dir + "/fall.mp4");
  ASSERT_TRUE(video.isOpened());
  int frames = 0;
  for (cv::Mat m; video.read(m);) ++frames;
  EXPECT_EQ(frames, 5);
}

TEST(FrameOutput, AFailedRunLeavesNothing) {
  const std::string dir = fresh("fail");
  {
    FrameOutput out(dir + "/frames", dir + "/fall.mp4", cv::Size(64, 48), 24);
    out.write(frame(0));
  }  // never committed: the run failed
  EXPECT_TRUE(fs::is_empty(dir));
}

// Into a folder that exists: a longer run's frames do not outlive a shorter one; other files stay.
TEST(FrameOutput, ReplacesEarlierFramesInAFolder) {
  const std::string dir = fresh("replace");
  fs::create_directories(dir + "/frames");
  std::ofstream(dir + "/frames/" + frame_name(7)) << "old";
  std::ofstream(dir + "/frames/notes.txt") << "mine";
  FrameOutput out(dir + "/frames", "", cv::Size(64, 48), 24);
  out.write(frame(0));
  out.commit();
  EXPECT_TRUE(fs::exists(dir + "/frames/" + frame_name(0)));
  EXPECT_FALSE(fs::exists(dir + "/frames/" + frame_name(7)));
  EXPECT_TRUE(fs::exists(dir + "/frames/notes.txt"));
}

TEST(FrameOutput, BadTargetsNameTheOption) {
  const std::string dir = fresh("bad");
  std::ofstream(dir + "/file") << "x";
  auto message = [](auto make) {
    try {
      make();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] { FrameOutput(dir + "/file", "", cv::Size(64, 48), 24); }).find("--frames"), std::string::npos);
  EXPECT_NE(message([&] { FrameOutput(dir + "/no/such", "", cv::Size(64, 48), 24); }).find("--frames"), std::string::npos);
  EXPECT_NE(message([&] { FrameOutput("", dir + "/fall.nosuchformat", cv::Size(64, 48), 24); }).find("--video"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir + "/file"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace sandpic
