// The estimate a run is checked against before anything is allocated.
#include <gtest/gtest.h>

#include "src/errors.h"
#include "src/estimate.h"

namespace sandpic {
namespace {

std::string refusal(const Estimate& e, const Limits& l) {
  try {
    check_estimate(e, l);
  } catch (const InputError& err) {
    return err.what();
  }
  return "";
}

TEST(Estimate, CountsOneGrainAPixelOfTheRegionAndGrowsWithIt) {
  Scene s;
  auto sim = make_simulator(s);
  const Estimate small = estimate_run(s, *sim);
  EXPECT_EQ(small.grains, int64_t(s.window.width) * s.region.height);
  s.window.width *= 4;
  const Estimate big = estimate_run(s, *sim);
  EXPECT_EQ(big.grains, 4 * small.grains);
  EXPECT_GT(big.bytes, small.bytes);
  EXPECT_GT(big.seconds, small.seconds);
}

TEST(Estimate, AScenePastTheLimitsIsRefusedWithTheFigure) {
  const Estimate e{1000000, 3e9, 7200};
  EXPECT_EQ(refusal(e, Limits{4e9, 8000}), "");
  const std::string memory = refusal(e, Limits{2e9, 8000});
  EXPECT_NE(memory.find("3.0 GB"), std::string::npos) << memory;
  EXPECT_NE(memory.find("--max-memory-gb"), std::string::npos) << memory;
  const std::string time = refusal(e, Limits{4e9, 3600});
  EXPECT_NE(time.find("2.0 h"), std::string::npos) << time;
  EXPECT_NE(time.find("--max-hours"), std::string::npos) << time;
}

TEST(Estimate, TheDefaultMemoryLimitIsThisMachines) {
  EXPECT_GT(machine_memory_bytes(), 1e8);
  const Estimate huge{1, 100 * machine_memory_bytes(), 0};
  EXPECT_NE(refusal(huge, Limits{}), "");
}

}  // namespace
}  // namespace sandpic
