#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/layers.h"

namespace sandpic {
namespace {

LayerRule rule() {
  LayerRule r;
  r.rest_px = 0.05;
  r.rest_cycles_any_slope = 3;
  r.slope_limit_rad = 35 * std::numbers::pi / 180;
  r.band_px = 10;
  return r;
}

TEST(Layers, SlopeIsTheSteepestDropToTheStaticLayer) {
  LayerHeights h(20);
  EXPECT_NEAR(static_slope_rad(h, 10, 0), 0, 1e-12);  // on the flat floor
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 0.5 * j;  // a ramp of slope 0.5
  EXPECT_NEAR(static_slope_rad(h, 10, 5), std::atan(0.5), 1e-12);
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 10 - 0.5 * j;  // the other way: the same drop
  EXPECT_NEAR(static_slope_rad(h, 10, 5), std::atan(0.5), 1e-12);
  // An apex: the paper's mean (θ1 + θ2)/2 would be 0 here.
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 10 - std::abs(j - 10);
  EXPECT_NEAR(static_slope_rad(h, 10, 11), std::atan(2.0), 1e-12);
  // In a hollow there is no drop.
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = std::abs(j - 10);
  EXPECT_LT(static_slope_rad(h, 10, 0.5), 0);
}

TEST(Layers, StaticNeedsRestAndAGentleSlopeOrLongRest) {
  LayerHeights h(20);
  LayerRule r = rule();
  EXPECT_FALSE(becomes_static(h, r, 5, 0.5, 0.2, 0));  // moving
  EXPECT_TRUE(becomes_static(h, r, 5, 0.5, 0.01, 1));  // at rest on the flat
  EXPECT_DOUBLE_EQ(h.hs[5], 0.5);
  for (int j = 0; j < 20; ++j) h.hs[size_t(j)] = 2.0 * j;  // 63°: steeper than α
  EXPECT_FALSE(becomes_static(h, r, 10, 20, 0.01, 1));
  EXPECT_TRUE(becomes_static(h, r, 10, 20, 0.01, 3));  // held there for three cycles
  r.rest_cycles_any_slope = 0;  // the default: never static on a slope steeper than α
  EXPECT_FALSE(becomes_static(h, r, 10, 20, 0.01, 1000));
}

TEST(Layers, FixedOnlyUnderTheStaticBand) {
  LayerHeights h(20);
  LayerRule r = rule();
  for (auto& v : h.hs) v = 30;
  EXPECT_FALSE(becomes_fixed(h, r, 10, 25));  // inside the band
  EXPECT_TRUE(becomes_fixed(h, r, 10, 15));
  EXPECT_DOUBLE_EQ(h.hf[10], 15);
  h.hs[12] = 18;  // a low static column nearby keeps the band whole
  EXPECT_FALSE(becomes_fixed(h, r, 11, 12));
}

}  // namespace
}  // namespace sandpic
