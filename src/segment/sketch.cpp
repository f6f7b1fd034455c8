#include "src/segment/sketch.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>
#include <opencv2/imgproc.hpp>

#include "src/errors.h"
#include "src/init/init.h"
#include "src/rng.h"

namespace sandpic {

namespace {

constexpr double kDeg = std::numbers::pi / 180;

std::vector<std::vector<Vec2>> to_lines(const std::vector<Polyline>& lines) {
  std::vector<std::vector<Vec2>> out;
  for (const Polyline& l : lines) {
    std::vector<Vec2> pts;
    for (const auto& p : l) pts.emplace_back(p[0], p[1]);
    out.push_back(std::move(pts));
  }
  return out;
}

cv::Mat stroke_mask(const cv::Mat& bgr, Rgb c) {
  // A stroke pixel is within 80 (of 441) of the colour: antialiased edges
  // and a saved JPEG's ringing stay in, the other colour stays out.
  cv::Mat mask(bgr.size(), CV_8U);
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      const double d = std::hypot(p[2] - c.r, p[1] - c.g, p[0] - c.b);
      mask.at<uint8_t>(y, x) = d < 80 ? 255 : 0;
    }
  return mask;
}

// Each connected stroke of a mask as a line: its pixels binned every 3 px
// along their principal axis (Eigen), the bins' means in order. Ridge lines
// and arc-like curves are both long one way, so one axis orders them.
std::vector<std::vector<Vec2>> stroke_lines(const cv::Mat& mask) {
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  std::vector<std::vector<Vec2>> pixels(size_t(std::max(0, n)));
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x)
      if (int l = labels.at<int>(y, x); l > 0) pixels[size_t(l)].emplace_back(x + 0.5, y + 0.5);
  std::vector<std::vector<Vec2>> lines;
  for (int l = 1; l < n; ++l) {
    const auto& pts = pixels[size_t(l)];
    if (pts.size() < 8) continue;  // specks
    Vec2 mean = Vec2::Zero();
    for (const Vec2& p : pts) mean += p;
    mean /= double(pts.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (const Vec2& p : pts) cov += (p - mean) * (p - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
    const Vec2 axis = eig.eigenvectors().col(1);  // largest eigenvalue last
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec2& p : pts) lo = std::min(lo, (p - mean).dot(axis)), hi = std::max(hi, (p - mean).dot(axis));
    constexpr double kBin = 3;
    const size_t bins = size_t(std::floor((hi - lo) / kBin)) + 1;
    std::vector<Vec2> sum(bins, Vec2::Zero());
    std::vector<int> count(bins, 0);
    for (const Vec2& p : pts) {
      const size_t b = std::min(bins - 1, size_t(((p - mean).dot(axis) - lo) / kBin));
      sum[b] += p, ++count[b];
    }
    std::vector<Vec2> line;
    for (size_t b = 0; b < bins; ++b)
      if (count[b]) line.push_back(sum[b] / count[b]);
    if (line.size() >= 2) lines.push_back(std::move(line));
  }
  return lines;
}

bool segment_cross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double& t, double& u) {
  const Vec2 r = b - a, q = d - c;
  const double den = r.x() * q.y() - r.y() * q.x();
  if (std::abs(den) < 1e-12) return false;  // parallel: no single crossing
  const Vec2 w = c - a;
  t = (w.x() * q.y() - w.y() * q.x()) / den;
  u = (w.x() * r.y() - w.y() * r.x()) / den;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}

Unit ellipse_unit(Vec2 c, double a, double b, double theta, bool inserted) {
  Unit u;
  u.ellipse = Ellipse{c, a, b, theta};
  u.inserted = inserted;
  return u;
}

}  // namespace

