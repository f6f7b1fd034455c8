// physics/outline_watch.h: when a DEM run is over.
#include "physics/outline_watch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/holds.h"

namespace sandpic {
namespace {

constexpr double kHold = 0.03;  // px: 0.05 of a 0.6 px grain
constexpr double kEvery = kHoldSeconds / 10;

// Feeds outlines of `columns` columns from t0 for `seconds`, every tenth of
// kHoldSeconds, column j at height(j, t); returns the watch's verdicts.
template <class Height>
std::vector<bool> feed(OutlineWatch& w, int columns, double t0, double seconds, Height height) {
  std::vector<bool> holds;
  for (double t = t0; t <= t0 + seconds + 1e-9; t += kEvery) {
    if (!w.due(t)) continue;
    std::vector<double> top(static_cast<size_t>(columns));
    for (int j = 0; j < columns; ++j) top[size_t(j)] = height(j, t);
    w.add(t, top);
    holds.push_back(w.holds());
  }
  return holds;
}

TEST(OutlineWatch, AStillOutlineHoldsOnceWatchedForTheHoldTime) {
  OutlineWatch w(kHold);
  const auto v = feed(w, 100, 0, 2, [](int j, double) { return 10.0 + j % 7; });
  ASSERT_EQ(v.size(), 21u);
  for (size_t i = 0; i < 10; ++i) EXPECT_FALSE(v[i]) << i;  // under a second watched
  for (size_t i = 10; i < v.size(); ++i) EXPECT_TRUE(v[i]) << i;
}

// An all-dynamic heap's surface sinks as the heap compacts: slower than the
// hold distance a second, it holds, though it moves on and on.
TEST(OutlineWatch, ASurfaceSinkingSlowerThanTheHoldDistanceASecondHolds) {
  OutlineWatch w(kHold);
  const auto v = feed(w, 100, 0, 5, [](int, double t) { return 20.0 - 0.6 * kHold * t; });
  EXPECT_TRUE(v.back());
  OutlineWatch faster(kHold);
  EXPECT_FALSE(feed(faster, 100, 0, 5, [](int, double t) { return 20.0 - 1.2 * kHold * t; }).back());
}

// A flank creeping at 1.5 px/s never holds; a slump in one column starts
// the second over.
TEST(OutlineWatch, ACreepingFlankOrASlumpDoesNotHold) {
  OutlineWatch creep(kHold);
  for (bool h : feed(creep, 100, 0, 5, [](int j, double t) { return j < 40 ? 20.0 : 20.0 - 1.5 * t; })) EXPECT_FALSE(h);

  OutlineWatch slump(kHold);
  const auto v = feed(slump, 100, 0, 4, [](int j, double t) { return j == 50 && t > 2.05 ? 19.0 : 20.0; });
  ASSERT_EQ(v.size(), 41u);
  EXPECT_TRUE(v[20]);   // t = 2.0: held since t = 1
  EXPECT_FALSE(v[21]);  // t = 2.1: column 50 fell
  EXPECT_FALSE(v[30]);  // t = 3.0: within a second of the fall
  EXPECT_TRUE(v[31]);   // t = 3.1: held a second since
}

// A grain jittering somewhere must not keep the run going: all but 0.2% of
// the columns hold. A column with no number moves.
TEST(OutlineWatch, AllButAFewColumnsMustHold) {
  const auto jitter = [](int moving) {
    return [moving](int j, double t) { return j < moving ? 20.0 + (int(std::lround(t * 10)) % 2) : 20.0; };
  };
  OutlineWatch two(kHold), three(kHold);
  EXPECT_TRUE(feed(two, 1000, 0, 2, jitter(2)).back());
  EXPECT_FALSE(feed(three, 1000, 0, 2, jitter(3)).back());
  OutlineWatch nan(kHold);
  EXPECT_FALSE(feed(nan, 100, 0, 2, [](int j, double) { return j == 3 ? NAN : 20.0; }).back());
}

}  // namespace
}  // namespace sandpic
