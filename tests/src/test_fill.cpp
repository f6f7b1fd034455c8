#include <gtest/gtest.h>

#include <set>

#include "src/errors.h"
#include "src/init/init.h"

namespace sandpic {
namespace {

Scene small_cells() {
  Scene s;
  s.init.tessellation = TessellationKind::Uniform;
  s.init.cell_width = 10;
  s.init.cell_height = 10;  // 3500 cells
  return s;
}

// paper Algorithm 1: expected shares 0.8·p_k + 0.2·Σ_{m≠k} p_m/3.
TEST(Fill, SharesMatchAlgorithm1) {
  Scene s = small_cells();
  Initialization init = initialize(s);
  auto n = init.grains.per_class();
  const double expected[4] = {0.342, 0.342, 0.158, 0.158};
  // Per-cell draws dominate the spread: sd ≈ sqrt(p(1-p)/3500)·0.8 ≈ 0.007.
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(double(n[k]) / double(init.grains.size()), expected[k], 0.03) << k;
}

TEST(Fill, EachCellHasItsTwoClassesDominantAboutFourFifths) {
  Scene s = small_cells();
  Initialization init = initialize(s);
  int64_t dominant = 0, total = 0;
  for (const Cell& c : init.tessellation.cells) {
    EXPECT_NE(c.dominant, c.secondary);
    std::set<int> seen;
    for (int y = c.y0; y < c.y1; ++y)
      for (int x = c.x0; x < c.x1; ++x) {
        int k = init.grains.cls[size_t(y) * 1000 + size_t(x)];
        seen.insert(k);
        dominant += k == c.dominant;
        ++total;
      }
    EXPECT_LE(seen.size(), 2u);
    for (int k : seen) EXPECT_TRUE(k == c.dominant || k == c.secondary);
  }
  EXPECT_NEAR(double(dominant) / double(total), 0.8, 0.005);
}

TEST(Fill, OverridesSetACellsClasses) {
  Scene s = small_cells();
  s.init.cell_overrides = {{5, 3, 2}};
  Initialization init = initialize(s);
  EXPECT_EQ(init.tessellation.cells[5].dominant, 3);
  EXPECT_EQ(init.tessellation.cells[5].secondary, 2);
  s.init.cell_overrides = {{999999, 0, 1}};
  EXPECT_THROW(initialize(s), InputError);
}

TEST(Fill, SameLayoutSeedSameGrainsOtherSeedOther) {
  Scene s = small_cells();
  auto a = initialize(s).grains.cls;
  EXPECT_EQ(initialize(s).grains.cls, a);
  s.physics_seed = 99;  // the physics seed does not touch the layout
  EXPECT_EQ(initialize(s).grains.cls, a);
  s.layout_seed = 2;
  EXPECT_NE(initialize(s).grains.cls, a);
}

}  // namespace
}  // namespace sandpic
