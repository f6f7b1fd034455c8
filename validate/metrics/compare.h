#pragma once
// Image similarity between two pictures of one scene: SSIM and
// PSNR on luminance, and measures that suit two stochastic piles whose
// grains never line up pixel for pixel: the silhouette error, the per-class
// composition error per horizontal band and SSIM after a Gaussian blur.
#include <array>
#include <vector>

#include <opencv2/core.hpp>

#include "src/scene.h"

namespace sandpic {

// BT.601 luma, 0.299 R + 0.587 G + 0.114 B, as doubles (not rounded), of an
// 8-bit BGR picture.
cv::Mat luminance601(const cv::Mat& bgr);

// Mean SSIM (Wang et al. 2004) of two luminance images (CV_64F, same size):
// Gaussian window σ = 1.5 truncated at 3.5σ (11×11), K1 = 0.01, K2 = 0.03,
// data range 255, population covariance, mirrored borders, the mean over
// the area 5 px inside the borders: scikit-image's structural_similarity(a,
// b, gaussian_weights=True, sigma=1.5, use_sample_covariance=False,
// data_range=255).
double ssim(const cv::Mat& a, const cv::Mat& b);

// PSNR in dB of two luminance images (data range 255); +inf when identical.
double psnr(const cv::Mat& a, const cv::Mat& b);

// A rendered picture back to its class map (CV_8U, class 0-3 or kNoSand):
// a pixel of a class's exact colour is sand of that class, anything else
// (background colour or picture) is empty.
cv::Mat decode_classes(const cv::Mat& bgr, const std::array<Rgb, kClasses>& colours);

// Per horizontal band (`bands` of equal height, top to bottom): the total
// variation distance between the two bands' compositions, each the share
// of the band's pixels held by each class and by no sand (0: the same mix,
// 1: nothing in common).
std::vector<double> composition_error(const cv::Mat& classes_a, const cv::Mat& classes_b, int bands);
// Its mean over the bands (Comparison::composition_error).
double mean_composition_error(const std::vector<double>& per_band);

struct Comparison {
  int width = 0, height = 0;
  double ssim = 0, psnr_db = 0;       // psnr_db: +inf when the pictures are identical
  double silhouette_error = 0;        // mean |Δ sand height| per column / window height
  std::vector<double> composition;    // per band, top to bottom
  double composition_error = 0;       // mean over the bands
  double blur_sigma_px = 0;
  double ssim_blurred = 0;            // SSIM of the luminance blurred by σ = blur_sigma_px
};

// Where two pictures differ (compare --diff): the first picture's luminance
// dimmed to grey, and every pixel whose colour differs in red, brighter the
// larger its largest channel difference. 8-bit BGR of one size.
cv::Mat difference_picture(const cv::Mat& a, const cv::Mat& b);

// Both pictures 8-bit BGR of one size (the caller checks).
Comparison compare_pictures(const cv::Mat& a, const cv::Mat& b, const std::array<Rgb, kClasses>& colours, int bands,
                            double blur_sigma_px);

}  // namespace sandpic