Sketch sketch_from_image(const cv::Mat& bgr, Rgb ridge, Rgb arc, int width, int height) {
  cv::Mat img = bgr;
  if (img.cols != width || img.rows != height) cv::resize(bgr, img, cv::Size(width, height), 0, 0, cv::INTER_NEAREST);
  cv::Mat r = stroke_mask(img, ridge), a = stroke_mask(img, arc);
  // A stroke drawn over the other cuts it in two at the crossing: each mask
  // takes the other's pixels within 4 px of its own, which bridges strokes
  // up to 8 px wide.
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(9, 9));
  cv::Mat r_near, a_near;
  cv::dilate(r, r_near, kernel);
  cv::dilate(a, a_near, kernel);
  cv::Mat r_joined = r | (a & r_near), a_joined = a | (r & a_near);
  return Sketch{stroke_lines(r_joined), stroke_lines(a_joined), 12};
}

void draw_lines(cv::Mat& img, const std::vector<std::vector<Vec2>>& lines, cv::Scalar bgr, int thickness) {
  for (const auto& l : lines)
    for (size_t i = 0; i + 1 < l.size(); ++i)
      cv::line(img, cv::Point2d(l[i].x(), l[i].y()), cv::Point2d(l[i + 1].x(), l[i + 1].y()), bgr, thickness, cv::LINE_AA);
}

