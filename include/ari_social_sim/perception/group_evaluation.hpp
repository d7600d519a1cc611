#pragma once

#include <cstddef>
#include <vector>

#include "ari_social_sim/perception/grouping.hpp"

// The F-formation evaluation protocol of GCFF's `ff_evalgroups` (Setti 2015).

namespace ari_social_sim::perception {

/// Match thresholds T of the protocol: a ground-truth group g is found when some detected group d
/// has |d ∩ g| / max(|d|, |g|) >= T. Two thirds ("card") is the default of the literature.
constexpr double kMatchTwoThirds = 2.0 / 3.0;
constexpr double kMatchAll = 1.0;

/// Score of one frame, singletons dropped from both sides.
struct FrameScore {
  size_t detected{0};        ///< |D|: detected groups with >= 2 members.
  size_t truth{0};           ///< |G|: ground-truth groups with >= 2 members.
  size_t true_positives{0};  ///< Ground-truth groups matched by some detected group.
  /// TP / |D|, with the degenerate cases: D = G = {} gives 1; D = {} gives 1; G = {} gives 0.
  double precision{1.0};
  /// TP / |G|, with the degenerate cases: D = G = {} gives 1; D = {} gives 0; G = {} gives 1.
  double recall{1.0};

  size_t false_positives() const { return detected - true_positives; }
  size_t false_negatives() const { return truth - true_positives; }
};

/// Score of a data set: means of the per-frame precision and recall over the annotated frames, F1
/// from these two means (0 when both are 0), plus the pooled counts (which some later papers use
/// instead: TP / (TP + FP) over all frames).
struct EvaluationScore {
  size_t frames{0};
  double precision{0.0};
  double recall{0.0};
  double f1{0.0};
  size_t true_positives{0};
  size_t false_positives{0};
  size_t false_negatives{0};
};

/// Scores the detected groups of one frame against the ground truth. Each ground-truth group is
/// matched against any detected group (first match wins, no one-to-one bookkeeping); with T > 1/2
/// a detected group can match at most one of the disjoint ground-truth groups, so FP >= 0.
/// Throws core::ConfigError unless 1/2 < threshold <= 1.
FrameScore score_frame(const Grouping& detected, const Grouping& truth, double threshold);

/// Scores every frame of `frames` (a frame missing from a table has no groups there, and still
/// counts). Throws core::ConfigError for a bad threshold or an empty frame list.
EvaluationScore evaluate_groups(const GroupTable& detected, const GroupTable& truth,
                                const std::vector<FrameId>& frames, double threshold);

}  // namespace ari_social_sim::perception
