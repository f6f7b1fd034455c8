#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "validate/metrics/statistics.h"

namespace sandpic {
namespace {

TEST(Statistics, MedianMeanAndSpread) {
  EXPECT_DOUBLE_EQ(median({3, NAN, 1, 2}), 2);
  EXPECT_DOUBLE_EQ(median({4, 1, 2, 3}), 2.5);
  EXPECT_TRUE(std::isnan(median({NAN})));
  EXPECT_DOUBLE_EQ(mean({1, 2, 6}), 3);
  EXPECT_DOUBLE_EQ(spread({5}), 0);
  EXPECT_DOUBLE_EQ(spread({1, 3}), std::sqrt(2.0));
}

TEST(Statistics, MeanShiftLimitIsStudentsTest) {
  // Spreads √2 and 0 over 2 and 3 seeds: pooled √(2/3), 3 degrees of freedom.
  EXPECT_NEAR(mean_shift_limit({1, 3}, {7, 7, 7}), 3.182 * std::sqrt(2.0 / 3) * std::sqrt(1.0 / 2 + 1.0 / 3), 1e-12);
  EXPECT_DOUBLE_EQ(mean_shift_limit({7, 7, 7}, {1, 3}), mean_shift_limit({1, 3}, {7, 7, 7}));
  EXPECT_NEAR(mean_shift_limit({1, 3}, {5, 7}), 4.303 * std::sqrt(2.0) * 1, 1e-12);
  EXPECT_TRUE(std::isnan(mean_shift_limit({}, {1, 2})));
  EXPECT_TRUE(std::isnan(mean_shift_limit({1}, {2})));
}

// Two sets of seeds drawn from one distribution (a step that changes
// nothing): the limit is passed one time in twenty, where the larger seed
// spread between the means was passed a fifth to a third of the time.
TEST(Statistics, MeanShiftLimitRarelyFailsWhereNothingChanged) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> angle(30, 3);
  for (int n : {2, 3, 6}) {
    int over_limit = 0, over_spread = 0;
    const int trials = 20000;
    for (int t = 0; t < trials; ++t) {
      std::vector<double> a, b;
      for (int i = 0; i < n; ++i) a.push_back(angle(rng)), b.push_back(angle(rng));
      const double shift = std::abs(mean(a) - mean(b));
      over_limit += shift > mean_shift_limit(a, b);
      over_spread += shift > std::max(spread(a), spread(b));
    }
    EXPECT_NEAR(double(over_limit) / trials, 0.05, 0.008) << n << " seeds";
    if (n < 6) EXPECT_GT(over_spread, trials / 6) << n << " seeds";
  }
}

}  // namespace
}  // namespace sandpic
