#include "ari_social_sim/perception/transient_ids.hpp"

namespace ari_social_sim::perception {
namespace {

// Each Feistel half holds 12 bits: 2^24 = 16.8 million >= 26^5 = 11.9 million, so cycle-walking
// needs 16.8 / 11.9 = 1.4 rounds of the network per id on average.
constexpr int kHalfBits = 12;
constexpr uint32_t kHalfMask = (1u << kHalfBits) - 1u;

// SplitMix64's finaliser: every input bit flips about half the output bits.
uint64_t mix(uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

TransientIds::TransientIds(core::Rng rng) {
  for (uint64_t& key : round_keys_) {
    key = rng.next_u64();
  }
}

uint32_t TransientIds::permute(uint32_t index) const {
  // A balanced Feistel network is a permutation of [0, 2^24) for any round function; walking
  // its cycle until the value falls below kIdCount restricts it to a permutation of
  // [0, kIdCount) (Black & Rogaway, "Ciphers with arbitrary finite domains", 2002).
  uint32_t x = index;
  do {
    uint32_t left = x >> kHalfBits;
    uint32_t right = x & kHalfMask;
    for (const uint64_t key : round_keys_) {
      const uint32_t next_right = left ^ static_cast<uint32_t>(mix(right ^ key) & kHalfMask);
      left = right;
      right = next_right;
    }
    x = (left << kHalfBits) | right;
  } while (x >= kIdCount);
  return x;
}

std::string TransientIds::next() {
  uint32_t word = permute(static_cast<uint32_t>(issued_ % kIdCount));
  ++issued_;
  // The word's base-26 digits, most significant first.
  std::string id(kLength, 'a');
  for (int i = kLength - 1; i >= 0; --i) {
    id[static_cast<size_t>(i)] = static_cast<char>('a' + word % 26u);
    word /= 26u;
  }
  return id;
}

}  // namespace ari_social_sim::perception
