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

}  // namespace
}  // namespace sandpic
