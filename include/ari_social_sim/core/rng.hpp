#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ari_social_sim::core {

/// The one source of randomness: a seeded xoshiro256** generator with hand-written distributions,
/// so that a seed reproduces a run bit for bit on any standard library (std::*_distribution
/// results are implementation-defined). Owned by the caller and passed by reference; never global.
class Rng {
 public:
  explicit Rng(uint64_t seed);

  /// An independent generator for a sub-stream (e.g. one per human), so that adding a human does
  /// not shift the draws of the others. Same (seed, stream) gives the same generator.
  static Rng for_stream(uint64_t seed, uint64_t stream);

  uint64_t next_u64();
  /// Uniform in [0, 1).
  double uniform();
  /// Uniform in [low, high).
  double uniform(double low, double high);
  /// Uniform in the axis-aligned box [low, high) (x drawn first, then y).
  Eigen::Vector2d uniform_point(const Eigen::Vector2d& low, const Eigen::Vector2d& high);
  /// Uniform integer in [0, count). Precondition: count > 0.
  uint64_t uniform_index(uint64_t count);
  /// Exponential with the given mean (> 0).
  double exponential(double mean);
  /// Normal with the given mean and standard deviation (>= 0).
  double normal(double mean, double stddev);
  /// True with the given probability.
  bool bernoulli(double probability);
  /// Index drawn with probability proportional to weights (non-negative, positive sum).
  size_t categorical(const std::vector<double>& weights);

 private:
  uint64_t state_[4];
};

}  // namespace ari_social_sim::core
