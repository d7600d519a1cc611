#include "ari_social_sim/core/rng.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"

namespace ari_social_sim::core {
namespace {

// splitmix64 spreads a 64-bit seed over the generator state (the seeding xoshiro's authors advise).
uint64_t splitmix64(uint64_t& x) {
  uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

uint64_t rotl(uint64_t x, int k) {
  return (x << k) | (x >> (64 - k));
}

}  // namespace

Rng::Rng(uint64_t seed) {
  uint64_t x = seed;
  for (uint64_t& word : state_) {
    word = splitmix64(x);
  }
}

Rng Rng::for_stream(uint64_t seed, uint64_t stream) {
  uint64_t x = stream;
  return Rng(seed ^ splitmix64(x));
}

uint64_t Rng::next_u64() {
  const uint64_t result = rotl(state_[1] * 5, 7) * 9;
  const uint64_t t = state_[1] << 17;
  state_[2] ^= state_[0];
  state_[3] ^= state_[1];
  state_[1] ^= state_[2];
  state_[0] ^= state_[3];
  state_[2] ^= t;
  state_[3] = rotl(state_[3], 45);
  return result;
}

double Rng::uniform() {
  // The top 53 bits give every double in [0, 1) on a 2^-53 lattice.
  return static_cast<double>(next_u64() >> 11) * 0x1.0p-53;
}

double Rng::uniform(double low, double high) {
  return low + (high - low) * uniform();
}

Eigen::Vector2d Rng::uniform_point(const Eigen::Vector2d& low, const Eigen::Vector2d& high) {
  // A braced list is evaluated in order: x is drawn first.
  return {uniform(low.x(), high.x()), uniform(low.y(), high.y())};
}

uint64_t Rng::uniform_index(uint64_t count) {
  ARI_CHECK(count > 0);
  // Rejection keeps the draw unbiased for counts that do not divide 2^64.
  const uint64_t limit = UINT64_MAX - UINT64_MAX % count;
  uint64_t draw = next_u64();
  while (draw >= limit) {
    draw = next_u64();
  }
  return draw % count;
}

double Rng::exponential(double mean) {
  ARI_CHECK(mean > 0.0);
  return -mean * std::log1p(-uniform());
}

double Rng::normal(double mean, double stddev) {
  // Box-Muller; one of the pair is dropped so the generator state stays a pure function of draws.
  const double u1 = 1.0 - uniform();  // (0, 1]
  const double u2 = uniform();
  return mean + stddev * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

bool Rng::bernoulli(double probability) {
  return uniform() < probability;
}

size_t Rng::categorical(const std::vector<double>& weights) {
  ARI_CHECK(!weights.empty());
  double total = 0.0;
  for (double w : weights) {
    total += w;
  }
  ARI_CHECK(total > 0.0);
  double draw = uniform() * total;
  for (size_t i = 0; i < weights.size(); ++i) {
    if (draw < weights[i]) {
      return i;
    }
    draw -= weights[i];
  }
  // Rounding can leave a sliver past the last bin; it belongs to the last positive weight.
  for (size_t i = weights.size(); i-- > 0;) {
    if (weights[i] > 0.0) {
      return i;
    }
  }
  return weights.size() - 1;
}

}  // namespace ari_social_sim::core
