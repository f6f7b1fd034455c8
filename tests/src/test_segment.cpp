#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/errors.h"
#include "src/segment/segment.h"

namespace sandpic {
namespace {

TEST(Ellipse, RowSpanAgreesWithLevel) {
  Ellipse e{Vec2(50, 40), 30, 12, 0.6};
  for (double y = 20; y < 60; y += 3.7) {
    double x0, x1;
    if (!e.row_span(y, x0, x1)) continue;
    EXPECT_NEAR(e.level(Vec2(x0, y)), 1, 1e-9);
    EXPECT_NEAR(e.level(Vec2(x1, y)), 1, 1e-9);
    EXPECT_LT(e.level(Vec2((x0 + x1) / 2, y)), 1);
  }
  double x0, x1;
  EXPECT_FALSE(e.row_span(40 + e.half_height() + 0.01, x0, x1));
}

TEST(Ellipse, LowestPointIsOnTheEllipseAndLowest) {
  Ellipse e{Vec2(10, 20), 8, 3, 30 * std::numbers::pi / 180};
  Vec2 p = e.lowest();
  EXPECT_NEAR(e.level(p), 1, 1e-9);
  EXPECT_NEAR(p.y(), 20 + e.half_height(), 1e-9);
  Ellipse flat{Vec2(10, 20), 8, 3, 0};
  EXPECT_NEAR(flat.lowest().x(), 10, 1e-9);
  EXPECT_NEAR(flat.lowest().y(), 23, 1e-9);
}

TEST(Segment, OverlapGoesToTheUnitThatFallsFirstAndGapsToTheNearest) {
  std::vector<Unit> units(2);
  units[0].ellipse = Ellipse{Vec2(30, 20), 15, 10, 0};
  units[1].ellipse = Ellipse{Vec2(45, 20), 15, 10, 0};
  auto owner = assign_grains(units, 100, 40);
  EXPECT_EQ(owner[20 * 100 + 38], 0);  // inside both: the first
  EXPECT_EQ(owner[20 * 100 + 55], 1);  // inside the second only
  EXPECT_EQ(owner[20 * 100 + 90], 1);  // in none: the nearest
  EXPECT_EQ(owner[20 * 100 + 2], 0);
  for (int32_t o : owner) EXPECT_GE(o, 0);
}

TEST(Segment, AutomaticEllipsesCoverTheRegionLargerTowardTheBottom) {
  Scene s;
  Segmentation seg = segment(s, Tessellation{});
  ASSERT_GT(seg.units.size(), 10u);
  int64_t inside = 0;
  for (int y = 0; y < s.region.height; ++y)
    for (int x = 0; x < s.window.width; ++x)
      for (const Unit& u : seg.units)
        if (u.ellipse.level(Vec2(x + 0.5, y + 0.5)) <= 1) {
          ++inside;
          break;
        }
  EXPECT_GT(double(inside) / (s.window.width * s.region.height), 0.97);
  double bottom_a = 0, top_a = 0;
  int bottom_n = 0, top_n = 0;
  for (const Unit& u : seg.units) {
    EXPECT_GE(u.ellipse.b / u.ellipse.a, std::sqrt(1 - 0.65 * 0.65) - 1e-9);
    EXPECT_LE(u.ellipse.b / u.ellipse.a, std::sqrt(1 - 0.45 * 0.45) + 1e-9);
    if (u.row == 0) bottom_a += u.ellipse.a, ++bottom_n;
    if (u.row == seg.units.back().row) top_a += u.ellipse.a, ++top_n;
  }
  EXPECT_GT(bottom_a / bottom_n, 1.5 * top_a / top_n);
}

TEST(Segment, CellsAreUnitsOnlyWithATessellation) {
  Scene s;
  s.segment.method = SegmentMethod::Cells;
  Initialization init = initialize(s);
  Segmentation seg = segment(s, init.tessellation);
  EXPECT_EQ(seg.units.size(), init.tessellation.cells.size());
  for (size_t id = 0; id < seg.unit_of.size(); ++id) {
    const Unit& u = seg.units[size_t(seg.unit_of[id])];
    Vec2 p = init.grains.position(int64_t(id));
    ASSERT_TRUE(p.x() >= u.x0 && p.x() < u.x1 && p.y() >= u.y0 && p.y() < u.y1);
  }
  EXPECT_THROW(segment(s, Tessellation{}), InputError);
}

}  // namespace
}  // namespace sandpic
