#pragma once

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/navigation/goal_finder.hpp"

namespace ari_social_sim::navigation {

/// A goal names a person or group perception does not report (unknown or no longer tracked id).
class UnknownTarget : public core::RequestError {
 public:
  using core::RequestError::RequestError;
};

/// No pose can be found or reached for a goal: the pose is inside an obstacle or off the map, a
/// group has no room for ARI, or no collision-free path joins ARI to the goal.
class GoalUnreachable : public core::RequestError {
 public:
  using core::RequestError::RequestError;
};

/// Throws the error of a goal that cannot be started: UnknownTarget or GoalUnreachable.
[[noreturn]] inline void refuse_goal(const GoalFailure& failure) {
  if (failure.kind == GoalFailure::Kind::kUnknownTarget) {
    throw UnknownTarget(failure.reason);
  }
  throw GoalUnreachable(failure.reason);
}

}  // namespace ari_social_sim::navigation
