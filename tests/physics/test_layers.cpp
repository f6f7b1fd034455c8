#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/layers.h"

namespace sandpic {
namespace {

LayerRule rule() {
  LayerRule r;
  r.rest_px = 0.05;
  r.patience_cycles = 3;
  r.slope_limit_rad = 35 * std::numbers::pi / 180;
  r.baseline = 3;
  r.support_px = 0.1;
  r.band_px = 10;
  return r;
}

TEST(Layers, AStaticGrainRaisesTheColumnsItCoversToItsOutline) {
  LayerHeights h(10);
  h.add_static(4.3, 2.0, 0.55);  // covers columns 4 (its centre) and 5 (from x = 4.5)
  EXPECT_DOUBLE_EQ(h.hs[4], 2.55);
  EXPECT_NEAR(h.hs[5], 2.0 + std::sqrt(0.55 * 0.55 - 0.2 * 0.2), 1e-12);
  EXPECT_EQ(h.hs[3], 0);
  EXPECT_EQ(h.hs[6], 0);
  h.add_static(4.3, 1.0, 0.55);  // a lower grain never lowers a column
  EXPECT_DOUBLE_EQ(h.hs[4], 2.55);
  EXPECT_DOUBLE_EQ(h.support(4.9, 0.28), h.hs[5]);  // a small grain over column 5 rests on it
  h.add_fixed(4.3, 1.0, 0.55);
  EXPECT_DOUBLE_EQ(h.hf[4], 1.55);
  EXPECT_EQ(h.hs.size(), h.hf.size());
}

TEST(Layers, SlopeIsTheSteepestDropOfTheStaticSurfaceABaselineAway) {
  LayerHeights h(20);
  EXPECT_NEAR(static_slope_rad(h, 10, 3), 0, 1e-12);  // on the flat floor
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 0.5 * j;  // a ramp of slope 0.5
  EXPECT_NEAR(static_slope_rad(h, 10, 3), std::atan(0.5), 1e-12);
  EXPECT_NEAR(static_slope_rad(h, 10.4, 3), std::atan(0.5), 1e-12);  // read at the grain's column
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 10 - 0.5 * j;  // the other way: the same drop
  EXPECT_NEAR(static_slope_rad(h, 10, 3), std::atan(0.5), 1e-12);
  // An apex: the paper's signed mean (θ1 + θ2)/2 would be 0 here.
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 10 - std::abs(j - 10);
  EXPECT_NEAR(static_slope_rad(h, 10, 3), std::atan((10 - 2.0 / 3 - 7) / 3), 1e-12);
  // In a hollow there is no drop.
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = std::abs(j - 10);
  EXPECT_LT(static_slope_rad(h, 10, 3), 0);
  // Grain-scale roughness (the outline dips between grains: every third
  // column 0.6 lower) reads the same at both ends: no slope.
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 5 - 0.6 * (j % 3 == 0);
  EXPECT_NEAR(static_slope_rad(h, 9, 3), 0, 1e-12);
  EXPECT_NEAR(static_slope_rad(h, 10, 3), 0, 1e-12);
  // At a wall only the open side counts.
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 5;
  h.hs[4] = h.hs[5] = h.hs[6] = 4;
  EXPECT_NEAR(static_slope_rad(h, 2, 3), std::atan2(1, 3), 1e-12);
}

// paper §8.1: "the static layer never grows steeper than α". The slope is
// the static surface's, smoothed alike at both ends: we measured the drop
// from the grain's bottom to H_s (the grains' tops) before, and a grain
// nested in a flank, its bottom 0.3-1.1 px under the tops beside it, read
// the flank up to 15° low (on verify-dem's quick heap a 17° static core
// grew at α 9.2°). From the grain's top, a grain lying on a flat static bed
// read as a bump of 14°: no new layer could start below that.
TEST(Layers, TheSlopeIsTheStaticSurfacesNotTheGrains) {
  LayerHeights h(30);
  LayerRule r = rule();
  r.patience_cycles = 0;
  r.slope_limit_rad = 12 * std::numbers::pi / 180;
  const double t = std::tan(20 * std::numbers::pi / 180);
  // A 20° static flank of grain tops, dipping 0.5 px between grains.
  for (int j = 0; j < 30; ++j) h.hs[size_t(j)] = 10 + t * j - 0.5 * (j % 2);
  EXPECT_FALSE(becomes_static(h, r, 11, h.hs[11] - 0.5 + 0.5, 0.5, 0.01, 1));  // nested in a dip
  EXPECT_FALSE(becomes_static(h, r, 10, h.hs[10] + 0.5, 0.5, 0.01, 1));        // lying on a top
  r.slope_limit_rad = 25 * std::numbers::pi / 180;
  EXPECT_TRUE(becomes_static(h, r, 11, h.hs[11], 0.5, 0.01, 1));
  // A flat static bed: a grain lying on it starts a new layer at any α.
  for (int j = 0; j < 30; ++j) h.hs[size_t(j)] = 3 - 0.5 * (j % 2);
  r.slope_limit_rad = 1 * std::numbers::pi / 180;
  EXPECT_TRUE(becomes_static(h, r, 12, 3.5, 0.5, 0.01, 1));
  // The bare floor reads as a first layer of the largest grains' tops, so
  // the second layer reaches to the first one's edge.
  LayerHeights edge(30);
  for (int j = 0; j < 12; ++j) edge.hs[size_t(j)] = 1.1;  // a first layer over columns 0-11
  EXPECT_FALSE(becomes_static(edge, r, 10, 1.65, 0.55, 0.01, 1));
  r.floor_px = 1.1;
  EXPECT_TRUE(becomes_static(edge, r, 10, 1.65, 0.55, 0.01, 1));
}

TEST(Layers, StaticNeedsRestSupportAndAGentleSlopeOrLongRest) {
  LayerHeights h(20);
  LayerRule r = rule();
  EXPECT_FALSE(becomes_static(h, r, 5, 0.5, 0.5, 0.2, 0));   // moving
  EXPECT_FALSE(becomes_static(h, r, 5, 0.5, 0.5, 0.01, 0));  // not yet a whole cycle at rest
  EXPECT_TRUE(becomes_static(h, r, 5, 0.5, 0.5, 0.01, 1));   // at rest on the floor
  EXPECT_FALSE(becomes_static(h, r, 5, 1.5, 0.5, 0.01, 1));  // at rest on a grain that is not static
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 2.0 * j;    // 63°: steeper than α
  EXPECT_FALSE(becomes_static(h, r, 10, 20.5, 0.5, 0.01, 1));
  EXPECT_TRUE(becomes_static(h, r, 10, 20.5, 0.5, 0.01, 3));  // held there for three cycles
  r.patience_cycles = 0;  // the default: never static on a slope steeper than α
  EXPECT_FALSE(becomes_static(h, r, 10, 20.5, 0.5, 0.01, 1000));
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 0.5 * j;  // 27°: gentler than α
  EXPECT_TRUE(becomes_static(h, r, 10, 5.5, 0.5, 0.01, 1));
  // At the toe of a static flank gentler than α, on the floor.
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = j < 11 ? 0.0 : 0.5 * (j - 10);
  EXPECT_TRUE(becomes_static(h, r, 10, 0.5, 0.5, 0.01, 1));
}

// A grain at rest beside a static flank steeper than α, in the hollow of the
// grain uphill (whose outline reaches over its column): it stays dynamic and
// rolls on, or the static layer grows as steep as the grains happen to jam.
TEST(Layers, AGrainBesideASteepStaticFlankStaysDynamic) {
  LayerHeights h(40);
  LayerRule r = rule();
  r.patience_cycles = 0;
  const double c = std::cos(50 * std::numbers::pi / 180), s = std::sin(50 * std::numbers::pi / 180);
  for (int i = 5; i < 20; ++i) h.add_static(10 + i * c, 0.5 + i * s, 0.5);  // a 50° chain of touching grains
  const double x = 10 + 4 * c, y = 0.5 + 4 * s;  // the next grain down the chain
  ASSERT_GT(h.hs[size_t(h.column(x))], y + 0.5);  // the grain uphill reaches over its column
  EXPECT_FALSE(becomes_static(h, r, x, y, 0.5, 0.01, 1));
  EXPECT_TRUE(becomes_static(h, r, 10 + 0 * c, 0.5, 0.5, 0.01, 1));  // the chain's foot, on the floor
}

TEST(Layers, FixedOnlyUnderTheStaticBand) {
  LayerHeights h(20);
  LayerRule r = rule();
  for (auto& v : h.hs) v = 30;
  for (auto& v : h.hf) v = 18.9;  // each grain rests on the fixed layer
  EXPECT_FALSE(becomes_fixed(h, r, 10, 19.6, 0.5));  // its top is inside the band
  EXPECT_TRUE(becomes_fixed(h, r, 10, 19.4, 0.5));
  for (auto& v : h.hf) v = 11.5;
  h.hs[13] = 18;  // a low static column within the baseline keeps the band whole
  EXPECT_FALSE(becomes_fixed(h, r, 11, 12, 0.5));
  EXPECT_TRUE(becomes_fixed(h, r, 5, 12, 0.5));  // but not further away
}

// The fixed layer grows from the floor up: a grain deep under the band but
// resting on a grain that is not fixed stays static until that one is.
TEST(Layers, FixedOnlyOnTheFixedLayer) {
  LayerHeights h(20);
  LayerRule r = rule();
  for (auto& v : h.hs) v = 30;
  EXPECT_TRUE(becomes_fixed(h, r, 10, 0.5, 0.5));    // on the floor
  EXPECT_FALSE(becomes_fixed(h, r, 10, 1.45, 0.5));  // on the grain below, not yet fixed
  h.add_fixed(10, 0.5, 0.5);
  EXPECT_TRUE(becomes_fixed(h, r, 10, 1.45, 0.5));
  EXPECT_TRUE(becomes_fixed(h, r, 10.8, 1.2, 0.5));  // on its flank
  EXPECT_FALSE(becomes_fixed(h, r, 10.3, 2.45, 0.5));  // on a static grain over the fixed one
}

}  // namespace
}  // namespace sandpic
