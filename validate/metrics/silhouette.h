#pragma once
// The pile's outline: the height of sand in every pixel column, and the
// silhouette error between two pictures of one scene (issue 3: the cost in
// accuracy of each DEM speed-up, measured against every grain a body).
#include <vector>

#include <opencv2/core.hpp>

namespace sandpic {

// Sand height (px above the floor) of every column of a class map (CV_8U,
// kNoSand where no grain lies).
std::vector<double> silhouette(const cv::Mat& class_map);

// Mean |h_a − h_b| over the columns, as a fraction of the window's height.
// Both maps must have the same size.
double silhouette_error(const cv::Mat& a, const cv::Mat& b);

// The heap angle of a single pile poured from a point, in degrees (paper
// Fig. 9): a least-squares line through each flank between 20% and 80% of
// the peak height, the two averaged. NaN if a flank has fewer than three
// columns in that band. (A picture of many mountains has no one flank: use
// scene_slope_deg.)
double heap_angle_deg(const std::vector<double>& heights, double column_width = 1);

// The scene slope of a picture of many mountains, in degrees: the mean of
// |dh/dx| over every column of the outline smoothed by a running mean
// `smoothing` columns wide (verify-dem: 8 large-grain diameters), as an angle.
double scene_slope_deg(const std::vector<double>& heights, double smoothing);

}  // namespace sandpic
