// The benchmark's statistics: speedups are ratios of means, intervals come
// from quantiles.
#include "foveate/core/stats.hpp"

#include <gtest/gtest.h>

using namespace foveate;

TEST(Stats, MeanOfAlternatingFrameTimesIsTheirAverage) {
  // A half-rate technique: cheap and dear frames in turn. The median of an
  // odd count picks one phase; the mean is what the frames cost on average.
  const std::vector<double> frames{6.7, 298.6, 6.4};
  EXPECT_NEAR(mean(frames), 103.9, 1e-9);
  EXPECT_DOUBLE_EQ(quantile(frames, 0.5), 6.7);
  EXPECT_EQ(mean({}), 0.0);
}

TEST(Stats, QuantileInterpolatesBetweenRanks) {
  const std::vector<double> v{4, 1, 3, 2};  // sorted: 1 2 3 4
  EXPECT_DOUBLE_EQ(quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 2.5);
  EXPECT_EQ(quantile({}, 0.5), 0.0);
}