cv::Mat sketch_image(const Sketch& k, Rgb ridge, Rgb arc, int width, int height, int thickness) {
  cv::Mat img(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  draw_lines(img, k.ridges, cv::Scalar(ridge.b, ridge.g, ridge.r), thickness);
  draw_lines(img, k.arcs, cv::Scalar(arc.b, arc.g, arc.r), thickness);
  return img;
}

Sketch scene_sketch(const Scene& s) {
  const auto& k = s.segment.sketch;
  if (k.image.empty()) return Sketch{to_lines(k.ridges), to_lines(k.arcs)};
  const cv::Mat img = read_image(s.resolve(k.image), "segment.sketch.image");
  Sketch sk = sketch_from_image(img, k.ridge_color, k.arc_color, s.window.width, s.region.height);
  if (sk.ridges.empty()) throw key_error("segment.sketch.ridge_color", "no stroke of this colour in '" + k.image + "'");
  if (sk.arcs.empty()) throw key_error("segment.sketch.arc_color", "no stroke of this colour in '" + k.image + "'");
  return sk;
}

std::vector<Crossing> crossings(const Sketch& k) {
  std::vector<Crossing> out;
  for (size_t ri = 0; ri < k.ridges.size(); ++ri) {
    const auto& ridge = k.ridges[ri];
    std::vector<Crossing> here;
    double start = 0;
    for (size_t i = 0; i + 1 < ridge.size(); ++i) {
      const double len = (ridge[i + 1] - ridge[i]).norm();
      for (size_t ai = 0; ai < k.arcs.size(); ++ai) {
        const auto& arc = k.arcs[ai];
        for (size_t j = 0; j + 1 < arc.size(); ++j) {
          double t, u;
          if (!segment_cross(ridge[i], ridge[i + 1], arc[j], arc[j + 1], t, u)) continue;
          here.push_back({ridge[i] + t * (ridge[i + 1] - ridge[i]), int(ri), int(ai), start + t * len});
        }
      }
      start += len;
    }
    std::stable_sort(here.begin(), here.end(), [](const Crossing& a, const Crossing& b) { return a.along < b.along; });
    // Crossings of one arc within merge_px along the ridge: their middle one.
    std::vector<bool> used(here.size(), false);
    const size_t first = out.size();
    for (size_t i = 0; i < here.size(); ++i) {
      if (used[i]) continue;
      std::vector<size_t> group;
      for (size_t m = i; m < here.size() && here[m].along - here[i].along <= k.merge_px; ++m)
        if (!used[m] && here[m].arc == here[i].arc) group.push_back(m), used[m] = true;
      out.push_back(here[group[group.size() / 2]]);
    }
    std::stable_sort(out.begin() + long(first), out.end(),
                     [](const Crossing& a, const Crossing& b) { return a.along < b.along; });
  }
  return out;
}

double sketch_max_major(const Scene& s, const Sketch& k) {
  const double H = s.region.height;
  int near_bottom = 0;
  for (const auto& ridge : k.ridges) {
    double lowest = -INFINITY;  // largest window y
    for (const Vec2& p : ridge) lowest = std::max(lowest, p.y());
    near_bottom += lowest >= H * (1 - s.segment.sketch.bottom_band);
  }
  return s.window.width / double(std::max(1, near_bottom));
}

double sketch_semi_major(const Scene& s, double a_m, double y) {
  const double up = s.region.height - y;  // paper P_i(y): height above the region's bottom
  return std::max(s.segment.sketch.semi_major_floor, 0.5 * a_m - s.segment.sketch.shrink_per_px * up);
}

std::vector<Unit> sketch_units(const Scene& s, const Sketch& k) {
  const auto& sg = s.segment;
  const double W = s.window.width, H = s.region.height;
  std::vector<Crossing> all = crossings(k);
  std::vector<Crossing> inside;
  for (const Crossing& c : all)
    if (c.p.x() >= 0 && c.p.x() <= W && c.p.y() >= 0 && c.p.y() <= H) inside.push_back(c);
  if (inside.empty())
    throw key_error("segment.sketch.arcs", "no arc-like curve crosses a ridge line inside the region (" +
                                               std::to_string(all.size()) + " crossings outside it)");
  const double a_m = sketch_max_major(s, k);
  std::vector<Unit> units;
  std::vector<double> semi_minor;
  for (size_t i = 0; i < inside.size(); ++i) {
    KeyedRng rng(s.layout(), Stream::Sketch, i);
    const double a = sketch_semi_major(s, a_m, inside[i].p.y());
    const double e = rng.real(sg.eccentricity_min, sg.eccentricity_max);
    const double b = a * std::sqrt(1 - e * e);
    // paper: O = (P_x, P_y - b) upward, so the ellipse's top touches P.
    units.push_back(ellipse_unit(Vec2(inside[i].p.x(), inside[i].p.y() + b), a, b, 0, false));
    semi_minor.push_back(b);
  }
  if (!sg.sketch.narrow) return units;
  // paper Fig. 7b-c: where the next crossing up a ridge is farther than
  // 1.2 b of the lower ellipse, the piles leave the ridge; two long narrow
  // ellipses on the lower one's top, along its tangent, keep it.
  std::vector<bool> insert(inside.size(), false);
  for (size_t i = 0; i + 1 < inside.size(); ++i) {
    if (inside[i].ridge != inside[i + 1].ridge) continue;
    const size_t lower = inside[i].p.y() >= inside[i + 1].p.y() ? i : i + 1;
    if ((inside[i].p - inside[i + 1].p).norm() > sg.sketch.narrow_spacing * semi_minor[lower]) insert[lower] = true;
  }
  for (size_t i = 0; i < inside.size(); ++i) {
    if (!insert[i]) continue;
    const Ellipse lower = units[i].ellipse;
    KeyedRng rng(s.layout(), Stream::Sketch, i);
    rng.real();  // the lower ellipse's eccentricity
    for (auto [lo, hi] : {std::pair{kNarrowRightMinDeg, kNarrowRightMaxDeg}, {kNarrowLeftMinDeg, kNarrowLeftMaxDeg}}) {
      const double th = rng.real(lo, hi) * kDeg;
      // Upward frame to window: y flips.
      const Vec2 q = lower.c + Vec2(lower.a * std::cos(th), -lower.b * std::sin(th));
      const Vec2 tangent(-lower.a * std::sin(th), -lower.b * std::cos(th));
      double angle = std::atan2(tangent.y(), tangent.x());
      if (angle > std::numbers::pi / 2) angle -= std::numbers::pi;
      if (angle <= -std::numbers::pi / 2) angle += std::numbers::pi;
      const double a = kNarrowMajorRatio * lower.a, e = rng.real(kNarrowEccMin, kNarrowEccMax);
      units.push_back(ellipse_unit(q, a, a * std::sqrt(1 - e * e), angle, true));
    }
  }
  return units;
}

}  // namespace sandpic
