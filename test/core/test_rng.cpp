#include <gtest/gtest.h>

#include <cmath>

#include "ari_social_sim/core/rng.hpp"

namespace ari_social_sim::core {
namespace {

TEST(Rng, SameSeedSameSequenceOtherSeedOther) {
  Rng a(7), b(7), c(8);
  int differing = 0;
  for (int i = 0; i < 100; ++i) {
    const uint64_t x = a.next_u64();
    EXPECT_EQ(x, b.next_u64());
    differing += x != c.next_u64();
  }
  EXPECT_EQ(differing, 100);
}

TEST(Rng, StreamsAreIndependentOfEachOther) {
  Rng s1 = Rng::for_stream(7, 1), s1_again = Rng::for_stream(7, 1), s2 = Rng::for_stream(7, 2);
  EXPECT_EQ(s1.next_u64(), s1_again.next_u64());
  EXPECT_NE(Rng::for_stream(7, 1).next_u64(), s2.next_u64());
}

TEST(Rng, ExponentialMeanAndNormalMoments) {
  Rng rng(1);
  const int n = 200000;
  double exp_sum = 0, norm_sum = 0, norm_sq = 0;
  for (int i = 0; i < n; ++i) {
    exp_sum += rng.exponential(2.5);
    const double x = rng.normal(1.0, 0.5);
    norm_sum += x;
    norm_sq += x * x;
  }
  // Standard error of the exponential mean: 2.5 / sqrt(2e5) = 0.0056; allow 4 sigma.
  EXPECT_NEAR(exp_sum / n, 2.5, 0.023);
  const double mean = norm_sum / n;
  EXPECT_NEAR(mean, 1.0, 0.005);
  EXPECT_NEAR(std::sqrt(norm_sq / n - mean * mean), 0.5, 0.005);
}

TEST(Rng, CategoricalFollowsWeights) {
  Rng rng(3);
  std::vector<int> counts(3, 0);
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    ++counts[rng.categorical({0.2, 0.0, 0.8})];
  }
  EXPECT_EQ(counts[1], 0);
  EXPECT_NEAR(counts[0] / double(n), 0.2, 0.006);  // 4.7 sigma of sqrt(0.16/1e5)
}

TEST(Rng, UniformIndexStaysInRange) {
  Rng rng(5);
  for (int i = 0; i < 10000; ++i) {
    EXPECT_LT(rng.uniform_index(26), 26u);
  }
}

}  // namespace
}  // namespace ari_social_sim::core
