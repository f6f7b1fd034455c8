// paper §9-10, Fig. 18: regular patterns, their order, and the symmetric copy.
#include <gtest/gtest.h>

#include <algorithm>

#include "src/init/init.h"
#include "src/render.h"
#include "src/scene_file.h"
#include "src/segment/pattern.h"
#include "src/simulator.h"

namespace sandpic {
namespace {

Scene pattern_scene() {
  Scene s;
  s.window = {400, 300};
  s.region.height = 140;
  s.segment.method = SegmentMethod::Pattern;
  s.segment.pattern.row_height_min = 20;
  s.segment.pattern.row_height_max = 40;
  s.segment.pattern.separator = 3;
  return s;
}

TEST(Pattern, RowsAndSeparatorsTileTheRegionFromTheBottomUp) {
  const Scene s = pattern_scene();
  const auto rows = pattern_rows(s);
  ASSERT_GE(rows.size(), 3u);
  double below = 140;
  for (const PatternRow& r : rows) {
    EXPECT_DOUBLE_EQ(r.y1, below);
    EXPECT_GE(r.y1 - r.y0, 20 - 1e-9);
    EXPECT_DOUBLE_EQ(r.separator_y1, r.y0);
    EXPECT_LE(r.separator_y1 - r.separator_y0, 3 + 1e-9);
    EXPECT_NE(r.a1, r.a2);  // two ellipses of different axes
    EXPECT_LE(r.b1, (r.y1 - r.y0) / 2 + 1e-9);
    below = r.separator_y0;
  }
  EXPECT_DOUBLE_EQ(below, 0);
}

TEST(Pattern, EachRowRepeatsItsUnitAlongXAndFallsBeforeItsSeparator) {
  Scene s = pattern_scene();
  const Initialization init = initialize(s);
  const Segmentation seg = segment(s, init.tessellation);
  const auto rows = pattern_rows(s);
  // Falling order: row 0, its separator, row 1, ... (bands never interleave).
  int last = -1;
  for (const Unit& u : seg.units) {
    EXPECT_GE(u.band, last);
    last = u.band;
  }
  // Row 0: ellipses alternate a1, a2 with the unit's period.
  std::vector<const Unit*> row0;
  for (const Unit& u : seg.units)
    if (u.band == 0) row0.push_back(&u);
  std::sort(row0.begin(), row0.end(), [](auto* p, auto* q) { return p->ellipse.c.x() < q->ellipse.c.x(); });
  ASSERT_GE(row0.size(), 4u);
  for (size_t i = 0; i + 2 < row0.size(); ++i) {
    EXPECT_NEAR(row0[i + 2]->ellipse.c.x() - row0[i]->ellipse.c.x(), rows[0].period(), 1e-9);
    EXPECT_NEAR(row0[i]->ellipse.a + row0[i + 1]->ellipse.a, rows[0].a1 + rows[0].a2, 1e-9);
  }
  // Separators are thin rectangles of band 1.
  int separators = 0;
  for (const Unit& u : seg.units)
    if (u.band == 1) {
      ++separators;
      EXPECT_FALSE(u.is_ellipse);
      EXPECT_NEAR(u.y1 - u.y0, 3, 1e-9);
    }
  EXPECT_GE(separators, 1);
}

TEST(Pattern, SeparatorGrainsTakeTheirClassAndNoneWithoutSeparators) {
  Scene s = pattern_scene();
  s.grains.proportions = {0, 0, 0, 1};
  s.init.dominant_share = 1;
  s.segment.pattern.separator_class = 2;
  const auto rows = pattern_rows(s);
  const Initialization init = initialize(s);
  const int y = int(rows[0].separator_y0) + 1;  // inside the first separator
  EXPECT_EQ(init.grains.cls[size_t(y) * 400 + 17], 1);
  EXPECT_EQ(init.grains.cls[size_t(int(rows[0].y0) + 5) * 400 + 17], 3);
  s.segment.pattern.separator_class = 0;
  const Initialization plain = initialize(s);
  EXPECT_TRUE(std::all_of(plain.grains.cls.begin(), plain.grains.cls.end(), [](uint8_t c) { return c == 3; }));
}

TEST(Pattern, ValidateRefusesRowsTooThinForTheirEllipses) {
  Scene s = pattern_scene();
  s.segment.pattern.row_height_min = 1.5;
  s.segment.pattern.minor_share_min = 0.5;
  EXPECT_THROW(validate(s), InputError);
}

TEST(Symmetric, MirrorAboutTheDeepestValleyLeavesNoHoleAndIsExact) {
  // A 6-column pile whose surface dips to row 7 in column 2.
  cv::Mat m(12, 6, CV_8U, cv::Scalar(kNoSand));
  const int surface[6] = {5, 6, 7, 6, 4, 5};
  for (int x = 0; x < 6; ++x)
    for (int y = surface[x]; y < 12; ++y) m.at<uint8_t>(y, x) = uint8_t((x + y) % 4);
  const cv::Mat before = m.clone();
  const int axis = mirror_over(m, kNoSand);
  EXPECT_EQ(axis, 7);
  for (int i = 0; i < 5; ++i)  // rows 7..11 mirrored onto 6..2
    for (int x = 0; x < 6; ++x) EXPECT_EQ(m.at<uint8_t>(6 - i, x), before.at<uint8_t>(7 + i, x));
  for (int y = 7; y < 12; ++y)  // the sand itself untouched
    for (int x = 0; x < 6; ++x) EXPECT_EQ(m.at<uint8_t>(y, x), before.at<uint8_t>(y, x));
  EXPECT_EQ(m.at<uint8_t>(1, 0), kNoSand);  // beyond the copy's reach
  cv::Mat empty(5, 5, CV_8U, cv::Scalar(kNoSand));
  EXPECT_EQ(mirror_over(empty, kNoSand), 5);
  EXPECT_EQ(cv::countNonZero(empty != kNoSand), 0);
}

}  // namespace
}  // namespace sandpic
