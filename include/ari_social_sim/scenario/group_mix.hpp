#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/model/fformation_arrangement.hpp"

namespace ari_social_sim::scenario {

/// A kind of group random scenes draw: an arrangement and a size, with its weight in the mix.
struct GroupKind {
  model::Arrangement arrangement{model::Arrangement::kCircle};
  unsigned size{2};
  double weight{1.0};
};

/// The groups of recorded gatherings (docs/world.md section 4.8): pairs and triads in each
/// arrangement as often as the recorded sets hold them, and circles of four to six as often as
/// Coleman and James' equilibrium distribution of group sizes gives them, fitted to the recorded
/// ratio of triads to pairs.
std::vector<GroupKind> recorded_group_mix();
/// Each arrangement equally often, then each of its sizes (group_sizes_of) equally often: the
/// mix of random group scenes before issue 31.
std::vector<GroupKind> uniform_group_mix();
/// The kinds of `mix` whose arrangement is one of `arrangements`.
std::vector<GroupKind> kinds_of(const std::vector<GroupKind>& mix,
                                const std::vector<model::Arrangement>& arrangements);

/// The most people a drawn group has.
inline constexpr unsigned kLargestDrawnGroup = 6;
/// What makes a mix unusable: what was expected and what it has.
struct MixProblem {
  std::string expected;
  std::string got;
};
/// The first problem of `mix` (a weight not finite or negative, a size outside 2 to
/// kLargestDrawnGroup, a circle of two, no positive weight), or nothing.
std::optional<MixProblem> mix_problem(const std::vector<GroupKind>& mix);

/// The sizes (people) uniform_group_mix draws a group of `arrangement` with, inclusive.
struct GroupSizeRange {
  unsigned min{2};
  unsigned max{2};
};
GroupSizeRange group_sizes_of(model::Arrangement arrangement);

}  // namespace ari_social_sim::scenario
