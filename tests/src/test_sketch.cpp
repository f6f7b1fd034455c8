#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "src/errors.h"
#include "src/init/init.h"
#include "src/scene_file.h"
#include "src/segment/sketch.h"

namespace sandpic {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

// Two vertical ridge lines at x = 250 and 750 from the region's bottom to
// its top, and a horizontal arc across each at the given heights (window y).
Scene sketch_scene(std::vector<double> left_y, std::vector<double> right_y) {
  Scene s;
  s.segment.method = SegmentMethod::Sketch;
  s.segment.sketch.ridges = {{{250, 350}, {250, 0}}, {{750, 350}, {750, 0}}};
  for (double y : left_y) s.segment.sketch.arcs.push_back({{200, y}, {300, y}});
  for (double y : right_y) s.segment.sketch.arcs.push_back({{700, y}, {800, y}});
  return s;
}

std::vector<Unit> ellipses(const std::vector<Unit>& units, bool inserted) {
  std::vector<Unit> out;
  for (const Unit& u : units)
    if (u.inserted == inserted) out.push_back(u);
  return out;
}

TEST(Sketch, CrossingsOfPolylinesInOrderAlongEachRidge) {
  Sketch k;
  k.ridges = {{Vec2(0, 100), Vec2(100, 0)}, {Vec2(200, 100), Vec2(200, 50), Vec2(200, 0)}};
  k.arcs = {{Vec2(0, 20), Vec2(300, 20)}, {Vec2(0, 50), Vec2(300, 50)}, {Vec2(0, 90), Vec2(40, 90)}};
  std::vector<Crossing> c = crossings(k);
  ASSERT_EQ(c.size(), 5u);  // ridge 1: y 90, 50, 20; ridge 2: 50 (through its corner point, once) and 20
  EXPECT_EQ(c[0].ridge, 0);
  EXPECT_NEAR(c[0].p.x(), 10, 1e-9);
  EXPECT_NEAR(c[0].p.y(), 90, 1e-9);
  EXPECT_NEAR(c[1].p.y(), 50, 1e-9);
  EXPECT_NEAR(c[2].p.y(), 20, 1e-9);
  EXPECT_NEAR(c[2].along, 80 * std::sqrt(2.0), 1e-9);
  EXPECT_EQ(c[3].ridge, 1);
  EXPECT_NEAR(c[3].p.y(), 50, 1e-9);
  EXPECT_NEAR(c[4].p.y(), 20, 1e-9);
}

TEST(Sketch, EllipsesSitUnderTheCrossingsWithThePapersSizes) {
  Scene s = sketch_scene({300, 270}, {200});
  s.segment.sketch.narrow = false;
  Sketch k = scene_sketch(s);
  // Both ridges reach the region's bottom: A_m = 1000 / 2.
  EXPECT_DOUBLE_EQ(sketch_max_major(s, k), 500);
  std::vector<Unit> units = sketch_units(s, k);
  ASSERT_EQ(units.size(), 3u);
  const std::vector<Vec2> p = {Vec2(250, 300), Vec2(250, 270), Vec2(750, 200)};
  for (size_t i = 0; i < 3; ++i) {
    const Ellipse& e = units[i].ellipse;
    // a_i = 0.5 A_m - 0.3 P_i(y), P_i(y) up from the region's bottom (350).
    EXPECT_NEAR(e.a, 250 - 0.3 * (350 - p[i].y()), 1e-9) << i;
    const double ecc = std::sqrt(1 - e.b * e.b / (e.a * e.a));
    EXPECT_GE(ecc, 0.45 - 1e-12);
    EXPECT_LE(ecc, 0.65 + 1e-12);
    // Centre b below the crossing: the ellipse's top touches it.
    EXPECT_NEAR(e.c.x(), p[i].x(), 1e-9);
    EXPECT_NEAR(e.c.y(), p[i].y() + e.b, 1e-9);
    EXPECT_NEAR(e.level(p[i]), 1, 1e-9);
    EXPECT_FALSE(units[i].inserted);
  }
  // Higher crossings get smaller ellipses, down to the floor.
  EXPECT_LT(units[1].ellipse.a, units[0].ellipse.a);
  s.segment.sketch.shrink_per_px = 2;
  EXPECT_DOUBLE_EQ(sketch_units(s, k)[2].ellipse.a, s.segment.sketch.semi_major_floor);
}

TEST(Sketch, MaxMajorCountsOnlyRidgesReachingTheBottom) {
  Scene s = sketch_scene({300}, {300});
  s.segment.sketch.ridges.push_back({{500, 100}, {500, 0}});  // high up: not near the bottom
  Sketch k = scene_sketch(s);
  EXPECT_DOUBLE_EQ(sketch_max_major(s, k), 500);
  s.segment.sketch.bottom_band = 0.8;  // now it reaches the band
  EXPECT_NEAR(sketch_max_major(s, k), 1000 / 3.0, 1e-9);
}

TEST(Sketch, NarrowEllipsesExactlyWhereCrossingsAlongARidgeAreFarApart) {
  // Left ridge: crossings 300 and 200 px down the window. Right ridge: one.
  Scene s = sketch_scene({300, 200}, {250});
  Sketch k = scene_sketch(s);
  s.segment.sketch.narrow = false;
  const std::vector<Unit> plain = sketch_units(s, k);
  s.segment.sketch.narrow = true;
  const double b_lower = plain[0].ellipse.b;  // the crossing at y = 300
  // The spacing rule: far = more than narrow_spacing x b of the lower ellipse.
  s.segment.sketch.narrow_spacing = 100 / b_lower - 1e-6;  // 100 px is just farther
  std::vector<Unit> units = sketch_units(s, k);
  std::vector<Unit> narrow = ellipses(units, true);
  ASSERT_EQ(narrow.size(), 2u);
  ASSERT_EQ(ellipses(units, false).size(), 3u);
  const Ellipse& lower = plain[0].ellipse;
  bool right = false, left = false;
  for (const Unit& u : narrow) {
    const Ellipse& e = u.ellipse;
    EXPECT_NEAR(e.a, 0.6 * lower.a, 1e-9);  // paper: 0.6 a of the lower ellipse
    const double ecc = std::sqrt(1 - e.b * e.b / (e.a * e.a));
    EXPECT_GE(ecc, 0.96 - 1e-12);
    EXPECT_LE(ecc, 0.98 + 1e-12);
    EXPECT_NEAR(lower.level(e.c), 1, 1e-9);  // centred on the lower ellipse
    // At a parametric angle in the documented ranges, upward from its major axis.
    const double th = std::atan2((lower.c.y() - e.c.y()) / lower.b, (e.c.x() - lower.c.x()) / lower.a) / kDeg;
    if (th >= kNarrowRightMinDeg && th <= kNarrowRightMaxDeg) right = true;
    if (th >= kNarrowLeftMinDeg && th <= kNarrowLeftMaxDeg) left = true;
    // Along the lower ellipse's tangent there.
    const Vec2 tangent(-lower.a * std::sin(th * kDeg), -lower.b * std::cos(th * kDeg));
    const Vec2 axis(std::cos(e.theta), std::sin(e.theta));
    EXPECT_NEAR(std::abs(axis.dot(tangent.normalized())), 1, 1e-9);
  }
  EXPECT_TRUE(right);
  EXPECT_TRUE(left);
  // Just nearer than the rule: none.
  s.segment.sketch.narrow_spacing = 100 / b_lower + 1e-6;
  EXPECT_TRUE(ellipses(sketch_units(s, k), true).empty());
}

TEST(Sketch, ImageStrokesGiveTheSameCrossingsAsTheLines) {
  Scene s;
  s.segment.method = SegmentMethod::Sketch;
  s.segment.sketch.ridges = {{{200, 350}, {320, 40}}, {{800, 350}, {700, 30}}};
  s.segment.sketch.arcs = {{{140, 280}, {200, 240}, {270, 230}, {330, 260}},
                           {{230, 120}, {290, 80}, {360, 110}},
                           {{680, 220}, {740, 180}, {820, 210}}};
  const std::vector<Crossing> exact = crossings(scene_sketch(s));
  ASSERT_EQ(exact.size(), 3u);
  // The same sketch drawn 3 px wide, arcs over ridges (cutting them).
  const cv::Mat img =
      sketch_image(scene_sketch(s), s.segment.sketch.ridge_color, s.segment.sketch.arc_color, 1000, 350, 3);
  const Sketch k = sketch_from_image(img, s.segment.sketch.ridge_color, s.segment.sketch.arc_color, 1000, 350);
  EXPECT_EQ(k.ridges.size(), 2u);
  EXPECT_EQ(k.arcs.size(), 3u);
  const std::vector<Crossing> found = crossings(k);
  ASSERT_EQ(found.size(), exact.size());
  for (const Crossing& e : exact) {
    double nearest = INFINITY;
    for (const Crossing& f : found) nearest = std::min(nearest, (f.p - e.p).norm());
    EXPECT_LT(nearest, 3.0) << e.p.transpose();
  }
}

TEST(Sketch, SceneErrorsNameTheKey) {
  auto fails_at = [](const std::string& text, const std::string& key) {
    try {
      Scene s;
      apply_json(s, json::parse(text));
      validate(s);
      segment(s, tessellate(s));
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "no error for " << text;
  };
  fails_at(R"({"segment": {"method": "sketch"}})", "segment.sketch.ridges");
  fails_at(R"({"segment": {"method": "sketch", "sketch": {"ridges": [[[1, 2], [3, 4]]]}}})", "segment.sketch.arcs");
  fails_at(R"({"segment": {"method": "sketch", "sketch": {"ridges": [[[1, 2]]], "arcs": []}}})",
           "segment.sketch.ridges[0]");
  fails_at(R"({"segment": {"sketch": {"arcs": [[[1, 2], [3, "x"]]]}}})", "segment.sketch.arcs[0][1][1]");
  // No arc crosses a ridge.
  fails_at(R"({"segment": {"method": "sketch", "sketch": {"ridges": [[[10, 300], [10, 0]]],
                                                           "arcs": [[[100, 100], [200, 100]]]}}})",
           "segment.sketch.arcs");
  fails_at(R"({"segment": {"method": "sketch", "sketch": {"image": "/nonexistent/sketch.png"}}})",
           "segment.sketch.image");
}

}  // namespace
}  // namespace sandpic
