#include <gtest/gtest.h>

#include "src/init/init.h"

namespace sandpic {
namespace {

void expect_exact_cover(const Scene& s, const Tessellation& t) {
  std::vector<int> hits(size_t(s.window.width) * s.region.height, 0);
  for (const Cell& c : t.cells) {
    EXPECT_LT(c.x0, c.x1);
    EXPECT_LT(c.y0, c.y1);
    for (int y = c.y0; y < c.y1; ++y)
      for (int x = c.x0; x < c.x1; ++x) ++hits[size_t(y) * s.window.width + size_t(x)];
  }
  for (int h : hits) ASSERT_EQ(h, 1);
}

TEST(Tessellation, EveryKindCoversTheRegionOnce) {
  for (auto kind : {TessellationKind::Uniform, TessellationKind::Varying, TessellationKind::Strips}) {
    Scene s;
    s.init.tessellation = kind;
    expect_exact_cover(s, tessellate(s));
  }
}

TEST(Tessellation, VaryingRowsGrowDownwardWithWidthsInRange) {
  Scene s;
  Tessellation t = tessellate(s);
  int last_height = 0, last_y0 = -1;
  for (const Cell& c : t.cells) {
    if (c.y0 == last_y0) continue;
    if (c.y1 < s.region.height) {  // the last row takes the remainder
      EXPECT_GE(c.y1 - c.y0, last_height);
      last_height = c.y1 - c.y0;
    }
    last_y0 = c.y0;
  }
  EXPECT_GT(last_height, s.init.row_height_min * 2);
  for (const Cell& c : t.cells) {
    if (c.x1 < s.window.width) {
      EXPECT_GE(c.x1 - c.x0, s.init.cell_width_min - 1);
    }
  }
}

TEST(Tessellation, StripsSpanTheWidth) {
  Scene s;
  s.init.tessellation = TessellationKind::Strips;
  for (const Cell& c : tessellate(s).cells) {
    EXPECT_EQ(c.x0, 0);
    EXPECT_EQ(c.x1, s.window.width);
  }
}

}  // namespace
}  // namespace sandpic
