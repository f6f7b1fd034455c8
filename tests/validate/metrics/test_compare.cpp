#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "src/render.h"
#include "src/simulator.h"
#include "validate/metrics/compare.h"

namespace sandpic {
namespace {

cv::Mat fixture(const std::string& name) {
  cv::Mat img = cv::imread(std::string(SANDPIC_FIXTURES) + "/compare/" + name, cv::IMREAD_COLOR);
  EXPECT_FALSE(img.empty()) << name;
  return img;
}

// Within 0.005 of scikit-image's structural_similarity on every
// pair of tests/fixtures/compare (values computed once by scikit-image,
// make_fixture.py), and PSNR likewise.
TEST(Compare, SsimAndPsnrAgreeWithScikitImage) {
  std::ifstream in(std::string(SANDPIC_FIXTURES) + "/compare/expected.json");
  const nlohmann::json expected = nlohmann::json::parse(in);
  ASSERT_GE(expected.size(), 5u);
  for (const auto& e : expected) {
    const cv::Mat a = luminance601(fixture(e["a"])), b = luminance601(fixture(e["b"]));
    const double s = ssim(a, b), p = psnr(a, b);
    std::printf("%s vs %s: SSIM %.6f (scikit-image %.6f)\n", e["a"].get<std::string>().c_str(),
                e["b"].get<std::string>().c_str(), s, e["ssim"].get<double>());
    EXPECT_NEAR(s, e["ssim"].get<double>(), 0.005) << e["a"] << " vs " << e["b"];
    if (e["psnr_db"].is_null())
      EXPECT_TRUE(std::isinf(p));
    else
      EXPECT_NEAR(p, e["psnr_db"].get<double>(), 0.01);
  }
}

TEST(Compare, ClassesComeBackFromTheirColours) {
  Scene s;
  cv::Mat img(3, 2, CV_8UC3, bgr(s.render.background_color));
  img.at<cv::Vec3b>(2, 1) = bgr(s.grains.colors[2]);
  img.at<cv::Vec3b>(1, 1) = bgr(s.grains.colors[2]) + cv::Vec3b(0, 0, 1);  // near is not the colour
  cv::Mat k = decode_classes(img, s.grains.colors);
  EXPECT_EQ(k.at<uint8_t>(2, 1), 2);
  EXPECT_EQ(k.at<uint8_t>(1, 1), kNoSand);
  EXPECT_EQ(k.at<uint8_t>(0, 0), kNoSand);
}

TEST(Compare, CompositionErrorIsTheShareOfPixelsThatDiffer) {
  cv::Mat a(4, 4, CV_8U, cv::Scalar(kNoSand)), b;
  a.rowRange(2, 4).setTo(0);  // the bottom half class 0
  b = a.clone();
  EXPECT_EQ(composition_error(a, b, 2), (std::vector<double>{0, 0}));
  b.rowRange(3, 4).setTo(1);  // the bottom row class 1 instead
  EXPECT_EQ(composition_error(a, b, 2), (std::vector<double>{0, 0.5}));
  b.row(0).colRange(0, 2).setTo(3);  // 2 of the top band's 8 pixels are sand in b only
  EXPECT_EQ(composition_error(a, b, 2), (std::vector<double>{0.25, 0.5}));
}

TEST(Compare, TwoPilesOfOneSceneAreCloseOnThePileMeasures) {
  const cv::Mat a = fixture("dem_seed1.png"), b = fixture("dem_seed2.png"), c = fixture("three_seed1.png");
  const Scene s;
  const Comparison same = compare_pictures(a, a, s.grains.colors, 8, 3);
  EXPECT_EQ(same.ssim, 1.0);
  EXPECT_EQ(same.silhouette_error, 0.0);
  EXPECT_EQ(same.composition_error, 0.0);
  const Comparison seeds = compare_pictures(a, b, s.grains.colors, 8, 3);
  const Comparison models = compare_pictures(a, c, s.grains.colors, 8, 3);
  // Grains never line up: plain SSIM is low, blurred SSIM is high.
  EXPECT_LT(seeds.ssim, 0.7);
  EXPECT_GT(seeds.ssim_blurred, 0.9);
  EXPECT_GT(seeds.silhouette_error, 0.0);
  // The three-layer pile stands taller than every-grain-a-body: further off.
  EXPECT_GT(models.silhouette_error, 2 * seeds.silhouette_error);
  EXPECT_EQ(seeds.composition.size(), 8u);
}

}  // namespace
}  // namespace sandpic
