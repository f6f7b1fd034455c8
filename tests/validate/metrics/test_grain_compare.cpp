#include "validate/metrics/grain_compare.h"

#include <cmath>

#include <gtest/gtest.h>

#include "src/errors.h"

namespace sandpic {
namespace {

// Ten grains of class 0 in unit 0 whose falls start at 100: grain i rests
// travel[i] px to the right of it.
std::vector<GrainRow> table(const std::vector<double>& travel, double release = 100) {
  std::vector<GrainRow> rows;
  for (size_t i = 0; i < travel.size(); ++i) {
    GrainRow r;
    r.id = int32_t(i), r.cls = 0, r.unit = 0, r.order = int64_t(i);
    r.release_x = release, r.x = release + travel[i], r.y = 50;
    rows.push_back(r);
  }
  return rows;
}

TEST(GrainCompare, ATableMatchesItself) {
  const auto a = table({0, 1, 1.5, 2, 3, 4, 5, 6, 8, 20});
  const GrainComparison c = compare_grains(a, a, "a", "b");
  EXPECT_EQ(c.grains, 10);
  EXPECT_TRUE(c.same_release);
  EXPECT_DOUBLE_EQ(c.grain_dx_px, 0);
  EXPECT_DOUBLE_EQ(c.grain_dy_px, 0);
  EXPECT_DOUBLE_EQ(c.travel_distance_px[0], 0);
  const TravelStats& t = c.travel_a[0];
  EXPECT_EQ(t.grains, 10);
  EXPECT_DOUBLE_EQ(t.mean_px, 5.05);
  EXPECT_DOUBLE_EQ(t.median_px, 4);  // nearest rank: the 6th of 10
  EXPECT_DOUBLE_EQ(t.p90_px, 20);
  EXPECT_DOUBLE_EQ(t.within_2px, 0.4);
  EXPECT_EQ(c.travel_a[1].grains, 0);
  EXPECT_DOUBLE_EQ(c.unit_spread_a_px, c.unit_spread_b_px);
}

TEST(GrainCompare, GrainsThatRestFartherTravelFarther) {
  const auto a = table({0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  const auto b = table({3, 3, 3, 3, 3, -3, -3, -3, -3, -3});
  const GrainComparison c = compare_grains(a, b, "a", "b");
  EXPECT_TRUE(c.same_release);
  EXPECT_DOUBLE_EQ(c.grain_dx_px, 3);
  EXPECT_DOUBLE_EQ(c.travel_distance_px[0], 3);
  EXPECT_DOUBLE_EQ(c.travel_b[0].within_2px, 0);
  EXPECT_DOUBLE_EQ(c.unit_spread_a_px, 0);
  EXPECT_DOUBLE_EQ(c.unit_spread_b_px, 3);  // ±3 around 100
}

TEST(GrainCompare, OtherReleasePointsCompareTravelButNotGrains) {
  const auto a = table({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  auto b = table({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 140);  // another physics seed's jitter
  const GrainComparison c = compare_grains(a, b, "a", "b");
  EXPECT_FALSE(c.same_release);
  EXPECT_TRUE(std::isnan(c.grain_dx_px));
  EXPECT_TRUE(std::isnan(c.grain_dy_px));
  EXPECT_DOUBLE_EQ(c.travel_distance_px[0], 0);
}

// Two units of five grains: b puts unit 1's sand 4 px further right and
// spreads unit 0's over ±3 px where a stacks it on one point.
TEST(GrainCompare, UnitsCompareByWhereAndHowWidelyTheirSandLies) {
  std::vector<GrainRow> a, b;
  const double b_unit0[] = {97, 103, 97, 103, 100};
  for (int i = 0; i < 10; ++i) {
    GrainRow r;
    r.id = i, r.cls = 0, r.unit = i / 5, r.order = i, r.release_x = i < 5 ? 100 : 200, r.y = 50;
    r.x = r.release_x;
    a.push_back(r);
    r.x = i < 5 ? b_unit0[i] : 204;
    b.push_back(r);
  }
  const GrainComparison c = compare_grains(a, b, "a", "b");
  EXPECT_DOUBLE_EQ(c.unit_centroid_distance_px, 2);  // (5 · 0 + 5 · 4) / 10
  EXPECT_NEAR(c.unit_spread_difference_px, std::sqrt(7.2) / 2, 1e-12);  // unit 0: σ = √7.2, half the grains
  EXPECT_DOUBLE_EQ(c.unit_spread_a_px, 0);
  EXPECT_NEAR(c.unit_spread_b_px, std::sqrt(7.2) / 2, 1e-12);
  const GrainComparison same = compare_grains(a, a, "a", "a");
  EXPECT_DOUBLE_EQ(same.unit_centroid_distance_px, 0);
  EXPECT_DOUBLE_EQ(same.unit_spread_difference_px, 0);
}

TEST(GrainCompare, TablesOfOtherScenesAreRefusedNamingTheFile) {
  const auto a = table({1, 2, 3});
  auto fewer = table({1, 2});
  auto other_class = a;
  other_class[1].cls = 2;
  for (const auto& b : {fewer, other_class}) {
    try {
      compare_grains(a, b, "lattice.csv", "dem.csv");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("dem.csv"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace sandpic
