// tetcut::percentile, the one percentile of reports, tetcut stats and the benchmarks: nearest
// rank, always one of the samples, NaN when there is none.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tetcut/percentile.hpp"

namespace tetcut {
namespace {

TEST(Percentile, IsTheNearestRankSample) {
  EXPECT_DOUBLE_EQ(percentile({5, 1, 3, 2, 4}, 0.5), 3);
  EXPECT_DOUBLE_EQ(percentile({5, 1, 3, 2, 4}, 0.99), 5);
  EXPECT_DOUBLE_EQ(percentile({5, 1, 3, 2, 4}, 0.4), 2);   // rank ceil(0.4 * 5) = 2: no interpolation
  EXPECT_DOUBLE_EQ(percentile({10, 20, 30, 40}, 0.5), 20);  // not 25
}

TEST(Percentile, ZeroIsTheMinimumAndOneTheMaximum) {
  const std::vector<double> v = {4, 9, 1, 7};
  EXPECT_DOUBLE_EQ(percentile(v, 0.0), 1);
  EXPECT_DOUBLE_EQ(percentile(v, 1.0), 9);
  EXPECT_DOUBLE_EQ(percentile({7}, 0.0), 7);
  EXPECT_DOUBLE_EQ(percentile({7}, 1.0), 7);
}

TEST(Percentile, OfNoSamplesIsNaN) {
  EXPECT_TRUE(std::isnan(percentile({}, 0.5)));
  EXPECT_TRUE(std::isnan(percentile({}, 0.0)));
  EXPECT_TRUE(std::isnan(percentile({}, 1.0)));
}

}  // namespace
}  // namespace tetcut
