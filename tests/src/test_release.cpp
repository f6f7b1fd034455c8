#include <gtest/gtest.h>

#include <cmath>
#include <queue>
#include <random>

#include "src/release.h"

namespace sandpic {
namespace {

TEST(Release, Equation2CarriesTheGrainToTheOutlet) {
  Scene s;
  ReleaseModel m = release_model(s);
  EXPECT_NEAR(m.gravity_px_s2, 9810 / 0.18, 1e-6);
  EXPECT_NEAR(m.outlet_width_px, 15 / 0.18, 1e-9);
  GrainSet g = empty_region(s);
  Unit u;
  u.ellipse = Ellipse{Vec2(500, 200), 300, 100, 0};  // outlet (500, 300)
  Outlet o = outlet(m, u);
  const int32_t id = 100 * 1000 + 380;  // grain at (380.5, 100.5)
  ReleasePath p = release(m, o, g, id);
  double dx = 500 - 380.5, dy = 300 - 100.5;
  EXPECT_NEAR(p.vx, dx * std::sqrt(m.gravity_px_s2 / (2 * dy)), 1e-9);
  // Eq. 1: after t the grain is at the outlet.
  EXPECT_NEAR(p.start.x() + p.vx * p.t, 500, 1e-9);
  EXPECT_NEAR(p.start.y() + m.gravity_px_s2 * p.t * p.t / 2, 300, 1e-9);
  EXPECT_LE(std::abs(p.exit_x - 500), o.width / 2);
}

TEST(Release, DropIsAtLeastOneDiameterAndOutletNoWiderThanTheUnit) {
  Scene s;
  ReleaseModel m = release_model(s);
  GrainSet g = empty_region(s);
  Unit u;
  u.ellipse = Ellipse{Vec2(500, 100), 20, 10, 0};
  Outlet o = outlet(m, u);
  EXPECT_NEAR(o.width, 40, 1e-9);
  ReleasePath p = release(m, o, g, 110 * 1000 + 480);  // below the outlet
  EXPECT_TRUE(std::isfinite(p.vx));
  EXPECT_NEAR(p.t, std::sqrt(2 * m.min_drop_px[g.cls[0]] / m.gravity_px_s2), 1e-12);
  double lo = 1e9, hi = -1e9;
  for (int32_t id = 0; id < 5000; ++id) {
    double x = exit_x(m, o, id);
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  EXPECT_GE(lo, 480);
  EXPECT_LE(hi, 520);
  EXPECT_LT(lo, 481);  // the jitter spans the outlet
  EXPECT_GT(hi, 519);
}

// A unit reaching past a side wall drops its grains from inside the window,
// across the outlet's whole width, not in one file down the wall.
TEST(Release, AnOutletPastAWallIsMovedInside) {
  Scene s;
  ReleaseModel m = release_model(s);
  for (double cx : {-30.0, 1010.0}) {
    Unit u;
    u.ellipse = Ellipse{Vec2(cx, 100), 150, 40, 0};
    Outlet o = outlet(m, u);
    EXPECT_NEAR(o.width, 15 / 0.18, 1e-9);
    for (int32_t id = 0; id < 1000; ++id) {
      double x = exit_x(m, o, id);
      EXPECT_GE(x, 0);
      EXPECT_LE(x, s.window.width);
    }
    EXPECT_NEAR(std::abs(o.centre.x() - s.window.width / 2.0), s.window.width / 2.0 - o.width / 2, 1e-9);
  }
}

// The calendar queue gives the arrivals in exactly the order of a plain
// heap: by time, ties in falling order, whatever the bucket width, with
// pushes into the open bucket, into the past and far beyond the last bucket.
TEST(Arrivals, TheCalendarKeepsTheOrderOfAPlainHeap) {
  for (double bucket_s : {0.0, 1e-3, 0.25, 7.0}) {
    Arrivals calendar(bucket_s);
    std::priority_queue<Arrival, std::vector<Arrival>, std::greater<>> heap;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> later(0, 2);
    double now = 0;
    int64_t order = 0;
    std::vector<int64_t> got, want;
    for (int step = 0; step < 20000; ++step) {
      const int pushes = int(rng() % 3);
      for (int p = 0; p < pushes; ++p) {
        double t = now + later(rng);
        if (rng() % 50 == 0) t = now;                  // due at once
        if (rng() % 97 == 0) t = std::max(0.0, now - 1);  // in the past
        if (rng() % 499 == 0) t = now + 1e9;             // past the last bucket
        if (rng() % 7 == 0 && !want.empty()) t = std::floor(now * 4) / 4 + 0.25;  // ties
        calendar.push({t, order});
        heap.push({t, order});
        ++order;
      }
      if (rng() % 2 && !heap.empty()) {
        ASSERT_FALSE(calendar.empty());
        EXPECT_EQ(calendar.top().time, heap.top().time);
        got.push_back(calendar.top().order);
        want.push_back(heap.top().order);
        now = std::max(now, heap.top().time);
        calendar.pop();
        heap.pop();
      }
      ASSERT_EQ(calendar.size(), heap.size());
    }
    while (!heap.empty()) {
      got.push_back(calendar.top().order);
      want.push_back(heap.top().order);
      calendar.pop();
      heap.pop();
    }
    EXPECT_TRUE(calendar.empty());
    EXPECT_EQ(got, want) << "bucket " << bucket_s << " s";
  }
}

}  // namespace
}  // namespace sandpic
