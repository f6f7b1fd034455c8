#include <gtest/gtest.h>

#include <algorithm>

#include "src/falling_order.h"

namespace sandpic {
namespace {

TEST(FallingOrder, UnitsRowByRowLowestFirstRandomWithinARow) {
  std::vector<Unit> units(5);
  double ys[5] = {10, 50, 52, 30, 49};
  for (int i = 0; i < 5; ++i) units[size_t(i)].ellipse = Ellipse{Vec2(i * 20.0, ys[i]), 5, 5, 0};
  std::vector<int> firsts;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    auto u = units;
    order_units(u, 5, seed);
    std::vector<double> cy;
    for (auto& x : u) cy.push_back(x.centre().y());
    // Rows: {52, 50, 49}, {30}, {10}.
    EXPECT_EQ(u[0].row, 0);
    EXPECT_EQ(u[2].row, 0);
    EXPECT_EQ(u[3].row, 1);
    EXPECT_EQ(u[4].row, 2);
    EXPECT_DOUBLE_EQ(cy[3], 30);
    EXPECT_DOUBLE_EQ(cy[4], 10);
    firsts.push_back(int(cy[0]));
  }
  std::sort(firsts.begin(), firsts.end());
  EXPECT_GT(std::unique(firsts.begin(), firsts.end()) - firsts.begin(), 1);  // random within the row
}

TEST(FallingOrder, GrainsByDistanceToTheOutletTiesRandom) {
  Scene s;
  s.window.width = 41;
  s.region.height = 20;
  GrainSet g = empty_region(s);
  Segmentation seg;
  seg.units.resize(1);
  seg.units[0].ellipse = Ellipse{Vec2(20.5, 10), 25, 15, 0};  // outlet at x = 20.5: mirror pairs tie
  seg.unit_of.assign(size_t(g.size()), 0);
  FallingOrder a = falling_order(seg, g, 1), b = falling_order(seg, g, 2);
  ASSERT_EQ(a.grain.size(), size_t(g.size()));
  auto sorted = a.grain;
  std::sort(sorted.begin(), sorted.end());
  for (size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], int32_t(i));  // a permutation
  Vec2 outlet = seg.units[0].outlet();
  for (size_t i = 1; i < a.grain.size(); ++i)
    ASSERT_LE((g.position(a.grain[i - 1]) - outlet).squaredNorm(), (g.position(a.grain[i]) - outlet).squaredNorm());
  EXPECT_EQ(falling_order(seg, g, 1).grain, a.grain);  // same seed, same order
  EXPECT_NE(b.grain, a.grain);                         // ties broken otherwise
}

}  // namespace
}  // namespace sandpic
