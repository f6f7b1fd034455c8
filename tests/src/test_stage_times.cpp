#include <gtest/gtest.h>

#include <thread>

#include "src/stage_times.h"

namespace sandpic {
namespace {

TEST(StageTimes, EachStageGetsTheTimeOfItsOwnCallsInItsOrder) {
  StageTimes<3> t({"first", "second", "third"});
  int calls = 0;
  t.time(1, [&] {
    ++calls;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  });
  t.time(1, [&] { ++calls; });
  const ordered_json j = t.json();
  EXPECT_EQ(calls, 2);
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j.begin().key(), "first");
  EXPECT_EQ(std::next(j.begin(), 2).key(), "third");
  EXPECT_EQ(j["first"].get<double>(), 0);
  EXPECT_GE(j["second"].get<double>(), 0.005);  // slept at least that long
  EXPECT_EQ(j["third"].get<double>(), 0);
}

// A stage timed inside another is reported on its own, not twice: the two
// add up to no more than the whole call took.
TEST(StageTimes, AnInnerStageIsTakenOutOfTheOuterOne) {
  StageTimes<2> t({"outer", "inner"});
  const auto start = std::chrono::steady_clock::now();
  t.time_without(0, 1, [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    t.time(1, [] { std::this_thread::sleep_for(std::chrono::milliseconds(30)); });
  });
  const double whole = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ordered_json j = t.json();
  EXPECT_GE(j["inner"].get<double>(), 0.030);
  EXPECT_GE(j["outer"].get<double>(), 0.002);
  EXPECT_LE(j["outer"].get<double>() + j["inner"].get<double>(), whole);
}

}  // namespace
}  // namespace sandpic
