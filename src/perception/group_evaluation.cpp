#include "ari_social_sim/perception/group_evaluation.hpp"

#include <algorithm>
#include <sstream>
#include <string>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::perception {
namespace {

// |d ∩ g| / max(|d|, |g|) >= T is tested as |d ∩ g| >= T max(|d|, |g|) with a margin far below one
// member, so that T = 2/3 accepts 2 of 3 whatever the rounding of 2/3.
constexpr double kCountMargin = 1e-9;

void require_threshold(double threshold) {
  if (!(threshold > 0.5 && threshold <= 1.0)) {
    std::ostringstream message;
    message << "group evaluation: threshold: expected a number in (0.5, 1], got " << threshold;
    throw core::ConfigError(message.str());
  }
}

size_t shared_members(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  size_t count = 0;
  for (const std::string& member : a) {
    count += std::count(b.begin(), b.end(), member) > 0 ? 1 : 0;
  }
  return count;
}

const Grouping& groups_of(const GroupTable& table, FrameId frame) {
  static const Grouping kNone;
  const auto found = table.find(frame);
  return found == table.end() ? kNone : found->second;
}

}  // namespace

FrameScore score_frame(const Grouping& detected, const Grouping& truth, double threshold) {
  require_threshold(threshold);
  FrameScore score;
  for (const std::vector<std::string>& group : detected) {
    score.detected += group.size() >= 2 ? 1 : 0;
  }
  for (const std::vector<std::string>& true_group : truth) {
    if (true_group.size() < 2) {
      continue;
    }
    ++score.truth;
    for (const std::vector<std::string>& group : detected) {
      if (group.size() < 2) {
        continue;
      }
      const double needed =
          threshold * static_cast<double>(std::max(group.size(), true_group.size()));
      if (static_cast<double>(shared_members(group, true_group)) >= needed - kCountMargin) {
        ++score.true_positives;
        break;
      }
    }
  }
  // Degenerate frames (1.4): nothing detected is never wrong; nothing to find is always found.
  if (score.detected == 0) {
    score.precision = 1.0;
    score.recall = score.truth == 0 ? 1.0 : 0.0;
  } else if (score.truth == 0) {
    score.precision = 0.0;
    score.recall = 1.0;
  } else {
    score.precision =
        static_cast<double>(score.true_positives) / static_cast<double>(score.detected);
    score.recall = static_cast<double>(score.true_positives) / static_cast<double>(score.truth);
  }
  return score;
}

EvaluationScore evaluate_groups(const GroupTable& detected, const GroupTable& truth,
                                const std::vector<FrameId>& frames, double threshold) {
  require_threshold(threshold);
  if (frames.empty()) {
    throw core::ConfigError("group evaluation: frames: expected at least one annotated frame");
  }
  EvaluationScore total;
  double precision_sum = 0.0;
  double recall_sum = 0.0;
  for (const FrameId frame : frames) {
    const FrameScore score =
        score_frame(groups_of(detected, frame), groups_of(truth, frame), threshold);
    precision_sum += score.precision;
    recall_sum += score.recall;
    total.true_positives += score.true_positives;
    total.false_positives += score.false_positives();
    total.false_negatives += score.false_negatives();
  }
  total.frames = frames.size();
  total.precision = precision_sum / static_cast<double>(frames.size());
  total.recall = recall_sum / static_cast<double>(frames.size());
  const double sum = total.precision + total.recall;
  total.f1 = sum > 0.0 ? 2.0 * total.precision * total.recall / sum : 0.0;
  return total;
}

}  // namespace ari_social_sim::perception
