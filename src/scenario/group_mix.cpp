#include "ari_social_sim/scenario/group_mix.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::scenario {
namespace {

using model::Arrangement;

// Groups of the recorded sets (CoffeeBreak and Synth, Cristani 2011) by size and the class
// perception's classify_arrangement gives them (docs/perception_gcff.md, "Geometry of recorded
// groups"). The sets hold no group of four or more.
struct RecordedGroups {
  Arrangement arrangement;
  unsigned size;
  double groups;
};
constexpr RecordedGroups kRecorded[] = {{Arrangement::kLShape, 2, 201},
                                        {Arrangement::kVisAVis, 2, 135},
                                        {Arrangement::kSideBySide, 2, 76},
                                        {Arrangement::kCircle, 3, 199},
                                        {Arrangement::kSideBySide, 3, 34}};

double recorded_groups_of_size(unsigned size) {
  double groups = 0.0;
  for (const RecordedGroups& recorded : kRecorded) {
    groups += recorded.size == size ? recorded.groups : 0.0;
  }
  return groups;
}

}  // namespace

std::vector<GroupKind> recorded_group_mix() {
  std::vector<GroupKind> mix;
  for (const RecordedGroups& recorded : kRecorded) {
    mix.push_back({recorded.arrangement, recorded.size, recorded.groups});
  }
  // Coleman and James' free-forming groups have sizes n >= 1 in a zero-truncated Poisson
  // distribution, P(n) proportional to lambda^n / n!, so P(n) / P(n - 1) = lambda / n. The
  // recorded triads per pair give lambda; each larger size follows from the one below. The
  // recorded classes put every group of three or more that is not a row in the circle class.
  const double lambda = 3.0 * recorded_groups_of_size(3) / recorded_groups_of_size(2);
  double groups = recorded_groups_of_size(3);
  for (unsigned size = 4; size <= kLargestDrawnGroup; ++size) {
    groups *= lambda / size;
    mix.push_back({Arrangement::kCircle, size, groups});
  }
  return mix;
}

std::vector<GroupKind> uniform_group_mix() {
  std::vector<GroupKind> mix;
  const double per_arrangement = 1.0 / std::size(model::kArrangements);
  for (const auto& arrangement : model::kArrangements) {
    const GroupSizeRange sizes = group_sizes_of(arrangement.value);
    for (unsigned size = sizes.min; size <= sizes.max; ++size) {
      mix.push_back({arrangement.value, size, per_arrangement / (sizes.max - sizes.min + 1)});
    }
  }
  return mix;
}

std::vector<GroupKind> kinds_of(const std::vector<GroupKind>& mix,
                                const std::vector<Arrangement>& arrangements) {
  std::vector<GroupKind> kinds;
  std::copy_if(mix.begin(), mix.end(), std::back_inserter(kinds), [&](const GroupKind& kind) {
    return std::find(arrangements.begin(), arrangements.end(), kind.arrangement) !=
           arrangements.end();
  });
  return kinds;
}

std::optional<MixProblem> mix_problem(const std::vector<GroupKind>& mix) {
  double total = 0.0;
  for (const GroupKind& kind : mix) {
    const std::string group =
        std::string(model::to_string(kind.arrangement)) + " of " + std::to_string(kind.size);
    if (!(std::isfinite(kind.weight) && kind.weight >= 0.0)) {
      return MixProblem{"weights that are finite and >= 0",
                        core::number_text(kind.weight) + " for a " + group};
    }
    if (kind.size < 2 || kind.size > kLargestDrawnGroup) {
      return MixProblem{"sizes from 2 to " + std::to_string(kLargestDrawnGroup), "a " + group};
    }
    if (kind.arrangement == Arrangement::kCircle && kind.size < 3) {
      return MixProblem{"circles of 3 or more (the world keeps a pair as a vis-a-vis)",
                        "a " + group};
    }
    total += kind.weight;
  }
  if (!(total > 0.0)) {
    return MixProblem{"a kind of group with a weight > 0",
                      std::to_string(mix.size()) + " kinds, none weighing"};
  }
  return std::nullopt;
}

GroupSizeRange group_sizes_of(Arrangement arrangement) {
  switch (arrangement) {
    case Arrangement::kCircle:
      return {3, 4};
    case Arrangement::kVisAVis:
    case Arrangement::kLShape:
      return {2, 4};
    case Arrangement::kSideBySide:
      return {2, 3};
  }
  return {};
}

}  // namespace ari_social_sim::scenario
